// The water grid's vertex exactly as the renderer draws it: the rest point of
// grid vertex `vertexId`, displaced by the waves its cell can carry, faded
// toward the horizon, raised by the surface sources. water.vert draws it;
// surface_probe.comp answers the frame's queries with it, so both are the
// same arithmetic. Its CPU twin is swell::DrawnSurface::vertex.
#ifndef SWELL_WATER_VERTEX_GLSL
#define SWELL_WATER_VERTEX_GLSL
#include "frame.glsl"
#include "grid.glsl"
#include "ocean.glsl"
#if SWELL_SURFACE_SOURCES
#include "surface_sources.glsl"
#endif

struct WaterVertex {
    vec2 rest;            // rest position relative to the render origin, m
    SurfacePoint surface; // the waves (and sources) there
    float cellSize;       // grid spacing, m
    float heightScale;    // horizon fade, 0..1
    vec2 sourceSlope;     // the surface sources' slopes, d/dx and d/dz (0 without sources)
};

WaterVertex waterVertex(int vertexId)
{
    GridVertex g = gridVertex(vertexId);
    vec2 rest = gridCenter + g.offset;
    float distance_m = length(rest - eyePosition.xz);
    float fade = horizonFade(distance_m);
    SurfacePoint p = oceanSurface(g.offset, g.cellSize, fade);
    vec2 sourceSlope = vec2(0.0);
#if SWELL_SURFACE_SOURCES
    // The surface sources (the bodies' wake, a host's own) raise the water at
    // the rest point (as swell::DrawnSurface adds them); their slopes tilt
    // the surface's partial derivatives.
    vec4 sources = surfaceSourcesAt(rest);
    p.displacement.y += sources.x;
    p.alongX.y += sources.y;
    p.alongZ.y += sources.z;
    p.normal = normalize(cross(p.alongZ, p.alongX));
    sourceSlope = sources.yz;
#endif
    return WaterVertex(rest, p, g.cellSize, fade, sourceSlope);
}

// Its displaced position relative to the render origin, m.
vec3 waterVertexPosition(WaterVertex w)
{
    return vec3(w.rest.x, 0.0, w.rest.y) + w.surface.displacement;
}
#endif
