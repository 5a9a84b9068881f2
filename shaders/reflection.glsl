// Looking up what the water reflects in the mirrored-world texture of pass 1.
#ifndef SWELL_REFLECTION_GLSL
#define SWELL_REFLECTION_GLSL
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
    return ndc * 0.5 + 0.5;
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

const float kOffTexture = -2e9;

// How far (m) the mirrored ray point at distance t lies behind the mirrored
// world seen in the same texel; negative in front. Sets uv. Very negative when nothing is there (kOffTexture off the texture).
float behindScene(vec3 surface, vec3 direction, float t, out vec2 uv)
{
    vec3 ray = surface + direction * t;
    vec3 p = projectMirrored(ray);
    uv = p.xy;
    if (any(lessThan(p.xy, vec2(0.0))) || any(greaterThan(p.xy, vec2(1.0))) || p.z >= 1.0)
        return kOffTexture;
    float sceneDepth = texture(reflectionDepth, p.xy).r;
    if (sceneDepth >= 1.0)
        return -1e9;
    vec3 mirroredRay = vec3(ray.x, -ray.y, ray.z);
    return distance(eyePosition, mirroredRay) - distance(eyePosition, worldFromScreen(p.xy, sceneDepth));
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

// March the reflected ray against the reflection depth buffer: geometric
// steps find where the ray passes behind the mirrored world, bisection finds
// the crossing, and it counts as a hit only if the ray is then within a few
// metres of the surface it passed (further means it went behind an object,
// not into it).
vec3 reflectRayMarch(vec3 surface, vec3 direction)
{
    const int steps = 20;
    const float growth = 1.5;
    // Only the stretch of the ray inside the world's boxes can meet anything.
    vec2 span = worldSpan(surface, direction);
    if (span.x > span.y)
        return applyFog(skyRadiance(direction), skyDistance(direction));
    float tFront = span.x;
    float t = max(0.5, span.x * growth);
    vec2 uv;
    for (int i = 0; i < steps && tFront <= span.y; ++i) {
        float behind = behindScene(surface, direction, t, uv);
        // Off the texture or past the far plane: a straight ray's image is a
        // straight path towards its vanishing point and never comes back.
        if (behind == kOffTexture)
            break;
        if (behind >= 0.0) {
            float tBehind = t;
            for (int j = 0; j < 6; ++j) {
                float tMid = 0.5 * (tFront + tBehind);
                if (behindScene(surface, direction, tMid, uv) >= 0.0)
                    tBehind = tMid;
                else
                    tFront = tMid;
            }
            behind = behindScene(surface, direction, tBehind, uv);
            if (behind < 1.0 + 0.01 * tBehind)
                return lookupWithFallback(uv, direction);
            tFront = t;
        } else if (behind > -1e8) {
            tFront = t;
        }
        t *= growth;
    }
    // Nothing hit: the sky itself, fogged as the sky pass fogs it (looking the
    // texture up at the ray's far end would find whatever object stands in
    // front of that part of the sky).
    return applyFog(skyRadiance(direction), skyDistance(direction));
}

vec3 reflectedRadiance(vec3 surface, vec3 direction)
{
    // A reflected ray heading down (steep wave slopes) would see more water;
    // bend it to the horizon instead of looking under the surface.
    direction.y = max(direction.y, 0.002);
    direction = normalize(direction);
#if SWELL_REFLECTION_MODE == SWELL_REFLECTION_FIXED
    return reflectFixedDistance(surface, direction);
#else
    return reflectRayMarch(surface, direction);
#endif
}
#endif
