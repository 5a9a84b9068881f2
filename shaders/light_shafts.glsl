// Shafts of light in the water column, seen from under the water: the
// sun's beam below the surface, focused and spread by the waves, scattered
// once towards the eye by the water's particles. The waves' focusing is the
// caustics map's (caustics.glsl), read along the view ray: where the map
// is bright the beam is, so the light scattered from it lies in sheets and
// columns along the sun's refracted rays, converging towards the sun's
// direction in perspective and moving with the waves.
//
// Single scattering of the beam (Mobley 1994, "Light and Water"): along the
// ray from the eye, at distance t and depth z(t),
//
//   dL = b P(theta) E sun.y F(p) / cosT exp(-a z / cosT) exp(-a t) dt
//
// with F the map's focus (the irradiance on a level plane over the air's,
// E sun.y, causticsFocus()), b SWELL_WATER_SCATTERING_PER_M, P
// Henyey-Greenstein with SWELL_WATER_PHASE_G, a the water's absorption
// (water.absorption_per_m, the attenuation the underwater fog uses), both on
// the beam's slant path from the surface and on the way to the eye. The
// integral splits into the level surface's mean, F = T Fresnel's
// transmittance, in closed form over the whole path (its C++ twin:
// src/render/light_shafts.h), and the pattern about it, F - T, marched in
// SWELL_SHAFTS_STEPS segments over the first SWELL_SHAFTS_REACH_M, each
// segment's weight the exact integral of exp(-k t) over it. The mean thus
// costs no samples and flat water is exact; the samples spend themselves on
// the shafts alone. The segments grow linearly away from the eye, and each
// is sampled at one point, offset within it by the pixel's dither: a march's
// bands become fine, fixed noise (the same in every frame and every run).
#ifndef SWELL_LIGHT_SHAFTS_GLSL
#define SWELL_LIGHT_SHAFTS_GLSL
#include "swell/gpu/underwater.h"
#include "gpu/constants.glsl"
#include "caustics.glsl"

// 0: no shafts (water.shafts = false): none of the sun's light scattered
// in the water column.
#ifndef SWELL_SHAFTS
#error "SWELL_SHAFTS is given by the program's flags (src/render/programs.h)"
#endif

// Henyey and Greenstein 1941: the share of scattered light per steradian at
// cosTheta from its first direction, 1/sr, its mean cosine g.
float shaftsPhase(float cosTheta)
{
    const float g = SWELL_WATER_PHASE_G;
    float denom = 1.0 + g * g - 2.0 * g * cosTheta;
    return (1.0 - g * g) / (4.0 * SWELL_PI * denom * sqrt(denom));
}

// The integral of exp(-k t) dt from t0 to t1, per channel (k may be
// negative, or zero: the ray then runs with the beam's own attenuation).
vec3 shaftsExpIntegral(vec3 k, float t0, float t1)
{
    float len = t1 - t0;
    vec3 kl = k * len;
    vec3 small = vec3(lessThan(abs(kl), vec3(1e-3)));
    vec3 safeK = mix(k, vec3(1.0), small);
    vec3 exact = (1.0 - exp(-safeK * len)) / safeK;
    vec3 series = len * (1.0 - 0.5 * kl);
    return exp(-k * t0) * mix(exact, series, small);
}

// Interleaved gradient noise (Jimenez 2014, "Next generation post
// processing in Call of Duty: Advanced Warfare", SIGGRAPH course): a
// dither in [0, 1) from the pixel's coordinate alone, its neighbours' far
// apart, so a march's steps leave no bands and a still renders the same
// bit for bit.
float shaftsDither(vec2 pixel)
{
    return fract(52.9829189 * fract(dot(floor(pixel), vec2(0.06711056, 0.00583715))));
}

// The sun's light scattered towards the eye along the ray from `start`
// (relative to the render origin, under the water) along d (unit), path_m
// long (an upward ray ends at the mean level). absorption_per_m: the
// water's, per channel; sunIrradiance: the sun's colour times its
// intensity; pixelSpread: a pixel's width over its distance (the map's mip
// level from the footprint); dither: the pixel's, in [0, 1).
vec3 shaftsInscatter(vec3 start, vec3 d, float path_m, vec3 absorption_per_m, vec3 sunIrradiance,
                     float pixelSpread, float dither)
{
#if !SWELL_SHAFTS
    return vec3(0.0);
#else
    if (causticsSun.y <= 0.0)
        return vec3(0.0);
    float z0 = max(-start.y, 0.0);
    if (d.y > 1e-6)
        path_m = min(path_m, z0 / d.y);
    vec3 ray = causticsLevelRay();
    float cosT = -ray.y;
    float level = causticsLevelTransmittance();
    vec3 k = absorption_per_m * (1.0 - d.y / cosT);
    vec3 beam = sunIrradiance * (causticsSun.y / cosT) * exp(-absorption_per_m * z0 / cosT);
    vec3 light = level * shaftsExpIntegral(k, 0.0, path_m);
#if SWELL_CAUSTICS
    float reach_m = min(path_m, SWELL_SHAFTS_REACH_M);
    // How fast the look-up moves across the map per metre of the ray: the
    // map is read where the sun's ray through the point crosses each slice
    // (causticsFocus()), so a ray along the beam stays on one texel.
    float across = length(d.xz + ray.xz / cosT * d.y);
    float t0 = 0.0;
    for (int i = 0; i < SWELL_SHAFTS_STEPS; ++i) {
        float u = float(i + 1) / float(SWELL_SHAFTS_STEPS);
        float t1 = reach_m * u * u;
        float t = mix(t0, t1, dither);
        // The map averaged over the pixel's footprint there or the
        // segment's half-length across it, whichever is wider.
        float footprint_m = max(t * pixelSpread, 0.5 * (t1 - t0) * across);
        float lod = log2(max(footprint_m / causticsTexel_m(), 1.0));
        light += (causticsFocus(start + d * t, lod) - level) * shaftsExpIntegral(k, t0, t1);
        t0 = t1;
    }
#endif
    return beam * (SWELL_WATER_SCATTERING_PER_M * shaftsPhase(dot(ray, -d))) * light;
#endif
}
#endif
