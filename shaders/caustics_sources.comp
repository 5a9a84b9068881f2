// The caustics pass, first step (render/caustics_map.h): each point of a
// regular grid of the sea's surface, displaced by the wave model as the
// water's grid is, with the sun's ray refracted there (Snell's law) and the
// share of its light the surface lets in (Fresnel). Once a point: the
// triangles (caustics_images.comp) share them.
#include "swell/gpu/bindings.h"
#include "gpu/constants.glsl"
#include "caustics.glsl"
#include "ocean.glsl"

layout(local_size_x = SWELL_CAUSTICS_GROUP) in;

struct CausticsSource {
    vec4 surface; // xyz: the displaced point, relative to the render origin, m; w: 1 - Fresnel
                  // reflectance of the sun's light there (0 when the sun is behind the facet)
    vec4 ray;     // xyz: the sun's refracted ray, unit, pointing down
};
layout(std430, binding = SWELL_STORAGE_CAUSTICS_SOURCES) writeonly buffer CausticsSources {
    CausticsSource sources[];
};

void main()
{
    int perSide = causticsCells + 1;
    int index = int(gl_GlobalInvocationID.x);
    if (index >= perSide * perSide)
        return;
    vec2 rest = causticsSourceCorner_m + vec2(index % perSide, index / perSide) * causticsCellSize_m;
    // The grid's own footprint filters out the waves it cannot sample (as
    // the water's grid does), so each cell stays a smooth facet.
    SurfacePoint s = oceanSurface(rest - causticsGridCenter_m, causticsCellSize_m, 1.0);
    float cosI = dot(s.normal, causticsSun);
    float transmittance = cosI > 0.0 ? 1.0 - fresnelDielectric(cosI, 1.0, SWELL_WATER_IOR) : 0.0;
    sources[index].surface = vec4(vec3(rest.x, 0.0, rest.y) + s.displacement, transmittance);
    sources[index].ray = vec4(refract(-causticsSun, s.normal, 1.0 / SWELL_WATER_IOR), 0.0);
}
