// The built-in boat's seakeeping: its heave and pitch in regular head
// waves against the closed-form strip-theory transfer functions of Jensen,
// Mansour & Olsen (2004), "Estimation of ship motions using closed-form
// expressions", Ocean Engineering 31(1), 61-85, sec. 2 (their heave
// transfer function Phi_w = eta F and pitch Phi_theta = eta G; the hull a
// homogeneously loaded box of the ship's length and draft and of breadth
// C_B B, its added mass taken equal to its mass). Their curves have the
// shape every strip theory gives (Journee & Massie 2001, Offshore
// Hydromechanics, TU Delft, ch. 6 and 8): heave amplitude over wave
// amplitude, and pitch amplitude over wave-slope amplitude, tend to 1 for
// waves much longer than the hull (it rides them like a cork) and to 0 for
// waves shorter than it (their crests and troughs along it cancel).
//
// Swell's bodies keep only the hydrostatic part of the waves' pressure
// (docs/BODIES.md), without added mass and with a damping ratio of 0.1, so
// near the hull's own period the two differ; the test checks the regimes
// a picture shows: the long waves that carry the boat, within a factor of
// 1.5, and the short ones, which must leave it nearly still, as they would
// not before the water under a body was sampled without aliasing (a 2 m
// wave read on a 1.9 m lattice as a tilt of the whole hull).
#include "assets/mesh_data.h"
#include "support/body_fixtures.h"
#include "swell/constants.h"
#include "swell/floating_body.h"
#include "swell/scene/waves.h"

#include <glm/geometric.hpp>
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>

