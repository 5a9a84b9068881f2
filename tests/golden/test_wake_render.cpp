// The wake in rendered frames, checked against its geometry rather than a
// stored image: a boat under way on flat water, seen from straight above,
// changes the picture inside Kelvin's wedge astern of it (half-angle 19.47
// deg; 25 deg allowed for the wedge's own width and the foam) and hardly
// anywhere else; the wedge's arms are drawn, not only the stern's foam
// trail; and the same scene and time give the same image bit for bit.
// The arms are judged on the waves alone (the foam term left out): this
// boat's crests break, and their foam, drawn with the whitecaps' look down
// to its faint old flecks and the bubbles under it, fills the V between
// the arms as the boat sweeps them along.
#include "support/camera_rays.h"
#include "support/gl_test.h"
#include "support/golden.h"
#include "swell/debug.h"
#include "swell/flat_model.h"
#include "swell/gpu/variants.h"
#include "swell/renderer.h"

#include <glm/trigonometric.hpp>

#include <cmath>
#include <cstdio>
#include <memory>

namespace {

class WakeRender : public swell::test::GlTest {};

constexpr glm::ivec2 kWakeRenderSize{256, 256};
constexpr double kWakeRenderTime_s = 20.0;

// The built-in boat at 4 m/s along -z on flat water, a camera 60 m above
// the 60 m of water astern of it. It carries 450 kg over its design
// displacement, 2950 kg, what the built-in boat this test was first made
// with weighed (250 kg/m^3 over its 11.8 m^3), so the wake's source is as
// strong; its centre of mass is the one that trims it level at its design
// waterline (docs/SCENE.md).
swell::Scene wakeScene()
{
    swell::Scene scene = swell::defaultScene();
    scene.showTerrain = false;
    swell::SceneObject boat;
    boat.path = "builtin:boat";
    boat.yaw_deg = 90.0; // bow towards -z
    boat.floats = true;
    boat.mass_kg = 2950.0;
    boat.centerOfMassOffset_m = {-0.598, -0.203, 0.0};
    boat.velocity_m_per_s = {0.0, 0.0, -4.0};
    scene.objects = {boat};
    scene.camera.position_m = {0.0, 60.0, -60.0};
    scene.camera.yaw_deg = 0.0;
    scene.camera.pitch_deg = -89.0;
    return scene;
}

struct Rendered {
    swell::Image image;
    glm::dvec3 boat_m{0.0};
};

Rendered render(const swell::Scene& scene, unsigned omittedWaterTerms = 0)
{
    const std::unique_ptr<swell::Renderer> created = swell::RendererTesting::create(scene, {}, omittedWaterTerms);
    swell::Renderer& renderer = *created;
    renderer.setWaveModel(std::make_shared<swell::FlatModel>());
    const swell::Camera camera = swell::cameraAt(scene.camera, kWakeRenderTime_s);
    Rendered r;
    r.image = renderer.renderImage(camera, kWakeRenderTime_s, kWakeRenderSize);
    r.boat_m = glm::dvec3(renderer.objectTransforms()[0][3]);
    return r;
}

TEST_F(WakeRender, TheWakeIsKelvinsWedgeAsternOfTheBoat)
{
    swell::Scene scene = wakeScene();
    const Rendered with = render(scene);
    const Rendered again = render(scene);
    EXPECT_EQ(swell::compareImages(with.image, again.image).maxChannel, 0);
    const Rendered wavesOnly = render(scene, SWELL_TERM_FOAM);
    scene.wake.enabled = false;
    const Rendered without = render(scene);
    const Rendered withoutWavesOnly = render(scene, SWELL_TERM_FOAM);
    // The boat rides its own wake a little (it trims), but it is where it was carried.
    ASSERT_NEAR(with.boat_m.z, without.boat_m.z, 0.1);

    const swell::Camera camera = swell::cameraAt(scene.camera, kWakeRenderTime_s);
    const double outer = std::tan(glm::radians(25.0)), inner = std::tan(glm::radians(10.0));
    auto differs = [](const swell::Image& a, const swell::Image& b, std::size_t i) {
        int d = 0;
        for (int c = 0; c < 3; ++c)
            d = std::max(d, std::abs(int(a.rgba[i + c]) - int(b.rgba[i + c])));
        return d >= 2; // the renders differ by the wake alone: 2 steps of 8 bits is a change seen
    };
    int changed = 0, astern = 0, inWedge = 0, ahead = 0, wavesAstern = 0, onArms = 0;
    for (int y = 0; y < kWakeRenderSize.y; ++y)
        for (int x = 0; x < kWakeRenderSize.x; ++x) {
            const std::size_t i = (std::size_t(y) * kWakeRenderSize.x + std::size_t(x)) * 4;
            const glm::dvec3 ray = swell::test::pixelRay(camera, kWakeRenderSize, x, y);
            const glm::dvec3 water = camera.position_m + ray * (-camera.position_m.y / ray.y);
            const double behind_m = water.z - with.boat_m.z, across_m = std::abs(water.x - with.boat_m.x);
            if (behind_m > 10.0 && differs(wavesOnly.image, withoutWavesOnly.image, i)) {
                ++wavesAstern;
                onArms += across_m > behind_m * inner + 4.0 && across_m < behind_m * outer;
            }
            if (!differs(with.image, without.image, i))
                continue;
            ++changed;
            if (behind_m < -10.0)
                ++ahead; // more than a hull length ahead of the boat's centre
            if (behind_m > 10.0) {
                ++astern;
                inWedge += across_m < behind_m * outer + 4.0;
            }
        }
    const std::string saved = swell::test::saveTestImage(with.image, "wake_render_with") + " vs " +
                              swell::test::saveTestImage(without.image, "wake_render_without");
    RecordProperty("changed", changed);
    RecordProperty("astern", astern);
    RecordProperty("in_wedge", inWedge);
    RecordProperty("waves_astern", wavesAstern);
    RecordProperty("on_arms", onArms);
    RecordProperty("ahead", ahead);
    std::printf("changed %d, astern %d, in the wedge %d, ahead %d; the waves alone astern %d, on the arms %d\n", changed,
                astern, inWedge, ahead, wavesAstern, onArms);
    // The wake covers a good part of the water astern in view...
    EXPECT_GT(changed, kWakeRenderSize.x * kWakeRenderSize.y / 50) << saved;
    // ...nearly all of it inside the wedge, almost none ahead of the bow...
    EXPECT_GT(inWedge, astern * 9 / 10) << saved;
    EXPECT_LT(ahead, changed / 20) << saved;
    // ...and it is a V: its arms, off the stern's trail, are drawn.
    EXPECT_GT(onArms, wavesAstern / 5) << saved;
}

} // namespace
