// The seabed's analytic shapes in their own frames (swell/scene/seabed.h):
// where each reaches (its footprint), the lines across it where its
// profile bends (so a mesh with rows there draws it exactly), and the
// height grids of heightmaps and hosts, sampled bilinearly. Seabed
// (assets/seabed.cpp) combines them; the drawn seabed (assets/seabed_mesh.cpp)
// takes its vertices from the same functions.
#pragma once

#include "swell/scene/seabed_settings.h"

#include <glm/vec2.hpp>

#include <optional>
#include <string>
#include <vector>

namespace swell::detail {

// A shape's frame: u runs seaward (down its slope) from `origin`, v along
// its shore (u turned a quarter clockwise seen from above), m.
struct ShoreFrame {
    glm::dvec2 origin_m{0.0};
    glm::dvec2 seaward{0.0, -1.0}; // unit [x, z]
    glm::dvec2 along{1.0, 0.0};    // unit [x, z]

    glm::dvec2 world(double u_m, double v_m) const { return origin_m + u_m * seaward + v_m * along; }
};

ShoreFrame beachFrame(const SeabedBeach& beach);
ShoreFrame shelfFrame(const SeabedShelf& shelf);

// A rectangle in a shape's frame: u from uMin to uMax, v from -halfLength to
// halfLength, and the u of each line across it where the profile bends
// (both ends included, increasing).
struct ShoreSpan {
    double halfLength_m = 0.0;
    std::vector<double> bends_u_m;
};

ShoreSpan beachSpan(const SeabedBeach& beach, double toe_m);
ShoreSpan shelfSpan(const SeabedShelf& shelf, double toe_m);

// How far the breakwater's sides reach from its axis, m: the crest's half
// width and the run of its side down to the toe.
double breakwaterHalfFootprint_m(const SeabedBreakwater& breakwater, double toe_m);

// The smallest rectangle holding every point of `corners`.
SeabedExtent boundsOf(const std::vector<glm::dvec2>& corners);
// The world rectangle each shape reaches.
SeabedExtent beachExtent(const SeabedBeach& beach, double toe_m);
SeabedExtent shelfExtent(const SeabedShelf& shelf, double toe_m);
SeabedExtent breakwaterExtent(const SeabedBreakwater& breakwater, double toe_m);
// Whether the point lies in the rectangle (edges included).
bool contains(const SeabedExtent& box, glm::dvec2 point_m);
// The rectangle holding both.
SeabedExtent joined(const SeabedExtent& a, const SeabedExtent& b);

// Heights on a regular grid over a world rectangle, sampled bilinearly:
// a heightmap's (relative to the sea's mean level) or a host's (made so).
struct HeightGrid {
    int columns = 0, rows = 0;
    std::vector<float> heights_m; // row-major, row 0 at min_m.y
    glm::dvec2 min_m{0.0}, max_m{0.0};

    // The height at world [x, z], or nothing outside the rectangle.
    std::optional<double> at(glm::dvec2 world_xz_m) const;
    SeabedExtent extent() const { return {min_m, max_m}; }
};

// The first problem of the scene's [seabed] besides its keys' ranges (the
// parameter table's): a breakwater of zero length. Its key as a scene file
// names it ("seabed.breakwaters[2].end_m") and the message; nothing when
// there is none.
struct SeabedProblem {
    std::string key;
    std::string message;
};
std::optional<SeabedProblem> seabedShapeProblem(const SeabedSettings& seabed);

} // namespace swell::detail
