// The water's push on a floating body: the hydrostatic pressure rho g d at
// depth d below the surface, integrated over the submerged part of the
// body's closed surface. On flat water this is exactly Archimedes' buoyancy
// (rho g V, up, through the centre of buoyancy); on waves it is the
// hydrostatic part of the Froude-Krylov force, the usual approximation for
// bodies small against the wavelength (Journee & Massie 2001, Offshore
// Hydromechanics, TU Delft, ch. 6).
#pragma once

#include "swell/surface_query.h"

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include <array>
#include <cmath>
#include <cstdint>
#include <vector>

namespace swell::detail {

// The surface under a body: heights on a kPatchSamples^2 lattice over a
// square round its centre, interpolated bilinearly. A few dozen queries a
// step instead of one per vertex; the lattice spacing (a fraction of the
// body's size) also smooths ripples far shorter than the body, which a
// rigid body does not follow.
inline constexpr int kPatchSamples = 6;

struct WaterPatch {
    glm::dvec2 centre_m{0.0}; // world x, z of the square's centre
    double halfSize_m = 0.0;
    glm::dvec2 corner_m{0.0}; // world x, z of sample (0, 0)
    double spacing_m = 1.0;
    std::array<double, kPatchSamples * kPatchSamples> height_m{};

    // Bilinear height at world (x, z), m; clamped to the patch's edge outside it.
    double heightAt(glm::dvec2 world_m) const;


// Whether the square holds every point within reach_m of world_m.
    bool covers(glm::dvec2 world_m, double reach_m) const
    {
        return std::abs(world_m.x - centre_m.x) + reach_m <= halfSize_m &&
               std::abs(world_m.y - centre_m.y) + reach_m <= halfSize_m;
    }
};

// The patch between two samplings of the same lattice, a fraction f (0..1) of the way from `from` to `to`.
WaterPatch blend(const WaterPatch& from, const WaterPatch& to, double f);

// Samples `surface` at time_s over the square of half-size halfSize_m round centre_m.
WaterPatch sampleWater(const SurfaceQuery& surface, glm::dvec2 centre_m, double halfSize_m, double time_s,
                       const SurfaceFilter& filter);

struct HydrostaticLoad {
    glm::dvec3 force_N{0.0};
    glm::dvec3 torque_N_m{0.0}; // about the reference point
    double submergedVolume_m3 = 0.0; // the force's vertical part over rho g
};

// The pressure load on the surface `indices` make of `world_m` (outward
// winding), with torque about `reference_m`, in water of density
// density_kg_per_m3 whose surface is `water`. The waterline cuts triangles
// where the linearly interpolated depth is zero.
HydrostaticLoad hydrostaticLoad(const std::vector<glm::dvec3>& world_m, const std::vector<std::uint32_t>& indices,
                                glm::dvec3 reference_m, const WaterPatch& water, double density_kg_per_m3);

} // namespace swell::detail
