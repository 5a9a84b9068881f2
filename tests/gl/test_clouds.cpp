// The cloud layer's GLSL twin (shaders/clouds.glsl) against the C++ model
// (swell/scene/clouds.h): the same optical depth and the same transmittance
// along every direction, the one that shades the sun in the frame; and the
// frame's sunlight and ambient light under the layer (render/sky_light.h);
// the layer's shadow map (render/cloud_shadow_map.h) and its look-up
// (shaders/cloud_shadow.glsl) against the C++ model's transmittance along
// the sun's ray from a point (cloudShadowTransmittance).
#include "render/cloud_shadow_map.h"
#include "render/gpu/blocks.h"
#include "render/programs.h"
#include "render/sky_light.h"
#include "support/gl_test.h"
#include "support/shader_probe.h"
#include "swell/gl/handle.h"
#include "swell/gl/shader.h"
#include "swell/gl/shader_sources.h"
#include "swell/gpu/bindings.h"
#include "swell/gpu/sky.h"
#include "swell/scene/clouds.h"

#include <glm/geometric.hpp>
#include <glm/vec4.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <random>
#include <vector>

namespace {

class CloudsGpu : public swell::test::GlTest {};

const char* const kCloudsProbe = R"(
#include "clouds.glsl"
layout(local_size_x = 64) in;
layout(std430, binding = 0) readonly buffer Directions { vec4 directions[]; };
layout(std430, binding = 1) buffer Results { vec4 results[]; };
void main()
{
    uint i = gl_GlobalInvocationID.x;
    vec3 d = directions[i].xyz;
    CloudHit hit = cloudHit(d);
    results[i] = vec4(cloudTransmittance(d), cloudOpticalDepthAt(hit.xz_m, hit.footprint_m), hit.distance_m,
                      hit.footprint_m);
}
)";

// For each direction: transmittance, optical depth, distance, footprint.
std::vector<glm::vec4> gpuLayer(const swell::CloudSettings& clouds, const std::vector<glm::vec4>& directions)
{
    const swell::gl::Program program = swell::test::buildShaderProbe(kCloudsProbe);
    auto uniform = [&](const char* name, double v) {
        glProgramUniform1f(program.id(), glGetUniformLocation(program.id(), name), float(v));
    };
    uniform("cloudCover", clouds.cover);
    uniform("cloudAltitude_m", clouds.altitude_m);
    uniform("cloudOpticalDepth", clouds.opticalDepth);
    uniform("cloudScale_m", clouds.scale_m);
    return swell::test::runShaderProbe<glm::vec4, glm::vec4>(program, directions, directions.size(),
                                                              GLuint(directions.size() / 64));
}

// 64^2 directions all over the sky (uniform in solid angle above the
// horizon), a few below it.
std::vector<glm::vec4> skyDirections()
{
    std::mt19937 rng(3);
    std::uniform_real_distribution<float> u(0.0f, 1.0f);
    std::vector<glm::vec4> d(64 * 64);
    for (glm::vec4& v : d) {
        const float y = u(rng) * 1.05f - 0.05f, phi = 6.2831853f * u(rng);
        const float s = std::sqrt(std::max(1.0f - y * y, 0.0f));
        v = glm::vec4(s * std::cos(phi), y, s * std::sin(phi), 0.0f);
    }
    return d;
}

