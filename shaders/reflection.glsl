// Looking up what the water reflects in the mirrored-world texture of pass 1.
#ifndef SWELL_REFLECTION_GLSL
#define SWELL_REFLECTION_GLSL
#include "swell/gpu/bindings.h"
#include "swell/gpu/variants.h"
#include "frame.glsl"
#include "fog.glsl"
#include "sky.glsl"

layout(binding = SWELL_UNIT_REFLECTION_COLOR) uniform sampler2D reflectionColor;
layout(binding = SWELL_UNIT_REFLECTION_DEPTH) uniform sampler2D reflectionDepth;

// A point above the water, mirrored below it, as the camera sees it:
// xy texture coordinate of the reflection texture, z window depth.
vec3 projectMirrored(vec3 p)
{
    vec4 clip = cameraViewProj * vec4(p.x, -p.y, p.z, 1.0);
    vec3 ndc = clip.xyz / max(clip.w, 1e-6);
    return vec3(ndc.xy * 0.5 + 0.5, windowDepth(ndc.z));
}

// How much a lookup at uv can be trusted: fades to 0 over the last few
// percent of the texture so samples off its edge never smear.
float edgeWeight(vec2 uv)
{
    vec2 e = smoothstep(vec2(0.0), vec2(0.04), uv) * (1.0 - smoothstep(vec2(0.96), vec2(1.0), uv));
    return e.x * e.y;
}

vec3 lookupWithFallback(vec2 uv, vec3 direction)
{
    float w = edgeWeight(uv);
    vec3 fallback = skyRadiance(direction);
    return w > 0.0 ? mix(fallback, texture(reflectionColor, uv).rgb, w) : fallback;
}

// The paper's lookup: step a fixed distance along the reflected ray.
vec3 reflectFixedDistance(vec3 surface, vec3 direction)
{
    vec3 p = projectMirrored(surface + direction * reflectionFixedDistance_m);
    return lookupWithFallback(p.xy, direction);
}

// The distances along the ray from surface where it is inside any world box
// (x: first entry, y: last exit; x > y when it misses them all).
vec2 worldSpan(vec3 surface, vec3 direction)
{
    int boxes = worldBoxCount;
    if (boxes < 0)
        return vec2(0.0, 1e30);
    // Axis-parallel components would divide by zero: nudge them.
    vec3 d = mix(direction, vec3(1e-7), lessThan(abs(direction), vec3(1e-7)));
    vec3 inverse = 1.0 / d;
    vec2 span = vec2(1e30, -1e30);
    for (int b = 0; b < boxes; ++b) {
        vec3 t0 = (worldBoxes[b].min_m - surface) * inverse;
        vec3 t1 = (worldBoxes[b].max_m - surface) * inverse;
        vec3 near = min(t0, t1), far = max(t0, t1);
        float enter = max(max(near.x, near.y), max(near.z, 0.0));
        float exit = min(min(far.x, far.y), far.z);
        if (enter <= exit)
            span = vec2(min(span.x, enter), max(span.y, exit));
    }
    return span;
}

// What the reflection texture shows where the mirrored ray's point at
// distance t lies: the mirrored world point seen there (relative to the
// render origin, mirrored back above the water), or, with w = 0, nothing
// (sky or off the texture; xyz then undefined). uv is set either way.
vec4 mirroredSceneAt(vec3 surface, vec3 direction, float t, out vec2 uv, out bool onTexture)
{
    vec3 p = projectMirrored(surface + direction * t);
    uv = p.xy;
    onTexture = all(greaterThanEqual(p.xy, vec2(0.0))) && all(lessThanEqual(p.xy, vec2(1.0))) && depthHasGeometry(p.z);
    if (!onTexture)
        return vec4(0.0);
    float depth = texture(reflectionDepth, p.xy).r;
    if (!depthHasGeometry(depth))
        return vec4(0.0);
    vec3 q = worldFromScreen(p.xy, depth);
    return vec4(q.x, -q.y, q.z, 1.0);
}

