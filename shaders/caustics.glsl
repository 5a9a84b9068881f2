// Caustics: the sun's light focused and spread by the waves on what lies
// under the water. The caustics pass (caustics_sources.comp,
// caustics_images.comp, caustics.vert/.frag; src/render/caustics_map.h) refracts the drawn surface's grid of the sun's
// rays down to SWELL_CAUSTICS_SLICES level slices and adds each cell's flux
// into a camera-following map; this file holds the map's uniform block and
// its look-up, shared by the pass and the world's shading (mesh.frag).
//
// The map holds, per texel of a slice, the sun's irradiance on a level
// plane at the slice's depth over the irradiance on a level plane in the
// air (E sun.y), absorption left out: under flat water that is Fresnel's
// transmittance 1 - R(sun) everywhere; waves move the light about and keep
// its mean (each cell's flux lands somewhere, only spread over another area).
#ifndef SWELL_CAUSTICS_GLSL
#define SWELL_CAUSTICS_GLSL
#include "swell/gpu/bindings.h"
#include "swell/gpu/underwater.h"
#include "gpu/constants.glsl"
#include "water_optics.glsl"

// 0: no map drawn (water.caustics = false); the light under a level
// surface everywhere.
#ifndef SWELL_CAUSTICS
#error "SWELL_CAUSTICS is given by the program's flags (src/render/programs.h)"
#endif

// The Caustics block (swell::detail::CausticsUniforms, src/render/gpu/blocks.h).
#include "gpu/caustics_block.glsl"

#if SWELL_CAUSTICS
layout(binding = SWELL_UNIT_CAUSTICS) uniform sampler2DArray causticsMap;
#endif

// The sun's ray under a level surface (Snell's law), pointing down.
vec3 causticsLevelRay()
{
    return refract(-causticsSun, vec3(0.0, 1.0, 0.0), 1.0 / SWELL_WATER_IOR);
}

// The share of the sun's light a level surface lets in: 1 - R, Fresnel's
// reflectance of unpolarised light from the air (water_optics.glsl).
float causticsLevelTransmittance()
{
    return 1.0 - fresnelDielectric(causticsSun.y, 1.0, SWELL_WATER_IOR);
}

// The width of the map's texels, m.
float causticsTexel_m() { return causticsMapSize_m / float(SWELL_CAUSTICS_SIZE); }

// The map's value at p (relative to the render origin, below the mean
// level): the slices above and below p's depth, each looked up where the
// sun's ray through p crosses it, interpolated in depth. Above the first
// slice the surface itself (no focusing yet, the level transmittance);
// below the last, the last. Towards the map's borders and beyond it, the
// level transmittance (the mean the map keeps). lod: the mip level, from
// the footprint the caller averages over (log2 of it in texels), so a far
// floor shows the pattern's mean rather than its aliases.
float causticsFocus(vec3 p, float lod)
{
    float level = causticsLevelTransmittance();
#if !SWELL_CAUSTICS
    return level;
#else
    float depth_m = max(-p.y, 0.0);
    vec3 ray = causticsLevelRay();
    vec2 drift = ray.xz / -ray.y; // horizontal travel per metre of depth
    float aboveDepth_m = 0.0;
    float above = level;
    for (int k = 0; k < SWELL_CAUSTICS_SLICES; ++k) {
        float sliceDepth_m = causticsSliceDepth_m[k];
        vec2 uv = (p.xz + drift * (sliceDepth_m - depth_m) - causticsMapCorner_m) / causticsMapSize_m;
        vec2 edge = min(uv, 1.0 - uv);
        float inside = smoothstep(0.0, 0.05, min(edge.x, edge.y));
        float value = mix(level, textureLod(causticsMap, vec3(uv, float(k)), lod).r, inside);
        if (depth_m <= sliceDepth_m)
            return mix(above, value, (depth_m - aboveDepth_m) / (sliceDepth_m - aboveDepth_m));
        above = value;
        aboveDepth_m = sliceDepth_m;
    }
    return above;
#endif
}

// The sun's direct light on a surface facing n at p under the water, over
// the sun's irradiance at normal incidence in the air (what phongDiffuse()
// is in the air): the map's irradiance on a level plane, turned to the
// surface's facing towards the refracted ray, and absorbed per channel
// along the ray's path from the surface (Beer-Lambert with the water's
// absorption_per_m). Nothing when the sun is below the horizon. lod: as
// for causticsFocus().
vec3 causticsSunlight(vec3 n, vec3 p, vec3 absorption_per_m, float lod)
{
    if (causticsSun.y <= 0.0)
        return vec3(0.0);
    vec3 ray = causticsLevelRay();
    float cosT = -ray.y;
    float path_m = max(-p.y, 0.0) / cosT;
    float facing = max(dot(n, -ray), 0.0) / cosT;
    return vec3(causticsFocus(p, lod) * causticsSun.y * facing) * exp(-absorption_per_m * path_m);
}
#endif
