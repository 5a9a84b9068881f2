// Whitecaps of the spectral ocean: where a cascade's surface folds (the
// Jacobian of the horizontal displacement, J = (1 + dDx/dx)(1 + dDz/dz) -
// (dDx/dz)^2, falls below a threshold; Tessendorf 2001, sec. 4.4; Dupuy &
// Bruneton 2012), foam is made; everywhere, foam decays as exp(-dt/tau)
// (tau the foam's e-folding time: 3.85 s on salt water, Monahan &
// O'Muircheartaigh 1986). Foam stays where the wave broke: it lives in the
// cascade's world-fixed patch, not on the moving crest.
#include "swell/shader_constants.h"

layout(local_size_x = 16, local_size_y = 16) in;

layout(binding = 2, rgba32f) uniform readonly image2DArray displacement; // .w: dDx/dz
layout(binding = 3, rgba32f) uniform readonly image2DArray derivatives;  // .z: dDx/dx, .w: dDz/dz
layout(binding = 4, r16f) uniform image2DArray foam;                     // 0..1

uniform float decay;              // exp(-dt/tau) since the last step; 0 starts afresh
uniform float foldThreshold[SWELL_FFT_CASCADES]; // J below which each cascade makes foam
uniform float foldSoftness;       // foam fades out over this much J above the threshold
uniform int foamCascades;         // cascades 0..foamCascades-1 make foam; the rest only decay

void main()
{
    ivec3 p = ivec3(gl_GlobalInvocationID);
    float old = imageLoad(foam, p).r * decay;
    float made = 0.0;
    if (p.z < foamCascades) {
        float dxz = imageLoad(displacement, p).w;
        vec4 d = imageLoad(derivatives, p);
        float jacobian = (1.0 + d.z) * (1.0 + d.w) - dxz * dxz;
        // Full foam at the threshold, fading over foldSoftness above it: the
        // cover the calibration counts is where J < threshold.
        made = clamp(1.0 - (jacobian - foldThreshold[p.z]) / foldSoftness, 0.0, 1.0);
    }
    imageStore(foam, p, vec4(max(old, made)));
}
