// The label pass (swell/dataset/labels.h) against geometry worked out on the CPU:
// on calm water every water pixel's range is the distance along its ray to
// the sea's plane, and the sky meets the water on the horizon line, for a
// camera low and high, rolled; an object's pixels carry its instance, their
// box lies within its projected 3D box, and every range on it lands inside
// that box; the colour image changes where the mask says the object is.
#include "support/gl_test.h"

#include "assets/mesh_data.h"
#include "support/mesh_ray_cast.h"
#include "support/open_sea.h"
#include "swell/dataset/labels.h"
#include "swell/dataset/sensor.h"
#include "swell/flat_model.h"
#include "swell/gpu/label_classes.h"
#include "swell/renderer.h"
#include "swell/scene/scene.h"

#include <glm/geometric.hpp>
#include <glm/matrix.hpp>
#include <glm/trigonometric.hpp>

#include <algorithm>
#include <cmath>
#include <memory>

namespace {

class Labels : public swell::test::GlTest {};

// The world direction of the ray through pixel (x, y)'s centre (not unit).
glm::dvec3 labelsPixelRay(const swell::CameraCalibration& c, int x, int y)
{
    const glm::dvec3 camera((x + 0.5 - c.cx_px) / c.fx_px, (y + 0.5 - c.cy_px) / c.fy_px, 1.0);
    return glm::dmat3(c.worldFromCamera) * camera;
}

struct CalmResult {
    int waterPixels = 0, wrongRange = 0, wrongSide = 0;
    double worstRange_m = 0.0, worstHorizon_px = 0.0;
};

CalmResult renderCalm(double height_m, double roll_deg, double pitch_deg, double far_m = 20000.0)
{
    swell::Scene scene = swell::test::openSea();
    scene.camera.far_m = far_m; // the grid reaches the far plane, the labels' water the horizon
    swell::Renderer renderer(scene);
    renderer.setWaveModel(std::make_shared<swell::FlatModel>());
    swell::Camera camera = swell::cameraAt(scene.camera, 0.0);
    camera.position_m = glm::dvec3(30.0, height_m, -12.0);
    camera.roll_deg = roll_deg;
    camera.pitch_deg = pitch_deg;
    camera.yaw_deg = 25.0;
    const glm::ivec2 size(320, 240);
    renderer.renderImage(camera, 0.0, size);
    const swell::FrameLabels labels = renderer.renderLabels(camera, size);
    CalmResult r;
    EXPECT_TRUE(labels.horizon.visible);
    for (int y = 0; y < size.y; ++y)
        for (int x = 0; x < size.x; ++x) {
            const std::size_t i = std::size_t(y) * std::size_t(size.x) + std::size_t(x);
            const glm::dvec3 d = labelsPixelRay(labels.camera, x, y);
            // Which side of the horizon line the pixel's centre is on: a
            // pixel more than 1 px inside the water's side must be water,
            // more than 1 px inside the sky's, sky.
            const double side_px = glm::dot(labels.horizon.line, glm::dvec3(x + 0.5, y + 0.5, 1.0));
            const std::uint16_t s = labels.semantic[i];
            if ((side_px < -1.0 && s != SWELL_LABEL_WATER) || (side_px > 1.0 && s != SWELL_LABEL_SKY))
                ++r.wrongSide;
            if (s == SWELL_LABEL_WATER || s == SWELL_LABEL_SKY)
                r.worstHorizon_px = std::max(r.worstHorizon_px, (s == SWELL_LABEL_WATER) == (side_px > 0.0) ? std::abs(side_px) : 0.0);
            if (s != SWELL_LABEL_WATER)
                continue;
            ++r.waterPixels;
            const double expected_m = height_m / -d.y * glm::length(d);
            const double error_m = std::abs(double(labels.range_m[i]) - expected_m);
            if (expected_m < 1.0e5)
                r.worstRange_m = std::max(r.worstRange_m, error_m);
            // 1 cm; past 131 km, where a 32-bit float's own spacing is
            // wider (rays within a fraction of a pixel of the horizon reach
            // thousands of km), one unit in its last place.
            const float stored = float(expected_m);
            const double ulp_m = double(std::nextafter(stored, INFINITY) - stored);
            if (!(error_m <= std::max(0.01, ulp_m)))
                ++r.wrongRange;
        }
    return r;
}

TEST_F(Labels, CalmWaterRangeIsTheRayPlaneDistanceAndMeetsTheSkyOnTheHorizon)
{
    for (double height : {2.0, 50.0})
        for (double roll : {0.0, 15.0}) {
            SCOPED_TRACE(::testing::Message() << "camera at " << height << " m, rolled " << roll << " deg");
            const CalmResult r = renderCalm(height, roll, -4.0);
            EXPECT_GT(r.waterPixels, 320 * 240 / 4);
            EXPECT_EQ(r.wrongRange, 0) << "worst within 100 km: " << r.worstRange_m << " m";
            EXPECT_LE(r.worstRange_m, 0.01);
            EXPECT_EQ(r.wrongSide, 0);
            EXPECT_LE(r.worstHorizon_px, 1.0);
        }
    // The grid ends at a near far plane, 7 px below the horizon: past it the
    // labels' water is the sea's plane up to the horizon.
    const CalmResult r = renderCalm(50.0, 15.0, -4.0, 1000.0);
    EXPECT_EQ(r.wrongRange, 0) << "worst within 100 km: " << r.worstRange_m << " m";
    EXPECT_EQ(r.wrongSide, 0);
    EXPECT_LE(r.worstHorizon_px, 1.0);
}

TEST_F(Labels, AnObjectsPixelsBoxAndRangesAreItsOwn)
{
    swell::Scene scene = swell::test::openSea();
    swell::SceneObject buoy;
    buoy.path = "builtin:buoy";
    buoy.position_m = glm::dvec3(3.0, 0.0, -25.0);
    scene.objects.push_back(buoy);
    scene.antialiasing = swell::Antialiasing::Msaa4; // colour edges blended, labels never
    const glm::ivec2 size(320, 240);
    swell::Camera camera = swell::cameraAt(scene.camera, 0.0);
    camera.position_m = glm::dvec3(0.0, 4.0, 0.0);
    camera.pitch_deg = -6.0;
    camera.yaw_deg = 0.0;

    swell::Renderer renderer(scene);
    const swell::Image withBuoy = renderer.renderImage(camera, 3.0, size);
    const swell::FrameLabels labels = renderer.renderLabels(camera, size);
    scene.objects.clear();
    swell::Renderer without(scene);
    const swell::Image noBuoy = without.renderImage(camera, 3.0, size);

    ASSERT_EQ(labels.objects.size(), 1u);
    const swell::ObjectLabel& o = labels.objects[0];
    EXPECT_EQ(o.className, "buoy");
    EXPECT_EQ(labels.classes.at(o.semanticClass), "buoy");
    ASSERT_GT(o.visiblePixels, 50);

    // Its 2D box within its 3D box's projection (1 px of slack for the
    // rasteriser's rule at the edges).
    glm::dvec2 lo(1e9), hi(-1e9);
    for (const glm::dvec3& corner : o.box3d_m) {
        const std::optional<glm::dvec2> p = swell::projectToImage(labels.camera, corner);
        ASSERT_TRUE(p);
        lo = glm::min(lo, *p);
        hi = glm::max(hi, *p);
    }
    EXPECT_GE(o.box_px.x, lo.x - 1.0);
    EXPECT_GE(o.box_px.y, lo.y - 1.0);
    EXPECT_LE(o.box_px.z, hi.x + 1.0);
    EXPECT_LE(o.box_px.w, hi.y + 1.0);

    // Every range on it lands in its box (1 cm of slack); every pixel of it
    // has its class; and the colour changed where it is and not 2 px away
    // from it.
    const glm::dvec3 eye = camera.position_m;
    const glm::dvec3 boxLo = glm::min(o.box3d_m[0], o.box3d_m[7]) - 0.01, boxHi = glm::max(o.box3d_m[0], o.box3d_m[7]) + 0.01;
    int outside = 0, wrongClass = 0, unchangedInside = 0, changedFarOutside = 0, inside = 0;
    auto isBuoy = [&](int x, int y) {
        return x >= 0 && y >= 0 && x < size.x && y < size.y &&
               labels.instance[std::size_t(y) * std::size_t(size.x) + std::size_t(x)] == o.instance;
    };
    for (int y = 0; y < size.y; ++y)
        for (int x = 0; x < size.x; ++x) {
            const std::size_t i = std::size_t(y) * std::size_t(size.x) + std::size_t(x);
            int diff = 0;
            for (int c = 0; c < 3; ++c)
                diff = std::max(diff, std::abs(int(withBuoy.rgba[4 * i + std::size_t(c)]) - int(noBuoy.rgba[4 * i + std::size_t(c)])));
            if (isBuoy(x, y)) {
                ++inside;
                wrongClass += labels.semantic[i] != o.semanticClass;
                const glm::dvec3 p = eye + double(labels.range_m[i]) * glm::normalize(labelsPixelRay(labels.camera, x, y));
                if (glm::any(glm::lessThan(p, boxLo)) || glm::any(glm::greaterThan(p, boxHi)))
                    ++outside;
                // Its reflection and the water's refraction also change around
                // it, so only its own pixels are held to changing.
                unchangedInside += diff < 8;
                continue;
            }
            bool near = false;
            for (int dy = -2; dy <= 2 && !near; ++dy)
                for (int dx = -2; dx <= 2 && !near; ++dx)
                    near = isBuoy(x + dx, y + dy);
            // Away from it, its reflection below it may change the water: only
            // pixels above its top row, beside it, are held to unchanged.
            if (!near && y < o.box_px.y && x >= o.box_px.x && x < o.box_px.z)
                changedFarOutside += diff >= 8;
        }
    EXPECT_EQ(outside, 0);
    EXPECT_EQ(wrongClass, 0);

    // Every range on it is the distance along its pixel's ray to its mesh,
    // placed where it is drawn (a ray cast on the CPU, Moller and Trumbore
    // 1997), within 1 cm; a ray that grazes the silhouette may miss it.
    const swell::detail::MeshData mesh = swell::detail::makeBuiltinModel("buoy");
    const glm::dmat4 pose = renderer.objectTransforms().at(0);
    int hits = 0, misses = 0, off = 0;
    double worst_m = 0.0;
    for (int y = 0; y < size.y; ++y)
        for (int x = 0; x < size.x; ++x) {
            if (!isBuoy(x, y))
                continue;
            const glm::dvec3 d = glm::normalize(labelsPixelRay(labels.camera, x, y));
            const double nearest = swell::test::rayCastMesh(mesh, pose, eye, d);
            if (!std::isfinite(nearest)) {
                ++misses;
                continue;
            }
            ++hits;
            const double error_m = std::abs(double(labels.range_m[std::size_t(y) * std::size_t(size.x) + std::size_t(x)]) - nearest);
            worst_m = std::max(worst_m, error_m);
            off += error_m > 0.01;
        }
    EXPECT_EQ(off, 0) << "worst " << worst_m << " m";
    EXPECT_LE(misses, hits / 50);
    EXPECT_LE(unchangedInside, inside / 20) << "of " << inside;
    EXPECT_EQ(changedFarOutside, 0);
}

} // namespace

