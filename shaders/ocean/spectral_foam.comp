// Whitecaps of the spectral ocean, kept in the world: where the surface of
// the breaking-scale cascades folds (the Jacobian of the horizontal
// displacement, J = (1 + dDx/dx)(1 + dDz/dz) - (dDx/dz)(dDz/dx), falls below
// a threshold; Tessendorf 2001, sec. 4.4; Dupuy & Bruneton 2012), foam is
// made; everywhere, foam decays as exp(-dt/tau) (tau the foam's e-folding
// time: 3.85 s on salt water, Monahan & O'Muircheartaigh 1986). Foam stays
// where the wave broke, on texels fixed in the world: each level is a window
// of SWELL_FOAM_SIZE^2 texels around the grid centre, stored toroidally
// (world texel w at w mod N), so a moving camera only brings in the texels
// along the window's edges, which start without history.
// The Jacobian is the sum of the cascades' gradients at each one's warped
// point, exactly as the CPU twin computes it for the threshold
// (swell::spectral::CpuSurface::foldJacobianAt).
#include "swell/gpu/bindings.h"
#include "swell/gpu/ocean.h"
// Built with SWELL_OCEAN_FILE naming ocean/spectral.glsl.
#include "ocean.glsl"

layout(local_size_x = SWELL_FOAM_STEP_GROUP, local_size_y = SWELL_FOAM_STEP_GROUP) in;

layout(binding = SWELL_IMAGE_SPECTRAL_FOAM, r16f) uniform image2DArray foam; // 0..1, one layer a level

uniform float decay;         // exp(-dt/tau) since the last step; 0 starts afresh
uniform float foldThreshold; // J below which foam is made
uniform float foldSoftness;  // foam fades out over this much J above the threshold
uniform int foamCascades;    // cascades 0..foamCascades-1 fold into foam, at every level
uniform ivec2 windowOrigin[SWELL_FOAM_LEVELS];   // world texel index of each window's first texel (x, z)
uniform ivec2 previousOrigin[SWELL_FOAM_LEVELS]; // ... at the last step
uniform ivec2 centreIndex[SWELL_FOAM_LEVELS];    // world texel index holding the grid centre
uniform vec2 centreFraction[SWELL_FOAM_LEVELS];  // the grid centre within that texel, 0..1
uniform float texel_m[SWELL_FOAM_LEVELS];        // each level's texel size, m

void main()
{
    ivec3 p = ivec3(gl_GlobalInvocationID);
    int level = p.z;
    // The world texel this stored texel holds now, and whether it held it
    // at the last step.
    ivec2 origin = windowOrigin[level];
    ivec2 world = origin + ((p.xy - origin) & (SWELL_FOAM_SIZE - 1));
    ivec2 sinceLast = world - previousOrigin[level];
    bool kept = all(greaterThanEqual(sinceLast, ivec2(0))) && all(lessThan(sinceLast, ivec2(SWELL_FOAM_SIZE)));
    float old = kept ? imageLoad(foam, p).r * decay : 0.0;

    // The texel's centre from the grid centre, m. Coarser levels sample the
    // same field more sparsely (level 1 at two samples to cascade 1's
    // shortest wave): averaging 2 x 2 samples a texel there made the foam
    // steps of a still's replayed history take 3.4 s instead of about 1 s
    // on llvmpipe.
    vec2 restOffset_m = (vec2(world - centreIndex[level]) + 0.5 - centreFraction[level]) * texel_m[level];
    float jacobian = foldJacobian(restOffset_m, foamCascades);
    // Full foam at the threshold, fading over foldSoftness above it: the
    // cover the calibration counts is where J < threshold.
    float made = clamp(1.0 - (jacobian - foldThreshold) / foldSoftness, 0.0, 1.0);
    imageStore(foam, p, vec4(max(old, made)));
}
