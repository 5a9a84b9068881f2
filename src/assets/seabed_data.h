// What a Seabed holds (swell/scene/seabed.h), for the code that samples it
// (assets/seabed.cpp) and the code that draws it (assets/seabed_mesh.cpp).
#pragma once

#include "core/seabed_shapes.h"
#include "swell/scene/seabed.h"

#include <limits>
#include <optional>
#include <vector>

namespace swell {

struct Seabed::Data {
    double floor_m = -std::numeric_limits<double>::infinity(); // where nothing reaches: -waves.depth_m
    double toe_m = 100.0;                                        // Seabed::toeDepth_m()
    SeabedSettings shapes;                                       // the heightmap's path only names it
    // Each shape's world rectangle, in the order of `shapes`' lists: a
    // point outside it needs no more of that shape.
    std::vector<SeabedExtent> beachBoxes, shelfBoxes, breakwaterBoxes;
    std::optional<detail::HeightGrid> heightmap; // relative to the sea's mean level
    std::optional<detail::HeightGrid> host;      // made relative to the sea's mean level
    // The built-in island (Scene::showTerrain), and the height of its y = 0
    // above the sea's mean level (the renderer places it in the sea frame).
    bool island = false;
    double islandBase_m = 0.0;
    std::optional<SeabedExtent> extent;
};

} // namespace swell