namespace {

// A camera mounted on the boat under way (camera.mount_object): where the
// boat is drawn, it stands at its offset and rolls with it.
TEST_F(Labels, AMountedCameraRidesItsBody)
{
    swell::Scene scene = swell::defaultScene();
    swell::SceneObject boat;
    boat.path = "builtin:boat";
    boat.position_m = glm::dvec3(0.0, 0.0, -20.0);
    boat.floats = true;
    boat.density_kg_per_m3 = 400.0;
    scene.objects = {boat};
    scene.camera.mountObject = 0;
    scene.camera.mountOffset_m = glm::dvec3(0.0, 2.5, 0.0);
    scene.camera.pitch_deg = -5.0;
    swell::Renderer renderer(scene);
    double rollMin = 1e9, rollMax = -1e9;
    for (double t : {3.0, 4.0, 5.5, 7.0}) {
        const swell::Camera camera = renderer.sceneCameraAt(t);
        renderer.renderImage(camera, t, {64, 48});
        const glm::dmat4 pose = renderer.objectTransforms().at(0);
        const glm::dvec3 at(pose * glm::dvec4(scene.camera.mountOffset_m, 1.0));
        EXPECT_NEAR(glm::distance(camera.position_m, at), 0.0, 1e-9) << "at " << t << " s";
        rollMin = std::min(rollMin, camera.roll_deg);
        rollMax = std::max(rollMax, camera.roll_deg);
    }
    EXPECT_GT(rollMax - rollMin, 0.05) << "the camera does not roll with the boat";
}

} // namespace

