// Floating bodies at the edges of what docs/SCENE.md allows: each one either
// simulates an hour with a finite state, or is refused when the scene's
// bodies are built, naming the object and the key to change. Three bodies
// within the documented ranges once drove the state to NaN, and a NaN
// turned into an index crashed the program.
#include "assets/mesh_data.h"
#include "objects/scene_bodies.h"
#include "swell/error.h"
#include "swell/scene/scene.h"

#include "support/body_fixtures.h"

#include <gtest/gtest.h>

#include <cmath>
#include <optional>
#include <random>
#include <string>

using namespace swell;

namespace {

// A long swell a metre high, so every body heaves and heels.
std::shared_ptr<const test::TestWater> swellWater()
{
    static const auto water = std::make_shared<const test::TestWater>(1.0, 60.0);
    return water;
}

// The shape a scene gives a built-in's body (assets/scene_assets.h, SceneShapes): its hull
// volume when it has one, else the model.
detail::MeshData shapeOf(const std::string& path)
{
    const std::string name = path.substr(kBuiltinObjectPrefix.size());
    detail::MeshData hull = detail::makeBuiltinHullVolume(name);
    return hull.indices.empty() ? detail::makeBuiltinModel(name) : hull;
}

struct SimulatedRun {
    std::optional<std::string> refusal; // the message, when the bodies were refused
    bool finite = true;                 // every pose of the hour was finite
    std::string stopped;                // what stopped the simulation, if anything did
};

// Builds the scene's bodies for one object and steps them for `duration_s`,
// checking the pose every simulated second. Without a wake unless asked: an
// hour of it is minutes of transforms, and it does not move the body.
SimulatedRun simulate(const SceneObject& object, double duration_s, bool wake = false)
{
    Scene scene;
    scene.objects = {object};
    scene.wake.enabled = wake;
    scene.wake.cells = 64; // a quarter of the default's side: the same waves near the body, at a 16th of the cost
    const detail::MeshData shape = shapeOf(object.path);
    SimulatedRun outcome;
    try {
        detail::SceneBodies bodies(scene, {&shape}, swellWater());
        for (double t = 1.0; t <= duration_s; t += 1.0) {
            bodies.advanceTo(t);
            const glm::dmat4 pose = bodies.poseAt(0, t).value();
            for (int c = 0; c < 4; ++c)
                for (int r = 0; r < 4; ++r)
                    outcome.finite = outcome.finite && std::isfinite(pose[c][r]);
            if (!outcome.finite) {
                outcome.stopped = "a pose that is not finite at t = " + std::to_string(t);
                break;
            }
        }
    } catch (const InputError& e) {
        outcome.refusal = e.message();
    } catch (const Error& e) {
        outcome.finite = false;
        outcome.stopped = e.what();
    }
    return outcome;
}

SceneObject floatingBoat()
{
    SceneObject o;
    o.path = "builtin:boat";
    o.floats = true;
    return o;
}

} // namespace

// A hull of several cubic metres weighing a gram heaves faster than the
// 1/120 s step can follow: refused at its mass, with the least it needs.
TEST(BodyLimits, AHullOfCubicMetresWeighingAGramIsRefusedAtItsMass)
{
    SceneObject o = floatingBoat();
    o.mass_kg = 0.001;
    const SimulatedRun out = simulate(o, 3600.0);
    ASSERT_TRUE(out.refusal.has_value()) << "simulated: " << out.stopped;
    EXPECT_NE(out.refusal->find("objects[0].mass_kg = 0.001"), std::string::npos) << *out.refusal;
    EXPECT_NE(out.refusal->find("it needs at least"), std::string::npos) << *out.refusal;
}

// The smallest density a double holds (5e-324 kg/m^3, within 0..100000):
// refused at its density, not divided by.
TEST(BodyLimits, TheSmallestDensityIsRefusedAtItsDensity)
{
    SceneObject o = floatingBoat();
    o.density_kg_per_m3 = 5e-324;
    const SimulatedRun out = simulate(o, 3600.0);
    ASSERT_TRUE(out.refusal.has_value()) << "simulated: " << out.stopped;
    EXPECT_NE(out.refusal->find("objects[0].density_kg_per_m3 = 5e-324"), std::string::npos) << *out.refusal;
}

// A centre of mass a kilometre above the hull (the range's end): the boat
// capsizes and tumbles, slowly, for an hour, every state finite.
TEST(BodyLimits, ACentreOfMassAKilometreUpSimulatesAnHourFinite)
{
    SceneObject o = floatingBoat();
    o.density_kg_per_m3 = 300.0;
    o.centerOfMassOffset_m = {0.0, 1000.0, 0.0};
    const SimulatedRun out = simulate(o, 3600.0);
    ASSERT_FALSE(out.refusal.has_value()) << *out.refusal;
    EXPECT_TRUE(out.finite) << out.stopped;
}

// As dense as the water it displaces, a body floats awash (docs/BODIES.md
// refuses only one heavier); one a tenth of a percent denser sinks.
TEST(BodyLimits, ABodyAsDenseAsTheWaterFloatsAndADenserOneIsRefused)
{
    SceneObject o = floatingBoat();
    o.density_kg_per_m3 = kSeaWaterDensity_kg_per_m3;
    const SimulatedRun awash = simulate(o, 60.0);
    EXPECT_FALSE(awash.refusal.has_value()) << *awash.refusal;
    EXPECT_TRUE(awash.finite) << awash.stopped;
    o.density_kg_per_m3 = 1.001 * kSeaWaterDensity_kg_per_m3;
    const SimulatedRun sinks = simulate(o, 1.0);
    ASSERT_TRUE(sinks.refusal.has_value());
    EXPECT_NE(sinks.refusal->find("sinks"), std::string::npos) << *sinks.refusal;
    EXPECT_NE(sinks.refusal->find("objects[0].density_kg_per_m3"), std::string::npos) << *sinks.refusal;
}

