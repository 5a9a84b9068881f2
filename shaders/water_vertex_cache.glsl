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
// The wave model's own vertex data (ocean.glsl's SWELL_OCEAN_VERTEX_DATA:
// the spectral model's warped lookups) is not kept: the shading pass runs
// once a pixel, and computing the lookups there costs less than reading
// them at three corners, which llvmpipe gathers lane by lane (the viewer's
// storm on llvmpipe: its water 46.9 ms of CPU a frame, 53.4 and 56.5 with
// them read; the storm at 640 x 480: 141.3 and 144.8, 159.4 and 154.5 with
// them read, 141.9 to 152.4 in one pass).
#ifndef SWELL_WATER_VERTEX_CACHE_GLSL
#define SWELL_WATER_VERTEX_CACHE_GLSL
#include "swell/gpu/bindings.h"
#include "ocean.glsl"

#if SWELL_SURFACE_SOURCES
#define SWELL_WATER_CACHED_SOURCES 1
#else
#define SWELL_WATER_CACHED_SOURCES 0
#endif
#define SWELL_WATER_CACHED_VEC4S (4 + SWELL_WATER_CACHED_SOURCES)

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
