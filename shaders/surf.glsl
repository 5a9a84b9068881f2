// The surf: whitewater where the coast's waves break, for every wave model
// (each binds the coast field's block and textures, coast_field.glsl). The
// coast field's common texel says how hard the waves break at each point
// (its fourth channel: the share of the shoaled height the breaking cut
// took, swell::CoastCommonSample::breaking); the drawn surface itself says
// where in its wave a point is, so the foam rides the crests rather than
// lying in a static band:
// - the roller: fresh, dense foam on a breaking crest and the face just
//   ahead of it, the bores that run up the beach in the inner surf;
// - behind each crest its foam thins into lace and fades over the wave's
//   cycle, leaving a faint sheet of old foam over the whole surf zone.
// The foam takes the whitecaps' look (whitecap_foam.glsl) on lattices of
// its own, anchored to the world at the render origin.
// Called by water.frag's shading and its labels alike.
#ifndef SWELL_SURF_GLSL
#define SWELL_SURF_GLSL
#include "coast_field.glsl"
#include "gpu/constants.glsl"
#include "whitecap_foam.glsl"

// The roller: the foam is a crest's own, breaking now, where the water
// stands above kSurfRollerStart of the crest's height, on the face it
// tumbles down as on the crest, and whole above kSurfRollerFull of it.
// Keyed on the height rather than on the phase, so the roller has no edge
// where a crest stands lower than gamma h / 2 (the wind's waves share the
// height the cut leaves).
const float kSurfRollerStart = -0.2;
const float kSurfRollerFull = 0.5;
// Behind the crest the surf's foam fades as exp(-phase / this): a fifth
// of it half way to the trough, 4% at the trough (chosen by eye: lace
// over the back of the wave, open water before the next roller, as in
// photographs of spilling surf from above; 1.3 rad covered the back of the
// wave in a grey carpet of lace seen from 7 m).
const float kSurfFadePhase_rad = 1.0;
// The rise towards the shore (m per m) over which the lace fades in behind
// a trough: a tenth of the slope of a 1 m wave 60 m long.
const float kSurfLaceRise = 0.01;
// The amount the shading draws as a breaking's own (dense, bright): the
// foam less than half a radian behind its crest, exp(-0.5 / 1.0).
const float kSurfFreshAmount = 0.61;
// The sheet of old foam over the whole surf zone, from the waves before:
// this much of the fresh foam's amount (chosen by eye).
const float kSurfOldFoam = 0.05;
// The breaking measure at which the surf is at its full strength: a crest
// that has lost a fifth of its shoaled height is breaking in earnest.
const float kSurfFullBreaking = 0.2;
// The breaker index the coast field cut the waves with (SWELL_BREAKER_INDEX,
// swell::kBreakerIndex, McCowan 1894): in the surf the waves are gamma h
// high, which places a point's elevation in its wave.
const float kSurfBreakerIndex = SWELL_BREAKER_INDEX;

// The surf foam's texture: the whitecaps' lattices (src/ocean/foam/
// foam_texture.cpp: 3.3 m cells down to 3.4 cm, each turned by the golden
// angle from the last, and a warp), without the wind's streaks, which the
// surf's foam does not show.
const FoamNoise kSurfNoise[SWELL_FOAM_NOISE_MAPS] = FoamNoise[](
    FoamNoise(vec4(-0.221211, 0.202647, -0.202647, -0.221211), vec2(17.310, 83.400), 0.300000),
    FoamNoise(vec4(0.065569, -0.747128, 0.747128, 0.065569), vec2(34.620, 36.100), 0.750000),
    FoamNoise(vec4(1.140823, 1.488001, -1.488001, 1.140823), vec2(51.930, 77.800), 1.875000),
    FoamNoise(vec4(-4.615844, -0.816478, 0.816478, -4.615844), vec2(69.240, 30.500), 4.687500),
    FoamNoise(vec4(9.887757, -6.289782, 6.289782, 9.887757), vec2(86.550, 72.200), 11.718750),
    FoamNoise(vec4(-7.605595, 28.292434, -28.292434, -7.605595), vec2(6.860, 24.900), 29.296875),
    FoamNoise(vec4(-0.055309, -0.106494, 0.106494, -0.055309), vec2(24.170, 66.600), 0.120000));

// The gradient of the coast field's depth at the cell's point, per metre:
// its bilinear reading's, from the cell's edges.
vec2 surfDepthGradient(CoastCell cell)
{
    CoastCell edge = cell;
    edge.f = vec2(0.0, cell.f.y);
    float west = coastCommonAt(edge).x;
    edge.f = vec2(1.0, cell.f.y);
    float east = coastCommonAt(edge).x;
    edge.f = vec2(cell.f.x, 0.0);
    float south = coastCommonAt(edge).x;
    edge.f = vec2(cell.f.x, 1.0);
    float north = coastCommonAt(edge).x;
    return vec2(east - west, north - south) / coastCell_m;
}

// The surf's foam amount at a rest point (from the grid centre), given the
// drawn surface there: its height above the mean level (m) and its normal.
// The waves run up the depth's gradient; a point's place in its wave is
// found from its height in a wave gamma h high and the sign of the
// surface's rise towards the shore (behind a crest the water rises
// towards it): its phase since the crest passed, acos(height).
float surfAmount(vec2 restOffset_m, float elevation_m, vec3 normal)
{
    CoastCell cell = coastCellAt(restOffset_m);
    vec4 everyWave = coastEveryWaveAt(cell);
    float breaking = everyWave.w;
    if (breaking <= 0.0)
        return 0.0;
    vec2 downhill = -surfDepthGradient(cell);
    vec2 shoreward = downhill / max(length(downhill), 1e-6);
    // Half the height the cut leaves: the crest's elevation over the mean level.
    float crest_m = 0.5 * kSurfBreakerIndex * max(everyWave.x, 0.05);
    // n is (-dh/dx, 1, -dh/dz) over its y for a height field.
    float riseShoreward = -dot(normal.xz, shoreward) / max(normal.y, 0.1);
    float height = clamp(elevation_m / crest_m, -1.0, 1.0);
    float roller = smoothstep(kSurfRollerStart, kSurfRollerFull, height);
    // Behind the crest (the water rising towards it) the roller's foam is
    // left as lace that fades with the phase since the crest passed.
    // It fades in over the first kSurfLaceRise of the rise, so that no edge
    // lies where the surface turns at a trough.
    float lace = exp(-acos(height) / kSurfFadePhase_rad) * smoothstep(0.0, kSurfLaceRise, riseShoreward);
    float strength = smoothstep(0.0, kSurfFullBreaking, breaking);
    return strength * max(max(roller, lace), kSurfOldFoam);
}

// What a pixel sees of the surf's foam of this amount at world point
// anchor_m (from the render origin), footprint_m wide.
FoamLook surfLook(float amount, vec2 anchor_m, float footprint_m)
{
    return foamLook(kSurfNoise, kSurfFreshAmount, amount, anchor_m, footprint_m);
}

// Whether the surf's foam covers the point itself: the labels' rule
// (foamAtPoint in whitecap_foam.glsl).
float surfFoamAtPoint(float amount, vec2 anchor_m)
{
    return foamAtPoint(kSurfNoise, kSurfFreshAmount, amount, anchor_m);
}
#endif