// The reflected ray's hit, found from the planar reflection with a bounded
// refinement: at most kRefineTaps + 1 depth taps (the first guess, which the
// fallback reuses, and the refinement) and one colour tap per pixel; a ray
// that misses every world box needs none on a GPU, though a software
// rasteriser runs the taps masked wherever a neighbouring pixel needs them:
//
// The reflection texture holds, along each of the camera's lines of sight,
// the nearest point of the mirrored world. Start from the distance t of what
// flat water would reflect here; then repeatedly look up what the texture
// shows at the ray's point at t and move t to that point's distance along
// the ray. Where the ray meets a surface the texture shows, this settles on
// the meeting point at once: a line of sight through the meeting point ends
// at the meeting point. It counts as a hit only if it has settled, the ray's
// point at t and the surface seen there within a texel's reach of each other.
// A ray that passes behind something (over an object, seen from below the
// water) never settles: the texture cannot tell what it meets, so it shows
// what flat water shows there (the planar lookup). A ray that leaves the world's boxes, or
// finds only sky, shows the sky in its own direction.
const int kRefineTaps = 4;

// erfc(x) for x >= 0 within 1.5e-7 (Abramowitz & Stegun 1964, eq. 7.1.26).
float erfcPositive(float x)
{
    float t = 1.0 / (1.0 + 0.3275911 * x);
    float poly = t * (0.254829592 + t * (-0.284496736 + t * (1.421413741 + t * (-1.453152027 + t * 1.061405429))));
    return poly * exp(-x * x);
}

// The share of reflected rays leaving the water in `direction` that no other
// wave stops: Smith's masking function G1 = 1 / (1 + Lambda) for a Gaussian
// sea of mean square slope s2 (both directions; s2 / 2 along the ray's
// azimuth), Lambda(nu) = (exp(-nu^2) / (nu sqrt(pi)) - erfc(nu)) / 2 with
// nu = tan(elevation) / sqrt(s2): Smith's shadowing function for a Gaussian
// surface (Smith 1967, "Geometrical shadowing of a random rough surface",
// IEEE Trans. Antennas Propag. 15(5)), as Bruneton, Neyret & Holzschuch 2010
// ("Real-time realistic ocean lighting") use it for the sea.
// From a sea of s2 = 0.05 (about a 9 m/s wind) a ray 0.3 degrees up escapes
// 8 times in 100, 2 degrees up 43, 10 degrees up 94: a grazing facet's
// reflection of a distant shore is mostly the next wave's face instead.
float unmaskedShare(vec3 direction)
{
    float s2 = waveMeanSquareSlope;
    if (s2 <= 0.0)
        return 1.0;
    float nu = direction.y / max(length(direction.xz), 1e-6) / sqrt(s2);
    if (nu > 4.0)
        return 1.0; // Lambda < 1e-8
    nu = max(nu, 1e-4);
    float lambda = 0.5 * (exp(-nu * nu) / (nu * 1.7724539) - erfcPositive(nu));
    return 1.0 / (1.0 + max(lambda, 0.0));
}

// Geometry the ray meets at uv, seen as often as the ray escapes the waves
// around it; the waves that stop it mostly reflect the sky. skyUnfogged is
// skyRadiance(direction), sky the same fogged.
vec3 maskedHit(vec2 uv, vec3 direction, vec3 skyUnfogged, vec3 sky)
{
    float w = edgeWeight(uv);
    vec3 seen = w > 0.0 ? mix(skyUnfogged, texture(reflectionColor, uv).rgb, w) : skyUnfogged;
    return mix(sky, seen, unmaskedShare(direction));
}

// How the march below ends. On a software rasteriser (llvmpipe) every branch
// of a shader runs for all the pixels it shades together, masked, so each
// lookup is written once, after the march, and the march only decides which
// one: the sky, the texture where the ray settled, or what flat water shows.
const int kShowSky = 0;
const int kShowHit = 1;
const int kShowUnsettled = 2;

