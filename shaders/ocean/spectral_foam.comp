// Whitecaps of the spectral ocean, kept in the world: where the surface of
// the breaking-scale cascades folds (the Jacobian of the horizontal
// displacement, J = (1 + dDx/dx)(1 + dDz/dz) - (dDx/dz)(dDz/dx), is low;
// Tessendorf 2001, sec. 4.4; Dupuy & Bruneton 2012) against its own
// neighbourhood (swell/gpu/breaking.h: the breaking score), foam is made;
// everywhere, foam decays as exp(-dt/tau) (tau the foam's e-folding time:
// 3.85 s on salt water, Monahan & O'Muircheartaigh 1986). Foam stays where
// the wave broke, on texels fixed in the world: each level is a window of
// SWELL_FOAM_SIZE^2 texels around the grid centre, stored toroidally (world
// texel w at w mod N), so a moving camera only brings in the texels along
// the window's edges, which start without history.
// The Jacobian is the sum of the cascades' gradients at each one's warped
// point, exactly as the CPU twin computes it for the ramp
// (swell::spectral::CpuSurface::foldJacobianAt); the score is
// swell::spectral::breakingScore's, in the same order of sums, and the
// ramps each level's, found for each sea (swell::spectral::calibratedBreakingRamps).
#include "swell/gpu/bindings.h"
#include "swell/gpu/breaking.h"
#include "swell/gpu/ocean.h"
// Built with SWELL_OCEAN_FILE naming ocean/spectral.glsl.
#include "ocean.glsl"

layout(local_size_x = SWELL_FOAM_STEP_GROUP, local_size_y = SWELL_FOAM_STEP_GROUP) in;

layout(binding = SWELL_IMAGE_SPECTRAL_FOAM, r16f) uniform image2DArray foam; // 0..1, one layer a level

uniform float decay;            // exp(-dt/tau) since the last step; 0 starts afresh
uniform float breakingStart[SWELL_FOAM_LEVELS]; // each level's breaking score below which foam is made
uniform float breakingSpan[SWELL_FOAM_LEVELS];  // ... in full this much further down
uniform int foamCascades;       // cascades 0..foamCascades-1 fold into foam, at every level
uniform ivec2 windowOrigin[SWELL_FOAM_LEVELS];   // world texel index of each window's first texel (x, z)
uniform ivec2 previousOrigin[SWELL_FOAM_LEVELS]; // ... at the last step
uniform ivec2 centreIndex[SWELL_FOAM_LEVELS];    // world texel index holding the grid centre
uniform vec2 centreFraction[SWELL_FOAM_LEVELS];  // the grid centre within that texel, 0..1
uniform float texel_m[SWELL_FOAM_LEVELS];        // each level's texel size, m

// The workgroup's tile of world texels and the margin around it the boxes
// and the spread reach: J - 1 of each, computed once (the tile's 16^2
// texels take 22^2 J's, not 16^2 * 25); then each row's sums over 5 texels
// (of J - 1 and its square) for every box start along it, which the boxes
// down the row share; then the foam each texel of the tile and the
// spread's margin makes.
const int kRadius = SWELL_FOAM_BREAKING_RADIUS;
const int kSide = 2 * kRadius + 1;
const int kSpread = SWELL_FOAM_BREAKING_SPREAD;
const int kMargin = kRadius + kSpread;
const int kSpan = SWELL_FOAM_STEP_GROUP + 2 * kMargin;
const int kMadeSpan = SWELL_FOAM_STEP_GROUP + 2 * kSpread;
const int kGroup = SWELL_FOAM_STEP_GROUP * SWELL_FOAM_STEP_GROUP;
shared float tileJ[kSpan * kSpan];                // J - 1
shared float rowSum[kSpan * kMadeSpan];           // sum over 5 of a row from each box start
shared float rowSquares[kSpan * kMadeSpan];       // ... of the squares
shared float tileMade[kMadeSpan * kMadeSpan];

