// A floating body in the surf rides the shoaled waves (issue 44): on the
// coast preset's beach a small float heaves as the water under it does,
// offshore, in 4 m of water and in the surf in 2 m alike, where the waves
// cut by their depth leave it heaving far less than offshore.
#include "ocean/coast/coast_grid.h"
#include "support/body_fixtures.h"

#include "swell/floating_body.h"
#include "swell/gerstner_model.h"
#include "swell/scene/scene.h"
#include "swell/scene/scene_file.h"
#include "swell/scene/seabed.h"
#include "swell/scene/waves.h"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <vector>

namespace {

// The standard deviation of v, m.
double deviation(const std::vector<double>& v)
{
    double mean = 0.0;
    for (double x : v)
        mean += x;
    mean /= double(v.size());
    double sum = 0.0;
    for (double x : v)
        sum += (x - mean) * (x - mean);
    return std::sqrt(sum / double(v.size()));
}

struct Ride {
    double body_m = 0.0;  // the float's heave, standard deviation
    double water_m = 0.0; // the water's height at its place
};

// A 1 m cube of half the water's density at (x, z), over 60 s after 20 s
// to settle, sampled every 0.25 s.
Ride rideAt(const swell::SurfaceQuery& water, glm::dvec2 place_m)
{
    const glm::dvec3 size(1.0, 1.0, 1.0);
    swell::BodySettings settings;
    settings.mass_kg = 0.5 * swell::kSeaWaterDensity_kg_per_m3 * size.x * size.y * size.z;
    swell::FloatingBody body(swell::test::box(size), settings, {{place_m.x, 0.0, place_m.y}, 0.0, {0.0, 0.0, 0.0}},
                             water);
    std::vector<double> heave, height;
    for (double t = 20.0; t < 80.0; t += 0.25) {
        heave.push_back(body.poseAt(t)[3].y);
        height.push_back(water.heightAt(place_m, t));
    }
    return {deviation(heave), deviation(height)};
}

TEST(BodyInTheSurf, AFloatRidesTheShoaledSwell)
{
    const swell::Scene scene =
        swell::loadScene(std::filesystem::path(SWELL_SOURCE_DIR) / "scenes" / "coast.toml");
    swell::WaveSet waves = swell::resolveWaves(scene);
    swell::limitSteepness(waves);
    waves.coast = swell::coast::coastFieldOf(swell::Seabed(scene), waves);
    ASSERT_TRUE(waves.coast);
    const swell::GerstnerSurface water(waves);
    // The beach's waterline runs along x at z = 300 m, 1:40: 30 m deep at
    // z = -900 m, 4 m at z = 140 m, 2 m at z = 220 m, in the surf (the
    // sea's height there is cut to 0.78 of the depth).
    const Ride offshore = rideAt(water, {-200.0, -900.0});
    const Ride shoaling = rideAt(water, {-200.0, 140.0});
    const Ride surf = rideAt(water, {-200.0, 220.0});
    for (const Ride& r : {offshore, shoaling, surf})
        EXPECT_NEAR(r.body_m, r.water_m, 0.1 * r.water_m) << "the float heaves as the water under it";
    // Where the sea breaks the float heaves with the cut waves, not the
    // open sea's (a float that felt the open sea there would heave as
    // offshore).
    EXPECT_LT(surf.water_m, 0.8 * offshore.water_m);
    EXPECT_LT(surf.body_m, 0.8 * offshore.body_m);
}

} // namespace
