// One pass of the spectral ocean's inverse 2D FFT: every row (or, with
// SWELL_FFT_VERTICAL 1, every column) of every cascade, one workgroup each,
// transformed in place through shared memory: radix-2 decimation in time,
// inputs in bit-reversed order, log2(N) stages of butterflies with
// twiddles exp(+2 pi i j / size) (the inverse transform, unnormalised, as
// the CPU twin's kissfft computes it). Each sample carries two complex
// numbers per image, so one pass transforms all four packed fields.
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
#include "swell/shader_constants.h"

#if SWELL_FFT_LOG2_SIZE % 2 != 0
#error "the stages go two at a time: SWELL_FFT_SIZE must be a power of 4"
#endif
#define SWELL_FFT_QUARTER (SWELL_FFT_SIZE / 4)
layout(local_size_x = SWELL_FFT_QUARTER) in;

layout(binding = 2, rgba32f) uniform image2DArray spectrumA;
layout(binding = 3, rgba32f) uniform image2DArray spectrumB;

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
        float angle = 3.14159265358979 * float(k) / float(SWELL_FFT_SIZE / 2);
        twiddle[k] = vec2(cos(angle), sin(angle));
    }
    for (int i = t; i < SWELL_FFT_SIZE; i += SWELL_FFT_QUARTER) {
        bufferA[bitReversed(i)] = imageLoad(spectrumA, sampleAt(i));
        bufferB[bitReversed(i)] = imageLoad(spectrumB, sampleAt(i));
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
        imageStore(spectrumA, sampleAt(i), bufferA[i]);
        imageStore(spectrumB, sampleAt(i), bufferB[i]);
    }
}
