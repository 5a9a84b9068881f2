// Where a hull under way throws spray from its bow, and how much
// (docs/RENDERING.md "Spray"; drawn by the spray's passes built with
// SWELL_BOW_SPRAY: shaders/spray_clumps.comp to spray.vert). The bow's waterline is found once from the closed hull;
// the hull's share of spray is sampled from its body's steps, so, like the
// poses, it is a function of the scene and the time alone.
#pragma once

#include "swell/floating_body.h"
#include "swell/gpu/spray.h"

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include <array>
#include <optional>

namespace swell::detail {

// Where the bow's sheet leaves the hull, in the shape's frame (m). The
// water the bow meets climbs it by up to its stagnation head U^2 / 2g
// (Bernoulli: the flow meets the stem at the hull's speed U) before it
// leaves the hull as a sheet, so the sheet leaves where the hull is cut by
// a plane that high above its calm waterline (the plane where it floats
// upright at its mass), outboard of the waterline as far as the bow flares.
struct BowLine {
    glm::dvec3 forward{1.0, 0.0, 0.0}; // the heading of travel, horizontal, unit
    glm::dvec3 across{0.0, 0.0, 1.0};  // horizontal, unit, towards the first side's stations
    double waterline_m = 0.0;          // the calm waterline's height
    double climb_m = 0.0;              // the cut's height above it
    double length_m = 0.0;             // the waterline's length along `forward`
    // The cotangent of the bow's flare: how far the cut lies outboard of
    // the waterline for each metre of the climb, the mean over the
    // stations aft of the stem (0: wall sided; 0 when there is no climb).
    // It sets how fast a plunging bow throws its sheet (spray.glsl's
    // bowSlamJet_mps: Wagner's jet).
    double flareCot = 0.0;
    // Each side's points on the cut (the first side's, then the other's),
    // from the stem (both sides' first point) aft over
    // SWELL_BOW_SPRAY_REACH of the waterline's length, evenly.
    std::array<std::array<glm::dvec3, SWELL_BOW_SPRAY_STATIONS>, 2> stations{};
};

// The bow's line of a closed hull (BodyShape's frame and winding) of
// `mass_kg` in water of `density_kg_per_m3`, travelling along
// `forwardInShape` (its horizontal part is used) at `speed_mps`: cut
// U^2 / 2g above its waterline, at most half way from there to the hull's
// top; nothing when the hull is not cut there or has no horizontal heading.
std::optional<BowLine> bowLineOf(const BodyShape& shape, double mass_kg, double density_kg_per_m3,
                                 glm::dvec3 forwardInShape, double speed_mps);

// The relative vertical speed of the bow and the water past which a hull
// of waterline length length_m slams (Ochi 1964, "Prediction of occurrence
// and severity of ship slamming at sea", 5th Symposium on Naval
// Hydrodynamics: 12 ft/s for a 520 ft ship, scaled by Froude's law),
// 0.093 sqrt(g L), m/s.
double slamThreshold_mps(double length_m);

// The share (0..1) of a hull's bow slots born at a moment: none at rest,
// growing with its Froude number U / sqrt(g L) to full at 0.4 (a
// displacement hull's bow wave is fully made about its hull speed, the
// waves it makes as long as its waterline), a fifth of that in calm water
// and the rest as the bow plunges into the waves towards the slamming
// speed (slamThreshold_mps; chosen by eye). plunge_mps: how fast the water
// rises against the bow (the water's rise less the bow's), > 0 plunging.
double bowSprayShare(double speed_mps, double length_m, double plunge_mps);

// The hull at one sample: the share, the plunge (m/s, >= 0) and the
// height its sheet leaves the hull at (m): the water's at the stem plus
// the climb (BowLine::climb_m).
struct BowSample {
    float share = 0.0f;
    float plunge_mps = 0.0f;
    float leaves_m = 0.0f;
};

// The sample of `body` (its shape the one `line` was found on) at its last
// step, carried at horizontal velocity `velocity_m_per_s` (x, z).
BowSample bowSampleOf(const FloatingBody& body, const BowLine& line, glm::dvec2 velocity_m_per_s);

} // namespace swell::detail
