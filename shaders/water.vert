// Water surface: grid vertex from gl_VertexID, displaced by the ocean surface in world space.
#include "frame.glsl"
#include "grid.glsl"
#include "ocean.glsl"
#if SWELL_SURFACE_SOURCES
#include "surface_sources.glsl"
#endif

out vec3 vPosition;    // displaced position relative to the render origin, m
out vec3 vNormal;
out vec3 vAlongX;      // the surface's partial derivatives at the grid's footprint (for the shading)
out vec3 vAlongZ;
out vec2 vRestPoint;   // rest position relative to the render origin, m (captured by tests)
out float vCellSize;   // grid spacing, m (for the LOD view)
out float vHeightScale; // horizon fade, 0..1
#if SWELL_SURFACE_SOURCES
out vec2 vSourceSlope; // the surface sources' slopes at the vertex, d/dx and d/dz (the fragment's own replace them)
#endif

void main()
{
    GridVertex g = gridVertex(gl_VertexID);
    vec2 rest = gridCenter + g.offset;
    float distance_m = length(rest - eyePosition.xz);
    float fade = horizonFade(distance_m);
    SurfacePoint p = oceanSurface(g.offset, g.cellSize, fade);
#if SWELL_SURFACE_SOURCES
    // The surface sources (the bodies' wake, a host's own) raise the water at
    // the rest point (as swell::DrawnSurface adds them); their slopes tilt
    // the surface's partial derivatives.
    vec4 sources = surfaceSourcesAt(rest);
    p.displacement.y += sources.x;
    p.alongX.y += sources.y;
    p.alongZ.y += sources.z;
    p.normal = normalize(cross(p.alongZ, p.alongX));
    vSourceSlope = sources.yz;
#endif
    vPosition = vec3(rest.x, 0.0, rest.y) + p.displacement;
    vNormal = p.normal;
    vAlongX = p.alongX;
    vAlongZ = p.alongZ;
    vRestPoint = rest;
    vCellSize = g.cellSize;
    vHeightScale = fade;
    gl_Position = passViewProj * vec4(vPosition, 1.0);
}
