// Every preset's objects stand as their sea would stand them: sampled every
// second of a still's developed history up to t = 20 s (the bodies stepped
// from their start as `swell render --time` steps them), no object is
// pitched or rolled past 45 degrees, and the built-in boat past 25.
//
// None of the presets' seas could put a body past 45 degrees: their
// significant slopes (pi Hs / lambda_p; the gale's 1.9 m at 49 m, 7 degrees,
// the steepest a boat sails in) are a fraction of it. The boat's bound is
// strip theory's: its pitch is the waves' slope times a response that is 1
// in waves much longer than the hull and at most 2.6 at the gale's 5 m/s
// (Jensen, Mansour & Olsen 2004, Ocean Engineering 31, 61-85, sec. 2: at
// lambda = 3.1 L; tests/cpu/test_seakeeping.cpp), so 2.6 x 7 = 18 degrees,
// and a few degrees of trim under way: 25. The buoys, tall and light, roll
// further in a passing wake (30 degrees measured in scenes/under-way.toml).
// A boat stood on its stern fails it: scenes/gale-under-way.toml's before
// the water under a body was sampled without aliasing (44 degrees bow-up
// at t = 20 s; 17 degrees at most since).
#include "support/gl_test.h"
#include "swell/renderer.h"
#include "swell/scene/scene_file.h"

#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <string>
#include <vector>

namespace {

namespace fs = std::filesystem;
using namespace swell;

class PresetPoses : public test::GlTest {};

// An object's pitch and roll, degrees: how far its own x (the bow) and z
// (the beam) axes rise out of the horizontal.
struct Tilt {
    double pitch_deg = 0.0, roll_deg = 0.0;
};

Tilt tiltOf(const glm::dmat4& transform)
{
    const glm::dvec3 bow = glm::normalize(glm::dvec3(transform[0]));
    const glm::dvec3 beam = glm::normalize(glm::dvec3(transform[2]));
    return {glm::degrees(std::asin(std::clamp(bow.y, -1.0, 1.0))),
            glm::degrees(std::asin(std::clamp(beam.y, -1.0, 1.0)))};
}

std::vector<fs::path> presets()
{
    std::vector<fs::path> files;
    for (const auto& entry : fs::directory_iterator(fs::path(SWELL_SOURCE_DIR) / "scenes"))
        if (entry.path().extension() == ".toml")
            files.push_back(entry.path());
    std::sort(files.begin(), files.end());
    return files;
}

TEST_F(PresetPoses, NoPresetTiltsABodyFurtherThanItsSeaWould)
{
    constexpr double kLimit_deg = 45.0, kBoatLimit_deg = 25.0;
    // A still's times, every second from the first frame to the README's
    // and the docs' t = 20 s: the bodies step through them in one history.
    std::vector<double> times_s;
    for (int t = 0; t <= 20; ++t)
        times_s.push_back(t);
    int objectsSeen = 0;
    for (const fs::path& file : presets()) {
        const Scene scene = loadScene(file);
        if (scene.objects.empty())
            continue;
        Renderer renderer(scene);
        std::vector<double> steepest_deg(scene.objects.size(), 0.0);
        for (double t : times_s) {
            renderer.advanceTo(t, renderer.sceneCameraAt(t).position_m);
            const std::vector<glm::dmat4> poses = renderer.objectTransforms();
            for (std::size_t i = 0; i < poses.size(); ++i) {
                const Tilt tilt = tiltOf(poses[i]);
                const double limit_deg = scene.objects[i].path == "builtin:boat" ? kBoatLimit_deg : kLimit_deg;
                EXPECT_LT(std::abs(tilt.pitch_deg), limit_deg)
                    << file.filename() << " object " << i << " (" << scene.objects[i].path << ") at t = " << t;
                EXPECT_LT(std::abs(tilt.roll_deg), limit_deg)
                    << file.filename() << " object " << i << " (" << scene.objects[i].path << ") at t = " << t;
                steepest_deg[i] = std::max({steepest_deg[i], std::abs(tilt.pitch_deg), std::abs(tilt.roll_deg)});
                ++objectsSeen;
            }
        }
        for (std::size_t i = 0; i < steepest_deg.size(); ++i)
            std::printf("%s, object %zu (%s): pitched or rolled %.1f degrees at most\n", file.filename().c_str(), i,
                        scene.objects[i].path.c_str(), steepest_deg[i]);
    }
    EXPECT_GT(objectsSeen, 0) << "no preset has an object: the test shows nothing";
}

} // namespace
