// A surface plus surface sources (swell/composed_surface.h). The sources
// add one after another, in their order, so that a composition's numbers
// are the same wherever it is built.
#include "swell/composed_surface.h"

#include "swell/error.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <utility>

namespace swell {

ComposedSurface::ComposedSurface(std::shared_ptr<const SurfaceQuery> surface,
                                 std::vector<std::shared_ptr<const SurfaceSource>> sources, double surfaceClockOffset_s)
    : surface_(std::move(surface)), sources_(std::move(sources)), surfaceClockOffset_s_(surfaceClockOffset_s)
{
    if (!surface_)
        throw Error("ComposedSurface: no surface (null)");
    for (const std::shared_ptr<const SurfaceSource>& source : sources_)
        if (!source)
            throw Error("ComposedSurface: a source is null");
}

WaveReach ComposedSurface::reach() const { return surface_->reach(); }
double ComposedSurface::heightDeviation_m() const { return surface_->heightDeviation_m(); }

SurfacePoint ComposedSurface::surfaceAt(glm::dvec2 rest, double time_s, const SurfaceFilter& filter) const
{
    SurfacePoint p = surface_->surfaceAt(rest, time_s + surfaceClockOffset_s_, filter);
    // A height field's normal is (-dh/dx, 1, -dh/dz) normalised: the sources'
    // slopes add to the surface's.
    glm::dvec3 n = p.normal / std::max(p.normal.y, 1e-3);
    bool tilted = false;
    for (const std::shared_ptr<const SurfaceSource>& source : sources_) {
        const glm::dvec3 h = source->heightAt(rest, time_s);
        p.displacement_m.y += h.x;
        n.x -= h.y;
        n.z -= h.z;
        tilted = tilted || h.y != 0.0 || h.z != 0.0;
    }
    if (tilted)
        p.normal = glm::normalize(n);
    return p;
}

glm::dvec3 ComposedSurface::displacementAt(glm::dvec2 rest, double time_s, const SurfaceFilter& filter) const
{
    glm::dvec3 d = surface_->displacementAt(rest, time_s + surfaceClockOffset_s_, filter);
    for (const std::shared_ptr<const SurfaceSource>& source : sources_)
        d.y += source->heightAt(rest, time_s).x;
    return d;
}

glm::dvec2 ComposedSurface::restPointUnder(glm::dvec2 world, double time_s, const SurfaceFilter& filter) const
{
    return surface_->restPointUnder(world, time_s + surfaceClockOffset_s_, filter);
}

} // namespace swell
