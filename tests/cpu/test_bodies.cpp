// Floating rigid bodies (swell/floating_body.h) against published numbers:
// the mass properties of a box, Archimedes' draft, the heave period of a
// linear spring of stiffness rho g A_waterplane, damped motion, and poses
// that do not depend on how often they were asked for.
#include "objects/scene_bodies.h"
#include "support/body_fixtures.h"
#include "swell/constants.h"
#include "swell/error.h"
#include "swell/floating_body.h"

#include <glm/gtc/matrix_access.hpp>
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

namespace {

using swell::test::TestWater;
using swell::test::box;
using swell::test::meshOf;

constexpr double kRho = swell::kSeaWaterDensity_kg_per_m3;
// 4 m square, 1.5 m tall: at density 0.5 it draws 0.75 m and floats
// upright (metacentric height B^2 / (12 T) + T/2 - H/2 = 1.40 m > 0), and a
// release 0.5 m above rest keeps it partly wet, so the spring stays linear.
const glm::dvec3 kBox{4.0, 1.5, 4.0};

swell::BodySettings halfDensityBox()
{
    swell::BodySettings b;
    b.mass_kg = 0.5 * kRho * kBox.x * kBox.y * kBox.z;
    return b;
}

double centreHeight(swell::FloatingBody& body, double t) { return body.poseAt(t)[3].y; }

TEST(BodyMass, BoxVolumeCentroidAndInertia)
{
    // A solid box about its centre: I_x = m (b^2 + c^2) / 12 (any mechanics
    // text, e.g. Goldstein, Classical Mechanics, 3rd ed., table of moments).
    swell::BodyShape s = box({2.0, 3.0, 4.0});
    for (glm::dvec3& p : s.positions_m)
        p += glm::dvec3(10.0, -5.0, 1.0);
    const swell::MassProperties m = swell::massPropertiesOf(s);
    EXPECT_NEAR(m.volume_m3, 24.0, 1e-9);
    EXPECT_NEAR(m.centroid_m.x, 10.0, 1e-9);
    EXPECT_NEAR(m.centroid_m.y, -5.0, 1e-9);
    EXPECT_NEAR(m.centroid_m.z, 1.0, 1e-9);
    const glm::dmat3& I = m.inertiaAboutCentroid_kg_m2;
    EXPECT_NEAR(I[0][0], 24.0 * (9.0 + 16.0) / 12.0, 1e-9);
    EXPECT_NEAR(I[1][1], 24.0 * (4.0 + 16.0) / 12.0, 1e-9);
    EXPECT_NEAR(I[2][2], 24.0 * (4.0 + 9.0) / 12.0, 1e-9);
    EXPECT_NEAR(I[0][1], 0.0, 1e-9);
    EXPECT_NEAR(I[1][2], 0.0, 1e-9);
}

TEST(BodyMass, OpenMeshIsRefused)
{
    swell::BodyShape s = box({1.0, 1.0, 1.0});
    s.indices.resize(s.indices.size() - 3); // a missing triangle: a hole
    try {
        (void)swell::massPropertiesOf(s);
        FAIL() << "an open mesh was accepted";
    } catch (const swell::InputError& e) {
        EXPECT_NE(e.message().find("not closed"), std::string::npos) << e.message();
    }
    // A triangle wound the wrong way: its edges run twice one way, none the other.
    swell::BodyShape flipped = box({1.0, 1.0, 1.0});
    std::swap(flipped.indices[1], flipped.indices[2]);
    EXPECT_THROW((void)swell::massPropertiesOf(flipped), swell::InputError);
    // Faces with their own vertices (flat normals) are closed all the same.
    swell::BodyShape split = box({1.0, 1.0, 1.0});
    swell::BodyShape separate;
    for (std::uint32_t i : split.indices) {
        separate.indices.push_back(std::uint32_t(separate.positions_m.size()));
        separate.positions_m.push_back(split.positions_m[i]);
    }
    EXPECT_NEAR(swell::massPropertiesOf(separate).volume_m3, 1.0, 1e-12);
}

TEST(BodyMass, BodyHeavierThanItsDisplacementIsRefused)
{
    const TestWater flat;
    swell::BodySettings b = halfDensityBox();
    b.mass_kg *= 2.5;
    EXPECT_THROW(swell::FloatingBody(box(kBox), b, {}, flat), swell::InputError);
}

TEST(FloatingBody, HalfDensityBoxFloatsAtHalfItsHeight)
{
    const TestWater flat;
    // Dropped from 0.3 m above rest, then left for a minute to settle.
    swell::FloatingBody body(box(kBox), halfDensityBox(), {.origin_m = {0.0, 0.3, 0.0}}, flat);
    const double bottom = centreHeight(body, 60.0) - 0.5 * kBox.y;
    const double draftFraction = -bottom / kBox.y;
    EXPECT_NEAR(draftFraction, 0.5, 0.02 * 0.5) << "draft " << -bottom << " m of " << kBox.y << " m";
    RecordProperty("draft_fraction", std::to_string(draftFraction));
    // At rest: the motion has died away.
    EXPECT_LT(std::abs(body.state().heaveVelocity_m_per_s), 1e-3);
}

TEST(FloatingBody, HeavesWithTheLinearSpringPeriodAndDecays)
{
    const TestWater flat;
    const swell::BodySettings settings = halfDensityBox();
    swell::FloatingBody body(box(kBox), settings, {.origin_m = {0.0, 0.5, 0.0}}, flat);
    // Linear spring of stiffness rho g A_waterplane, added mass neglected
    // (docs/BODIES.md): T = 2 pi sqrt(m / (rho g A)).
    const double stiffness = kRho * swell::kGravity * kBox.x * kBox.z;
    const double expected_s = swell::kTwoPi * std::sqrt(settings.mass_kg / stiffness);
    // The rest height is the centre at the waterline (half the height drawn).
    std::vector<double> upCrossings, peaks;
    double before = centreHeight(body, 0.0), beforeThat = before;
    for (int i = 1; i <= 20 * swell::kBodyStepsPerSecond; ++i) {
        const double t = i * swell::kBodyStep_s;
        const double y = centreHeight(body, t);
        if (before < 0.0 && y >= 0.0)
            upCrossings.push_back(t - swell::kBodyStep_s * y / (y - before));
        if (before > beforeThat && before >= y)
            peaks.push_back(before);
        beforeThat = before;
        before = y;
    }
    ASSERT_GE(upCrossings.size(), 4u);
    const double measured_s = (upCrossings[3] - upCrossings[0]) / 3.0;
    EXPECT_NEAR(measured_s, expected_s, 0.10 * expected_s) << "expected " << expected_s << " s";
    RecordProperty("heave_period_s", std::to_string(measured_s));
    RecordProperty("spring_period_s", std::to_string(expected_s));
    // Decay: every peak lower than the one before, and little left at the end.
    ASSERT_GE(peaks.size(), 4u);
    for (std::size_t i = 1; i < peaks.size(); ++i)
        EXPECT_LT(peaks[i], peaks[i - 1]) << "peak " << i;
    EXPECT_LT(peaks.back(), 0.1 * 0.5);
    RecordProperty("peaks_m", std::to_string(peaks[0]) + " " + std::to_string(peaks[1]) + " .. " + std::to_string(peaks.back()));
}

TEST(FloatingBody, ReleasedWithAHeaveVelocity)
{
    // velocity_m_per_s's y is the heave velocity at t = 0: 1 m/s up from
    // rest rises about 1 m/s * 0.05 s in the first 0.05 s (gravity and
    // buoyancy balance at rest, so only the spring slows it, by under 10%).
    const TestWater flat;
    swell::FloatingBody body(box(kBox), halfDensityBox(), {.velocity_m_per_s = {0.0, 1.0, 0.0}}, flat);
    EXPECT_NEAR(centreHeight(body, 0.05), 0.05, 0.005);
    EXPECT_EQ(body.poseAt(0.05)[3].x, 0.0) << "carried only at x and z";
}

TEST(FloatingBody, PosesDoNotDependOnHowOftenTheyWereAsked)
{
    const TestWater waves(0.6, 25.0);
    const swell::BodyStart start{.origin_m = {3.0, 0.2, -2.0}, .yaw_deg = 30.0, .velocity_m_per_s = {1.5, 0.0, 0.5}};
    swell::FloatingBody everyFrame(box(kBox), halfDensityBox(), start, waves);
    swell::FloatingBody once(box(kBox), halfDensityBox(), start, waves);
    swell::FloatingBody backwards(box(kBox), halfDensityBox(), start, waves);
    const double end_s = 12.345;
    // Uneven frame times, as a viewer's are.
    for (double t = 0.0; t < end_s; t += 0.013 + 0.011 * std::sin(37.0 * t))
        (void)everyFrame.poseAt(t);
    (void)backwards.poseAt(end_s + 5.0);
    (void)backwards.poseAt(1.0); // earlier than the state: starts again from t = 0
    const glm::dmat4 a = everyFrame.poseAt(end_s), b = once.poseAt(end_s), c = backwards.poseAt(end_s);
    for (int col = 0; col < 4; ++col) {
        EXPECT_EQ(a[col], b[col]) << "column " << col;
        EXPECT_EQ(a[col], c[col]) << "column " << col;
    }
    // And the waves did move it: it is not simply resting.
    EXPECT_GT(std::abs(a[3].y - once.poseAt(end_s + 0.5)[3].y), 1e-3);
}

TEST(FloatingBody, RidesTheWavesAndIsCarriedAlong)
{
    const TestWater waves(0.5, 60.0);
    swell::FloatingBody body(box(kBox), halfDensityBox(), {.velocity_m_per_s = {2.0, 0.0, 0.0}}, waves);
    double low = 1e9, high = -1e9;
    for (double t = 20.0; t < 30.0; t += 0.05) {
        const double y = centreHeight(body, t);
        low = std::min(low, y);
        high = std::max(high, y);
    }
    // A 4 m box on 60 m waves follows them nearly fully: about 1 m crest to trough.
    EXPECT_GT(high - low, 0.8);
    EXPECT_LT(high - low, 1.2);
    EXPECT_NEAR(body.poseAt(30.0)[3].x, 60.0, 1e-9);
}


// A scene's bodies step in lockstep (so they share the surface's sample
// times); each still moves exactly as it would alone.
TEST(FloatingBody, SceneBodiesInLockstepMoveAsEachAlone)
{
    const auto waves = std::make_shared<const TestWater>(0.4, 30.0);
    const swell::BodyShape shape = box(kBox);
    const swell::detail::MeshData mesh = meshOf(shape);
    swell::Scene scene;
    scene.objects.resize(3);
    scene.objects[0] = {.path = "a", .position_m = {0.0, 0.2, 0.0}, .floats = true, .density_kg_per_m3 = 500.0};
    scene.objects[1] = {.path = "b", .position_m = {9.0, 0.0, 2.0}, .floats = true}; // a rider, not a body
    scene.objects[2] = {.path = "c", .position_m = {-7.0, 0.0, 5.0}, .yaw_deg = 40.0, .floats = true,
                        .density_kg_per_m3 = 300.0, .velocity_m_per_s = {0.0, 0.0, 3.0}};
    // Without the wake, which a body alone does not stir for the others
    // (test_wake_bodies.cpp shows the bodies feel it).
    scene.wake.enabled = false;
    // From t = 0, as each body alone below starts (a scene's bodies start
    // 60 s earlier by default: history_start_s).
    scene.historyStart_s = 0.0;
    swell::detail::SceneBodies bodies(scene, {&mesh, &mesh, &mesh}, waves);
    EXPECT_EQ(bodies.count(), 2u);
    EXPECT_FALSE(bodies.poseAt(1, 1.0).has_value());
    const swell::SurfaceFilter filter = swell::detail::bodySurfaceFilter(scene);
    for (std::size_t i : {0u, 2u}) {
        const swell::SceneObject& o = scene.objects[i];
        swell::BodySettings settings;
        settings.mass_kg = o.density_kg_per_m3 * kBox.x * kBox.y * kBox.z;
        swell::FloatingBody alone(shape, settings, {o.position_m, o.yaw_deg, o.velocity_m_per_s}, *waves, filter);
        for (double t : {0.7, 3.3, 2.0, 9.1}) {
            bodies.advanceTo(t);
            EXPECT_EQ(*bodies.poseAt(i, t), alone.poseAt(t)) << "object " << i << " at " << t << " s";
        }
    }
}

// A scaled model is a bigger body: its draft scales with it, and the pose
// maps model space (scale included) to the world.
TEST(FloatingBody, AScaledObjectFloatsAsTheBiggerBody)
{
    const auto flat = std::make_shared<const TestWater>();
    const swell::BodyShape shape = box(kBox);
    const swell::detail::MeshData mesh = meshOf(shape);
    swell::Scene scene;
    scene.objects = {{.path = "a", .position_m = {2.0, 0.0, 3.0}, .scale = 2.0, .floats = true,
                      .density_kg_per_m3 = 0.25 * kRho}};
    swell::detail::SceneBodies bodies(scene, {&mesh}, flat);
    bodies.advanceTo(1.0);
    const glm::dmat4 pose = *bodies.poseAt(0, 1.0);
    // At a quarter of the water's density it draws a quarter of its scaled
    // height: the model's bottom, 0.75 m below its origin, lies 0.75 m deep.
    const glm::dvec4 bottom = pose * glm::dvec4(0.0, -0.5 * kBox.y, 0.0, 1.0);
    EXPECT_NEAR(bottom.y, -0.25 * 2.0 * kBox.y, 0.02 * 0.25 * 2.0 * kBox.y);
    EXPECT_NEAR(bottom.x, 2.0, 1e-9);
    EXPECT_NEAR(glm::length(glm::dvec3(pose[0])), 2.0, 1e-9) << "the scale is in the pose";
}

} // namespace

