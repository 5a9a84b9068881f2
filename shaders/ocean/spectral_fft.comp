// One pass of the spectral ocean's inverse 2D FFT: every row (or, with
// SWELL_FFT_VERTICAL 1, every column) of every cascade, one workgroup each,
// transformed in place through shared memory: radix-2 decimation in time,
// inputs in bit-reversed order, log2(N) stages of butterflies with
// twiddles exp(+2 pi i j / size) (the inverse transform, unnormalised, as
// the CPU twin's kissfft computes it). Each sample carries two complex
// numbers per image, so one pass transforms all four packed fields. The row
// pass (the first) evolves its samples itself (spectraAt() below) and
// writes the images; the column pass reads them back.
//
// Each invocation takes a group of four samples through two stages at a
// time in registers (the four a stage of span s and the next of span 2s
// join), so the samples go through shared memory once every two stages;
// the twiddles come from a table of N/2 made once. A software rasteriser
// scatters and gathers shared memory lane by lane, which made those trips
// most of the transform's cost. The butterflies, their order and their
// twiddles are those of one stage at a time, so the results are the same
// bits: a table entry's angle is the stage's angle times a power of two
// over the same power of two, which float arithmetic keeps exact.
#include "swell/gpu/bindings.h"
#include "swell/gpu/ocean.h"
#include "gpu/constants.glsl"

#if SWELL_FFT_LOG2_SIZE % 2 != 0
#error "the stages go two at a time: SWELL_FFT_SIZE must be a power of 4"
#endif
#define SWELL_FFT_QUARTER (SWELL_FFT_SIZE / 4)
layout(local_size_x = SWELL_FFT_QUARTER) in;

#if SWELL_FFT_VERTICAL
layout(binding = SWELL_IMAGE_SPECTRAL_DISPLACEMENT, rgba32f) uniform image2DArray spectrumA;
layout(binding = SWELL_IMAGE_SPECTRAL_DERIVATIVES, rgba32f) uniform image2DArray spectrumB;
// The shading's copy of the derivatives (layers 0 .. SWELL_FFT_CASCADES - 1)
// and the slopes' second moments (the next SWELL_FFT_CASCADES), in half
// floats: what the water's pixels filter (src/ocean/spectral/gpu/spectral_gpu.cpp).
layout(binding = SWELL_IMAGE_SPECTRAL_SLOPES, rgba16f) uniform writeonly image2DArray slopes;
#else
layout(binding = SWELL_IMAGE_SPECTRAL_DISPLACEMENT, rgba32f) uniform writeonly image2DArray spectrumA;
layout(binding = SWELL_IMAGE_SPECTRAL_DERIVATIVES, rgba32f) uniform writeonly image2DArray spectrumB;

// The row pass's samples: the spectra at a time (src/ocean/spectral/
// spectral_field.h has the formulas; evolve() there is the CPU twin): per
// sample,
//   hhat = h0 exp(-i w t) + conj(h0(-k)) exp(i w t)
// and the displacement and slope fields packed two real fields to a complex
// sample, ready for the inverse transform. Evolved as they are read, they
// are never written out before the transform.
// h0.re, h0.im, conj(h0(-k)).re, .im
layout(binding = SWELL_IMAGE_SPECTRAL_INITIAL, rgba32f) uniform readonly image2DArray initial;
// w, rad/s, as a double's two words
layout(binding = SWELL_IMAGE_SPECTRAL_OMEGA, rg32ui) uniform readonly uimage2DArray omega;

uniform double time_s;                         // simulation time, s
uniform float choppiness;                      // lambda
uniform float patchSize_m[SWELL_FFT_CASCADES]; // L of each cascade, m

vec2 cmul(vec2 a, vec2 b) { return vec2(a.x * b.x - a.y * b.y, a.x * b.y + a.y * b.x); }
vec2 timesI(vec2 a) { return vec2(-a.y, a.x); }

// The two packed spectra at sample p (x, y, cascade):
// a = (Dx + i Dy), (Dz + i dDx/dz); b = (dDy/dx + i dDy/dz), (dDx/dx + i dDz/dz).
void spectraAt(ivec3 p, out vec4 a, out vec4 b)
{
    vec4 h0 = imageLoad(initial, p);
    double w = packDouble2x32(imageLoad(omega, p).xy);
    // The phase in double, reduced before it becomes float: exact after days.
    const double twoPi = 6.283185307179586LF;
    float phase = float(mod(w * time_s, twoPi));
    vec2 e = vec2(cos(phase), sin(phase));
    vec2 h = cmul(h0.xy, vec2(e.x, -e.y)) + cmul(h0.zw, e);
    if (w == 0.0LF)
        h = vec2(0.0);
    int n = SWELL_FFT_SIZE;
    vec2 f = vec2(p.x < n / 2 ? p.x : p.x - n, p.y < n / 2 ? p.y : p.y - n);
    vec2 k = f * (6.28318530717958647 / patchSize_m[p.z]);
    float kLength = max(length(k), 1e-30);
    vec2 dx = timesI(h) * (choppiness * k.x / kLength);
    vec2 dz = timesI(h) * (choppiness * k.y / kLength);
    vec2 dxx = -h * (choppiness * k.x * k.x / kLength);
    vec2 dzz = -h * (choppiness * k.y * k.y / kLength);
    vec2 dxz = -h * (choppiness * k.x * k.y / kLength);
    a = vec4(dx + timesI(h), dz + timesI(dxz));
    // The slopes' pair, i h kx + i (i h kz), written out: NVIDIA's compiler
    // (driver 580.159.04, H200) got dyx + timesI(dyz) with dyx = timesI(h) kx,
    // dyz = timesI(h) kz wrong, and both slopes of every cascade were off by
    // up to 1.5 times their rms (tests/gl/test_spectral_fields.cpp).
    b = vec4(-h.y * k.x - h.x * k.y, h.x * k.x - h.y * k.y, dxx + timesI(dzz));
}
#endif

