// The water-to-air optics of shaders/water_optics.glsl (Snell's window), run on the GPU
// through a compute shader and checked against published figures and
// Fresnel's own reciprocity, not against the code's earlier output.
#include "render/waterline.h"
#include "support/gl_test.h"
#include "support/shader_probe.h"
#include "swell/camera.h"
#include "swell/gl/shader.h"
#include "swell/view.h"

#include <glm/matrix.hpp>
#include <glm/trigonometric.hpp>

#include <cmath>
#include <vector>

namespace {

class UnderwaterOptics : public swell::test::GlTest {};

// For each incidence angle (degrees, from the normal) in the input buffer:
// the shader's reflectance from water into air, from air into water at the
// refracted angle, and the length of GLSL's refracted ray from the water.
const char* const kUnderwaterOpticsProbe = R"(
#include "gpu/constants.glsl"
#include "water_optics.glsl"
layout(local_size_x = 1) in;
layout(std430, binding = 0) buffer Probe { float data[]; };
void main()
{
    uint i = gl_GlobalInvocationID.x;
    float angle = radians(data[4u * i]);
    float cosI = cos(angle);
    float sinT = SWELL_WATER_IOR * sin(angle);
    float cosT = sqrt(max(1.0 - sinT * sinT, 0.0));
    data[4u * i + 1u] = fresnelDielectric(cosI, SWELL_WATER_IOR, 1.0);
    data[4u * i + 2u] = sinT < 1.0 ? fresnelDielectric(cosT, 1.0, SWELL_WATER_IOR) : -1.0;
    vec3 d = vec3(sin(angle), cosI, 0.0); // upwards through a level surface
    data[4u * i + 3u] = length(refract(d, vec3(0.0, -1.0, 0.0), SWELL_WATER_IOR));
}
)";

struct Probe {
    float angle_deg, waterToAir, airToWater, refractedLength;
};

std::vector<Probe> runProbe(const std::vector<float>& angles_deg)
{
    const swell::gl::Program program = swell::test::buildShaderProbe(kUnderwaterOpticsProbe);
    std::vector<Probe> probes;
    for (float a : angles_deg)
        probes.push_back({a, 0.0f, 0.0f, 0.0f});
    swell::gl::Buffer buffer = swell::gl::Buffer::create();
    glNamedBufferData(buffer.id(), GLsizeiptr(probes.size() * sizeof(Probe)), probes.data(), GL_DYNAMIC_READ);
    glUseProgram(program.id());
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 0, buffer.id());
    glDispatchCompute(GLuint(probes.size()), 1, 1);
    glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
    glGetNamedBufferSubData(buffer.id(), 0, GLsizeiptr(probes.size() * sizeof(Probe)), probes.data());
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 0, 0);
    glUseProgram(0);
    return probes;
}

TEST_F(UnderwaterOptics, FresnelAndSnellFromWaterIntoAirMatchPublishedFigures)
{
    const std::vector<Probe> p = runProbe({0.0f, 20.0f, 36.87f, 45.0f, 48.4f, 48.8f, 60.0f, 80.0f});
    // Straight up, water reflects ((n - 1) / (n + 1))^2 = 2.0% (Hecht,
    // "Optics": about 2% for an air-water surface at normal incidence).
    EXPECT_NEAR(p[0].waterToAir, 0.0204, 0.0005);
    // Reciprocity (Stokes relations): an interface reflects the same share
    // of light from either side along one path, water at i, air at t.
    for (int i : {1, 2, 3, 4})
        EXPECT_NEAR(p[size_t(i)].waterToAir, p[size_t(i)].airToWater, 1e-4) << "at " << p[size_t(i)].angle_deg << " deg";
    // Brewster's angle from water, atan(1 / 1.333) = 36.87 degrees: the p
    // wave is not reflected, so the mean reflectance is half the s one,
    // rs^2 / 2 = cos^2(2 * 36.87 deg) / 2 = 3.9%.
    EXPECT_NEAR(p[2].waterToAir, 0.5 * std::pow(std::cos(glm::radians(2.0 * 36.87)), 2.0), 1e-3);
    // The critical angle, asin(1 / 1.333) = 48.6 degrees: just inside it
    // light still leaves the water, just beyond it all is reflected.
    EXPECT_LT(p[4].waterToAir, 1.0f);
    EXPECT_GT(p[4].refractedLength, 0.5f);
    for (int i : {5, 6, 7}) {
        EXPECT_EQ(p[size_t(i)].waterToAir, 1.0f) << "at " << p[size_t(i)].angle_deg << " deg";
        EXPECT_EQ(p[size_t(i)].refractedLength, 0.0f) << "at " << p[size_t(i)].angle_deg << " deg";
    }
    // Reflectance rises monotonically towards the critical angle.
    for (int i : {1, 2, 3, 4})
        EXPECT_GT(p[size_t(i)].waterToAir, p[size_t(i) - 1].waterToAir);
}

