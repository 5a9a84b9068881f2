// What every surface query shares: the rest-point inverse for surfaces
// without analytic derivatives, and the height query built on it.
#include "swell/surface_query.h"
#include "swell/wave_model.h"

#include <glm/geometric.hpp>

namespace swell {

SurfaceQuery::~SurfaceQuery() = default;
WaveModel::~WaveModel() = default;

double SurfaceQuery::heightDeviation_m() const { return 0.25 * reach().vertical_m; }

glm::dvec3 SurfaceQuery::displacementAt(glm::dvec2 restPoint_m, double time_s, const SurfaceFilter& filter) const
{
    return surfaceAt(restPoint_m, time_s, filter).displacement_m;
}

glm::dvec2 SurfaceQuery::restPointUnder(glm::dvec2 worldPoint_m, double time_s, const SurfaceFilter& filter) const
{
    // Fixed-point iteration x0 <- p - Dxz(x0): a contraction wherever the
    // surface does not fold (|dDxz/dx0| < 1), converging linearly. Stops
    // once a step moves the rest point less than 1e-7 m, or after 64 steps.
    glm::dvec2 rest = worldPoint_m;
    for (int i = 0; i < 64; ++i) {
        const glm::dvec3 d = displacementAt(rest, time_s, filter);
        const glm::dvec2 next = worldPoint_m - glm::dvec2(d.x, d.z);
        const double step = glm::length(next - rest);
        rest = next;
        if (step < 1e-7)
            break;
    }
    return rest;
}

double SurfaceQuery::heightAt(glm::dvec2 worldPoint_m, double time_s, const SurfaceFilter& filter) const
{
    return displacementAt(restPointUnder(worldPoint_m, time_s, filter), time_s, filter).y;
}

} // namespace swell
