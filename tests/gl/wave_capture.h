// Captures what the water vertex shader computes (transform feedback) and
// what the CPU wave function says the same vertices should be.
#pragma once

#include "swell/camera.h"
#include "swell/renderer.h"

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include <vector>

namespace swell::test {

struct WaterVertex {
    glm::dvec2 rest_m{};     // absolute world x,z of the rest point
    glm::dvec3 position_m{}; // absolute world position after displacement
    glm::dvec3 normal{};
    int i = 0, j = 0;       // grid line indices
    double snapMargin = 0.5;    // CPU only: how near its snap was to a tie, lattice steps (swell::GridPoint)
    double latticeStep_m = 0.0; // CPU only: the coarser lattice step it snapped to
};

// The GPU's vertices, made absolute with the render origin (camera x,z).
std::vector<WaterVertex> captureGpu(Renderer& renderer, const Camera& camera, double time_s);

// The same vertices from the CPU: grid lines from swell/scene/grid.h, waves weighted
// by the horizon fade and the wavelength filter, displaced by swell::displacementAt.
std::vector<WaterVertex> computeCpu(const Renderer& renderer, const Camera& camera, double time_s);

} // namespace swell::test