shared vec4 bufferA[SWELL_FFT_SIZE];
shared vec4 bufferB[SWELL_FFT_SIZE];
// twiddle[k] = exp(i pi k / (N/2)), k < N/2.
shared vec2 twiddle[SWELL_FFT_SIZE / 2];

ivec3 sampleAt(int i)
{
    int line = int(gl_WorkGroupID.x), cascade = int(gl_WorkGroupID.y);
#if SWELL_FFT_VERTICAL
    return ivec3(line, i, cascade);
#else
    return ivec3(i, line, cascade);
#endif
}

// Two complex numbers (xy, zw) times one (w).
vec4 cmul2(vec2 w, vec4 v) { return vec4(w.x * v.x - w.y * v.y, w.x * v.y + w.y * v.x, w.x * v.z - w.y * v.w, w.x * v.w + w.y * v.z); }

int bitReversed(int i) { return int(bitfieldReverse(uint(i)) >> (32 - SWELL_FFT_LOG2_SIZE)); }

// The butterfly of a stage of span `span` joining samples e and o, whose
// place within its group of 2 * span is m: e + w o and e - w o.
void butterfly(inout vec4 eA, inout vec4 eB, inout vec4 oA, inout vec4 oB, int m, int span)
{
    vec2 w = twiddle[m * (SWELL_FFT_SIZE / 2 / span)];
    vec4 wA = cmul2(w, oA), wB = cmul2(w, oB);
    oA = eA - wA;
    oB = eB - wB;
    eA = eA + wA;
    eB = eB + wB;
}

void main()
{
    int t = int(gl_LocalInvocationID.x);
    for (int k = t; k < SWELL_FFT_SIZE / 2; k += SWELL_FFT_QUARTER) {
        float angle = SWELL_PI * float(k) / float(SWELL_FFT_SIZE / 2);
        twiddle[k] = vec2(cos(angle), sin(angle));
    }
    for (int i = t; i < SWELL_FFT_SIZE; i += SWELL_FFT_QUARTER) {
#if SWELL_FFT_VERTICAL
        bufferA[bitReversed(i)] = imageLoad(spectrumA, sampleAt(i));
        bufferB[bitReversed(i)] = imageLoad(spectrumB, sampleAt(i));
#else
        vec4 a, b;
        spectraAt(sampleAt(i), a, b);
        bufferA[bitReversed(i)] = a;
        bufferB[bitReversed(i)] = b;
#endif
    }
    barrier();
    // Stages of span s and 2s: the group of 4s holding invocation t's four
    // samples starts at base; m is their place within the first stage's group.
    for (int span = 1; span < SWELL_FFT_SIZE; span *= 4) {
        int m = t & (span - 1);
        int base = 4 * (t - m);
        int p0 = base + m, p1 = p0 + span, p2 = p0 + 2 * span, p3 = p0 + 3 * span;
        vec4 a0 = bufferA[p0], a1 = bufferA[p1], a2 = bufferA[p2], a3 = bufferA[p3];
        vec4 b0 = bufferB[p0], b1 = bufferB[p1], b2 = bufferB[p2], b3 = bufferB[p3];
        butterfly(a0, b0, a1, b1, m, span);
        butterfly(a2, b2, a3, b3, m, span);
        butterfly(a0, b0, a2, b2, m, 2 * span);
        butterfly(a1, b1, a3, b3, m + span, 2 * span);
        // The groups part the samples: no other invocation reads these four.
        bufferA[p0] = a0;
        bufferA[p1] = a1;
        bufferA[p2] = a2;
        bufferA[p3] = a3;
        bufferB[p0] = b0;
        bufferB[p1] = b1;
        bufferB[p2] = b2;
        bufferB[p3] = b3;
        barrier();
    }
    for (int i = t; i < SWELL_FFT_SIZE; i += SWELL_FFT_QUARTER) {
        ivec3 p = sampleAt(i);
        imageStore(spectrumA, p, bufferA[i]);
        imageStore(spectrumB, p, bufferB[i]);
#if SWELL_FFT_VERTICAL
        // The column pass ends with the fields themselves: the derivatives
        // again for shading, and the slopes' second moments beside them, in
        // layers SWELL_FFT_CASCADES and up of the slopes' image, so one mip
        // chain filters both (LEAN mapping: Olano & Baker 2010, "LEAN
        // Mapping", I3D, sec. 3: over any footprint, E[s^2] - E[s]^2 from
        // the two is the slope variance the footprint's mean slope leaves
        // out). The moments' fourth channel holds the cross derivative
        // dDx/dz (= dDz/dx), the normal's one term the derivatives' four
        // leave out, so that it is filtered by the footprint as they are.
        vec2 slope = bufferB[i].xy; // dDy/dx, dDy/dz
        imageStore(slopes, p, bufferB[i]);
        imageStore(slopes, ivec3(p.xy, p.z + SWELL_FFT_CASCADES),
                   vec4(slope.x * slope.x, slope.y * slope.y, slope.x * slope.y, bufferA[i].w));
#endif
    }
}
