// The fleet (issue 46, item 6; docs/SCENE.md and docs/BODIES.md, "The
// fleet"): the built-in vessels and marks that assets/models/fleet_model.py
// writes. Each is its design (length, beam, draft, displacement in its
// root's extras); each, stretched or not, floats at its design draft within
// 1 cm and upright when a scene floats it without a mass; a scene may
// stretch, repaint and strip it, and its keys are refused where they mean
// nothing or go past the model's bounds.
#include "assets/fleet_mesh.h"
#include "assets/scene_assets.h"
#include "core/fleet.h"
#include "objects/design_loading.h"
#include "objects/scene_bodies.h"
#include "support/body_fixtures.h"
#include "support/expect_input_error.h"
#include "swell/constants.h"
#include "swell/dataset/labels.h"
#include "swell/scene/scene_file.h"

#include <fmt/format.h>
#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

namespace {

using swell::detail::FleetDesign;
using swell::detail::MeshData;

swell::BodyShape hullShapeOf(const MeshData& mesh)
{
    swell::BodyShape s;
    for (const auto& v : mesh.vertices)
        s.positions_m.push_back(glm::dvec3(v.position));
    s.indices = mesh.indices;
    return s;
}

struct HullExtent {
    glm::dvec3 lo{std::numeric_limits<double>::max()}, hi{-std::numeric_limits<double>::max()};
};

HullExtent hullExtentOf(const MeshData& mesh)
{
    HullExtent e;
    for (const auto& v : mesh.vertices) {
        e.lo = glm::min(e.lo, glm::dvec3(v.position));
        e.hi = glm::max(e.hi, glm::dvec3(v.position));
    }
    return e;
}

// Each model's hull volume is closed and is its design: length, beam and
// draft within 1 mm, displacement below the waterline within 0.5 %.
TEST(Fleet, EachModelIsItsDesign)
{
    ASSERT_GE(swell::kFleetObjects.size(), 8u);
    for (std::string_view name : swell::kFleetObjects) {
        SCOPED_TRACE(std::string(name));
        const FleetDesign& d = swell::detail::fleetDesign(name);
        const MeshData hull = swell::detail::makeBuiltinHullVolume(std::string(name));
        ASSERT_FALSE(hull.indices.empty());
        ASSERT_NO_THROW((void)swell::massPropertiesOf(hullShapeOf(hull))); // closed and wound outwards
        const HullExtent e = hullExtentOf(hull);
        EXPECT_NEAR(e.hi.x - e.lo.x, d.length_m, 1e-3);
        EXPECT_NEAR(e.hi.z - e.lo.z, d.beam_m, 1e-3);
        EXPECT_NEAR(-e.lo.y, d.draft_m, 1e-3);
        const double displaced_kg =
            swell::kSeaWaterDensity_kg_per_m3 * swell::detail::volumeBelow(hullShapeOf(hull), 0.0).volume_m3;
        EXPECT_NEAR(displaced_kg / d.displacement_kg, 1.0, 0.005);
        EXPECT_FALSE(swell::detail::makeBuiltinModel(std::string(name)).vertices.empty());
    }
}

// A box of water-plane area A and draft T: the design loading weighs
// rho A T, its centre of mass above the box's centre of buoyancy (an
// analytic check of volumeBelow and designLoadingOf).
TEST(Fleet, DesignLoadingOfABoxIsArchimedes)
{
    swell::BodyShape box = swell::test::box({4.0, 2.0, 1.0});
    for (glm::dvec3& p : box.positions_m)
        p += glm::dvec3(0.5, 0.2, 0.0); // its bottom 0.8 m under the waterline, its middle 0.5 m forward
    const swell::detail::DesignLoading loading = swell::detail::designLoadingOf(box, 0.1, 1025.0);
    EXPECT_NEAR(loading.mass_kg, 1025.0 * 4.0 * 1.0 * 0.8, 1e-6);
    // The centroid is at (0.5, 0.2, 0); the centre of mass at (0.5, 0.1, 0).
    EXPECT_NEAR(loading.centerOfMassOffset_m.x, 0.0, 1e-9);
    EXPECT_NEAR(loading.centerOfMassOffset_m.y, -0.1, 1e-9);
}

struct Settled {
    double originHeight_m = 0.0; // the model origin (its design waterline) above the water
    double keelDepth_m = 0.0;    // the hull's lowest point below the water
    double trim_deg = 0.0, heel_deg = 0.0;
};

// The object alone in a scene on calm water, dropped 0.1 m above its rest
// and left to settle for 90 s.
Settled settle(const swell::SceneObject& object)
{
    swell::Scene scene;
    scene.objects = {object};
    scene.objects[0].floats = true;
    scene.objects[0].position_m = {0.0, 0.1, 0.0};
    scene.wake.enabled = false;
    const swell::detail::SceneAssets assets = swell::detail::loadSceneAssets(scene);
    const swell::detail::SceneShapes shapes(assets);
    swell::detail::SceneBodies bodies(scene, shapes.list(), std::make_shared<const swell::test::TestWater>());
    bodies.advanceTo(30.0);
    const glm::dmat4 pose = *bodies.poseAt(0, 30.0);
    Settled s;
    s.originHeight_m = pose[3].y;
    s.keelDepth_m = -std::numeric_limits<double>::max();
    for (const auto& v : shapes.objects[0]->vertices)
        s.keelDepth_m = std::max(s.keelDepth_m, -(pose * glm::dvec4(glm::dvec3(v.position), 1.0)).y);
    s.trim_deg = glm::degrees(std::asin(glm::normalize(glm::dvec3(pose[0])).y));
    s.heel_deg = glm::degrees(std::asin(glm::normalize(glm::dvec3(pose[2])).y));
    return s;
}

// Done when (issue 46, item 6): each model floats at its design draft
// within 1 cm, and upright (trim and heel within 0.5 degrees), at its
// design size and stretched: the design draft is the hull volume's lowest
// point below the design waterline (the keel; a yacht's fin; a buoy's float
// bottom), extras.draft_m.
TEST(Fleet, EachFloatsAtItsDesignDraftUpright)
{
    for (std::string_view name : swell::kFleetObjects) {
        const FleetDesign& d = swell::detail::fleetDesign(name);
        const struct {
            const char* look;
            double length_m, beam_m, scale;
        } looks[] = {{"design", 0.0, 0.0, 1.0},
                     {"stretched", 1.3 * d.length_m, 0.85 * d.beam_m, 1.0},
                     {"shortened and broadened", 0.7 * d.length_m, 1.2 * d.beam_m, 1.0},
                     {"scaled by 2", 0.0, 0.0, 2.0}};
        for (const auto& look : looks) {
            SCOPED_TRACE(std::string(name) + ", " + look.look);
            swell::SceneObject o;
            o.path = "builtin:" + std::string(name);
            o.length_m = look.length_m;
            o.beam_m = look.beam_m;
            o.scale = look.scale;
            const Settled s = settle(o);
            EXPECT_NEAR(s.keelDepth_m, d.draft_m * look.scale, 0.01) << "m: the design draft";
            EXPECT_NEAR(s.originHeight_m, 0.0, 0.01) << "m: the design waterline on the water";
            EXPECT_LT(std::abs(s.trim_deg), 0.5) << "trim, degrees";
            EXPECT_LT(std::abs(s.heel_deg), 0.5) << "heel, degrees";
            RecordProperty(std::string(name) + " " + look.look,
                           fmt::format("draft {:.4f} m of {:.4f}, trim {:.3f} deg, heel {:.3f} deg", s.keelDepth_m,
                                       d.draft_m * look.scale, s.trim_deg, s.heel_deg));
        }
    }
}

// A scene's look: stretched along its length and beam with its draft kept,
// its hull and superstructure repainted, its superstructure left out.
TEST(Fleet, ALookStretchesRepaintsAndStrips)
{
    const FleetDesign& d = swell::detail::fleetDesign("tug");
    const swell::detail::GltfModel design = swell::detail::makeFleetModel("tug");
    swell::detail::FleetLook look;
    look.lengthScale = 1.25;
    look.beamScale = 0.8;
    look.hullColor = {0.0, 0.5, 0.0};
    look.superstructureColor = {0.0, 0.0, 0.5};
    const swell::detail::GltfModel changed = swell::detail::makeFleetModel("tug", look);
    const HullExtent a = hullExtentOf(design.hull), b = hullExtentOf(changed.hull);
    EXPECT_NEAR(b.hi.x - b.lo.x, 1.25 * d.length_m, 1e-3);
    EXPECT_NEAR(b.hi.z - b.lo.z, 0.8 * d.beam_m, 1e-3);
    EXPECT_NEAR(b.lo.y, a.lo.y, 1e-6) << "the draft is kept";
    const auto count = [](const MeshData& mesh, glm::vec3 rgb) {
        return std::count_if(mesh.vertices.begin(), mesh.vertices.end(),
                             [&](const swell::detail::MeshVertex& v) { return glm::length(v.color - rgb) < 1e-4f; });
    };
    EXPECT_EQ(count(design.mesh, {0.0f, 0.5f, 0.0f}), 0);
    EXPECT_GT(count(changed.mesh, {0.0f, 0.5f, 0.0f}), 100) << "the hull repainted";
    EXPECT_GT(count(changed.mesh, {0.0f, 0.0f, 0.5f}), 20) << "the superstructure repainted";
    swell::detail::FleetLook stripped;
    stripped.superstructure = false;
    const MeshData bare = swell::detail::makeFleetModel("tug", stripped).mesh;
    EXPECT_LT(bare.vertices.size(), design.mesh.vertices.size());
    EXPECT_LT(hullExtentOf(bare).hi.y + 3.0, hullExtentOf(design.mesh).hi.y) << "no wheelhouse, no mast";
}

// Every class is a class in the labels, by its model's name.
TEST(Fleet, EachClassIsItsName)
{
    std::string toml;
    for (std::string_view name : swell::kFleetObjects)
        toml += "[[objects]]\npath = \"builtin:" + std::string(name) + "\"\n";
    const swell::Scene scene = swell::parseScene(toml, "fleet.toml");
    const std::vector<std::string> classes = swell::labelClassesOf(scene);
    for (std::string_view name : swell::kFleetObjects)
        EXPECT_NE(std::find(classes.begin(), classes.end(), std::string(name)), classes.end()) << name;
}

// The fleet's keys, written back, and refused at their file:line:column
// where they mean nothing or go past the model's bounds.
TEST(Fleet, KeysAreReadWrittenAndRefusedAtTheirPlace)
{
    const std::string tug = "[[objects]]\npath = \"builtin:tug\"\n";
    const swell::Scene scene = swell::parseScene(
        tug + "length_m = 30.0\nbeam_m = 10.0\nhull_color = [0.1, 0.2, 0.3]\nsuperstructure = false\n", "tug.toml");
    const swell::Scene again = swell::parseScene(swell::saveScene(scene), "again.toml");
    EXPECT_EQ(again.objects[0].length_m, 30.0);
    EXPECT_EQ(again.objects[0].beam_m, 10.0);
    EXPECT_EQ(again.objects[0].hullColor, glm::dvec3(0.1, 0.2, 0.3));
    EXPECT_EQ(again.objects[0].superstructureColor, glm::dvec3(-1.0));
    EXPECT_FALSE(again.objects[0].superstructure);

    const struct {
        std::string toml;
        int line, column;
        const char* message;
    } cases[] = {
        {"[[objects]]\npath = \"builtin:boat\"\nlength_m = 9.0\n", 3, 12, "objects[0].length_m is for the fleet's"},
        {"[[objects]]\npath = \"builtin:buoy\"\nsuperstructure = false\n", 3, 18, "objects[0].superstructure is for"},
        {tug + "length_m = 60.0\n", 3, 12, "objects[0].length_m = 60 m is outside 12 to 48 m"},
        {tug + "beam_m = 4.0\n", 3, 10, "objects[0].beam_m = 4 m is outside 6.75 to 13.5 m"},
        {tug + "hull_color = [-1.0, 0.5, 0.5]\n", 3, 14, "objects[0].hull_color = [-1, 0.5, 0.5]: give a linear RGB"},
        {tug + "class = \"\"\n", 3, 9, "objects[0].class is empty"},
    };
    for (const auto& c : cases) {
        SCOPED_TRACE(c.toml);
        const swell::InputError e = swell::test::expectInputError([&] { (void)swell::parseScene(c.toml, "bad.toml"); });
        EXPECT_EQ(e.place().path, "bad.toml");
        EXPECT_EQ(e.place().line, c.line) << e.what();
        EXPECT_EQ(e.place().column, c.column) << e.what();
        EXPECT_NE(e.message().find(c.message), std::string::npos) << e.what();
    }
}

} // namespace