// The GPU's layer is the C++ one: where the ray meets it, its optical
// depth and its transmittance, direction by direction. Tolerances: float
// arithmetic differs between the two only in rounding and in exp/log/sqrt's
// last bits (measured on llvmpipe: transmittance within 1.3e-5, optical
// depth 3.3e-4, distance 3.4e-7 relative), far below what a changed octave,
// constant or formula on one side brings (tenths).
TEST_F(CloudsGpu, LayerAgreesWithCpp)
{
    for (const double cover : {0.3, 0.7, 1.0}) {
        swell::CloudSettings clouds;
        clouds.cover = cover;
        clouds.scale_m = 1200.0;
        clouds.opticalDepth = 15.0;
        const std::vector<glm::vec4> directions = skyDirections();
        const std::vector<glm::vec4> gpu = gpuLayer(clouds, directions);
        double worstT = 0.0, worstTau = 0.0, worstDistance = 0.0;
        for (size_t i = 0; i < directions.size(); ++i) {
            const glm::vec3 d(directions[i]);
            const swell::CloudHit hit = swell::cloudHit(clouds, d);
            worstT = std::max(worstT, double(std::abs(gpu[i].x - swell::cloudTransmittance(clouds, d))));
            worstTau = std::max(worstTau, double(std::abs(gpu[i].y - swell::cloudOpticalDepth(clouds, hit.xz_m, hit.footprint_m))));
            worstDistance = std::max(worstDistance, double(std::abs(gpu[i].z - hit.distance_m) / hit.distance_m));
        }
        std::printf("cover %.1f: worst differences: transmittance %.2e, optical depth %.2e, distance %.2e (relative)\n",
                    cover, worstT, worstTau, worstDistance);
        EXPECT_LT(worstT, 2.0e-4);
        EXPECT_LT(worstTau, 0.005);
        EXPECT_LT(worstDistance, 1.0e-5);
    }
}

swell::Scene physicalScene(glm::dvec3 sun, const swell::CloudSettings& clouds)
{
    swell::Scene scene = swell::defaultScene();
    scene.sky.model = swell::SkyModel::Physical;
    scene.sun.direction = sun;
    scene.sky.clouds = clouds;
    return scene;
}

// The sun's light in the frame is the clear sky's times the layer's
// transmittance towards the sun (the model the GPU agrees with above): an
// overcast deck hides it, a gap lets it through whole; and the ambient
// light is the clouded sky's: under the deck, grey where the clear sky's is blue.
TEST(CloudLight, LayerShadesTheSunAndGreysTheAmbient)
{
    const glm::dvec3 sun = glm::normalize(glm::dvec3(0.3, 0.7, -0.6));
    const auto atmosphere = swell::detail::atmosphereFor(swell::AtmosphereSettings{});
    const swell::detail::SkyLight clear = swell::detail::skyLightOf(physicalScene(sun, {}), atmosphere.get());
    swell::CloudSettings deck;
    deck.cover = 1.0;
    deck.opticalDepth = 40.0;
    const swell::detail::SkyLight overcast = swell::detail::skyLightOf(physicalScene(sun, deck), atmosphere.get());
    const double t = swell::cloudTransmittance(deck, glm::vec3(sun));
    std::printf("deck: transmittance towards the sun %.3e; sun intensity %.4f -> %.3e; ambient (%.4f %.4f %.4f) -> (%.4f %.4f %.4f)\n",
                t, clear.sunIntensity, overcast.sunIntensity, clear.ambientSh[0].r, clear.ambientSh[0].g,
                clear.ambientSh[0].b, overcast.ambientSh[0].r, overcast.ambientSh[0].g, overcast.ambientSh[0].b);
    EXPECT_NEAR(overcast.sunIntensity, clear.sunIntensity * t, 1.0e-9 * clear.sunIntensity);
    EXPECT_LT(t, 1.0e-6);
    const glm::dvec3 a = clear.ambientSh[0], b = overcast.ambientSh[0];
    EXPECT_LT(b.b / b.r, 0.7 * (a.b / a.r));
    EXPECT_NE(overcast.zenith, clear.zenith);
    // Scattered clouds: the sun through a gap is the clear sky's, behind a
    // cloud it is dimmed; find one of each round the sky.
    swell::CloudSettings scattered;
    scattered.cover = 0.5;
    scattered.scale_m = 800.0;
    bool sawGap = false, sawCloud = false;
    for (int k = 0; k < 64 && !(sawGap && sawCloud); ++k) {
        const double phi = 0.3 * k;
        const glm::dvec3 s = glm::normalize(glm::dvec3(std::cos(phi), 0.8, std::sin(phi)));
        const double ts = swell::cloudTransmittance(scattered, glm::vec3(s));
        const swell::detail::SkyLight c = swell::detail::skyLightOf(physicalScene(s, {}), atmosphere.get());
        const swell::detail::SkyLight l = swell::detail::skyLightOf(physicalScene(s, scattered), atmosphere.get());
        EXPECT_NEAR(l.sunIntensity, c.sunIntensity * ts, 1.0e-9 * c.sunIntensity);
        sawGap = sawGap || ts > 0.99;
        sawCloud = sawCloud || ts < 0.01;
    }
    EXPECT_TRUE(sawGap && sawCloud);
}

