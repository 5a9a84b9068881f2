// The spectral ocean's spectra at a time (src/ocean/spectral/spectral_field.h
// has the formulas; evolve() there is the CPU twin): per sample,
//   hhat = h0 exp(-i w t) + conj(h0(-k)) exp(i w t)
// and the displacement and slope fields packed two real fields to a complex
// sample, ready for the inverse transform.
#include "swell/shader_constants.h"

layout(local_size_x = 16, local_size_y = 16) in;

layout(binding = 0, rgba32f) uniform readonly image2DArray initial;  // h0.re, h0.im, conj(h0(-k)).re, .im
layout(binding = 1, rg32ui) uniform readonly uimage2DArray omega;    // w, rad/s, as a double's two words
layout(binding = 2, rgba32f) uniform writeonly image2DArray spectrumA; // (Dx + i Dy), (Dz + i dDx/dz)
layout(binding = 3, rgba32f) uniform writeonly image2DArray spectrumB; // (dDy/dx + i dDy/dz), (dDx/dx + i dDz/dz)

uniform double time_s;                         // simulation time, s
uniform float choppiness;                      // lambda
uniform float patchSize_m[SWELL_FFT_CASCADES]; // L of each cascade, m

vec2 cmul(vec2 a, vec2 b) { return vec2(a.x * b.x - a.y * b.y, a.x * b.y + a.y * b.x); }
vec2 timesI(vec2 a) { return vec2(-a.y, a.x); }

void main()
{
    ivec3 p = ivec3(gl_GlobalInvocationID);
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
    vec2 dyx = timesI(h) * k.x, dyz = timesI(h) * k.y;
    vec2 dxx = -h * (choppiness * k.x * k.x / kLength);
    vec2 dzz = -h * (choppiness * k.y * k.y / kLength);
    vec2 dxz = -h * (choppiness * k.x * k.y / kLength);
    imageStore(spectrumA, p, vec4(dx + timesI(h), dz + timesI(dxz)));
    imageStore(spectrumB, p, vec4(dyx + timesI(dyz), dxx + timesI(dzz)));
}
