// Foam where the water meets what stands in it (issue 44, item 3;
// docs/RENDERING.md "Foam where water meets what stands in it"): a pile of
// Swell's world and one of a host's, and a floating hull at rest, each get
// a band of foam round them in a sea with waves, well above the foam of the
// sea farther out; the open sea with nothing in it draws exactly what it
// drew without the contact pass, and draws no pass.
#include "host_frame.h"
#include "support/foam_view.h"
#include "support/gl_test.h"
#include "support/golden.h"
#include "support/gltf_writer.h"
#include "support/open_sea.h"

#include "assets/mesh_data.h"
#include "swell/camera.h"
#include "swell/debug.h"
#include "swell/gpu/label_classes.h"
#include "swell/renderer.h"
#include "swell/scene/scene.h"

#include <glm/geometric.hpp>
#include <glm/matrix.hpp>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <functional>
#include <string>
#include <vector>

namespace {

namespace fs = std::filesystem;
using swell::test::GlTest;

constexpr double kPileRadius_m = 0.4;
constexpr int kContactView_px = 192;
// Straight down from this high over what is measured: 192 pixels span
// about 23 m (the default lens), 12 cm a pixel.
constexpr double kContactEyeHeight_m = 20.0;

// A vertical cylinder of radius r from y0 to y1 (m), capped, `sides` faces
// round, tarred brown.
swell::detail::MeshData contactPile(double r, double y0, double y1, int sides = 24)
{
    swell::detail::MeshData mesh;
    const glm::vec3 tar{0.10f, 0.08f, 0.06f};
    for (int i = 0; i <= sides; ++i) {
        const double a = 2.0 * M_PI * i / sides;
        const glm::vec3 out{float(std::cos(a)), 0.0f, float(std::sin(a))};
        mesh.vertices.push_back({out * float(r) + glm::vec3(0.0f, float(y0), 0.0f), out, tar});
        mesh.vertices.push_back({out * float(r) + glm::vec3(0.0f, float(y1), 0.0f), out, tar});
    }
    for (int i = 0; i < sides; ++i) {
        const auto b = std::uint32_t(2 * i);
        mesh.indices.insert(mesh.indices.end(), {b, b + 1, b + 2, b + 2, b + 1, b + 3});
    }
    // The caps: a fan round each end's centre.
    for (const double y : {y0, y1}) {
        const auto centre = std::uint32_t(mesh.vertices.size());
        const float up = y == y1 ? 1.0f : -1.0f;
        mesh.vertices.push_back({{0.0f, float(y), 0.0f}, {0.0f, up, 0.0f}, tar});
        for (int i = 0; i <= sides; ++i) {
            const double a = 2.0 * M_PI * i / sides;
            mesh.vertices.push_back({{float(r * std::cos(a)), float(y), float(r * std::sin(a))}, {0.0f, up, 0.0f}, tar});
        }
        for (int i = 0; i < sides; ++i)
            mesh.indices.insert(mesh.indices.end(), {centre, centre + 1 + std::uint32_t(i), centre + 2 + std::uint32_t(i)});
    }
    return mesh;
}

fs::path contactPileModel()
{
    const fs::path folder = fs::path(SWELL_TEST_OUTPUT_DIR) / "contact_foam";
    fs::create_directories(folder);
    const fs::path path = folder / "pile.gltf";
    swell::test::writeGltf(contactPile(kPileRadius_m, -8.0, 3.0), path);
    return path;
}

// The open sea under a light wind (5 m/s) with a 1 m, 8 s swell: waves
// that wash a pile, and hardly any whitecaps of their own.
swell::Scene contactSea()
{
    swell::Scene scene = swell::test::openSea();
    scene.sea.wind = swell::WindSettings{};
    scene.sea.wind->windSpeed_mps = 5.0;
    swell::SwellSettings swell;
    swell.height_m = 1.0;
    swell.period_s = 8.0;
    scene.sea.wind->swell = swell;
    return scene;
}

// Where the ray through pixel (x, y)'s centre meets the sea level (y = 0):
// rows counted from the top (an Image's) or from the bottom (a host's).
glm::dvec3 contactSeaPoint(const swell::View& view, glm::ivec2 size, int x, int y, bool topRowFirst)
{
    const glm::dmat4 inverse = glm::inverse(view.projection * view.view);
    const double u = 2.0 * (x + 0.5) / size.x - 1.0;
    const double v = topRowFirst ? 1.0 - 2.0 * (y + 0.5) / size.y : 2.0 * (y + 0.5) / size.y - 1.0;
    glm::dvec4 a = inverse * glm::dvec4(u, v, -1.0, 1.0), b = inverse * glm::dvec4(u, v, 1.0, 1.0);
    const glm::dvec3 p0 = glm::dvec3(a) / a.w, p1 = glm::dvec3(b) / b.w;
    const glm::dvec3 d = p1 - p0;
    return p0 + d * (-p0.y / d.y);
}

// The mean foam share of the pixels whose sea point lies in each of two
// bands of distance (m) from what the water meets (`distance` of a point).
struct ContactShares {
    double near = 0.0, far = 0.0;
    int nearPixels = 0, farPixels = 0;
};

ContactShares contactShares(const std::vector<double>& share, const std::vector<glm::dvec3>& points,
                            const std::function<double(glm::dvec3)>& distance, glm::dvec2 nearBand_m,
                            glm::dvec2 farBand_m)
{
    ContactShares s;
    for (std::size_t i = 0; i < share.size(); ++i) {
        const double d = distance(points[i]);
        if (d >= nearBand_m.x && d < nearBand_m.y) {
            s.near += share[i];
            ++s.nearPixels;
        } else if (d >= farBand_m.x && d < farBand_m.y) {
            s.far += share[i];
            ++s.farPixels;
        }
    }
    s.near /= std::max(s.nearPixels, 1);
    s.far /= std::max(s.farPixels, 1);
    return s;
}

// The foam view straight down over `at` (x, z) at time_s: each pixel's foam
// share and its sea point.
struct ContactView {
    std::vector<double> share;
    std::vector<glm::dvec3> points;
};

ContactView contactViewDown(swell::Renderer& renderer, const swell::Scene& scene, glm::dvec2 at, double time_s,
                            const char* name)
{
    ContactView v;
    const glm::dvec3 eye(at.x, kContactEyeHeight_m, at.y);
    v.share = swell::test::foamViewDown(renderer, scene, eye, 0.0, time_s, kContactView_px, name);
    swell::Camera camera = swell::cameraAt(scene.camera, 0.0);
    camera.position_m = eye;
    camera.yaw_deg = 0.0;
    camera.pitch_deg = -89.0;
    const swell::View view = swell::viewOf(camera, {kContactView_px, kContactView_px});
    for (int y = 0; y < kContactView_px; ++y)
        for (int x = 0; x < kContactView_px; ++x)
            v.points.push_back(contactSeaPoint(view, {kContactView_px, kContactView_px}, x, y, true));
    return v;
}

class ContactFoam : public GlTest {};

// A pile of Swell's world (a scene object) in a 1 m swell: the water within
// a metre of its face is foamed several times more than that 5 to 10 m off,
// and labelled surf there; without the contact pass it is not.
TEST_F(ContactFoam, APileOfTheWorldStandsInABandOfFoam)
{
    swell::Scene scene = contactSea();
    const glm::dvec3 pile_m(0.0, 0.0, -30.0);
    scene.objects.push_back({contactPileModel().string(), pile_m, 0.0, 1.0, false});
    const swell::Scene foamView = swell::test::foamDebugView(scene);
    const auto fromFace = [&](glm::dvec3 p) { return glm::length(glm::dvec2(p.x - pile_m.x, p.z - pile_m.z)) - kPileRadius_m; };
    const glm::dvec2 nearBand(0.15, 1.0), farBand(5.0, 10.0);

    double nearMean = 0.0, farMean = 0.0;
    for (const double t : {6.0, 13.0}) {
        swell::Renderer renderer(foamView);
        const ContactView v = contactViewDown(renderer, foamView, {pile_m.x, pile_m.z}, t,
                                              t == 6.0 ? "contact_foam_pile" : nullptr);
        EXPECT_EQ(renderer.counters().contactMaps, 1);
        const ContactShares s = contactShares(v.share, v.points, fromFace, nearBand, farBand);
        std::printf("t = %.0f s: foam share %.3f within %.2f..%.1f m of the pile's face (%d px), %.3f %.0f..%.0f m "
                    "off (%d px)\n",
                    t, s.near, nearBand.x, nearBand.y, s.nearPixels, s.far, farBand.x, farBand.y, s.farPixels);
        nearMean += 0.5 * s.near;
        farMean += 0.5 * s.far;
        ASSERT_GT(s.nearPixels, 200);
        EXPECT_GT(s.near, 0.12) << "the band round the pile at t = " << t << " s";
        EXPECT_GT(s.near, 5.0 * s.far + 0.05) << "the band against the sea farther out at t = " << t << " s";
    }

    // Without the contact pass: no band.
    swell::Renderer without(foamView);
    swell::RendererTesting::setContactFoam(without, false);
    const ContactView off = contactViewDown(without, foamView, {pile_m.x, pile_m.z}, 6.0, "contact_foam_pile_off");
    const ContactShares s = contactShares(off.share, off.points, fromFace, nearBand, farBand);
    std::printf("without the contact pass: %.3f near, %.3f far\n", s.near, s.far);
    EXPECT_EQ(without.counters().contactMaps, 0);
    EXPECT_LT(s.near, 0.5 * nearMean) << "the contact pass made the band";

    // The labels call it surf (docs/LABELS.md): water whose point is under
    // the contact's foam, near the pile only.
    swell::Renderer renderer(scene);
    swell::Camera camera = swell::cameraAt(scene.camera, 0.0);
    camera.position_m = glm::dvec3(pile_m.x, kContactEyeHeight_m, pile_m.z);
    camera.yaw_deg = 0.0;
    camera.pitch_deg = -89.0;
    const glm::ivec2 size(kContactView_px, kContactView_px);
    renderer.renderImage(camera, 6.0, size);
    const swell::FrameLabels labels = renderer.renderLabels(camera, size);
    const swell::View view = swell::viewOf(camera, size);
    int nearSurf = 0, near = 0, farSurf = 0, far = 0;
    for (int y = 0; y < size.y; ++y)
        for (int x = 0; x < size.x; ++x) {
            const std::uint16_t c = labels.semantic[std::size_t(y * size.x + x)];
            if (c != SWELL_LABEL_SURF && c != SWELL_LABEL_WATER && c != SWELL_LABEL_WHITECAP_FOAM)
                continue;
            const double d = fromFace(contactSeaPoint(view, size, x, y, true));
            const bool surf = c == SWELL_LABEL_SURF;
            if (d >= nearBand.x && d < nearBand.y) {
                ++near;
                nearSurf += surf;
            } else if (d >= farBand.x) {
                ++far;
                farSurf += surf;
            }
        }
    std::printf("labels: %d of %d water pixels near the pile are surf, %d of %d beyond %.0f m\n", nearSurf, near,
                farSurf, far, farBand.x);
    EXPECT_GT(nearSurf, near / 8) << "the contact's foam is labelled surf";
    EXPECT_LT(farSurf, far / 200 + 1) << "no surf away from the pile";
}

// A host's pile (a 0.5 m square box drawn by the host's own shader through
// PassGeometry, like the example host's pier) gets the same band; the
// contact pass is the first the host is asked to draw.
TEST_F(ContactFoam, AHostsPileStandsInABandOfFoam)
{
    const swell::Scene scene = swell::test::foamDebugView(contactSea());
    const glm::dvec3 pile_m(0.0, 0.0, -30.0);
    swell::test::HostScene host({{{pile_m.x - 0.25, -6.0, pile_m.z - 0.25}, {pile_m.x + 0.25, 3.0, pile_m.z + 0.25},
                                  {0.1f, 0.08f, 0.06f}}});
    const glm::ivec2 size(kContactView_px, kContactView_px);
    swell::Camera camera = swell::cameraAt(scene.camera, 0.0);
    camera.position_m = glm::dvec3(pile_m.x, kContactEyeHeight_m, pile_m.z);
    camera.yaw_deg = 0.0;
    camera.pitch_deg = -89.0;
    const swell::View view = swell::viewOf(camera, size);
    // Distance from the box's square section.
    const auto fromFace = [&](glm::dvec3 p) {
        const glm::dvec2 q = glm::max(glm::abs(glm::dvec2(p.x - pile_m.x, p.z - pile_m.z)) - 0.25, glm::dvec2(0.0));
        return glm::length(q);
    };
    const glm::dvec2 nearBand(0.15, 1.0), farBand(5.0, 10.0);

    auto drawn = [&](bool contact, const char* name) {
        swell::Renderer renderer(scene);
        swell::RendererTesting::setContactFoam(renderer, contact);
        swell::test::HostTarget target(size);
        host.passes.clear();
        swell::test::drawHostFrame(target, host, view, {0.0f, 0.0f, 0.0f, 1.0f});
        renderer.advanceTo(6.0, view.eye_m());
        swell::DrawOptions options;
        options.geometry = &host;
        options.sky = false;
        renderer.draw(view, target.framebuffer(), options);
        const std::vector<std::uint8_t> rgba = target.pixels();
        std::vector<double> share;
        std::vector<glm::dvec3> points;
        swell::Image image{size.x, size.y, {}};
        for (int y = size.y - 1; y >= 0; --y)
            for (int x = 0; x < size.x; ++x)
                image.rgba.insert(image.rgba.end(), rgba.begin() + (y * size.x + x) * 4,
                                  rgba.begin() + (y * size.x + x) * 4 + 4);
        swell::test::saveTestImage(image, name);
        for (int y = 0; y < size.y; ++y)
            for (int x = 0; x < size.x; ++x) {
                share.push_back(swell::test::srgbToLinear(rgba[std::size_t(y * size.x + x) * 4]));
                points.push_back(contactSeaPoint(view, size, x, y, false));
            }
        const ContactShares s = contactShares(share, points, fromFace, nearBand, farBand);
        std::printf("host's pile, contact %s: foam share %.3f within %.2f..%.1f m (%d px), %.3f %.0f..%.0f m off; "
                    "%d contact maps\n",
                    contact ? "on" : "off", s.near, nearBand.x, nearBand.y, s.nearPixels, s.far, farBand.x,
                    farBand.y, renderer.counters().contactMaps);
        return s;
    };
    const ContactShares on = drawn(true, "contact_foam_host_pile");
    ASSERT_FALSE(host.passes.empty());
    EXPECT_EQ(host.passes.front(), swell::PassKind::Contact);
    const ContactShares off = drawn(false, "contact_foam_host_pile_off");
    ASSERT_GT(on.nearPixels, 200);
    EXPECT_GT(on.near, 0.12);
    EXPECT_GT(on.near, 5.0 * on.far + 0.05);
    EXPECT_LT(off.near, 0.5 * on.near) << "the host's pile made the band";
}

// A floating hull at rest (the built-in boat, a rigid body) gets its ring:
// the water within a metre of where the hull meets it is foamed well above
// the water 6 to 12 m from the boat's centre.
TEST_F(ContactFoam, AFloatingHullAtRestHasItsRing)
{
    swell::Scene scene = contactSea();
    swell::SceneObject boat;
    boat.path = "builtin:boat";
    boat.position_m = glm::dvec3(0.0, 0.0, -30.0);
    boat.floats = true;
    boat.mass_kg = 2500.0;
    boat.centerOfMassOffset_m = glm::dvec3(-0.598, -0.203, 0.0);
    scene.objects.push_back(boat);
    const swell::Scene foamView = swell::test::foamDebugView(scene);
    const glm::ivec2 size(kContactView_px, kContactView_px);
    const double t = 8.0;
    swell::Renderer renderer(foamView);
    swell::Camera camera = swell::cameraAt(scene.camera, 0.0);
    camera.position_m = glm::dvec3(boat.position_m.x, kContactEyeHeight_m, boat.position_m.z);
    camera.yaw_deg = 0.0;
    camera.pitch_deg = -89.0;
    // The hull's own pixels from the labels: the water's distance to the
    // nearest of them is its distance from the hull (seen from above, its
    // widest outline is at the waterline or just above).
    renderer.renderImage(camera, t, size);
    const swell::FrameLabels labels = renderer.renderLabels(camera, size);
    const swell::View view = swell::viewOf(camera, size);
    std::vector<glm::dvec2> hull;
    for (int y = 0; y < size.y; ++y)
        for (int x = 0; x < size.x; ++x)
            if (labels.semantic[std::size_t(y * size.x + x)] >= SWELL_LABEL_FIRST_OBJECT_CLASS) {
                const glm::dvec3 p = contactSeaPoint(view, size, x, y, true);
                hull.emplace_back(p.x, p.z);
            }
    ASSERT_GT(hull.size(), 300u) << "the boat seen from above";
    const auto fromHull = [&](glm::dvec3 p) {
        double best = 1e9;
        for (const glm::dvec2& h : hull)
            best = std::min(best, glm::length(glm::dvec2(p.x, p.z) - h));
        return best;
    };
    const ContactView v = contactViewDown(renderer, foamView, {boat.position_m.x, boat.position_m.z}, t,
                                          "contact_foam_hull");
    EXPECT_EQ(renderer.counters().contactMaps, 1);
    const ContactShares s = contactShares(v.share, v.points, fromHull, {0.15, 1.0}, {4.0, 8.0});
    std::printf("hull at rest: foam share %.3f within 0.15..1 m of its outline (%d px), %.3f 4..8 m off (%d px)\n",
                s.near, s.nearPixels, s.far, s.farPixels);
    ASSERT_GT(s.nearPixels, 200);
    EXPECT_GT(s.near, 0.08) << "the ring round the hull";
    EXPECT_GT(s.near, 4.0 * s.far + 0.05);
}

// The open sea with nothing in it, or with its only object far from the
// eye: no contact pass, and the very frame drawn without the feature.
TEST_F(ContactFoam, TheOpenSeaDrawsNoPassAndTheSameFrame)
{
    for (const bool farBuoy : {false, true}) {
        swell::Scene scene = contactSea();
        if (farBuoy) {
            swell::SceneObject buoy;
            buoy.path = "builtin:buoy";
            buoy.position_m = glm::dvec3(0.0, 0.0, -900.0);
            scene.objects.push_back(buoy);
        }
        swell::Camera camera = swell::cameraAt(scene.camera, 0.0);
        camera.position_m = glm::dvec3(0.0, 6.0, 0.0);
        camera.pitch_deg = -10.0;
        swell::Renderer with(scene), without(scene);
        swell::RendererTesting::setContactFoam(without, false);
        const swell::Image a = with.renderImage(camera, 7.0, {160, 90});
        const swell::FrameCounters ca = with.counters();
        const swell::Image b = without.renderImage(camera, 7.0, {160, 90});
        const swell::FrameCounters cb = without.counters();
        EXPECT_EQ(ca.contactMaps, 0) << (farBuoy ? "a buoy 900 m off" : "nothing");
        EXPECT_EQ(ca.drawCalls, cb.drawCalls);
        EXPECT_EQ(ca.viewsGpu.dispatches, cb.viewsGpu.dispatches);
        EXPECT_TRUE(a.rgba == b.rgba) << "the frame changed with nothing in the water near the eye";
    }
}

} // namespace
