// A surface with surface sources added (swell/surface_source.h): the waves
// plus the bodies' wake and a host's sources, on the CPU as the drawn water
// adds them on the GPU. The one composition every CPU query of the water
// goes through: the floating bodies float on one, DrawnSurface draws one.
//
// Heights (and their slopes, in the normal) add at the rest point, as the
// grid's vertex over rest point x0 rises by the sources there
// (shaders/water.vert): the rest point under a world point is the
// surface's own, and so is the reach (the sources' changes with the time:
// SurfaceSource::reach_m, which the renderer adds to its culling).
#pragma once

#include "swell/export.h"
#include "swell/surface_query.h"
#include "swell/surface_source.h"

#include <memory>
#include <vector>

namespace swell {

class SWELL_API ComposedSurface final : public SurfaceQuery {
public:
    // `surface` (not null) plus `sources`, in their order. A query at time t
    // asks `surface` at t + surfaceClockOffset_s and the sources at t: the
    // floating bodies keep a clock of their own, from 0 at their start, on
    // which their wake runs too, while the waves and a host's sources run
    // on the scene's. Shares ownership of both.
    ComposedSurface(std::shared_ptr<const SurfaceQuery> surface,
                    std::vector<std::shared_ptr<const SurfaceSource>> sources, double surfaceClockOffset_s = 0.0);

    const SurfaceQuery& surface() const { return *surface_; }
    const std::vector<std::shared_ptr<const SurfaceSource>>& sources() const { return sources_; }

    WaveReach reach() const override;
    double heightDeviation_m() const override;
    // The surface's point, its height raised by the sources' and its normal
    // tilted by their slopes (left exactly as the surface gives it where no
    // source adds a slope).
    SurfacePoint surfaceAt(glm::dvec2 restPoint_m, double time_s, const SurfaceFilter& filter = {}) const override;
    glm::dvec3 displacementAt(glm::dvec2 restPoint_m, double time_s, const SurfaceFilter& filter = {}) const override;
    glm::dvec2 restPointUnder(glm::dvec2 worldPoint_m, double time_s, const SurfaceFilter& filter = {}) const override;

private:
    std::shared_ptr<const SurfaceQuery> surface_;
    std::vector<std::shared_ptr<const SurfaceSource>> sources_;
    double surfaceClockOffset_s_ = 0.0;
};

} // namespace swell
