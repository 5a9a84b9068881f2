// The sensor's time (swell/dataset/sensor.h, SensorTiming; docs/LABELS.md
// "Cameras as sensors"; issue 46, item 2): motion blur and a rolling
// shutter, held to the camera's motion rather than to their own
// arithmetic. The camera turns at a constant rate omega (a yaw path) past a
// buoy standing against the sky; near the image's centre the picture then
// slides sideways at v = f omega pixels a second (a rotation about the
// camera's vertical axis moves a pixel at x by f omega (1 + x^2 / f^2)).
// - Motion blur: a shutter open for S seconds averages the frames of its
//   window, so each row is the instant's row filtered by a box v S pixels
//   wide: the box width that best explains the blurred frame is measured.
// - Rolling shutter: row y is read out at t + ((y + 0.5) / H - 0.5) R, so it
//   is the instant's row slid by v times that: the slide of each row is
//   measured, and its slope against y is v R / H.
#include "support/gl_test.h"

#include "support/golden.h"
#include "support/open_sea.h"
#include "swell/dataset/sensor.h"
#include "swell/renderer.h"
#include "swell/scene/scene.h"

#include <glm/trigonometric.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <vector>

namespace {

class SensorMotion : public swell::test::GlTest {};

constexpr glm::ivec2 kSensorMotionSize(320, 240);
constexpr double kTurn_rad_s = 0.5; // the camera's yaw rate
constexpr double kSensorMotionTime_s = 1.0;     // the frame's time: the camera looks north then

// The open sea with a buoy four times its size standing in the air 30 m
// north, seen against the sky by a camera 2 m up that turns right at
// kTurn_rad_s (level, yaw -28.6 deg at 0 s to +28.6 at 2 s).
swell::Scene turningPastABuoy()
{
    swell::Scene scene = swell::test::openSea();
    swell::SceneObject buoy;
    buoy.path = "builtin:buoy";
    buoy.position_m = glm::dvec3(0.0, 10.0, -30.0);
    buoy.scale = 4.0;
    scene.objects.push_back(buoy);
    const double swing_deg = glm::degrees(kTurn_rad_s * kSensorMotionTime_s);
    for (const double t : {0.0, 2.0 * kSensorMotionTime_s}) {
        swell::CameraKey key;
        key.time_s = t;
        key.position_m = glm::dvec3(0.0, 2.0, 0.0);
        key.yaw_deg = -swing_deg + 2.0 * swing_deg * t / (2.0 * kSensorMotionTime_s);
        key.pitch_deg = 0.0;
        scene.camera.path.push_back(key);
    }
    return scene;
}

swell::Image frameOf(const swell::Scene& scene)
{
    swell::Renderer renderer(scene);
    return swell::renderSensorFrame(
               renderer, [&renderer](double t) { return renderer.sceneCameraAt(t); }, kSensorMotionTime_s, kSensorMotionSize, false)
        .image;
}

// The image's vertical focal length, pixels.
double focal_px(const swell::Scene& scene) { return 0.5 * kSensorMotionSize.y / std::tan(glm::radians(0.5 * scene.camera.fovY_deg)); }

struct Linear {
    std::vector<double> v; // linear RGB, rows top first
    double at(int x, int y, int ch) const { return v[(std::size_t(y) * kSensorMotionSize.x + std::size_t(x)) * 3 + std::size_t(ch)]; }
    // Linear interpolation along the row.
    double along(double x, int y, int ch) const
    {
        x = std::clamp(x, 0.0, double(kSensorMotionSize.x - 1));
        const int x0 = std::min(int(std::floor(x)), kSensorMotionSize.x - 2);
        const double f = x - x0;
        return (1.0 - f) * at(x0, y, ch) + f * at(x0 + 1, y, ch);
    }
};

Linear linearOf(const swell::Image& image)
{
    Linear l;
    for (int y = 0; y < kSensorMotionSize.y; ++y)
        for (int x = 0; x < kSensorMotionSize.x; ++x)
            for (int ch = 0; ch < 3; ++ch)
                l.v.push_back(swell::test::srgbToLinear(image.pixel(x, y)[ch]));
    return l;
}

// The rows above the horizon where the buoy is: those whose middle 160
// columns vary (the sky alone is smooth).
std::vector<int> buoyRows(const Linear& instant)
{
    std::vector<int> rows;
    for (int y = 0; y < kSensorMotionSize.y / 2 - 4; ++y) {
        double lo = 1e9, hi = -1e9;
        for (int x = kSensorMotionSize.x / 2 - 80; x < kSensorMotionSize.x / 2 + 80; ++x) {
            lo = std::min(lo, instant.at(x, y, 0));
            hi = std::max(hi, instant.at(x, y, 0));
        }
        if (hi - lo > 0.1)
            rows.push_back(y);
    }
    return rows;
}

// Mean absolute difference, over the buoy's rows and the middle 160
// columns, between `image` and the instant filtered by a box `width_px`
// wide along the rows.
double boxError(const Linear& image, const Linear& instant, const std::vector<int>& rows, double width_px)
{
    constexpr int kTaps = 64;
    double error = 0.0;
    std::size_t n = 0;
    for (const int y : rows)
        for (int x = kSensorMotionSize.x / 2 - 80; x < kSensorMotionSize.x / 2 + 80; ++x)
            for (int ch = 0; ch < 3; ++ch) {
                double box = 0.0;
                for (int k = 0; k < kTaps; ++k)
                    box += instant.along(x + width_px * ((k + 0.5) / kTaps - 0.5), y, ch);
                error += std::abs(image.at(x, y, ch) - box / kTaps);
                ++n;
            }
    return error / double(n);
}

// The slide s (pixels, + to the left) that best matches row y of `image` to
// the instant's row y moved by it: image(x) = instant(x + s).
double slideOf(const Linear& image, const Linear& instant, int y)
{
    double best = 0.0, bestError = std::numeric_limits<double>::infinity();
    for (double s = -20.0; s <= 20.0; s += 0.05) {
        double error = 0.0;
        for (int x = kSensorMotionSize.x / 2 - 60; x < kSensorMotionSize.x / 2 + 60; ++x)
            for (int ch = 0; ch < 3; ++ch)
                error += std::abs(image.at(x, y, ch) - instant.along(x + s, y, ch));
        if (error < bestError) {
            bestError = error;
            best = s;
        }
    }
    return best;
}

TEST_F(SensorMotion, AShutterBlursTheFrameByTheCamerasMotionOverIt)
{
    swell::Scene scene = turningPastABuoy();
    const Linear instant = linearOf(frameOf(scene));
    scene.camera.shutter_s = 0.1;
    scene.camera.motionSamples = 32;
    const Linear blurred = linearOf(frameOf(scene));
    const std::vector<int> rows = buoyRows(instant);
    ASSERT_GT(rows.size(), 40u) << "the buoy should fill many rows above the horizon";

    const double expected_px = focal_px(scene) * kTurn_rad_s * scene.camera.shutter_s;
    double bestWidth = 0.0, bestError = std::numeric_limits<double>::infinity();
    for (double w = 0.0; w <= 2.0 * expected_px; w += 0.25) {
        const double e = boxError(blurred, instant, rows, w);
        if (e < bestError) {
            bestError = e;
            bestWidth = w;
        }
    }
    const double sharpError = boxError(blurred, instant, rows, 0.0);
    std::printf("blur: the box that explains it is %.2f px wide (f omega S = %.2f px); error %.4f against %.4f "
                "unblurred\n",
                bestWidth, expected_px, bestError, sharpError);
    EXPECT_NEAR(bestWidth, expected_px, 0.1 * expected_px);
    EXPECT_LT(bestError, 0.3 * sharpError);
}

TEST_F(SensorMotion, ARollingShutterSlidesEachRowByTheMotionUntilItsReadout)
{
    swell::Scene scene = turningPastABuoy();
    const Linear instant = linearOf(frameOf(scene));
    scene.camera.readout_s = 0.2;
    scene.camera.motionSamples = 96;
    const Linear rolling = linearOf(frameOf(scene));
    const std::vector<int> rows = buoyRows(instant);
    ASSERT_GT(rows.size(), 40u);

    // A line fitted to each row's slide against the row.
    double sy = 0.0, ss = 0.0, syy = 0.0, sys = 0.0;
    for (const int y : rows) {
        const double s = slideOf(rolling, instant, y);
        sy += y;
        ss += s;
        syy += double(y) * y;
        sys += y * s;
    }
    const double n = double(rows.size());
    const double slope = (n * sys - sy * ss) / (n * syy - sy * sy);
    const double intercept = (ss - slope * sy) / n;
    // Row y's slide, v (t_y - t), with the row's time from its readout.
    const double v_px_s = focal_px(scene) * kTurn_rad_s;
    const double expectedSlope = v_px_s * scene.camera.readout_s / kSensorMotionSize.y;
    const double expectedAt0 = v_px_s * scene.camera.readout_s * (0.5 / kSensorMotionSize.y - 0.5);
    std::printf("rolling shutter: each row slides %.4f px a row (v R / H = %.4f); row 0 by %.2f px (%.2f)\n", slope,
                expectedSlope, intercept, expectedAt0);
    EXPECT_NEAR(slope, expectedSlope, 0.1 * expectedSlope);
    EXPECT_NEAR(intercept, expectedAt0, 0.1 * std::abs(expectedAt0));
}

TEST_F(SensorMotion, BlurAndRollingShutterAreTheSameBytesTwice)
{
    swell::Scene scene = turningPastABuoy();
    scene.camera.shutter_s = 0.02;
    scene.camera.readout_s = 0.03;
    scene.camera.motionSamples = 8;
    const swell::Image a = frameOf(scene), b = frameOf(scene);
    EXPECT_TRUE(a.rgba == b.rgba);
    // And with the labels of the instant, in one renderer drawing twice.
    swell::Renderer renderer(scene);
    const auto cameraAt = [&renderer](double t) { return renderer.sceneCameraAt(t); };
    const swell::SensorFrame first = swell::renderSensorFrame(renderer, cameraAt, kSensorMotionTime_s, kSensorMotionSize, true);
    const swell::SensorFrame second = swell::renderSensorFrame(renderer, cameraAt, kSensorMotionTime_s, kSensorMotionSize, true);
    EXPECT_TRUE(first.image.rgba == a.rgba);
    EXPECT_TRUE(second.image.rgba == a.rgba);
    ASSERT_TRUE(first.labels && second.labels);
    EXPECT_TRUE(first.labels->instance == second.labels->instance);
    EXPECT_TRUE(first.labels->range_m == second.labels->range_m);
    // The labels are the instant's: those an instant frame has.
    swell::Scene still = scene;
    still.camera.shutter_s = still.camera.readout_s = 0.0;
    swell::Renderer stillRenderer(still);
    const swell::SensorFrame instant = swell::renderSensorFrame(
        stillRenderer, [&stillRenderer](double t) { return stillRenderer.sceneCameraAt(t); }, kSensorMotionTime_s, kSensorMotionSize, true);
    EXPECT_TRUE(first.labels->instance == instant.labels->instance);
    EXPECT_TRUE(first.labels->range_m == instant.labels->range_m);
    EXPECT_EQ(first.camera.yaw_deg, instant.camera.yaw_deg);
}

} // namespace
