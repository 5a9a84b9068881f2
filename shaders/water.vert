// Water surface: grid vertex from gl_VertexID, displaced by the ocean surface in world space.
// In the water's visibility pass (SWELL_WATER_CACHES_VERTICES) each vertex
// is also kept for the shading pass (water_vertex_cache.glsl).
#include "water_vertex.glsl"
#ifndef SWELL_WATER_CACHES_VERTICES
#error "SWELL_WATER_CACHES_VERTICES is given by the program's flags (src/render/program_flags.h)"
#endif
#if SWELL_WATER_CACHES_VERTICES
#include "water_vertex_cache.glsl"
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
#ifdef SWELL_OCEAN_VERTEX_DATA
out vec4 vOceanData[SWELL_OCEAN_VERTEX_DATA]; // the wave model's, for its pixels (ocean.glsl)
#endif

void main()
{
    WaterVertex w = waterVertex(gl_VertexID);
    vPosition = waterVertexPosition(w);
    vNormal = w.surface.normal;
    vAlongX = w.surface.alongX;
    vAlongZ = w.surface.alongZ;
    vRestPoint = w.rest;
    vCellSize = w.cellSize;
    vHeightScale = w.heightScale;
#if SWELL_SURFACE_SOURCES
    vSourceSlope = w.sourceSlope;
#endif
#ifdef SWELL_OCEAN_VERTEX_DATA
    // Through a local array: outputs written through a function's out
    // array are "too complex" an lvalue for NVIDIA's compiler.
    vec4 oceanData[SWELL_OCEAN_VERTEX_DATA];
    oceanVertexData(w.rest - gridCenter, oceanData);
    vOceanData = oceanData;
#endif
#if SWELL_WATER_CACHES_VERTICES
    CachedWaterVertex cached;
    cached.v[0] = vec4(vPosition, vCellSize);
    cached.v[1] = vec4(vNormal, vHeightScale);
    cached.v[2] = vec4(vAlongX, vRestPoint.x);
    cached.v[3] = vec4(vAlongZ, vRestPoint.y);
#if SWELL_SURFACE_SOURCES
    cached.v[4] = vec4(vSourceSlope, 0.0, 0.0);
#endif
    cachedWaterVertices[gl_VertexID] = cached;
#endif
    gl_Position = passViewProj * vec4(vPosition, 1.0);
}
