// What the example host shows: a small ship riding at anchor off a pier,
// crates on the pier and one adrift between them. The host owns all of it
// (its boxes, its camera); Swell only tells it where the water is:
// the ship heaves, pitches and rolls on the drawn surface under its hull
// (plus a slow roll of its own, a swell from abeam), the loose crate sits
// on the drawn surface where it floats, and the camera stands on the
// ship's bridge wing and rolls with it. The host's sea floor (seabed())
// gives Swell the harbour's depth, its quay and a mole west of the pier:
// the swell from abeam reaches the ship and the pier only as far as it
// diffracts around the mole's head.
#pragma once

#include "boxes.h"

#include <swell/drawn_surface.h>
#include <swell/scene/seabed.h>

#include <glm/mat4x4.hpp>
#include <glm/vec3.hpp>

#include <vector>

namespace host {

class Harbour {
public:
    // The harbour with its sea at `level_m` (absolute world y, m).
    explicit Harbour(double level_m);

    // Where the water's simulation and its grid's detail are centred
    // (absolute world, m): the ship's anchorage, at the bridge's height.
    glm::dvec3 viewpoint_m() const;

    // Moves the ship and the loose crate to `time_s` on `water` (the
    // renderer's drawnSurface(viewpoint_m()) for that time) and writes every
    // box of the harbour into `boxes`.
    void update(double time_s, const swell::DrawnSurface& water, std::vector<Box>& boxes);

    // The camera on the bridge wing: world (absolute, m) to eye, rolling,
    // pitching and heaving with the ship. Valid after update().
    glm::dmat4 eyeView() const;
    // The harbour's floor, heights above the sea's mean level (m), for
    // Renderer::setSeabedHeights: 10 m of water, the quay's land behind the
    // pier, and a rubble mole from the quay out past the ship, west of it,
    // across the swell's way (the swell runs towards +x).
    swell::SeabedHeights seabed() const;
    // The ship's roll now, degrees (+: to starboard).
    double shipRoll_deg() const { return roll_deg_; }

private:
    double level_m_;
    glm::dmat4 ship_{1.0}; // ship frame (x starboard, y up, -z the bow; origin at the waterline amidships) to world
    double roll_deg_ = 0.0;
};

} // namespace host
