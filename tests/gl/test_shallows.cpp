// The bottom seen through shallow water (shaders/refraction.glsl with the
// floor's shading under the water, mesh.frag): under flat water over a
// sand shelf seen from straight above, the radiance coming up through the
// surface follows the shallow-water reflectance model of Lee et al. (1998,
// Appl. Opt. 37(27), 6329-6338): the floor's albedo times the daylight on
// it, attenuated on the way down and up, exp(-2 a H), plus the deep
// water's colour for the rest, 1 - exp(-2 a H). The model is computed here
// from the scene's own numbers (the water's absorption and deep colour, the
// sky's light, the floor's albedo), not from an earlier picture; at depth
// the water shows its deep colour alone.
#include "assets/seabed_mesh.h"
#include "render/sky_light.h"
#include "support/gl_test.h"
#include "swell/camera.h"
#include "swell/flat_model.h"
#include "swell/renderer.h"
#include "swell/scene/atmosphere.h"
#include "swell/scene/seabed.h"

#include <glm/geometric.hpp>

#include <cmath>

namespace {

using namespace swell;

class Shallows : public test::GlTest {};

constexpr glm::ivec2 kShallowsSize{64, 64};
constexpr double kCameraHeight_m = 12.0;

// A level sand shelf depth_m down under the camera, which looks straight
// down at it (as nearly as the camera allows) through flat water, the sun
// at the zenith: every leg of the light's path is vertical. Caustics off
// (flat water focuses nothing: the level transmittance everywhere), the
// sea's own reflection off.
Scene shelfScene(double depth_m)
{
    Scene scene = defaultScene();
    scene.objects.clear();
    scene.showTerrain = false;
    scene.sky.model = SkyModel::Gradient;
    scene.sun.direction = {0.0, 1.0, 0.0};
    scene.sun.place.reset();
    scene.sun.angles.reset();
    scene.water.caustics = false;
    scene.water.shafts = false;
    scene.antialiasing = Antialiasing::Off;
    // The light from below the surface alone, as the frame shades it (the
    // refraction debug view leaves out the light's way down): the surface
    // reflects nothing straight down (F0 = 0), and no highlight.
    scene.water.fresnelF0 = 0.0;
    scene.water.specularStrength = 0.0;
    scene.seabed.toeDepth_m = 200.0;
    scene.seabed.shelves.push_back(SeabedShelf{.edgePoint_m = {0.0, -300.0}, .seawardAzimuth_deg = 0.0,
                                               .depth_m = depth_m, .slope = 0.05, .width_m = 600.0, .length_m = 600.0});
    scene.camera.position_m = {0.0, kCameraHeight_m, 0.0};
    scene.camera.pitch_deg = -89.0;
    scene.camera.yaw_deg = 0.0;
    scene.camera.path.clear();
    return scene;
}

double srgbToLinear(double v)
{
    return v <= 0.04045 ? v / 12.92 : std::pow((v + 0.055) / 1.055, 2.4);
}

// The mean linear colour of the frame's middle 16 x 16 pixels.
glm::dvec3 middleColor(const Image& image)
{
    glm::dvec3 sum(0.0);
    int count = 0;
    for (int y = image.height / 2 - 8; y < image.height / 2 + 8; ++y)
        for (int x = image.width / 2 - 8; x < image.width / 2 + 8; ++x) {
            const std::uint8_t* p = image.pixel(x, y);
            sum += glm::dvec3(srgbToLinear(p[0] / 255.0), srgbToLinear(p[1] / 255.0), srgbToLinear(p[2] / 255.0));
            ++count;
        }
    return sum / double(count);
}

glm::dvec3 renderedThroughWater(double depth_m)
{
    const Scene scene = shelfScene(depth_m);
    Renderer renderer(scene);
    renderer.setWaveModel(std::make_shared<FlatModel>());
    return middleColor(renderer.renderImage(cameraAt(scene.camera, 0.0), 0.0, kShallowsSize));
}

// The floor's albedo where the camera looks: the drawn mesh's colour at the
// shelf's top.
glm::dvec3 floorAlbedo(const Scene& scene, double depth_m)
{
    const detail::SeabedMesh mesh = detail::makeSeabedMesh(Seabed(scene));
    for (const detail::MeshVertex& v : mesh.mesh.vertices)
        if (std::abs(double(v.position.y) + depth_m) < 1e-3)
            return glm::dvec3(v.color);
    ADD_FAILURE() << "no vertex of the shelf's top at depth " << depth_m;
    return glm::dvec3(0.0);
}

// Lee et al.'s model from the scene's numbers: the daylight on a level
// floor just under the surface (the sky's irradiance on an upward face, as
// mesh.frag takes it, plus the sun's at the zenith less what a level
// surface reflects: Fresnel at normal incidence, ((n - 1) / (n + 1))^2),
// times the floor's albedo, attenuated by exp(-a H) down and again up, and
// the deep colour for the rest.
glm::dvec3 leeModel(double depth_m)
{
    const Scene scene = shelfScene(depth_m);
    const detail::SkyLight sky = detail::skyLightOf(scene, nullptr);
    const std::array<double, 9> harmonics = shHarmonics({0.0, 1.0, 0.0});
    glm::dvec3 skyIrradiance(0.0);
    for (std::size_t i = 0; i < harmonics.size(); ++i)
        skyIrradiance += sky.ambientSh[i] * harmonics[i];
    const double ior = 1.333, reflected = std::pow((ior - 1.0) / (ior + 1.0), 2.0);
    const glm::dvec3 sun = sky.sunColor * sky.sunIntensity * (1.0 - reflected);
    const glm::dvec3 a = scene.water.absorption_per_m;
    const glm::dvec3 bothWays = glm::exp(-2.0 * a * depth_m);
    const glm::dvec3 bottom = floorAlbedo(scene, depth_m) * (skyIrradiance + sun);
    return bottom * bothWays + scene.water.deepColor * (1.0 - bothWays);
}

// Within 5% of the model per channel, or within one 8-bit step of the
// sRGB-encoded picture where the channel is so dark that a step is more
// than 5% of it (the deep water's red, about 0.01 linear: a step there is 3%).
void expectNear(glm::dvec3 rendered, glm::dvec3 model, const char* what, double depth_m)
{
    for (int c = 0; c < 3; ++c) {
        const double step = srgbToLinear(std::min(1.0, std::pow(model[c], 1.0 / 2.4) * 1.055 - 0.055 + 1.0 / 255.0)) - model[c];
        EXPECT_NEAR(rendered[c], model[c], std::max(0.05 * model[c], std::abs(step)))
            << what << " at depth " << depth_m << " m, channel " << c;
    }
}

TEST_F(Shallows, TheBottomShowsThroughTheWaterAsLeeEtAlsModelSays)
{
    for (double depth_m : {1.5, 4.0, 9.0}) {
        const glm::dvec3 rendered = renderedThroughWater(depth_m);
        const glm::dvec3 model = leeModel(depth_m);
        expectNear(rendered, model, "the shallows", depth_m);
    }
}

TEST_F(Shallows, DeeperWaterTendsToTheDeepColour)
{
    const glm::dvec3 deep = defaultScene().water.deepColor;
    double previous = 1e9;
    for (double depth_m : {3.0, 12.0, 40.0, 120.0}) {
        const glm::dvec3 rendered = renderedThroughWater(depth_m);
        const double off = glm::length(rendered - deep);
        EXPECT_LT(off, previous) << "depth " << depth_m;
        previous = off;
        if (depth_m >= 120.0)
            expectNear(rendered, deep, "deep water", depth_m);
    }
}

} // namespace
