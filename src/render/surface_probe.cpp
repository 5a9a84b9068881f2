#include "render/surface_probe.h"

#include "ocean/drawn_search.h"
#include "swell/gpu/bindings.h"

#include <epoxy/gl.h>
#include <glm/vec4.hpp>

#include <array>

namespace swell::detail {

namespace {

// Mirrors ProbeAnswer in shaders/surface_probe.comp (std430: vec4s only).
struct GpuAnswer {
    glm::vec4 rest;         // xy rest point, zw the block's first vertex (i, j)
    glm::vec4 displacement; // xyz
    glm::vec4 normal;       // xyz
    std::array<glm::vec4, SWELL_PROBE_BLOCK * SWELL_PROBE_BLOCK> vertices; // xyz, row j by row
};
static_assert(sizeof(GpuAnswer) == (3 + SWELL_PROBE_BLOCK * SWELL_PROBE_BLOCK) * 16);

} // namespace

std::vector<ProbedPoint> answerOnCpu(const std::vector<glm::dvec2>& points, const SurfaceQuery& model,
                                     const DrawnSurface& drawn, double time_s)
{
    std::vector<ProbedPoint> out(points.size());
    for (std::size_t q = 0; q < points.size(); ++q) {
        ProbedPoint& p = out[q];
        p.rest_m = model.restPointUnder(points[q], time_s);
        const SurfacePoint s = model.surfaceAt(p.rest_m, time_s);
        p.displacement_m = s.displacement_m;
        p.normal = s.normal;
        p.drawn = drawn.at(points[q]);
        p.drawnOnCpu = true;
    }
    return out;
}

void SurfaceProbe::release()
{
    queries_ = {};
    answers_ = {};
    capacity_ = 0;
}

std::size_t SurfaceProbe::answerBytes() { return sizeof(GpuAnswer); }

std::vector<ProbedPoint> SurfaceProbe::run(const std::vector<glm::dvec2>& points, glm::dvec3 origin,
                                           const GridShape& shape, const GridPlacement& placement,
                                           const DrawnSurface& cpu)
{
    std::vector<ProbedPoint> out(points.size());
    if (points.empty())
        return out;
    if (points.size() > capacity_) {
        capacity_ = points.size();
        queries_ = gl::Buffer::create();
        glNamedBufferStorage(queries_.id(), GLsizeiptr(capacity_ * sizeof(glm::vec2)), nullptr, GL_DYNAMIC_STORAGE_BIT);
        answers_ = gl::Buffer::create();
        glNamedBufferStorage(answers_.id(), GLsizeiptr(capacity_ * sizeof(GpuAnswer)), nullptr, GL_DYNAMIC_STORAGE_BIT);
    }
    const glm::dvec2 origin2(origin.x, origin.z);
    std::vector<glm::vec2> relative(points.size());
    for (std::size_t i = 0; i < points.size(); ++i)
        relative[i] = glm::vec2(points[i] - origin2);
    glNamedBufferSubData(queries_.id(), 0, GLsizeiptr(relative.size() * sizeof(glm::vec2)), relative.data());
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, SWELL_STORAGE_PROBE_QUERIES, queries_.id());
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, SWELL_STORAGE_PROBE_ANSWERS, answers_.id());
    glDispatchCompute(GLuint(points.size()), 1, 1);
    glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
    std::vector<GpuAnswer> answers(points.size());
    glGetNamedBufferSubData(answers_.id(), 0, GLsizeiptr(answers.size() * sizeof(GpuAnswer)), answers.data());

    const glm::dvec3 base(origin2.x, origin.y, origin2.y);
    for (std::size_t q = 0; q < points.size(); ++q) {
        const GpuAnswer& a = answers[q];
        ProbedPoint& p = out[q];
        p.rest_m = origin2 + glm::dvec2(a.rest.x, a.rest.y);
        p.displacement_m = glm::dvec3(a.displacement);
        p.normal = glm::dvec3(a.normal);
        const glm::ivec2 first(int(a.rest.z), int(a.rest.w));
        // The block's vertex (i, j), or nothing outside it.
        auto vertex = [&](int i, int j) -> std::optional<glm::dvec3> {
            const glm::ivec2 at = glm::ivec2(i, j) - first;
            if (at.x < 0 || at.y < 0 || at.x >= SWELL_PROBE_BLOCK || at.y >= SWELL_PROBE_BLOCK)
                return std::nullopt;
            return base + glm::dvec3(a.vertices[std::size_t(at.y * SWELL_PROBE_BLOCK + at.x)]);
        };
        const glm::ivec2 start = restCellOf(shape, placement, p.rest_m - placement.center_m);
        p.drawn = searchDrawnCells(shape, start, points[q], kMaxDrawnSearchRings, vertex);
        if (!p.drawn) {
            p.drawn = cpu.at(points[q]);
            p.drawnOnCpu = true;
        }
    }
    return out;
}

} // namespace swell::detail
