// The sea floor: where the water is shallow, where the land rises out of it.
// A scene describes it ([seabed], docs/SCENE.md) with analytic shapes that
// tests and presets need (plane beaches, shelves, breakwaters) and a
// heightmap image; the built-in island's terrain and a host's own height
// array (Renderer::setSeabedHeights) join them. Seabed answers the height
// of the floor at any point of the sea's plane; the depth of the water
// there is minus that height (the sea frame, swell/sea_frame.h: y = 0 at
// the sea's mean level). The scene's shapes: swell/scene/seabed_settings.h.
#pragma once

#include "swell/export.h"
#include "swell/scene/seabed_settings.h"

#include <glm/vec2.hpp>

#include <cstddef>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <vector>

namespace swell {

struct Scene;

// A grid of heights a host gives (Renderer::setSeabedHeights): `columns` x
// `rows` heights, row-major, row 0 at min_m.y (the -z edge), column 0 at
// min_m.x; the first and last samples lie on the rectangle's edges and
// heights between them are bilinear. Heights are world y, m (absolute, as
// the host's own geometry is), not relative to the sea's level.
struct SWELL_API SeabedHeights {
    int columns = 0, rows = 0;     // each 2..4096
    std::vector<float> heights_m;  // columns * rows, finite
    glm::dvec2 min_m{0.0};         // world [x, z] of the first sample, m
    glm::dvec2 max_m{0.0};         // world [x, z] of the last sample, m; > min_m in both
};

// The sea floor of a scene, ready to be sampled. Immutable; copies share
// their data.
class SWELL_API Seabed {
public:
    // A flat floor at the sea's depth everywhere (deep water when infinite).
    Seabed();
    // The floor `scene` describes: its [seabed], and the built-in island when
    // scene.showTerrain; `host`, when given, joins them. Reads the heightmap
    // image (relative to scene.assetFolder). Throws swell::InputError naming
    // the key ("seabed.heightmap.path", "seabed.breakwaters[2]") when a
    // setting is out of its range or the heightmap is missing, empty, not a
    // grey image or too large, at the key's place when the scene records it;
    // swell::Error when `host` is malformed (checkSeabedHeights).
    explicit Seabed(const Scene& scene, const SeabedHeights* host = nullptr);

    // The height of the floor (or of the land) above the sea's mean level
    // at world [x, z], m: negative under water. The highest of the shapes,
    // the heightmap, the island and the host's heights there; where none
    // reaches, -depth (the sea's waves.depth_m; -infinity: deep water).
    double elevation_m(glm::dvec2 world_xz_m) const;

    // The rectangle that holds every shape, the heightmap, the island and
    // the host's heights; empty when the floor is flat everywhere.
    std::optional<SeabedExtent> extent() const;

    // The depth at which beaches' and shelves' slopes end: the scene's
    // seabed.toe_depth_m, or the sea's depth when that is shallower, m.
    double toeDepth_m() const;

    // What it holds, for the library's own code (its drawn mesh).
    struct Data;
    const Data& data() const { return *data_; }

private:
    std::shared_ptr<const Data> data_;
};

// Throws swell::Error naming `what` (the caller's name for the array:
// "Renderer::setSeabedHeights()") when `heights` is malformed: a size
// outside 2..4096, an array that does not hold columns * rows heights, a
// height that is NaN or infinite, or a rectangle with no area.
SWELL_API void checkSeabedHeights(const SeabedHeights& heights, const std::string& what);

} // namespace swell
