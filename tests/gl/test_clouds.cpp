// The cloud layer's GLSL twin (shaders/clouds.glsl) against the C++ model
// (swell/clouds.h): the same optical depth and the same transmittance
// along every direction, the one that shades the sun in the frame; and the
// frame's sunlight and ambient light under the layer (render/sky_light.h).
#include "render/sky_light.h"
#include "support/gl_test.h"
#include "support/shader_probe.h"
#include "swell/clouds.h"
#include "swell/gl/handle.h"
#include "swell/gl/shader.h"

#include <glm/geometric.hpp>
#include <glm/vec4.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <random>
#include <vector>

namespace {

class CloudsGpu : public swell::test::GlTest {};

const char* const kProbe = R"(
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
    const swell::gl::Program program = swell::test::buildShaderProbe(kProbe);
    auto uniform = [&](const char* name, double v) {
        glProgramUniform1f(program.id(), glGetUniformLocation(program.id(), name), float(v));
    };
    uniform("cloudCover", clouds.cover);
    uniform("cloudAltitude_m", clouds.altitude_m);
    uniform("cloudOpticalDepth", clouds.opticalDepth);
    uniform("cloudScale_m", clouds.scale_m);
    const GLsizeiptr bytes = GLsizeiptr(directions.size() * sizeof(glm::vec4));
    swell::gl::Buffer in = swell::gl::Buffer::create(), out = swell::gl::Buffer::create();
    glNamedBufferData(in.id(), bytes, directions.data(), GL_STATIC_DRAW);
    glNamedBufferData(out.id(), bytes, nullptr, GL_DYNAMIC_READ);
    glUseProgram(program.id());
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 0, in.id());
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 1, out.id());
    glDispatchCompute(GLuint(directions.size() / 64), 1, 1);
    glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
    std::vector<glm::vec4> results(directions.size());
    glGetNamedBufferSubData(out.id(), 0, bytes, results.data());
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 0, 0);
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 1, 0);
    glUseProgram(0);
    return results;
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

} // namespace
