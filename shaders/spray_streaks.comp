// The spray's third pass (src/render/spray_passes.cpp): the streaks of the
// living clumps spray_list.comp listed (spray_clump.glsl), one invocation
// a streak, as many as the list's command says. Each clump flies apart
// into SWELL_SPRAY_DROPS drops (the bow's: a piece of its sheet,
// sheetPiece, then SWELL_BOW_SPRAY_DROPS drops), each drawn (spray.vert)
// as a streak of its own path (spray.glsl's closed form) over the last
// fraction of a second: a ribbon facing the eye through four points of
// that path, so the fine mist the wind takes up at once shows as thin
// sheets drawn out downwind, densest where the clump left the crest and
// thinning as they spread, and the larger drops as short streaks along
// their arcs. A streak narrower or shorter than a pixel is drawn out to
// one, made fainter by as much (its coverage kept), so distant spray thins
// into a haze instead of sparkling. Here its four points, lit, its path,
// its width and its opacity, or that it is not drawn.
#include "swell/gpu/bindings.h"
#include "swell/gpu/spray.h"
#include "frame.glsl"
#include "fog.glsl"
#include "lighting.glsl"
#include "spray.glsl"
#include "spray_clump.glsl"
#ifndef SWELL_CLOUD_SHADOWS
#error "SWELL_CLOUD_SHADOWS is given by the program's flags (src/render/programs.h)"
#endif
#if SWELL_CLOUD_SHADOWS
#include "cloud_shadow.glsl"
#endif

layout(local_size_x = SWELL_SPRAY_GROUP) in;

// A streak's colour at p: fine water drops, lit by the sky and the sun
// (drops scatter nearly all the light they meet, most of it forward),
// fogged with the distance as the world is. Lit as the whitecaps are
// (water.frag), the sun's share brighter looking towards it, with an albedo
// of 1 (drops absorb next to nothing; the foam's 0.55 to 0.65 is a layer
// the water shows through): chosen by eye. The sky lights a drop from
// every side: the mean of its irradiance from above and from below
// (skyAmbient, the sky's and the ground's light), so under an overcast
// deck, the sun hidden, the spray is still whiter than the sea. Per vertex,
// not per fragment: it hardly changes along a streak, and the fragments
// are many.
vec3 sprayColor(vec3 p)
{
    vec3 toEye = normalize(eyePosition - p);
    float forward = max(dot(-toEye, sunDirection), 0.0);
#if SWELL_CLOUD_SHADOWS
    // In the cloud layer's shadow or not (cloud_shadow.glsl): a pixel's
    // footprint at its distance.
    float cloudSun = cloudShadowAt(p, 2.0 * distance(p, eyePosition) / (viewportSize.y * projectionFocalY));
    vec3 sunLight = sunColor * (sunIntensity * cloudSun) * max(sunDirection.y, 0.0);
#else
    vec3 sunLight = sunColor * sunIntensity * max(sunDirection.y, 0.0);
#endif
    vec3 skyLight = 0.5 * (skyAmbient(vec3(0.0, 1.0, 0.0)) + skyAmbient(vec3(0.0, -1.0, 0.0)));
    vec3 light = sunLight * (0.6 + 0.4 * forward * forward) + max(skyLight, vec3(0.0));
    return passOutput(applyFog(light, distance(p, eyePosition), p - eyePosition)).rgb;
}

// A streak as its vertices draw it: the four points of its path (tail to
// head), the path tail to head before any drawing out, its half width as
// drawn, m, and its opacity.
struct Streak {
    vec3 points[4];
    vec3 path;
    float drawn_m;
    float opacity;
};

#ifdef SWELL_BOW_SPRAY
// The clump's piece of the water sheet (spray.glsl: bowSheetLaunch, its
// flight as its largest drops', bowSheetTorn): a wide streak of its path
// over the last SWELL_BOW_SPRAY_PIECE_TRAIL_S, facing the eye, opaque where
// the sheet holds and torn into streamers along its flight (spray.frag) as
// its holes open, gone when they have met. It widens as it flies (the fan
// spreads and thins; 0.1 m + 0.3 m/s half width, chosen by eye). False
// where it is not drawn.
bool sheetPiece(SprayClump c, float pixelSpread, float torn, out Streak streak)
{
    streak.points = vec3[4](vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0));
    streak.path = vec3(0.0);
    streak.drawn_m = 0.0;
    streak.opacity = 0.0;
    vec3 birth = c.birthAge.xyz;
    float age_s = c.birthAge.w;
    uint key = c.key.x;
    if (torn >= 1.0)
        return false;
    vec3 launch_mps = bowSheetLaunch(key, c.forward.xy, c.bow.xy, c.bow.z, c.bow.w, c.forward.z);
    // The piece is water, not mist: the air it meets is the crest
    // spray's, a drop's own eddy (its first sheet drop's).
    vec3 air_mps = sprayAir(key, uint(SWELL_SPRAY_MIST_DROPS), c.windOpacity.xy, c.windOpacity.z);
    float tau_s = bowSheetTau_s();
    float tail_s = max(age_s - float(SWELL_BOW_SPRAY_PIECE_TRAIL_S), 0.0);
    for (int k = 0; k < 4; ++k)
        streak.points[k] = birth + sprayDropOffset(launch_mps, air_mps, tau_s, mix(tail_s, age_s, float(k) / 3.0));
    streak.path = streak.points[3] - streak.points[0];
    float length_m = length(streak.path);
    if (length_m < 1e-4)
        return false;
    // Nearly opaque while whole (an aerated sheet scatters most of the
    // light it meets; chosen by eye), fading as it falls back to the
    // height it left at, where the foam takes it.
    float opacity = 0.85 * c.windOpacity.w * smoothstep(-0.3, 0.3, streak.points[3].y - birth.y);
    float halfWidth_m = 0.1 + 0.3 * age_s;
    float pixel_m = distance(eyePosition, streak.points[3]) * pixelSpread;
    streak.drawn_m = max(halfWidth_m, 0.6 * pixel_m);
    opacity *= halfWidth_m / streak.drawn_m;
    streak.opacity = opacity;
    return opacity > 0.002;
}
#endif

