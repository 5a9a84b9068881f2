// The water surface exactly as the renderer draws it for one camera and time:
// the grid's vertices, each displaced by the waves its cell can carry and
// faded toward the horizon, raised by the surface sources (swell/surface_source.h:
// the floating bodies' wake, a host's own) at its rest point, joined by flat
// triangles. The exact surface (SurfaceQuery::surfaceAt) differs from it by
// the waves the grid filters out and by the triangles' chords: centimetres
// near the camera, decimetres far away. Query this one to put things on the
// water the user sees.
#pragma once

#include "swell/export.h"
#include "swell/scene/grid.h"
#include "swell/sea_frame.h"
#include "swell/surface_query.h"

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include <array>
#include <memory>
#include <optional>
#include <vector>

namespace swell {

// Where a vertical line through a world point meets the drawn water.
struct SWELL_API DrawnPoint {
    glm::dvec3 position_m{0.0}; // absolute world position on the triangle, m
    glm::dvec3 normal{0.0, 1.0, 0.0}; // the triangle's unit normal, pointing up
    int cellI = 0, cellJ = 0;   // the grid cell whose triangle it is
    // The triangle's three grid vertices (i, j) and the point's barycentric
    // weights on them: at another time, the same material point of the
    // drawn surface is the sum of those vertices (vertex()) so weighted.
    std::array<glm::ivec2, 3> corners{};
    glm::dvec3 weights{0.0};
};

class SWELL_API DrawnSurface {
public:
    // What `surface` draws on the grid `shape` for a camera at eye_m
    // (relative to the water's mean level, m: the sea's frame) at time_s:
    // the waves with the heights of the sources as this frame draws them
    // (a swell::ComposedSurface, swell/composed_surface.h). Answers in the
    // world's frame `sea` gives (seaFrameOf(scene): the mean level added to
    // every height; the default answers in the sea's own). Shares ownership
    // of `surface` (not null).
    DrawnSurface(std::shared_ptr<const SurfaceQuery> surface, const GridShape& shape, const HorizonFade& fade,
                 glm::dvec3 eye_m, double time_s, SeaFrame sea = {});

    // The drawn water under world point (x, z). Empty only where no triangle
    // covers the point, which happens nowhere on the unbounded grid except
    // under extreme horizontal displacement beyond the search.
    std::optional<DrawnPoint> at(glm::dvec2 worldPoint_m) const;

    // Grid vertex (i, j) (0..cells each) as the vertex shader places it:
    // absolute world position, m.
    glm::dvec3 vertex(int i, int j) const;

    const GridPlacement& placement() const { return placement_; }

private:
    std::shared_ptr<const SurfaceQuery> surface_;
    GridShape shape_;
    HorizonFade fade_;
    GridPlacement placement_;
    glm::dvec3 eye_m_;
    double time_s_;
    SeaFrame sea_;
};

} // namespace swell
