// A camera rolled about its view direction (a camera on a rolling deck):
// its frame is the level frame turned by the roll, and a scene's
// camera.roll_deg, and its path's, reach the camera.
#include "support/gl_test.h"
#include "support/stage.h"
#include "swell/renderer.h"

#include <glm/common.hpp>
#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>

class CameraRoll : public swell::test::GlTest {};

namespace {

constexpr glm::ivec2 kCameraRollSize{320, 240};

// The image's colour at (x, y) in pixels (pixel centres at .5), bilinear.
glm::dvec3 sample(const swell::Image& image, double x, double y)
{
    const double u = std::clamp(x - 0.5, 0.0, image.width - 1.0), v = std::clamp(y - 0.5, 0.0, image.height - 1.0);
    const int i = std::min(int(u), image.width - 2), j = std::min(int(v), image.height - 2);
    const double fu = u - i, fv = v - j;
    auto at = [&](int a, int b) {
        const std::uint8_t* p = image.pixel(a, b);
        return glm::dvec3(p[0], p[1], p[2]);
    };
    return glm::mix(glm::mix(at(i, j), at(i + 1, j), fu), glm::mix(at(i, j + 1), at(i + 1, j + 1), fu), fv);
}

// The mean difference (0..255, per channel) between `rolled` and `level`
// turned by `roll_deg` about the image's centre, counter-clockwise on the
// screen for + (a point right of the centre moves up), inside a circle of
// 0.45 the height, which stays inside both images.
double differenceFromTurned(const swell::Image& rolled, const swell::Image& level, double roll_deg)
{
    const double r = glm::radians(roll_deg), c = std::cos(r), s = std::sin(r);
    const glm::dvec2 centre(0.5 * rolled.width, 0.5 * rolled.height);
    const double radius = 0.45 * rolled.height;
    double sum = 0.0;
    int count = 0;
    for (int y = 0; y < rolled.height; ++y)
        for (int x = 0; x < rolled.width; ++x) {
            const glm::dvec2 d = glm::dvec2(x + 0.5, y + 0.5) - centre;
            if (glm::length(d) > radius)
                continue;
            // Where this pixel of the rolled view was in the level one: the
            // turn undone ((1, 0) went to (c, -s), (0, 1) to (s, c)).
            const glm::dvec2 from = centre + glm::dvec2(d.x * c - d.y * s, d.x * s + d.y * c);
            const std::uint8_t* p = rolled.pixel(x, y);
            const glm::dvec3 diff = glm::abs(glm::dvec3(p[0], p[1], p[2]) - sample(level, from.x, from.y));
            sum += (diff.x + diff.y + diff.z) / 3.0;
            ++count;
        }
    return sum / count;
}

} // namespace

// A roll about the view direction turns a pinhole camera's image about its
// centre and changes nothing else: the rolled frame of still water, sky,
// sun and a buoy with its reflection is the level frame turned by the roll,
// counter-clockwise for + (the horizon's right end rises). Turned the other
// way, or not at all, the two differ by the sky's gradient, the horizon and
// the buoy: many times more.
TEST_F(CameraRoll, ARolledFrameIsTheLevelFrameTurnedByTheRoll)
{
    swell::Scene scene = swell::test::emptyStage();
    scene.camera.position_m = {0.0, 3.0, 0.0};
    scene.camera.pitch_deg = -2.0;
    scene.objects.push_back({"builtin:buoy", {0.0, 0.0, -40.0}, 0.0, 2.0, false});
    swell::Renderer renderer(scene);
    const swell::Camera levelCamera = swell::cameraAt(scene.camera, 0.0);
    const swell::Image level = renderer.renderImage(levelCamera, 0.0, kCameraRollSize);
    for (double roll : {-30.0, 15.0, 90.0}) {
        swell::Camera camera = levelCamera;
        camera.roll_deg = roll;
        const swell::Image rolled = renderer.renderImage(camera, 0.0, kCameraRollSize);
        const double turned = differenceFromTurned(rolled, level, roll);
        const double otherWay = differenceFromTurned(rolled, level, -roll);
        const double unturned = differenceFromTurned(rolled, level, 0.0);
        // Bilinear resampling of the level frame softens the edges: 0.2 to
        // 0.5 levels on average as measured; a wrong turn gives over 10.
        EXPECT_LT(turned, 1.0) << "roll " << roll;
        EXPECT_GT(otherWay, 5.0) << "roll " << roll;
        EXPECT_GT(unturned, 5.0) << "roll " << roll;
        std::printf("roll %+.0f deg: mean difference %.2f turned by the roll, %.2f the other way, %.2f not turned\n",
                    roll, turned, otherWay, unturned);
    }
}

// camera.roll_deg of a scene file, and a path's keys interpolated, reach cameraAt().
TEST_F(CameraRoll, TheScenesRollAndThePathsRollReachTheCamera)
{
    swell::CameraSettings settings;
    settings.roll_deg = 12.0;
    EXPECT_EQ(swell::cameraAt(settings, 0.0).roll_deg, 12.0);
    settings.path = {{0.0, {0.0, 5.0, 0.0}, 0.0, 0.0, -10.0}, {10.0, {0.0, 5.0, 0.0}, 0.0, 0.0, 30.0}};
    EXPECT_DOUBLE_EQ(swell::cameraAt(settings, 5.0).roll_deg, 10.0);
}