namespace {

// The boat's design numbers (assets/models/boat_model.py): overall length,
// beam, keel draft, displacement.
constexpr double kLength_m = 7.0, kBeam_m = 2.4, kDraft_m = 0.48, kDisplacement_kg = 2500.0;

// One long-crested sine wave along +x that a filter sees as the GPU does:
// faded by swell::waveLodWeight for the footprint asked (the test water of
// body_fixtures.h keeps every wave whatever the footprint).
class RegularWave final : public swell::SurfaceQuery {
public:
    RegularWave(double amplitude_m, double wavelength_m)
        : amplitude_m_(amplitude_m), wavelength_m_(wavelength_m), k_(swell::kTwoPi / wavelength_m),
          omega_(std::sqrt(swell::kGravity * k_))
    {
    }
    swell::WaveReach reach() const override { return {amplitude_m_, 0.0}; }
    swell::SurfacePoint surfaceAt(glm::dvec2 rest, double t, const swell::SurfaceFilter& filter) const override
    {
        const double a = filter.heightScale * amplitude_m_ * swell::waveLodWeight(wavelength_m_, filter.footprint_m);
        const double phase = k_ * rest.x - omega_ * t;
        swell::SurfacePoint p;
        p.displacement_m.y = a * std::sin(phase);
        p.normal = glm::normalize(glm::dvec3(-a * k_ * std::cos(phase), 1.0, 0.0));
        return p;
    }

private:
    double amplitude_m_, wavelength_m_, k_, omega_;
};

// Jensen, Mansour & Olsen (2004), sec. 2: heave over wave amplitude and
// pitch over wave slope (k times the amplitude) of a box of length L, draft
// T and breadth C_B B in regular waves of wavelength lambda met at heading
// beta (180 degrees: head seas) at Froude number Fn = U / sqrt(g L).
struct Response {
    double heave = 0.0, pitch = 0.0;
};

Response closedFormResponse(double wavelength_m, double speed_m_per_s)
{
    const double g = swell::kGravity, L = kLength_m, T = kDraft_m;
    const double blockCoefficient = kDisplacement_kg / swell::kSeaWaterDensity_kg_per_m3 / (L * kBeam_m * T);
    const double B0 = blockCoefficient * kBeam_m;
    const double k = swell::kTwoPi / wavelength_m;
    const double Fn = speed_m_per_s / std::sqrt(g * L);
    const double cosBeta = -1.0; // head seas
    const double alpha = 1.0 - Fn * std::sqrt(k * L) * cosBeta; // encounter over wave frequency
    const double ke = std::abs(k * cosBeta);
    const double kappa = std::exp(-ke * T); // Smith's correction: the pressure's decay with depth
    // The sectional damping: the ratio of the radiated to the heaving amplitude of a 2-D section.
    const double A = 2.0 * std::sin(0.5 * k * B0 * alpha * alpha) * std::exp(-k * T * alpha * alpha);
    const double f = std::sqrt(std::pow(1.0 - k * T, 2) + std::pow(A * A / (k * B0 * std::pow(alpha, 3)), 2));
    const double x = 0.5 * ke * L;
    const double F = kappa * f * std::sin(x) / x;
    const double G = kappa * f * 24.0 / (ke * L * ke * L * L) * (std::sin(x) - x * std::cos(x));
    const double eta =
        1.0 / std::sqrt(std::pow(1.0 - 2.0 * k * T * alpha * alpha, 2) + std::pow(A * A / (k * B0 * alpha * alpha), 2));
    return {std::abs(eta * F), std::abs(eta * G) / k};
}

swell::BodyShape boatHull()
{
    const swell::detail::MeshData mesh = swell::detail::makeBuiltinHullVolume("boat");
    swell::BodyShape s;
    for (const auto& v : mesh.vertices)
        s.positions_m.push_back(glm::dvec3(v.position));
    s.indices = mesh.indices;
    return s;
}

// The design's centre of mass (the root node's extras, boat.gltf).
glm::dvec3 designCenterOfMass_m()
{
    std::ifstream in(std::filesystem::path(SWELL_SOURCE_DIR) / "assets" / "models" / "boat.gltf");
    const nlohmann::json doc = nlohmann::json::parse(in);
    for (const auto& node : doc.at("nodes"))
        if (node.value("name", "") == "boat") {
            const auto& c = node.at("extras").at("center_of_mass_m");
            return {c[0].get<double>(), c[1].get<double>(), c[2].get<double>()};
        }
    ADD_FAILURE() << "no node named 'boat' in boat.gltf";
    return glm::dvec3(0.0);
}

// Swell's boat heading into the wave (along -x) at speed_m_per_s: its
// heave amplitude over the wave's, and its pitch amplitude over the
// wave's slope, over the last 20 s of 50 (the start's transient damped).
Response simulatedResponse(double wavelength_m, double speed_m_per_s)
{
    const swell::BodyShape shape = boatHull();
    swell::BodySettings settings;
    settings.mass_kg = kDisplacement_kg;
    settings.centerOfMassOffset_m = designCenterOfMass_m() - swell::massPropertiesOf(shape).centroid_m;
    const double amplitude_m = 0.005 * wavelength_m; // a steepness of 1%: linear
    const RegularWave wave(amplitude_m, wavelength_m);
    swell::FloatingBody body(shape, settings, {.yaw_deg = 180.0, .velocity_m_per_s = {-speed_m_per_s, 0.0, 0.0}}, wave);
    double heaveLo = 1e9, heaveHi = -1e9, pitchLo = 1e9, pitchHi = -1e9;
    for (double t = 30.0; t <= 50.0; t += 0.01) {
        const glm::dmat4 pose = body.poseAt(t);
        const glm::dvec3 bow = glm::normalize(glm::dvec3(pose[0]));
        heaveLo = std::min(heaveLo, pose[3].y);
        heaveHi = std::max(heaveHi, pose[3].y);
        pitchLo = std::min(pitchLo, std::asin(bow.y));
        pitchHi = std::max(pitchHi, std::asin(bow.y));
    }
    const double slope = swell::kTwoPi / wavelength_m * amplitude_m;
    return {0.5 * (heaveHi - heaveLo) / amplitude_m, 0.5 * (pitchHi - pitchLo) / slope};
}

// Strip theory's response and Swell's to waves `lengths` boat lengths long
// met at speed_m_per_s, printed, and where they were taken, for messages.
struct Compared {
    Response expected, got;
    std::string where;
};

Compared compared(double lengths, double speed_m_per_s)
{
    const double wavelength_m = lengths * kLength_m;
    Compared c{closedFormResponse(wavelength_m, speed_m_per_s), simulatedResponse(wavelength_m, speed_m_per_s),
               "lambda/L " + std::to_string(lengths) + " at " + std::to_string(speed_m_per_s) + " m/s"};
    std::printf("lambda/L %.2f at %.1f m/s: heave %.3f (closed form %.3f), pitch %.3f (%.3f)\n", lengths,
                speed_m_per_s, c.got.heave, c.expected.heave, c.got.pitch, c.expected.pitch);
    return c;
}

// Waves 3 to 8 boat lengths long, at rest and at 2.5 m/s (Fn = 0.30, a
// speed strip theory is commonly used at): heave and pitch within a factor
// of 1.5 of the closed form's (which is 0.85 to 0.99 there).
TEST(Seakeeping, LongWavesCarryTheBoatAsStripTheorySays)
{
    for (double speed : {0.0, 2.5})
        for (double lengths : {3.0, 5.0, 8.0}) {
            const Compared c = compared(lengths, speed);
            EXPECT_LT(c.got.heave, 1.5 * c.expected.heave) << c.where;
            EXPECT_GT(c.got.heave, c.expected.heave / 1.5) << c.where;
            EXPECT_LT(c.got.pitch, 1.5 * c.expected.pitch) << c.where;
            EXPECT_GT(c.got.pitch, c.expected.pitch / 1.5) << c.where;
        }
}

// Waves shorter than the boat (half and a third of its length) leave it
// nearly still, in strip theory (under 0.05) as at sea; Swell's within
// 0.15 of the wave's amplitude and slope, at rest and at the preset's
// 5 m/s.
TEST(Seakeeping, ShortWavesLeaveTheBoatNearlyStill)
{
    for (double speed : {0.0, 5.0})
        for (double lengths : {0.33, 0.5}) {
            const Compared c = compared(lengths, speed);
            EXPECT_LT(c.expected.heave, 0.05) << c.where;
            EXPECT_LT(c.expected.pitch, 0.05) << c.where;
            EXPECT_LT(c.got.heave, 0.15) << c.where;
            EXPECT_LT(c.got.pitch, 0.15) << c.where;
        }
}

} // namespace