// Which side of the water the near plane lies on: per pixel whenever any of
// its rectangle may be within the waves' reach, never a single switch there.
// The rectangle is the view's own (any roll or tilt), from its inverse
// view-projection.
TEST(WaterlineMedium, NearPlaneWithinTheWavesReachIsDecidedPerPixel)
{
    using swell::detail::NearPlaneMedium;
    using swell::detail::nearPlaneCorners;
    using swell::detail::nearPlaneMedium;
    swell::Camera camera;
    camera.near_m = 0.1;
    camera.fovY_deg = 60.0;
    const glm::ivec2 size(1600, 900);
    auto medium = [&](double eyeY, const swell::WaveReach& reach) {
        camera.position_m.y = eyeY;
        const swell::View view = swell::viewOf(camera, size);
        return nearPlaneMedium(nearPlaneCorners(glm::inverse(view.projection * view.view), -1.0), reach);
    };
    const swell::WaveReach calm{0.0, 0.0}, swell1m{1.0, 0.5};
    // Level: the rectangle's top and bottom edges lie 0.1 * tan(30 deg) = 0.0577 m above and below the eye.
    EXPECT_EQ(medium(0.057, calm), NearPlaneMedium::Both) << "its bottom edge dips under still water";
    EXPECT_EQ(medium(0.058, calm), NearPlaneMedium::Air);
    EXPECT_EQ(medium(-0.057, calm), NearPlaneMedium::Both);
    EXPECT_EQ(medium(-0.058, calm), NearPlaneMedium::Water);
    // Waves 1 m high: anywhere within 1.0577 m of the mean level is decided per pixel.
    for (double y : {-1.057, -0.5, 0.0, 0.5, 1.057})
        EXPECT_EQ(medium(y, swell1m), NearPlaneMedium::Both) << "eye at " << y << " m";
    EXPECT_EQ(medium(1.058, swell1m), NearPlaneMedium::Air);
    EXPECT_EQ(medium(-1.058, swell1m), NearPlaneMedium::Water);
    // Rolled 90 degrees, the rectangle's long side stands upright: its
    // corners reach 0.1 * tan(30 deg) * 16/9 = 0.1026 m above and below.
    camera.roll_deg = 90.0;
    EXPECT_EQ(medium(0.102, calm), NearPlaneMedium::Both);
    EXPECT_EQ(medium(0.103, calm), NearPlaneMedium::Air);
    // Looking straight down, the whole rectangle lies 0.1 m below the eye.
    camera.roll_deg = 0.0;
    camera.pitch_deg = -89.9;
    EXPECT_EQ(medium(0.099, calm), NearPlaneMedium::Water);
    EXPECT_EQ(medium(0.1, calm), NearPlaneMedium::Both);
    EXPECT_EQ(medium(0.101, calm), NearPlaneMedium::Air);
}

} // namespace
