// The water surface seen from below: Snell's window. Light from above
// reaches an eye under the water only inside a cone of half-angle
// asin(1 / n) = 48.6 degrees about the vertical (n = 1.333); beyond it the
// surface reflects everything (total internal reflection), so the water's
// own colour, seen in the mirror of the surface, surrounds the window.
#ifndef SWELL_UNDERWATER_SURFACE_GLSL
#define SWELL_UNDERWATER_SURFACE_GLSL
#include "gpu/constants.glsl"
#include "frame.glsl"
#include "fog.glsl"
#include "sky.glsl"
#include "refraction.glsl"
#include "underwater.glsl"
#include "water_optics.glsl"

// What comes through the surface at p along the refracted ray t (into the
// air): the world above the water, which the refraction pass renders when
// the eye is under the water, over the sky, fogged as the sky pass fogs it.
// The pass is cleared to alpha 0 and geometry writes alpha 1, so the
// filtered alpha is the geometry's coverage and its edges stay smooth when
// the half-size texture is magnified.
vec3 lightFromAbove(vec3 p, vec3 normalUp, vec3 t, vec2 screenUv)
{
    vec2 uv = clamp(screenUv - normalUp.xz * refractionDistortion, vec2(0.001), vec2(0.999));
    vec4 world = texture(refractionColor, uv);
    float depth = texture(refractionDepth, uv).r;
    // Only what really lies above this point of the surface (the pass holds
    // the world below instead while the eye is above the water).
    if (depthHasGeometry(depth) && worldFromScreen(uv, depth).y <= p.y)
        world = vec4(0.0);
    return world.rgb + applySkyFog(skyRadiance(t), t) * (1.0 - world.a);
}

// The colour of the surface at p, seen from the eye below it; normalUp is
// the surface's unit normal (pointing up), screenUv the pixel's coordinate.
vec3 surfaceFromBelow(vec3 p, vec3 normalUp, vec2 screenUv)
{
    vec3 toSurface = p - eyePosition;
    float path_m = length(toSurface);
    vec3 d = toSurface / max(path_m, 1e-6);
    // The normal on the eye's side; an interpolated one can face away at
    // grazing angles (as above the water), so it is bent back just past 90 degrees.
    vec3 n = -normalUp;
    if (dot(n, d) > 0.0)
        n = normalize(n - d * dot(n, d) * 1.01);
    float cosI = -dot(n, d);
    float reflectance = fresnelDielectric(cosI, SWELL_WATER_IOR, 1.0);
    // Snell's law (GLSL refract takes the ratio of indices, water to air);
    // beyond the critical angle it returns 0 and the reflectance is 1.
    vec3 t = refract(d, n, SWELL_WATER_IOR);
    vec3 transmitted = reflectance < 1.0 ? lightFromAbove(p, normalUp, t, screenUv) : vec3(0.0);
    // Reflected down into the water: its own in-scattered colour, seen from
    // the surface (depth 0) down a path with no end.
    vec3 reflected = underwaterBackground(reflect(d, n), max(-p.y, 0.0));
    vec3 color = mix(transmitted, reflected, reflectance);
    // The light reflected down carries no shafts of its own (its path
    // starts at the surface, out of the eye's sight of the map); the path
    // from the eye to the surface does.
    return underwaterFog(color, d, -eyePosition.y, path_m) + underwaterShafts(eyePosition, d, path_m);
}
#endif
