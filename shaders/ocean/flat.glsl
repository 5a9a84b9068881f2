// Flat water: the surface at rest, a perfect mirror. The GLSL twin of
// swell::FlatModel (src/ocean/flat/gpu/flat_model.cpp).
#ifndef SWELL_OCEAN_FLAT_GLSL
#define SWELL_OCEAN_FLAT_GLSL

SurfacePoint oceanSurface(vec2 restOffset_m, float footprint_m, float heightScale)
{
    return SurfacePoint(vec3(0.0), vec3(0.0, 1.0, 0.0), 0.0, vec3(1.0, 0.0, 0.0), vec3(0.0, 0.0, 1.0), 0.0, 0.0, vec2(0.0));
}

SurfacePoint oceanShading(vec2 restOffset_m, float pixelFootprint_m, float gridFootprint_m, vec3 gridAlongX,
                          vec3 gridAlongZ, float heightScale)
{
    return SurfacePoint(vec3(0.0), vec3(0.0, 1.0, 0.0), 0.0, vec3(1.0, 0.0, 0.0), vec3(0.0, 0.0, 1.0), 0.0, 0.0, vec2(0.0));
}

SurfacePoint oceanShading(vec2 restOffset_m, float pixelFootprint_m, mat2 pixelSteps_m, float gridFootprint_m,
                          vec3 gridAlongX, vec3 gridAlongZ, float heightScale)
{
    return oceanShading(restOffset_m, pixelFootprint_m, gridFootprint_m, gridAlongX, gridAlongZ, heightScale);
}

// No foam, so no bubbles under it.
float oceanFoamBelow(vec2 restOffset_m, float footprint_m) { return 0.0; }
float oceanFoamAtPoint(vec2 restOffset_m, float heightScale) { return 0.0; }
#endif
