// The caustics on a sea floor near the eye (render/view_frame.cpp's
// causticsWanted): a scene without the built-in island whose floor is a
// scene seabed, with a floating body as its first object, seen from 8 m
// over 1 to 1.5 m of water. The map must be drawn, and the floor within it
// lit as the floor beyond it is: the map keeps the mean light a level
// surface lets in, so the shallows are neither darker nor brighter for it
// on average. The frame's list of which world boxes float once left out
// the floor's box, took the floor for the floating body's, drew no map and
// left the floor reading an empty one: a dark, straight-edged square of
// floor around the eye in the harbour preset's shallows. From high up, where
// none of the water over the map's square is in view, no map is drawn and
// the picture is the one without caustics.
#include "support/gl_test.h"

#include "swell/renderer.h"
#include "swell/scene/scene.h"

#include <gtest/gtest.h>

namespace {

using namespace swell;

class CausticsShallows : public test::GlTest {};

constexpr glm::ivec2 kShallowsSize{160, 90};
constexpr double kShallowsTime_s = 20.0;

Scene shallowsScene(bool caustics, glm::dvec3 eye_m = {0.0, 8.0, 10.0}, double pitch_deg = -40.0)
{
    Scene scene = defaultScene();
    scene.showTerrain = false;
    // The floor rises to the waterline at z = 60 m at 1:50, the sea towards -z.
    scene.seabed.beaches = {SeabedBeach{.shorePoint_m = {0.0, 60.0}, .seawardAzimuth_deg = 0.0, .slope = 0.02}};
    // The first object floats, out of view.
    scene.objects = {SceneObject{.path = "builtin:buoy", .position_m = {60.0, 0.0, -80.0}, .floats = true}};
    scene.camera.path = {CameraKey{0.0, eye_m, 0.0, pitch_deg}};
    scene.camera.fovY_deg = 40.0;
    scene.water.caustics = caustics;
    return scene;
}

// The mean of the red, green and blue levels over the frame's lower half,
// where the floor within the map's 24 m of the eye is.
double lowerHalfMean(const Image& image)
{
    double sum = 0.0;
    long count = 0;
    for (int y = image.height / 2; y < image.height; ++y)
        for (int x = 0; x < image.width; ++x) {
            const std::uint8_t* p = image.pixel(x, y);
            sum += double(p[0]) + double(p[1]) + double(p[2]);
            count += 3;
        }
    return sum / double(count);
}

TEST_F(CausticsShallows, TheFloorNearTheEyeIsLitByTheMap)
{
    Renderer withMap(shallowsScene(true));
    const Camera camera = withMap.sceneCameraAt(kShallowsTime_s);
    const double lit = lowerHalfMean(withMap.renderImage(camera, kShallowsTime_s, kShallowsSize));
    EXPECT_GT(withMap.counters().causticsTriangles, 0) << "no caustics map was drawn over the shallows";
    Renderer level(shallowsScene(false));
    const double levelLit = lowerHalfMean(level.renderImage(camera, kShallowsTime_s, kShallowsSize));
    // The map moves the light about and keeps its mean: the floor's mean
    // level within a tenth of the level surface's light (measured 0.972;
    // 0.767 with the floor's box taken for the buoy's, and no map drawn).
    EXPECT_NEAR(lit / levelLit, 1.0, 0.1) << "with the map " << lit << ", with the level surface's light " << levelLit;
}

// 60 m up, looking 15 degrees down over the shallows: the nearest water in
// view lies about 86 m off, the map's square within 24 m of the eye.
TEST_F(CausticsShallows, AMapNoneOfWhoseWaterIsInViewIsNotDrawn)
{
    const glm::dvec3 eye_m{0.0, 60.0, 40.0};
    Renderer withMap(shallowsScene(true, eye_m, -15.0));
    const Camera camera = withMap.sceneCameraAt(kShallowsTime_s);
    const Image image = withMap.renderImage(camera, kShallowsTime_s, kShallowsSize);
    EXPECT_EQ(withMap.counters().causticsTriangles, 0) << "a map drawn that no pixel reads";
    Renderer level(shallowsScene(false, eye_m, -15.0));
    const ImageDifference d = compareImages(image, level.renderImage(camera, kShallowsTime_s, kShallowsSize));
    EXPECT_LE(d.maxChannel, 1) << "the picture without the map is not the one without caustics";
}

} // namespace