// The scattered layer the shadow tests bake, the sun 40 degrees up, and a
// render origin far from the world's origin (the map follows the camera;
// its texels are anchored in the world).
swell::CloudSettings shadowLayer()
{
    swell::CloudSettings clouds;
    clouds.cover = 0.5;
    clouds.scale_m = 1500.0;
    clouds.opticalDepth = 20.0;
    clouds.altitude_m = 1500.0;
    return clouds;
}
const glm::vec3 kShadowSun = glm::normalize(glm::vec3(0.45f, 0.643f, -0.62f));
const glm::dvec3 kShadowOrigin(3217.0, 0.0, -1289.0);

// The map baked as the frame bakes it (its texels' values and where they lie).
struct BakedShadowMap {
    swell::detail::CloudShadowMap map;
    std::vector<float> texels;
};

void bakeShadowMap(BakedShadowMap& baked, const swell::CloudSettings& clouds)
{
    const swell::gl::ShaderSources sources = swell::gl::ShaderSources::embedded();
    const swell::detail::CloudShadowBakeProgram program(sources);
    const swell::gl::VertexArray vao = swell::gl::VertexArray::create();
    EXPECT_TRUE(baked.map.update(program, vao.id(), clouds, kShadowSun, kShadowOrigin, 1.0f));
    // The same again: nothing to bake.
    EXPECT_FALSE(baked.map.update(program, vao.id(), clouds, kShadowSun, kShadowOrigin, 1.0f));
    baked.texels.resize(size_t(SWELL_CLOUD_SHADOW_SIZE) * SWELL_CLOUD_SHADOW_SIZE);
    glGetTextureImage(baked.map.texture(), 0, GL_RED, GL_FLOAT, GLsizei(baked.texels.size() * sizeof(float)),
                      baked.texels.data());
    glUseProgram(0);
}

// The baked map is the C++ model: each texel holds the layer's
// transmittance along the sun's ray from the texel's centre on the mean
// level (filtered to the texel), within float rounding (measured on
// llvmpipe: see the printed worst), far below a moved crossing point or
// a wrong altitude's change (tenths: the sampled texels cross clouds'
// edges). The map holds both shadow and sun.
TEST_F(CloudsGpu, ShadowMapAgreesWithCpp)
{
    const swell::CloudSettings clouds = shadowLayer();
    BakedShadowMap baked;
    bakeShadowMap(baked, clouds);
    const glm::dvec2 corner = baked.map.bakedCorner_m();
    const float texel = float(swell::detail::kCloudShadowTexel_m);
    // Centred on the origin's texel.
    EXPECT_LE(std::abs(corner.x + 0.5 * swell::detail::kCloudShadowTexel_m * SWELL_CLOUD_SHADOW_SIZE - kShadowOrigin.x),
              swell::detail::kCloudShadowTexel_m);
    double worst = 0.0;
    int shade = 0, sun = 0, n = 0;
    for (int j = 0; j < SWELL_CLOUD_SHADOW_SIZE; j += 5)
        for (int i = 0; i < SWELL_CLOUD_SHADOW_SIZE; i += 5) {
            // The texel's centre as the bake computes it, in float.
            const glm::vec2 xz = glm::vec2(corner) + (glm::vec2(float(i), float(j)) + 0.5f) * texel;
            const float expected = swell::cloudShadowTransmittance(clouds, glm::vec3(xz.x, 0.0f, xz.y), kShadowSun, texel);
            const float got = baked.texels[size_t(j) * SWELL_CLOUD_SHADOW_SIZE + size_t(i)];
            worst = std::max(worst, double(std::abs(got - expected)));
            shade += expected < 0.05f;
            sun += expected > 0.95f;
            ++n;
        }
    std::printf("%d texels: worst difference %.2e; %d in shadow, %d in sun\n", n, worst, shade, sun);
    EXPECT_LT(worst, 2.0e-4);
    EXPECT_GT(shade, n / 5);
    EXPECT_GT(sun, n / 5);
}

