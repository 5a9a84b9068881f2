// What the floating-body tests share: test water (flat or one sine wave),
// a closed box, and a shape made into the mesh a scene object would load.
#pragma once

#include "assets/mesh_data.h"
#include "swell/constants.h"
#include "swell/floating_body.h"
#include "swell/surface_query.h"

#include <glm/geometric.hpp>

#include <cmath>
#include <memory>
#include <string>

namespace swell::test {

// Water as a test wants it: flat, or one long-crested sine wave of height
// amplitude_m moving along +x (vertical displacement only, so the default
// restPointUnder() is exact).
class TestWater final : public swell::SurfaceQuery {
public:
    explicit TestWater(double amplitude_m = 0.0, double wavelength_m = 40.0) : amplitude_m_(amplitude_m)
    {
        k_ = swell::kTwoPi / wavelength_m;
        omega_ = std::sqrt(swell::kGravity * k_); // deep water: omega^2 = g k
    }
    swell::WaveReach reach() const override { return {amplitude_m_, 0.0}; }
    swell::SurfacePoint surfaceAt(glm::dvec2 rest, double t, const swell::SurfaceFilter& filter) const override
    {
        swell::SurfacePoint p;
        const double phase = k_ * rest.x - omega_ * t;
        p.displacement_m.y = filter.heightScale * amplitude_m_ * std::sin(phase);
        p.normal = glm::normalize(glm::dvec3(-filter.heightScale * amplitude_m_ * k_ * std::cos(phase), 1.0, 0.0));
        return p;
    }

private:
    double amplitude_m_, k_ = 0.0, omega_ = 0.0;
};

// A closed box centred on the origin, outward winding.
inline swell::BodyShape box(glm::dvec3 size_m)
{
    swell::BodyShape s;
    const glm::dvec3 h = 0.5 * size_m;
    for (int i = 0; i < 8; ++i)
        s.positions_m.push_back({(i & 1) ? h.x : -h.x, (i & 2) ? h.y : -h.y, (i & 4) ? h.z : -h.z});
    // Each face as two triangles, counter-clockwise seen from outside.
    s.indices = {0, 4, 6, 0, 6, 2,  1, 3, 7, 1, 7, 5,  0, 1, 5, 0, 5, 4,
                 2, 6, 7, 2, 7, 3,  0, 2, 3, 0, 3, 1,  4, 5, 7, 4, 7, 6};
    return s;
}

// The shape as a drawn mesh: what a scene object's model gives the bodies.
inline swell::detail::MeshData meshOf(const swell::BodyShape& shape)
{
    swell::detail::MeshData mesh;
    for (const glm::dvec3& p : shape.positions_m)
        mesh.vertices.push_back({glm::vec3(p), {}, {}});
    mesh.indices = shape.indices;
    return mesh;
}

} // namespace swell::test