namespace {

// Through a distorting lens (camera.distortion_*): on calm water, every
// pixel's label and range agree with the ray the written calibration and
// coefficients give its centre: the sky and the water on their sides of
// that ray's horizon, and the range within half a pixel of where that ray
// meets the sea (the range converted to pixels by its gradient).
TEST_F(Labels, ThroughALensTheWrittenModelFindsEachPixelsRay)
{
    const swell::Scene scene = swell::test::openSeaThroughALens();
    swell::Renderer renderer(scene);
    renderer.setWaveModel(std::make_shared<swell::FlatModel>());
    swell::Camera camera = swell::cameraAt(scene.camera, 0.0);
    const double height_m = 20.0;
    camera.position_m = glm::dvec3(10.0, height_m, 5.0);
    camera.pitch_deg = -12.0;
    camera.roll_deg = 10.0;
    const glm::ivec2 size(240, 180);
    const swell::SensorFrame frame = swell::renderSensorFrame(renderer, camera, 0.0, size, true);
    ASSERT_TRUE(frame.labels);
    const swell::FrameLabels& labels = *frame.labels;
    const swell::CameraCalibration& c = labels.camera;
    EXPECT_EQ(c.k1, -0.22);
    const swell::LensDistortion lens{c.k1, c.k2, c.k3, c.p1, c.p2};
    // The model's ray through a point of the image, and where it meets the sea.
    auto ray = [&](double px, double py) {
        const glm::dvec2 u = swell::undistort(lens, {(px - c.cx_px) / c.fx_px, (py - c.cy_px) / c.fy_px});
        return glm::normalize(glm::dmat3(c.worldFromCamera) * glm::dvec3(u, 1.0));
    };
    auto range = [&](double px, double py) {
        const glm::dvec3 d = ray(px, py);
        return d.y < 0.0 ? height_m / -d.y : INFINITY;
    };
    int none = 0, wrongSide = 0, water = 0, farFromModel = 0;
    double worst_px = 0.0;
    for (int y = 0; y < size.y; ++y)
        for (int x = 0; x < size.x; ++x) {
            const std::size_t i = std::size_t(y) * std::size_t(size.x) + std::size_t(x);
            const std::uint16_t s = labels.semantic[i];
            none += s == SWELL_LABEL_NONE;
            const bool below = ray(x + 0.5, y + 0.5).y < 0.0;
            bool nearHorizon = false;
            for (int dy = -1; dy <= 1; ++dy)
                for (int dx = -1; dx <= 1; ++dx)
                    nearHorizon = nearHorizon || (ray(x + 0.5 + dx, y + 0.5 + dy).y < 0.0) != below;
            if (!nearHorizon && (s == SWELL_LABEL_WATER) != below)
                ++wrongSide;
            // Ranges where they change smoothly: rays at least 2 degrees down.
            if (s != SWELL_LABEL_WATER || ray(x + 0.5, y + 0.5).y > -std::sin(glm::radians(2.0)))
                continue;
            ++water;
            const double model = range(x + 0.5, y + 0.5);
            const glm::dvec2 gradient(range(x + 1.0, y + 0.5) - range(x, y + 0.5), range(x + 0.5, y + 1.0) - range(x + 0.5, y));
            const double off_px = std::abs(double(labels.range_m[i]) - model) / glm::length(gradient);
            worst_px = std::max(worst_px, off_px);
            farFromModel += off_px > 0.5;
        }
    EXPECT_EQ(none, 0) << "pixels whose rays the pinhole frame did not hold";
    EXPECT_EQ(wrongSide, 0);
    EXPECT_GT(water, size.x * size.y / 3);
    EXPECT_EQ(farFromModel, 0) << "worst " << worst_px << " px";
    // A point on the sea, projected with the written model, lands on a pixel
    // labelled water whose range is that point's distance within half a pixel.
    const glm::dvec3 point = camera.position_m + glm::dvec3(30.0, -height_m, -60.0);
    const std::optional<glm::dvec2> at = swell::projectToImage(c, point);
    ASSERT_TRUE(at);
    const std::size_t i = std::size_t(at->y) * std::size_t(size.x) + std::size_t(at->x);
    EXPECT_EQ(labels.semantic[i], SWELL_LABEL_WATER);
    EXPECT_NEAR(glm::distance(ray(at->x, at->y) * range(at->x, at->y), point - camera.position_m), 0.0, 1e-6);
}

} // namespace

