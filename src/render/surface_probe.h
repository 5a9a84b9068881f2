// The frame's queries of the water answered on the GPU
// (shaders/surface_probe.comp): what the renderer's own frame asks of the
// surface (each floating object's water, the eye's side of it) read back
// from the fields and the arithmetic the water is drawn with, in the frame
// it is drawn, instead of from the wave model's CPU queries, which for the
// spectral model transform every cascade on the CPU at each new time.
//
// For each query point the GPU gives the exact surface's rest point under it
// (the fixed-point iteration of swell::SurfaceQuery::restPointUnder) with the
// surface there, and the drawn grid's vertices round the cell over that rest
// point; the CPU picks the triangle under the point from those vertices with
// DrawnSurface's own search (ocean/drawn_search.h). Where the triangle lies
// beyond the block (a point the filtered waves carry more than two cells
// away), that query alone is answered by the CPU's DrawnSurface.
// Library-internal.
#pragma once

#include "ocean/probed_point.h"
#include "swell/drawn_surface.h"
#include "swell/gl/handle.h"
#include "swell/scene/grid.h"
#include "swell/surface_query.h"

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include <cstddef>
#include <optional>
#include <vector>

namespace swell::detail {

// The same answers from the CPU: the model's queries and DrawnSurface (for
// a model whose CPU queries are cheap, WaveModelGpu::answersFrameQueries).
std::vector<ProbedPoint> answerOnCpu(const std::vector<glm::dvec2>& points, const SurfaceQuery& model,
                                     const DrawnSurface& drawn, double time_s);

class SurfaceProbe {
public:
    // GPU memory one query's answer takes (the frame counters' bytes written).
    static std::size_t answerBytes();

    // Answers `points` (x, z; the frame of `origin`, m) with the probe
    // program in use, and the Frame uniforms, the wave model's bindings and
    // the surface sources' in place for a view whose render origin is
    // `origin` and whose grid is `placement` of `shape`. Waits for the GPU.
    // `cpu`: the same surface on the CPU, for a triangle beyond the block
    // (its heights in the frame of `origin`, like the answers').
    std::vector<ProbedPoint> run(const std::vector<glm::dvec2>& points, glm::dvec3 origin, const GridShape& shape,
                                 const GridPlacement& placement, const DrawnSurface& cpu);

    // Gives its buffers back (a frame with nothing to ask the GPU keeps none).
    void release();

private:
    gl::Buffer queries_, answers_;
    std::size_t capacity_ = 0; // queries the buffers hold
};

} // namespace swell::detail
