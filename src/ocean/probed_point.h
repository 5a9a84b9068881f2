// The water under a point, as a frame's queries answer it (on the GPU,
// render/surface_probe.h, or on the CPU): what floating objects are placed
// on (objects/placement.h) and what tells the eye's side of the water.
#pragma once

#include "swell/drawn_surface.h"

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include <optional>

namespace swell::detail {

// One query's answer, in the frame the points were given in (x, z as asked;
// heights relative to the origin's y).
struct ProbedPoint {
    glm::dvec2 rest_m{0.0};           // the exact surface's rest point under the point
    glm::dvec3 displacement_m{0.0};   // the exact surface's displacement there, m
    glm::dvec3 normal{0.0, 1.0, 0.0}; // its unit normal
    std::optional<DrawnPoint> drawn;  // the drawn water under the point
    bool drawnOnCpu = false;          // answered on the CPU: all of it (answerOnCpu), or its triangle, which lay beyond the GPU's block
};

} // namespace swell::detail