namespace {

// The sensor: +1 EV doubles the linear light (where nothing clips); the
// noise has the standard deviation asked for, the same for the same frame
// and seed, and another for another seed.
TEST_F(Labels, ExposureDoublesTheLightAndNoiseIsTheSameForTheSameFrame)
{
    swell::Scene scene = swell::test::openSea();
    const glm::ivec2 size(96, 64);
    auto frameOf = [&](double ev, double noise, std::uint32_t seed) {
        swell::Scene s = scene;
        s.camera.exposure_ev = ev;
        s.camera.noiseStdDev = noise;
        s.camera.noiseSeed = seed;
        swell::Renderer renderer(s);
        return swell::renderSensorFrame(renderer, swell::cameraAt(s.camera, 2.0), 2.0, size, false).image;
    };
    const swell::Image plain = frameOf(0.0, 0.0, 0), brighter = frameOf(1.0, 0.0, 0);
    auto linear = [](int v) {
        const double c = v / 255.0;
        return c <= 0.04045 ? c / 12.92 : std::pow((c + 0.055) / 1.055, 2.4);
    };
    int compared = 0, off = 0;
    for (std::size_t i = 0; i < plain.rgba.size(); ++i)
        if (i % 4 != 3 && plain.rgba[i] > 40 && plain.rgba[i] < 150) {
            ++compared;
            // Twice the light, within the rounding of two 8-bit encodings.
            off += std::abs(linear(brighter.rgba[i]) - 2.0 * linear(plain.rgba[i])) > 0.012;
        }
    EXPECT_GT(compared, 1000);
    EXPECT_EQ(off, 0);

    const swell::Image noisy = frameOf(0.0, 0.05, 7), again = frameOf(0.0, 0.05, 7), other = frameOf(0.0, 0.05, 8);
    EXPECT_EQ(noisy.rgba, again.rgba);
    EXPECT_NE(noisy.rgba, other.rgba);
    double sum = 0.0, sumSquares = 0.0;
    int n = 0;
    for (std::size_t i = 0; i < plain.rgba.size(); ++i)
        if (i % 4 != 3 && plain.rgba[i] > 50 && plain.rgba[i] < 205) { // away from clipping
            const double d = double(noisy.rgba[i]) - double(plain.rgba[i]);
            sum += d;
            sumSquares += d * d;
            ++n;
        }
    ASSERT_GT(n, 1000);
    const double mean = sum / n, deviation = std::sqrt(sumSquares / n - mean * mean);
    EXPECT_NEAR(deviation, 0.05 * 255.0, 0.1 * 0.05 * 255.0);
    EXPECT_NEAR(mean, 0.0, 1.0);
}

} // namespace