// A drop's streak. False where it is not drawn.
bool dropStreak(SprayClump c, uint drop, float pixelSpread, out Streak streak)
{
    streak.points = vec3[4](vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0));
    streak.path = vec3(0.0);
    streak.drawn_m = 0.0;
    streak.opacity = 0.0;
    vec3 birth = c.birthAge.xyz;
    float age_s = c.birthAge.w;
    uint key = c.key.x;
    bool mist = drop < uint(SWELL_SPRAY_MIST_DROPS);
#ifdef SWELL_BOW_SPRAY
    float tau_s = bowSprayTau_s(key, drop);
    vec3 launch_mps = bowSprayLaunch(key, drop, c.forward.xy, c.bow.xy, c.bow.z, c.bow.w, c.forward.z);
    float trail_s = mist ? float(SWELL_SPRAY_MIST_TRAIL_S) : float(SWELL_BOW_SPRAY_SHEET_TRAIL_S);
#else
    float tau_s = sprayTau_s(key, drop);
    vec3 launch_mps = sprayLaunch(key, drop, c.windOpacity.xy, c.windOpacity.z);
    float trail_s = mist ? float(SWELL_SPRAY_MIST_TRAIL_S) : float(SWELL_SPRAY_DROP_TRAIL_S);
#endif
    vec3 air_mps = sprayAir(key, drop, c.windOpacity.xy, c.windOpacity.z);
    float tail_s = max(age_s - trail_s, 0.0);
    for (int k = 0; k < 4; ++k)
        streak.points[k] = birth + sprayDropOffset(launch_mps, air_mps, tau_s, mix(tail_s, age_s, float(k) / 3.0));
    // It fades as it falls back to the crest's height, where the foam takes it.
    float opacity = c.windOpacity.w * smoothstep(-0.3, 0.3, streak.points[3].y - birth.y);
    // Mist spreads as it flies (turbulent diffusion, chosen by eye),
    // fainter as it spreads; a drop stays a drop.
#ifdef SWELL_BOW_SPRAY
    // A sheet's drop stands for a ligament of the torn sheet, wider
    // than the crest's drops (6 cm: chosen by eye; at 16 cm their
    // streaks, a few metres long in a head wind, veiled the hull).
    float halfWidth_m = mist ? 0.03 + 0.08 * age_s : 0.03;
#else
    float halfWidth_m = mist ? 0.03 + 0.08 * age_s : 0.012;
#endif
#ifdef SWELL_BOW_SPRAY
    // The bow's mist is the torn sheet's fine spindrift, fainter than
    // a crest's spume beside its pieces and drops (chosen by eye: at
    // the crest's opacity it veils the hull aft of the bow).
    opacity *= mist ? 0.25 * sqrt(0.03 / halfWidth_m) : 0.9;
#else
    opacity *= mist ? 0.6 * sqrt(0.03 / halfWidth_m) : 0.9;
#endif
    float pixel_m = distance(eyePosition, streak.points[3]) * pixelSpread;
    streak.drawn_m = max(halfWidth_m, 0.6 * pixel_m);
    opacity *= halfWidth_m / streak.drawn_m;
    // A streak shorter than a pixel is drawn out to one, fainter by as
    // much, about its middle.
    streak.path = streak.points[3] - streak.points[0];
    float length_m = length(streak.path), drawnLength_m = max(length_m, pixel_m);
    opacity *= length_m / max(drawnLength_m, 1e-6);
    streak.opacity = opacity;
    if (length_m < 1e-4)
        return false; // at birth: nothing has left the crest yet
    vec3 middle = 0.5 * (streak.points[0] + streak.points[3]);
    for (int k = 0; k < 4; ++k)
        streak.points[k] = middle + (streak.points[k] - middle) * (drawnLength_m / length_m);
    return opacity > 0.002;
}

void main()
{
    uint index = gl_GlobalInvocationID.x;
    if (index >= sprayCommands.living * uint(SPRAY_STRIPS))
        return;
    SprayClump c = sprayClumps[sprayList[index / uint(SPRAY_STRIPS)]];
    int strip = int(index % uint(SPRAY_STRIPS));
    // A pixel's width per metre of distance.
    float pixelSpread = 2.0 / (projectionFocalY * viewportSize.y);
    Streak streak;
    SprayStreak drawn;
#ifdef SWELL_BOW_SPRAY
    float torn = bowSheetTorn(c.key.x, c.birthAge.w);
    bool lives = strip == 0 ? sheetPiece(c, pixelSpread, torn, streak)
                            : dropStreak(c, uint(strip - 1), pixelSpread, streak);
    vec2 sheet = strip == 0 ? vec2(sprayUnit(c.key.x, 111u), torn) : vec2(0.0, -1.0);
#else
    bool lives = dropStreak(c, uint(strip), pixelSpread, streak);
    vec2 sheet = vec2(0.0, -1.0);
#endif
    for (int k = 0; k < 4; ++k) {
        drawn.points[k] = vec4(streak.points[k], 0.0);
        drawn.colors[k] = vec4(lives ? sprayColor(streak.points[k]) : vec3(0.0), 0.0);
    }
    drawn.path = vec4(streak.path, streak.drawn_m);
    drawn.look = vec4(streak.opacity, lives ? 1.0 : 0.0, sheet);
    sprayStreaks[index] = drawn;
}
