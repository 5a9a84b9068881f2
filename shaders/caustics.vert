// The caustics pass's source grid (caustics.glsl): one vertex per point of a
// regular grid of the sea's surface, displaced by the wave model as the
// water's grid is, with the sun's ray refracted there (Snell's law) and the
// share of its light the surface lets in (Fresnel). The geometry shader
// takes each cell's triangles down to the slices.
#include "caustics.glsl"
#include "ocean.glsl"

out vec3 vSurface;        // the displaced point, relative to the render origin, m
out vec3 vRay;            // the sun's refracted ray, unit, pointing down
out float vTransmittance; // 1 - Fresnel reflectance of the sun's light there (0 when the sun is behind the facet)

void main()
{
    int perSide = causticsCells + 1;
    vec2 rest = causticsSourceCorner_m + vec2(gl_VertexID % perSide, gl_VertexID / perSide) * causticsCellSize_m;
    // The grid's own footprint filters out the waves it cannot sample (as
    // the water's grid does), so each cell stays a smooth facet.
    SurfacePoint s = oceanSurface(rest - causticsGridCenter_m, causticsCellSize_m, 1.0);
    vSurface = vec3(rest.x, 0.0, rest.y) + s.displacement;
    float cosI = dot(s.normal, causticsSun);
    vRay = refract(-causticsSun, s.normal, 1.0 / SWELL_WATER_IOR);
    vTransmittance = cosI > 0.0 ? 1.0 - fresnelDielectric(cosI, 1.0, SWELL_WATER_IOR) : 0.0;
    gl_Position = vec4(vSurface, 1.0); // placed by the geometry shader
}
