// The built-in boat (assets/models/boat.gltf, written by make_models.py)
// against the design numbers the script was given, which it stores in the
// root node's extras: its length, beam, draft and freeboards, the sea water
// its hull displaces at the design waterline, and a rigid body of that mass
// floating level with its origin on the water. Also: builtin:boat is that
// file, and its hull volume is closed.
#include "assets/mesh_data.h"
#include "support/body_fixtures.h"
#include "swell/floating_body.h"

#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>
#include <vector>

namespace {

namespace fs = std::filesystem;
using swell::detail::MeshData;

const fs::path kBoatFile = fs::path(SWELL_SOURCE_DIR) / "assets" / "models" / "boat.gltf";

// The design numbers: the root node's extras.
nlohmann::json design()
{
    std::ifstream in(kBoatFile);
    const nlohmann::json doc = nlohmann::json::parse(in);
    for (const auto& node : doc.at("nodes"))
        if (node.value("name", "") == "boat")
            return node.at("extras");
    ADD_FAILURE() << "no node named 'boat' in " << kBoatFile;
    return {};
}

swell::BodyShape shapeOf(const MeshData& mesh)
{
    swell::BodyShape s;
    for (const auto& v : mesh.vertices)
        s.positions_m.push_back(glm::dvec3(v.position));
    s.indices = mesh.indices;
    return s;
}

struct Extent {
    glm::dvec3 lo{std::numeric_limits<double>::max()}, hi{-std::numeric_limits<double>::max()};
};

Extent extentOf(const MeshData& mesh)
{
    Extent e;
    for (const auto& v : mesh.vertices) {
        e.lo = glm::min(e.lo, glm::dvec3(v.position));
        e.hi = glm::max(e.hi, glm::dvec3(v.position));
    }
    return e;
}

// The volume of a closed mesh below y = 0: each triangle clipped to its part
// below the plane, summed as signed tetrahedra with the origin, which lies
// on the plane, so the waterplane closing the cut adds nothing.
double volumeBelowWaterline_m3(const MeshData& mesh)
{
    double volume = 0.0;
    for (std::size_t t = 0; t + 2 < mesh.indices.size(); t += 3) {
        std::vector<glm::dvec3> below;
        for (int k = 0; k < 3; ++k) {
            const glm::dvec3 p(mesh.vertices[mesh.indices[t + k]].position);
            const glm::dvec3 q(mesh.vertices[mesh.indices[t + (k + 1) % 3]].position);
            if (p.y <= 0.0)
                below.push_back(p);
            if ((p.y < 0.0) != (q.y < 0.0) && p.y != q.y)
                below.push_back(p + (q - p) * (-p.y / (q.y - p.y)));
        }
        for (std::size_t k = 1; k + 1 < below.size(); ++k)
            volume += glm::dot(below[0], glm::cross(below[k], below[k + 1])) / 6.0;
    }
    return volume;
}

// The boat as its design floats it: weighing its displacement, its centre
// of mass where the design puts it.
swell::BodySettings designSettings(const swell::BodyShape& shape)
{
    const nlohmann::json d = design();
    const auto& c = d.at("center_of_mass_m");
    swell::BodySettings settings;
    settings.mass_kg = d.at("displacement_kg").get<double>();
    settings.centerOfMassOffset_m =
        glm::dvec3(c[0].get<double>(), c[1].get<double>(), c[2].get<double>()) - swell::massPropertiesOf(shape).centroid_m;
    return settings;
}

TEST(BoatModel, BuiltinBoatIsTheModelFile)
{
    const swell::detail::GltfModel file = swell::detail::loadGltf(kBoatFile, "hull");
    const MeshData builtin = swell::detail::makeBuiltinModel("boat");
    const MeshData hull = swell::detail::makeBuiltinHullVolume("boat");
    ASSERT_EQ(builtin.vertices.size(), file.mesh.vertices.size());
    ASSERT_EQ(hull.vertices.size(), file.hull.vertices.size());
    EXPECT_EQ(builtin.indices, file.mesh.indices);
    EXPECT_EQ(hull.indices, file.hull.indices);
    for (std::size_t i = 0; i < builtin.vertices.size(); ++i) {
        EXPECT_EQ(builtin.vertices[i].position, file.mesh.vertices[i].position) << i;
        EXPECT_EQ(builtin.vertices[i].color, file.mesh.vertices[i].color) << i;
    }
    for (std::size_t i = 0; i < hull.vertices.size(); ++i)
        EXPECT_EQ(hull.vertices[i].position, file.hull.vertices[i].position) << i;
}

TEST(BoatModel, HullVolumeIsClosedAndHoldsTheDrawnHull)
{
    const MeshData hull = swell::detail::makeBuiltinHullVolume("boat");
    swell::MassProperties m;
    ASSERT_NO_THROW(m = swell::massPropertiesOf(shapeOf(hull))); // refuses an open or inside-out mesh
    EXPECT_GT(m.volume_m3, 0.0);
    // The drawn model's hull lies on the volume's outline: the same length,
    // beam and keel (the wheelhouse and rail rise above it).
    const Extent drawn = extentOf(swell::detail::makeBuiltinModel("boat"));
    const Extent volume = extentOf(hull);
    EXPECT_NEAR(drawn.lo.x, volume.lo.x, 1e-3);
    EXPECT_NEAR(drawn.lo.y, volume.lo.y, 1e-3);
    EXPECT_NEAR(drawn.hi.z, volume.hi.z, 0.05); // the rubbing strake stands proud
    EXPECT_GT(drawn.hi.y, volume.hi.y + 1.0);   // a wheelhouse
}

TEST(BoatModel, DimensionsAreTheDesign)
{
    const nlohmann::json d = design();
    const MeshData hull = swell::detail::makeBuiltinHullVolume("boat");
    const Extent e = extentOf(hull);
    EXPECT_NEAR(e.hi.x - e.lo.x, d.at("length_m").get<double>(), 1e-3);
    EXPECT_NEAR(e.hi.x + e.lo.x, 0.0, 1e-3) << "the origin lies half way along";
    EXPECT_NEAR(e.hi.z - e.lo.z, d.at("beam_m").get<double>(), 1e-3);
    EXPECT_NEAR(e.lo.y, -d.at("draft_m").get<double>(), 1e-3) << "the keel, below the waterline at y = 0";
    EXPECT_NEAR(e.hi.y, d.at("freeboard_bow_m").get<double>(), 1e-3) << "the stem head is the sheer's highest";
    // The sheer at the flat transom: the highest point of the aftmost section.
    double transomTop = -1e9;
    for (const auto& v : hull.vertices)
        if (v.position.x < e.lo.x + 1e-4)
            transomTop = std::max(transomTop, double(v.position.y));
    EXPECT_NEAR(transomTop, d.at("freeboard_aft_m").get<double>(), 1e-3);
}

TEST(BoatModel, DisplacementAtTheWaterlineIsTheDesign)
{
    const nlohmann::json d = design();
    const double displaced_kg =
        swell::kSeaWaterDensity_kg_per_m3 * volumeBelowWaterline_m3(swell::detail::makeBuiltinHullVolume("boat"));
    EXPECT_NEAR(displaced_kg, d.at("displacement_kg").get<double>(), 0.005 * d.at("displacement_kg").get<double>());
    RecordProperty("displaced_kg", std::to_string(displaced_kg));
}

TEST(BoatModel, FloatsLevelAtItsDesignWaterline)
{
    // Weighing its displacement, its centre of mass where the design puts
    // it, dropped 0.2 m above rest and left a minute: its origin settles on
    // calm water, its deck level.
    const swell::BodyShape shape = shapeOf(swell::detail::makeBuiltinHullVolume("boat"));
    const swell::BodySettings settings = designSettings(shape);
    const swell::test::TestWater flat;
    swell::FloatingBody body(shape, settings, {.origin_m = {0.0, 0.2, 0.0}}, flat);
    const glm::dmat4 pose = body.poseAt(60.0);
    EXPECT_NEAR(pose[3].y, 0.0, 0.01) << "the origin, on the design waterline";
    // Trim and heel: the bow's and the beam's rise over their length.
    const glm::dvec3 forward = glm::normalize(glm::dvec3(pose[0]));
    const glm::dvec3 starboard = glm::normalize(glm::dvec3(pose[2]));
    EXPECT_LT(glm::degrees(std::abs(std::asin(forward.y))), 0.3) << "trim, degrees";
    EXPECT_LT(glm::degrees(std::abs(std::asin(starboard.y))), 0.3) << "heel, degrees";
    EXPECT_LT(std::abs(body.state().heaveVelocity_m_per_s), 1e-3);
}

// The waves' yaw moments on a hull that is not symmetric fore and aft would
// turn it off its course while it is carried along it (yaw has no
// hydrostatic stiffness); under way, the helm (swell::kHelmPeriod_s) holds
// it on the heading it started with, and a moored boat is left free.
TEST(BoatModel, UnderWayItHoldsItsHeadingInBeamSeas)
{
    const swell::BodyShape shape = shapeOf(swell::detail::makeBuiltinHullVolume("boat"));
    const swell::BodySettings settings = designSettings(shape);
    const swell::test::TestWater waves(0.5, 20.0); // crests along z: on the beam of a boat heading along -z
    auto worstHeadingError_deg = [&](glm::dvec3 velocity_m_per_s) {
        swell::FloatingBody body(shape, settings, {.yaw_deg = 90.0, .velocity_m_per_s = velocity_m_per_s}, waves);
        double worst = 0.0;
        for (double t = 0.0; t <= 60.0; t += 0.5) {
            const glm::dvec3 bow(body.poseAt(t)[0]);
            worst = std::max(worst, std::abs(glm::degrees(std::atan2(-bow.z, bow.x)) - 90.0));
        }
        return worst;
    };
    const double underWay = worstHeadingError_deg({0.0, 0.0, -4.0});
    const double moored = worstHeadingError_deg({0.0, 0.0, 0.0});
    EXPECT_LT(underWay, 3.0) << "degrees off its heading under way";
    EXPECT_GT(moored, 3.0 * underWay) << "the control: moored, the waves turn it (else the test shows nothing)";
    RecordProperty("heading_error_under_way_deg", std::to_string(underWay));
    RecordProperty("heading_error_moored_deg", std::to_string(moored));
}

TEST(BoatModel, BottomPaintBelowTheWaterlineOnly)
{
    // Antifouling (a red-brown, red over twice its green) on every drawn
    // vertex under the waterline, and on none a hand's breadth above it.
    const MeshData boat = swell::detail::makeBuiltinModel("boat");
    const auto antifouling = [](const glm::vec3& c) { return c.r > 2.0f * c.g && c.r > 2.0f * c.b; };
    int below = 0;
    for (const auto& v : boat.vertices) {
        if (v.position.y < -0.01f) {
            EXPECT_TRUE(antifouling(v.color)) << v.position.x << ", " << v.position.y << ", " << v.position.z;
            ++below;
        } else if (v.position.y > 0.15f) {
            EXPECT_FALSE(antifouling(v.color)) << v.position.x << ", " << v.position.y << ", " << v.position.z;
        }
    }
    EXPECT_GT(below, 100);
}

} // namespace
