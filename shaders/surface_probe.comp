// The frame's queries of the water answered on the GPU, from the very fields
// and arithmetic the water is drawn with (src/render/surface_probe.h): for
// each query point, the exact surface's rest point under it and the surface
// there, and the drawn grid's vertices round the cell over that rest point,
// from which the CPU picks the triangle under the point (DrawnSurface's
// search, src/core/drawn_search.h). One workgroup a query: its first
// invocation finds the rest point, then each invocation places one vertex
// of the block.
#include "swell/gpu/bindings.h"
#include "water_vertex.glsl"

layout(local_size_x = SWELL_PROBE_BLOCK, local_size_y = SWELL_PROBE_BLOCK) in;

// x,z of each query point relative to the render origin, m.
layout(std430, binding = SWELL_STORAGE_PROBE_QUERIES) readonly buffer ProbeQueries {
    vec2 queryPoints[];
};

struct ProbeAnswer {
    vec4 rest;         // xy: the exact surface's rest point under the query, relative to the
                       // render origin, m; zw: the block's first vertex (i, j)
    vec4 displacement; // xyz: the exact surface's displacement at that rest point, m
    vec4 normal;       // xyz: its unit normal
    vec4 vertices[SWELL_PROBE_BLOCK * SWELL_PROBE_BLOCK]; // xyz: the drawn vertices, row j by row, relative to the render origin, m
};
layout(std430, binding = SWELL_STORAGE_PROBE_ANSWERS) writeonly buffer ProbeAnswers {
    ProbeAnswer answers[];
};

// The exact surface (swell::SurfaceFilter{}: every wave, no fade). A footprint
// of 0 would make the models' smoothstep weights undefined; this one is
// far below any wave a model holds.
const float kExactFootprint_m = 1e-6;

shared ivec2 firstVertex;

void main()
{
    uint query = gl_WorkGroupID.x;
    if (gl_LocalInvocationIndex == 0u) {
        // As swell::WaveModel::restPointUnder: the fixed-point iteration
        // x0 <- p - Dxz(x0), to a step below what a float near the origin resolves.
        vec2 p = queryPoints[query];
        vec2 rest = p;
        for (int i = 0; i < 64; ++i) {
            vec3 d = oceanSurface(rest - gridCenter, kExactFootprint_m, 1.0).displacement;
            vec2 next = p - d.xz;
            float moved = length(next - rest);
            rest = next;
            if (moved < 1e-5)
                break;
        }
        SurfacePoint s = oceanSurface(rest - gridCenter, kExactFootprint_m, 1.0);
        // The block: SWELL_PROBE_BLOCK - 1 cells a side round the start cell.
        int lines = int(gridCells) + 1;
        ivec2 first = clamp(gridCellOf(rest - gridCenter) - (SWELL_PROBE_BLOCK / 2 - 1), ivec2(0),
                            ivec2(lines - SWELL_PROBE_BLOCK));
        firstVertex = first;
        answers[query].rest = vec4(rest, vec2(first));
        answers[query].displacement = vec4(s.displacement, 0.0);
        answers[query].normal = vec4(s.normal, 0.0);
    }
    barrier();
    ivec2 v = firstVertex + ivec2(gl_LocalInvocationID.xy);
    int lines = int(gridCells) + 1;
    WaterVertex w = waterVertex(v.y * lines + v.x);
    answers[query].vertices[gl_LocalInvocationIndex] = vec4(waterVertexPosition(w), 0.0);
}