// The foam the texel whose box starts at `box` (in tileJ) makes: its
// breaking score (J - mean) / deviation over the box, as
// swell::spectral::breakingScore sums it, on the level's ramp.
float madeAt(ivec2 box, int level)
{
    float sum = 0.0, squares = 0.0;
    for (int dz = 0; dz < kSide; ++dz) {
        sum += rowSum[(box.y + dz) * kMadeSpan + box.x];
        squares += rowSquares[(box.y + dz) * kMadeSpan + box.x];
    }
    const float count = float(kSide * kSide);
    float mean = sum / count;
    float variance = max(squares / count - mean * mean, 0.0);
    float deviation = max(sqrt(variance), SWELL_FOAM_LEAST_DEVIATION);
    float score = (tileJ[(box.y + kRadius) * kSpan + box.x + kRadius] - mean) / deviation;
    // No foam from the start up, full foam a span below it.
    return clamp((breakingStart[level] - score) / breakingSpan[level], 0.0, 1.0);
}

void main()
{
    int level = int(gl_GlobalInvocationID.z);
    // Invocations run over the window in world order (its texels from its
    // origin), so a tile's neighbours are the world's: texel w is stored at
    // w mod N.
    ivec2 origin = windowOrigin[level];
    ivec2 tileStart = origin + ivec2(gl_WorkGroupID.xy) * SWELL_FOAM_STEP_GROUP - kMargin;
    for (int i = int(gl_LocalInvocationIndex); i < kSpan * kSpan; i += kGroup) {
        ivec2 world = tileStart + ivec2(i % kSpan, i / kSpan);
        // The texel's centre from the grid centre, m. Coarser levels sample
        // the same field more sparsely (level 1 at two samples to cascade
        // 1's shortest wave): averaging 2 x 2 samples a texel there made the
        // foam steps of a still's replayed history take 3.4 s instead of
        // about 1 s on llvmpipe.
        vec2 restOffset_m = (vec2(world - centreIndex[level]) + 0.5 - centreFraction[level]) * texel_m[level];
        tileJ[i] = foldJacobian(restOffset_m, foamCascades) - 1.0;
    }
    memoryBarrierShared();
    barrier();
    for (int i = int(gl_LocalInvocationIndex); i < kSpan * kMadeSpan; i += kGroup) {
        int row = i / kMadeSpan, start = i % kMadeSpan;
        float sum = 0.0, squares = 0.0;
        for (int dx = 0; dx < kSide; ++dx) {
            float d = tileJ[row * kSpan + start + dx];
            sum += d;
            squares += d * d;
        }
        rowSum[i] = sum;
        rowSquares[i] = squares;
    }
    memoryBarrierShared();
    barrier();
    for (int i = int(gl_LocalInvocationIndex); i < kMadeSpan * kMadeSpan; i += kGroup)
        tileMade[i] = madeAt(ivec2(i % kMadeSpan, i / kMadeSpan), level);
    memoryBarrierShared();
    barrier();

    // A breaking whitens the water around it (swell/gpu/breaking.h): the
    // most foam made within the level's spread.
    ivec2 local = ivec2(gl_LocalInvocationID.xy);
    int spread = SWELL_FOAM_BREAKING_SPREAD_AT(level);
    float made = 0.0;
    for (int dz = -spread; dz <= spread; ++dz)
        for (int dx = -spread; dx <= spread; ++dx)
            made = max(made, tileMade[(local.y + kSpread + dz) * kMadeSpan + local.x + kSpread + dx]);

    ivec2 world = tileStart + kMargin + local;
    ivec3 p = ivec3(world & (SWELL_FOAM_SIZE - 1), level);
    // Whether the window held this world texel at the last step.
    ivec2 sinceLast = world - previousOrigin[level];
    bool kept = all(greaterThanEqual(sinceLast, ivec2(0))) && all(lessThan(sinceLast, ivec2(SWELL_FOAM_SIZE)));
    float old = kept ? imageLoad(foam, p).r * decay : 0.0;
    imageStore(foam, p, vec4(max(old, made)));
}