const char* const kShadowProbe = R"(
#include "cloud_shadow.glsl"
layout(local_size_x = 64) in;
layout(std430, binding = 0) readonly buffer Points { vec4 points[]; };
layout(std430, binding = 1) buffer Results { float results[]; };
void main()
{
    uint i = gl_GlobalInvocationID.x;
    results[i] = cloudShadowAt(points[i].xyz, 0.0);
}
)";

// The look-up (cloud_shadow.glsl) of points at any height, above and
// below the water (relative to the render origin), is the C++ model's
// transmittance along the sun's ray from each point: the points are
// chosen so that their ray meets the mean level at a texel's centre, where
// the map's bilinear filter returns the texel. A look-up at the wrong
// place (the point itself, not where its ray meets the mean level; or
// the observer's) breaks it.
TEST_F(CloudsGpu, ShadowLookupIsTheCppModelAtAnyHeight)
{
    const swell::CloudSettings clouds = shadowLayer();
    BakedShadowMap baked;
    bakeShadowMap(baked, clouds);
    swell::detail::FrameUniforms frame{};
    frame.sunDirection = kShadowSun;
    swell::gl::Buffer frameBuffer = swell::gl::Buffer::create();
    glNamedBufferData(frameBuffer.id(), sizeof(frame), &frame, GL_STATIC_DRAW);
    glBindBufferBase(GL_UNIFORM_BUFFER, SWELL_BINDING_FRAME, frameBuffer.id());
    baked.map.bind();
    const glm::dvec2 corner = baked.map.bakedCorner_m();
    const double texel = swell::detail::kCloudShadowTexel_m;
    std::mt19937 rng(5);
    std::uniform_int_distribution<int> cell(SWELL_CLOUD_SHADOW_SIZE / 8, SWELL_CLOUD_SHADOW_SIZE * 7 / 8);
    std::uniform_real_distribution<double> height(-20.0, 300.0);
    std::vector<glm::vec4> points(64 * 16);
    std::vector<double> expected(points.size());
    for (size_t k = 0; k < points.size(); ++k) {
        const glm::dvec2 centre = corner + (glm::dvec2(cell(rng), cell(rng)) + 0.5) * texel;
        const double y = height(rng);
        // Up the sun's ray from the texel's centre to height y.
        const glm::dvec2 xz = centre + glm::dvec2(kShadowSun.x, kShadowSun.z) * (y / double(kShadowSun.y));
        points[k] = glm::vec4(float(xz.x - kShadowOrigin.x), float(y), float(xz.y - kShadowOrigin.z), 0.0f);
        expected[k] = swell::cloudShadowTransmittance(clouds, glm::vec3(glm::dvec3(xz.x, y, xz.y)), kShadowSun,
                                                     float(texel));
    }
    const swell::gl::Program program = swell::test::buildShaderProbe(kShadowProbe, {"SWELL_CLOUD_SHADOWS 1"});
    const std::vector<float> got =
        swell::test::runShaderProbe<glm::vec4, float>(program, points, points.size(), GLuint(points.size() / 64));
    glBindBufferBase(GL_UNIFORM_BUFFER, SWELL_BINDING_FRAME, 0);
    glBindBufferBase(GL_UNIFORM_BUFFER, SWELL_BINDING_CLOUD_SHADOW, 0);
    glBindTextureUnit(SWELL_UNIT_CLOUD_SHADOW, 0);
    double worst = 0.0;
    int shade = 0;
    for (size_t k = 0; k < got.size(); ++k) {
        worst = std::max(worst, std::abs(double(got[k]) - expected[k]));
        shade += expected[k] < 0.05;
    }
    // The points' float coordinates move their ray's crossing by under a
    // millimetre: the bilinear filter's share of the next texel stays tiny
    // (measured on llvmpipe: see the printed worst).
    std::printf("%zu points: worst difference %.2e, %d in shadow\n", got.size(), worst, shade);
    EXPECT_LT(worst, 2.0e-3);
    EXPECT_GT(shade, int(got.size()) / 5);
}

} // namespace