// What a ray shows when the texture cannot tell what it meets (kShowUnsettled):
// what flat water shows here (the planar lookup) where that is geometry, so
// an object's mirror image stays whole; where flat water shows sky, the sky
// in the ray's own direction (the planar lookup's sky is the flat mirror's,
// nearer the horizon, and would brighten every such pixel).
//
// skyOnly: the caller knows the ray can meet nothing (it heads into the water).
vec3 reflectRayMarch(vec3 surface, vec3 direction, bool skyOnly)
{
    vec3 skyUnfogged = skyRadiance(direction);
    vec3 sky = applySkyFog(skyUnfogged, direction);
    // Only the stretch of the ray inside the world's boxes can meet anything.
    vec2 span = worldSpan(surface, direction);
    float tNear = max(span.x, 0.05), tFar = min(span.y, 1e6);
    // Flat water reflects, at this pixel, what the mirrored line of sight
    // through the surface point meets: the first guess.
    vec2 flatUv = projectMirrored(surface).xy;
    float flatDepth = texture(reflectionDepth, flatUv).r;
    bool flatOnTexture = all(greaterThanEqual(flatUv, vec2(0.0))) && all(lessThanEqual(flatUv, vec2(1.0)));
    bool flatShowsGeometry = flatOnTexture && depthHasGeometry(flatDepth);
    // The texture's angular resolution: how far apart, at distance 1 m from
    // the eye, two texels' lines of sight are.
    float texelAngle = 2.0 / (textureSize(reflectionDepth, 0).y * projectionFocalY);
    float t = depthHasGeometry(flatDepth) ? dot(vec3(1.0, -1.0, 1.0) * worldFromScreen(flatUv, flatDepth) - surface, direction) : tFar;
    t = clamp(t, tNear, tFar);
    int outcome = skyOnly || span.x > span.y ? kShowSky : kShowUnsettled;
    vec2 hitUv = flatUv;
    for (int i = 0; i < kRefineTaps && outcome == kShowUnsettled; ++i) {
        vec2 uv;
        bool onTexture;
        vec4 q = mirroredSceneAt(surface, direction, t, uv, onTexture);
        if (!onTexture)
            break;
        vec3 p = surface + direction * t;
        if (q.w == 0.0) {
            // Sky where the ray's point is: nothing the texture shows is
            // nearer along this line of sight; try the ray's far end once.
            if (t >= tFar)
                outcome = kShowSky;
            t = tFar;
            continue;
        }
        // Settled: the surface seen at the ray's point is the ray's point,
        // within the texture's resolution there (a texel's width, widened
        // for surfaces seen at a slant) and a little for depth precision.
        float reach_m = 0.05 + 4.0 * texelAngle * distance(eyePosition, vec3(p.x, -p.y, p.z));
        if (distance(q.xyz, p) < reach_m) {
            outcome = kShowHit;
            hitUv = uv;
        } else {
            t = clamp(dot(q.xyz - surface, direction), tNear, tFar);
        }
    }
    // Never settled (the ray passed behind something the texture shows in
    // front of it) or left the texture: what flat water shows, if geometry.
    if (outcome == kShowUnsettled && !flatShowsGeometry)
        outcome = kShowSky;
    return outcome == kShowSky ? sky : maskedHit(hitUv, direction, skyUnfogged, sky);
}

vec3 reflectedRadiance(vec3 surface, vec3 direction)
{
    // A reflected ray heading down (steep wave slopes) meets the next wave,
    // not the world above the water: bend it to the horizon, where the sky is
    // what that wave mostly reflects. The march never looks for geometry
    // along such a ray: every one of them would meet the same shoreline
    // texel and fill whole wave faces with it.
    bool intoTheWater = direction.y < 0.002;
    direction.y = max(direction.y, 0.002);
    direction = normalize(direction);
#if SWELL_REFLECTION_MODE == SWELL_REFLECTION_FIXED
    return reflectFixedDistance(surface, direction);
#else
    return reflectRayMarch(surface, direction, intoTheWater);
#endif
}
#endif