// docs/SCENE.md: "a built-in's hull volume" is its shape. The rock's is
// closed, so a light enough rock (pumice) floats.
TEST(BodyLimits, EveryBuiltinIsAClosedBody)
{
    for (const char* path : {"builtin:boat", "builtin:buoy", "builtin:rock"}) {
        SceneObject o;
        o.path = path;
        o.floats = true;
        o.density_kg_per_m3 = 500.0;
        const SimulatedRun out = simulate(o, 10.0);
        EXPECT_FALSE(out.refusal.has_value()) << path << ": " << *out.refusal;
        EXPECT_TRUE(out.finite) << path << ": " << out.stopped;
    }
}

// The fastest body the range allows, a light one, with its wake: finite.
TEST(BodyLimits, AFastLightBoatWithItsWakeStaysFinite)
{
    SceneObject o = floatingBoat();
    o.density_kg_per_m3 = 50.0;
    o.velocity_m_per_s = {100.0, 100.0, -100.0};
    const SimulatedRun out = simulate(o, 20.0, true);
    ASSERT_FALSE(out.refusal.has_value()) << *out.refusal;
    EXPECT_TRUE(out.finite) << out.stopped;
}

// A box wound inside out (every triangle turned): refused, saying so.
TEST(BodyLimits, AHullWoundInsideOutIsRefused)
{
    BodyShape shape = test::box({2.0, 1.0, 1.0});
    for (std::size_t t = 0; t < shape.indices.size(); t += 3)
        std::swap(shape.indices[t + 1], shape.indices[t + 2]);
    try {
        (void)massPropertiesOf(shape);
        FAIL() << "an inside-out hull was accepted";
    } catch (const InputError& e) {
        EXPECT_NE(e.message().find("wound inside out"), std::string::npos) << e.message();
    }
}

// Bodies drawn at random over the documented ranges of every body key
// (docs/SCENE.md), log-uniform where a range spans decades: each is refused
// or floats an hour with a finite state. Seeded: the same bodies every run.
TEST(BodyLimits, RandomBodiesOverTheDocumentedRangesAreRefusedOrStayFinite)
{
    std::mt19937_64 random(20261125);
    auto uniform = [&](double lo, double hi) { return std::uniform_real_distribution<double>(lo, hi)(random); };
    auto logUniform = [&](double lo, double hi) { return std::exp(uniform(std::log(lo), std::log(hi))); };
    auto signedLog = [&](double lo, double hi) { return (uniform(0.0, 1.0) < 0.5 ? -1.0 : 1.0) * logUniform(lo, hi); };
    const char* builtins[] = {"builtin:boat", "builtin:buoy", "builtin:rock"};
    int simulated = 0, refused = 0;
    constexpr int kBodies = 12;
    for (int i = 0; i < kBodies; ++i) {
        SceneObject o;
        o.path = builtins[i % 3];
        o.floats = true;
        o.scale = logUniform(0.01, 100.0);
        o.yaw_deg = uniform(-360.0, 360.0);
        if (i % 2 == 0)
            o.mass_kg = logUniform(1e-3, 1e9);
        else
            o.density_kg_per_m3 = logUniform(1e-3, 1e5);
        o.centerOfMassOffset_m = {signedLog(1e-3, 1e3), signedLog(1e-3, 1e3), signedLog(1e-3, 1e3)};
        if (i % 3 == 0) {
            // A solid's moments: each at most the sum of the other two.
            const double a = logUniform(1e-3, 1e12), b = logUniform(1e-3, 1e12);
            o.inertia_kg_m2 = {a, b, uniform(std::abs(a - b), a + b)};
        }
        o.velocity_m_per_s = {uniform(-100.0, 100.0), uniform(-100.0, 100.0), uniform(-100.0, 100.0)};
        o.dampingRatio = uniform(0.0, 2.0);
        o.position_m.y = uniform(-10.0, 10.0);
        const SimulatedRun out = simulate(o, 3600.0);
        SCOPED_TRACE(testing::Message() << "body " << i << ": " << o.path << ", scale " << o.scale << ", mass "
                                        << o.mass_kg << " kg, density " << o.density_kg_per_m3
                                        << " kg/m^3, centre of mass offset [" << o.centerOfMassOffset_m.x << ", "
                                        << o.centerOfMassOffset_m.y << ", " << o.centerOfMassOffset_m.z
                                        << "] m, inertia [" << o.inertia_kg_m2.x << ", " << o.inertia_kg_m2.y << ", "
                                        << o.inertia_kg_m2.z << "] kg m^2, damping ratio " << o.dampingRatio
                                        << ", velocity [" << o.velocity_m_per_s.x << ", " << o.velocity_m_per_s.y
                                        << ", " << o.velocity_m_per_s.z << "] m/s");
        if (out.refusal) {
            ++refused;
            EXPECT_NE(out.refusal->find("objects[0]"), std::string::npos) << *out.refusal;
        } else {
            ++simulated;
            EXPECT_TRUE(out.finite) << out.stopped;
        }
    }
    // Both outcomes occur: the draw covers light, heavy and possible bodies.
    EXPECT_GT(simulated, 0);
    EXPECT_GT(refused, 0);
}