// The bodies start again when, and only when, a parameter the table marks
// ParameterEffect::Bodies changes (an object's only where it is a body).
TEST(FloatingBody, TheParameterTableSaysWhatRestartsTheBodies)
{
    swell::Scene scene;
    scene.objects = {{.path = "a", .position_m = {0.0, 0.0, 0.0}, .floats = true, .density_kg_per_m3 = 500.0},
                     {.path = "b", .position_m = {9.0, 0.0, 2.0}, .floats = true}}; // a rider, not a body
    auto changed = [&](auto edit) {
        swell::Scene next = scene;
        edit(next);
        return !swell::detail::sameBodies(scene, next);
    };
    EXPECT_FALSE(changed([](swell::Scene&) {}));
    EXPECT_TRUE(changed([](swell::Scene& s) { s.objects[0].mass_kg = 80.0; }));
    EXPECT_TRUE(changed([](swell::Scene& s) { s.objects[0].position_m.x = 1.0; }));
    EXPECT_TRUE(changed([](swell::Scene& s) { s.objects[1].mass_kg = 80.0; })); // the rider becomes a body
    EXPECT_FALSE(changed([](swell::Scene& s) { s.objects[1].position_m.x = 1.0; }));
    EXPECT_TRUE(changed([](swell::Scene& s) { s.objects.pop_back(); }));
    EXPECT_TRUE(changed([](swell::Scene& s) { s.sea.level_m = 2.0; }));
    EXPECT_TRUE(changed([](swell::Scene& s) { s.sea.depth_m = 30.0; }));
    EXPECT_TRUE(changed([](swell::Scene& s) { s.wake.cells = 128; }));
    EXPECT_TRUE(changed([](swell::Scene& s) { s.historyStart_s = 0.0; }));
    EXPECT_TRUE(changed([](swell::Scene& s) { s.camera.far_m = 5000.0; })); // the grid's skirt: the bodies' filter
    EXPECT_FALSE(changed([](swell::Scene& s) { s.fog.start_m = 10.0; }));
    EXPECT_FALSE(changed([](swell::Scene& s) { s.camera.position_m.y = 40.0; }));
}
