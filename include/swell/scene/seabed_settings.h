// The sea floor a scene describes ([seabed], docs/SCENE.md): its analytic
// shapes (plane beaches, shelves, breakwaters) and its heightmap, plain data
// with units, and each shape's own height function. swell/scene/seabed.h
// combines them (with the island and a host's heights) into the floor.
//
// Azimuths are measured like a heading, as the sun's and the camera's are
// (docs/SCENE.md "Angles"): from -z (north) towards +x (east), degrees, so
// azimuth a points along [x, z] = [sin a, -cos a].
#pragma once

#include "swell/export.h"

#include <glm/vec2.hpp>

#include <cstddef>
#include <optional>
#include <string>
#include <vector>

namespace swell {

// A plane beach: the floor rises at `slope` from the sea up to the land.
// Across the shore (seaward distance u from the shoreline, m) its height is
// -slope * u, from the land's top (top_m at u = -top_m / slope, and flat for
// landWidth_m behind it) down to the toe (the depth Seabed::toeDepth_m(), at
// u = toe / slope), where the beach ends. Along the shore it reaches
// length_m, centred on shorePoint_m; past its ends and its back it stops
// (the floor there is whatever else is there).
struct SWELL_API SeabedBeach {
    glm::dvec2 shorePoint_m{0.0};    // world [x, z] where the floor crosses the sea's mean level, m
    double seawardAzimuth_deg = 0.0; // the way the beach faces the sea (down the slope), like a heading
    double slope = 0.02;             // rise over run, > 0 (0.02: 1:50)
    double length_m = 1000.0;        // along the shore, m, > 0
    double top_m = 3.0;              // the land's height above the sea's mean level at the beach's top, m, > 0
    double landWidth_m = 50.0;       // the flat land behind the top, m, >= 0
};

// A shelf: a flat floor depth_m below the sea's mean level with a sloping
// edge on its seaward side. Across the edge (seaward distance u from the
// edge's top line, m) its height is -depth_m for -width_m <= u <= 0, then
// falls at `slope` to the toe; along the edge it reaches length_m, centred
// on edgePoint_m. With a beach of the same azimuth its contours are
// straight and parallel to the beach's.
struct SWELL_API SeabedShelf {
    glm::dvec2 edgePoint_m{0.0};     // world [x, z] on the top line of the shelf's edge, m
    double seawardAzimuth_deg = 0.0; // the way the edge slopes down, like a heading
    double depth_m = 10.0;           // the flat top's depth below the sea's mean level, m, >= 0
    double slope = 0.05;             // the edge's rise over run, > 0
    double width_m = 500.0;          // the flat top's reach landward from the edge, m, > 0
    double length_m = 1000.0;        // along the edge, m, > 0
};

// A breakwater: a rubble mound from start_m to end_m whose cross-section is
// a trapezoid, crestWidth_m wide at crest_m, its sides falling at
// sideSlope to the floor; its heads are round (the same section turned
// about each end). It stands on whatever floor is there.
struct SWELL_API SeabedBreakwater {
    glm::dvec2 start_m{0.0};    // world [x, z], m
    glm::dvec2 end_m{100.0, 0.0}; // world [x, z], m; not start_m
    double crest_m = 3.0;       // the crest's height above the sea's mean level, m
    double crestWidth_m = 6.0;  // m, > 0
    double sideSlope = 0.67;    // the sides' rise over run, > 0 (0.67: 1:1.5, a rubble mound's)
};

// The floor from a grey image: row 0 is the north edge (-z), column 0 the
// west edge (-x); the first and last pixels lie on the edges of the
// rectangle (centre_m, size_m) and heights between pixels are bilinear.
// Black is blackHeight_m, white whiteHeight_m (relative to the sea's mean
// level); 8- and 16-bit grey PNGs, 2..4096 pixels a side.
struct SWELL_API SeabedHeightmap {
    std::string path;                // relative to the scene file; empty: no heightmap
    glm::dvec2 center_m{0.0};        // world [x, z] of the image's centre, m
    glm::dvec2 size_m{1000.0, 1000.0}; // its size along x and z, m, > 0
    double blackHeight_m = -20.0;    // the height black means, m
    double whiteHeight_m = 10.0;     // the height white means, m
};

// The scene's sea floor (Scene::seabed). Empty: the floor is flat at the
// sea's depth (waves.depth_m) everywhere.
struct SWELL_API SeabedSettings {
    // Where the sea is deep (waves.depth_m = inf), a beach's and a shelf's
    // slopes end this deep, m, > 0, and the sea beyond them is deep water;
    // with a finite depth they end where they reach it (or here, if this is
    // shallower). Seabed::toeDepth_m().
    double toeDepth_m = 100.0;
    std::vector<SeabedBeach> beaches;
    std::vector<SeabedShelf> shelves;
    std::vector<SeabedBreakwater> breakwaters;
    SeabedHeightmap heightmap;

    bool empty() const { return beaches.empty() && shelves.empty() && breakwaters.empty() && heightmap.path.empty(); }
};

// The most shapes of each kind a scene may list: each is drawn and summed
// at every point the seabed is sampled.
inline constexpr std::size_t kMaxSeabedShapes = 64;

// The world rectangle that holds every part of a seabed (x, z; m).
struct SWELL_API SeabedExtent {
    glm::dvec2 min_m{0.0};
    glm::dvec2 max_m{0.0};
};

// One shape's own height, m, where it reaches; nothing outside it. The
// seabed is the highest of them; the drawn meshes take their vertices
// from these same functions. `toe_m` is Seabed::toeDepth_m().
SWELL_API std::optional<double> beachElevation_m(const SeabedBeach& beach, double toe_m, glm::dvec2 world_xz_m);
SWELL_API std::optional<double> shelfElevation_m(const SeabedShelf& shelf, double toe_m, glm::dvec2 world_xz_m);
SWELL_API std::optional<double> breakwaterElevation_m(const SeabedBreakwater& breakwater, double toe_m,
                                                      glm::dvec2 world_xz_m);

// The unit vector [x, z] of an azimuth measured like a heading (from -z towards +x), deg.
SWELL_API glm::dvec2 azimuthDirection(double azimuth_deg);

} // namespace swell
