// The water's vertices as the visibility pass drew them, kept for the
// shading pass (water_deferred.glsl): water.vert stores each vertex it
// shades at its index (SWELL_WATER_CACHES_VERTICES), and the shading pass
// reads back the three of the triangle a pixel shows and interpolates them
// as the rasteriser would have. A vertex shaded twice stores the same
// values twice, so the order of the stores does not matter.
//
// A vertex is SWELL_WATER_CACHED_VEC4S vec4s:
//   0  displaced position relative to the render origin (m), cell size (m)
//   1  the displaced surface's normal, the horizon fade (0..1)
//   2  the surface's partial derivative along rest x, rest x relative to the render origin (m)
//   3  the surface's partial derivative along rest z, rest z relative to the render origin (m)
//   4  the surface sources' slopes d/dx, d/dz (with SWELL_SURFACE_SOURCES)
//   then the wave model's vertex data (SWELL_OCEAN_VERTEX_DATA vec4s, ocean.glsl)
#ifndef SWELL_WATER_VERTEX_CACHE_GLSL
#define SWELL_WATER_VERTEX_CACHE_GLSL
#include "swell/gpu/bindings.h"
#include "ocean.glsl"

#if SWELL_SURFACE_SOURCES
#define SWELL_WATER_CACHED_SOURCES 1
#else
#define SWELL_WATER_CACHED_SOURCES 0
#endif
#ifdef SWELL_OCEAN_VERTEX_DATA
#define SWELL_WATER_CACHED_OCEAN SWELL_OCEAN_VERTEX_DATA
#else
#define SWELL_WATER_CACHED_OCEAN 0
#endif
#define SWELL_WATER_CACHED_VEC4S (4 + SWELL_WATER_CACHED_SOURCES + SWELL_WATER_CACHED_OCEAN)

// One vertex: the renderer sizes the buffer by this struct's stride, read
// from the program (render/water_visibility.h).
struct CachedWaterVertex {
    vec4 v[SWELL_WATER_CACHED_VEC4S];
};

#if SWELL_WATER_CACHES_VERTICES
layout(std430, binding = SWELL_STORAGE_WATER_VERTICES) writeonly buffer WaterVertexCache {
    CachedWaterVertex cachedWaterVertices[];
};
#else
layout(std430, binding = SWELL_STORAGE_WATER_VERTICES) readonly buffer WaterVertexCache {
    CachedWaterVertex cachedWaterVertices[];
};
// The grid's index buffer (render/water_grid.h): triangle t is indices
// 3t, 3t + 1, 3t + 2.
layout(std430, binding = SWELL_STORAGE_WATER_INDICES) readonly buffer WaterIndices {
    uint waterIndices[];
};
#endif
#endif
