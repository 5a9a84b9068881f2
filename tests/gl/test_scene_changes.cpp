// The parameter table is the renderer's only change detector: for every
// parameter, a renderer that was drawing one scene and is switched to a scene
// with that parameter changed must draw exactly what a renderer built afresh
// for the changed scene draws. A parameter declared cheaper than it is (say
// Frame where the grid must be rebuilt) leaves stale state and fails here.
#include "core/fleet.h"
#include "support/gl_test.h"
#include "swell/debug.h"
#include "swell/error.h"
#include "swell/flat_model.h"
#include "swell/gl/handle.h"
#include "swell/renderer.h"
#include "swell/scene/parameters.h"
#include "swell/scene/scene_changes.h"
#include "swell/scene/scene_file.h"

#include <epoxy/gl.h>

#include <cmath>
#include <string>
#include <vector>

namespace {

using namespace swell;

class SceneChanges : public test::GlTest {};

// Small and early in time: enough pixels to show the sky, the island, an
// object and the waves, cheap enough for a renderer per parameter.
constexpr glm::ivec2 kSceneChangesSize{96, 54};
constexpr double kSceneChangesTime_s = 3.0;

Scene baseScene()
{
    Scene scene = defaultScene();
    // A fixed rock first: camera.mount_object's first other value (0) must
    // name an object a camera can ride; then a floating buoy.
    scene.objects = {SceneObject{.path = "builtin:rock", .position_m = {-12.0, 0.0, -45.0}},
                     SceneObject{.path = "builtin:buoy", .position_m = {8.0, 0.0, -30.0}, .floats = true}};
    scene.camera.path = {CameraKey{0.0, {0.0, 6.0, 0.0}, 0.0, -5.0}, CameraKey{10.0, {5.0, 8.0, -5.0}, 10.0, -8.0}};
    // A sea floor in view: a beach, a shelf before it and a breakwater.
    scene.seabed.beaches = {SeabedBeach{.shorePoint_m = {0.0, -400.0}, .seawardAzimuth_deg = 180.0, .slope = 0.05}};
    scene.seabed.shelves = {SeabedShelf{.edgePoint_m = {0.0, -250.0}, .seawardAzimuth_deg = 180.0, .depth_m = 6.0}};
    scene.seabed.breakwaters = {SeabedBreakwater{.start_m = {-60.0, -200.0}, .end_m = {40.0, -180.0}}};
    return scene;
}

// What a key needs of the scene to mean anything (true when it needs
// something): the fleet's keys one of the fleet's models as objects[0]
// (docs/SCENE.md, "The fleet"), the fisheye's coefficients the fisheye lens.
bool fleetKey(const Parameter& p)
{
    const std::string key(p.key);
    return key == "objects.length_m" || key == "objects.beam_m" || key == "objects.hull_color" ||
           key == "objects.superstructure_color" || key == "objects.superstructure";
}

bool prepareFor(const Parameter& p, Scene& scene)
{
    if (std::string(p.key).starts_with("camera.fisheye_")) {
        scene.camera.lens = LensModel::KannalaBrandt;
        return true;
    }
    if (fleetKey(p)) {
        scene.objects[0] = SceneObject{.path = "builtin:tug", .position_m = {-12.0, 0.0, -45.0}};
        return true;
    }
    return false;
}

// A value different from `value` that the parameter allows, picked inside
// its slider span; `attempt` gives other candidates when one is refused by
// a rule between parameters (fog end after start, say).
ParameterValue otherValue(const Parameter& p, const ParameterValue& value, int attempt)
{
    // The fleet's stretches: within their bounds of the tug's design.
    if (std::string(p.key) == "objects.length_m")
        return (1.1 + 0.1 * attempt) * detail::fleetDesign("tug").length_m;
    if (std::string(p.key) == "objects.beam_m")
        return (1.1 + 0.05 * attempt) * detail::fleetDesign("tug").beam_m;
    // The fleet's paints: a colour ([-1, -1, -1], the default, is the model's own).
    if (std::string(p.key) == "objects.hull_color" || std::string(p.key) == "objects.superstructure_color")
        return glm::dvec3(0.2 + 0.1 * attempt, 0.5, 0.7);
    const double fractions[] = {0.37, 0.81, 0.13, 0.07, 0.013, 0.004};
    const double f = fractions[attempt % 6];
    const double x = p.sliderMin + f * (p.sliderMax - p.sliderMin);
    switch (p.kind) {
    case ParameterKind::Real: return x;
    case ParameterKind::DateTime: return std::round(x); // an instant in the slider's years, whole seconds
    case ParameterKind::Integer: {
        const auto i = std::int64_t(std::llround(x));
        return i == std::get<std::int64_t>(value) ? i + 1 : i;
    }
    case ParameterKind::Flag: return !std::get<bool>(value);
    case ParameterKind::Choice:
        return (std::get<std::int64_t>(value) + 1 + attempt) % std::int64_t(p.choices.size());
    case ParameterKind::Colour:
    case ParameterKind::Vector3: return glm::dvec3(x, p.sliderMin + (1.0 - f) * (p.sliderMax - p.sliderMin), x);
    case ParameterKind::Direction3: return glm::dvec3(0.3 + f, 0.4, -0.7);
    case ParameterKind::Direction2: return glm::dvec2(0.3 + f, -0.7);
    case ParameterKind::Vector2: return glm::dvec2(x, p.sliderMin + (1.0 - f) * (p.sliderMax - p.sliderMin));
    }
    return value;
}

// What the renderer draws: the image, and the water's vertices (which show
// a stale grid even where fog hides it in the image).
struct SceneChangesDrawn {
    Image image;
    std::vector<float> vertices;
};

SceneChangesDrawn draw(Renderer& renderer)
{
    // The scene's camera as the renderer places it (on its mount, if any).
    const Camera camera = renderer.sceneCameraAt(kSceneChangesTime_s);
    SceneChangesDrawn d;
    d.image = renderer.renderImage(camera, kSceneChangesTime_s, kSceneChangesSize);
    const int count = swell::RendererTesting::waterVertexCount(renderer);
    gl::Buffer buffer = gl::Buffer::create();
    glNamedBufferStorage(buffer.id(), GLsizeiptr(count) * 8 * 4, nullptr, 0);
    swell::RendererTesting::captureWaterVertices(renderer, camera, kSceneChangesTime_s, buffer.id(), kSceneChangesSize);
    d.vertices.resize(size_t(count) * 8);
    glGetNamedBufferSubData(buffer.id(), 0, GLsizeiptr(d.vertices.size() * 4), d.vertices.data());
    return d;
}

TEST_F(SceneChanges, EveryParameterChangeDrawsWhatAFreshRendererDraws)
{
    const Scene base = baseScene();
    Renderer running(base);
    draw(running);
    int checked = 0;
    for (const Parameter& p : parameters()) {
        // The scene the key means something in, drawn first.
        Scene prepared = base;
        const bool needsMore = prepareFor(p, prepared);
        Scene changed = prepared;
        if (!isPresent(p, changed) || listSize(changed, p.list) == 0)
            continue;
        if (needsMore) {
            running.setScene(prepared);
            draw(running);
        }
        const ParameterValue before = p.get(changed, 0);
        bool valid = false;
        for (int attempt = 0; attempt < 6 && !valid; ++attempt) {
            changed = prepared;
            p.set(changed, 0, otherValue(p, before, attempt));
            try {
                validateScene(changed, "changes.toml");
                valid = p.get(changed, 0) != before;
            } catch (const InputError&) {
            }
        }
        if (!valid) {
            ADD_FAILURE() << std::string(p.key) << ": found no other valid value to try";
            continue;
        }
        SCOPED_TRACE(std::string(p.key) + " = " + formatValue(p, p.get(changed, 0)));
        running.setScene(changed);
        const SceneChangesDrawn incremental = draw(running);
        Renderer fresh(changed);
        const SceneChangesDrawn expected = draw(fresh);
        EXPECT_TRUE(incremental.image.rgba == expected.image.rgba) << "a change of " << p.key << " left a stale image";
        EXPECT_TRUE(incremental.vertices == expected.vertices) << "a change of " << p.key << " left a stale grid";
        running.setScene(base);
        ++checked;
    }
    // Every parameter with an item in the base scene was tried.
    EXPECT_GE(checked, 45);
}

TEST_F(SceneChanges, AReplacedWaveModelIsDrawnAndTheScenesComesBack)
{
    const Scene scene = baseScene();
    Renderer renderer(scene);
    const Image waves = draw(renderer).image;
    renderer.setWaveModel(std::make_shared<FlatModel>());
    EXPECT_EQ(renderer.waveModel().name(), "flat");
    EXPECT_EQ(renderer.waveModel().heightAt({3.0, 4.0}, kSceneChangesTime_s), 0.0);
    const Image flat = draw(renderer).image;
    EXPECT_FALSE(flat.rgba == waves.rgba);
    renderer.setWaveModel(nullptr);
    EXPECT_EQ(renderer.waveModel().name(), "gerstner");
    EXPECT_TRUE(draw(renderer).image.rgba == waves.rgba);
}

} // namespace
