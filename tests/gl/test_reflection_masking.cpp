// The reflection's masking term: the sea's mean square slope the renderer
// measures, and the GLSL Smith masking function it feeds, each against the
// formula it implements.
#include "render/gpu/blocks.h"
#include "render/slope_statistics.h"
#include "support/gl_test.h"
#include "support/shader_probe.h"
#include "swell/flat_model.h"
#include "swell/gerstner_model.h"
#include "swell/gl/handle.h"
#include "swell/gl/shader.h"
#include "swell/gpu/bindings.h"

#include <epoxy/gl.h>

#include <cmath>
#include <numbers>
#include <vector>

namespace {

class ReflectionMasking : public swell::test::GlTest {};

TEST_F(ReflectionMasking, MeanSquareSlopeOfSineWavesIsHalfTheSumOfTheirSquaredSteepness)
{
    // eta = sum A_i sin(k_i . x + phi_i): |grad eta|^2 averages to
    // sum (k_i A_i)^2 / 2 (each cos^2 averages 1/2, cross terms of waves
    // with different wavenumbers average 0).
    swell::WaveSet set;
    set.waves = {{{1.0, 0.0}, 8.0, 0.2, 0.0, 0.0}, {{0.3, 1.0}, 3.0, 0.04, 0.0, 1.0}};
    double expected = 0.0;
    for (const swell::Wave& w : set.waves)
        expected += 0.5 * std::pow(2.0 * std::numbers::pi / w.wavelength_m * w.amplitude_m, 2.0);
    // 2%: 4096 quasi-random samples of a 2 km square; the estimate's own
    // error is well under 1% here, a mistaken factor (no 1/2, sin for tan) is 50% or more.
    EXPECT_NEAR(swell::detail::meanSquareSlope(swell::GerstnerModel(set)), expected, 0.02 * expected);
    EXPECT_EQ(swell::detail::meanSquareSlope(swell::FlatModel()), 0.0);
}

// Smith's Lambda for a Gaussian surface, in double with the C library's erfc.
double smithLambda(double nu)
{
    return 0.5 * (std::exp(-nu * nu) / (nu * std::sqrt(std::numbers::pi)) - std::erfc(nu));
}

TEST_F(ReflectionMasking, TheShaderMasksLowRaysAsSmithsFunctionSays)
{
    const swell::gl::Program program = swell::test::buildShaderProbe(R"(#include "reflection.glsl"
layout(local_size_x = 1) in;
layout(std430, binding = 0) buffer Shares { float share[]; };
void main()
{
    float elevation_rad = radians(share[gl_GlobalInvocationID.x]);
    share[gl_GlobalInvocationID.x] = unmaskedShare(vec3(cos(elevation_rad), sin(elevation_rad), 0.0));
}
)",
                                                                      {"SWELL_REFLECTION_MODE SWELL_REFLECTION_RAYMARCH",
                                                                       "SWELL_CLOUD_SHADOWS 0"});

    swell::detail::FrameUniforms frame{};
    const double s2 = 0.05; // about a 9 m/s wind (Cox & Munk 1954: 0.003 + 5.12e-3 U)
    frame.waveMeanSquareSlope = float(s2);
    swell::gl::Buffer ubo = swell::gl::Buffer::create();
    glNamedBufferStorage(ubo.id(), sizeof(frame), &frame, 0);
    const std::vector<float> elevations_deg{0.1f, 0.3f, 1.0f, 2.0f, 5.0f, 10.0f, 30.0f};
    swell::gl::Buffer ssbo = swell::gl::Buffer::create();
    glNamedBufferStorage(ssbo.id(), GLsizeiptr(elevations_deg.size() * sizeof(float)), elevations_deg.data(), 0);
    glBindBufferBase(GL_UNIFORM_BUFFER, SWELL_BINDING_FRAME, ubo.id());
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 0, ssbo.id());
    glUseProgram(program.id());
    glDispatchCompute(GLuint(elevations_deg.size()), 1, 1);
    glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
    std::vector<float> shares(elevations_deg.size());
    glGetNamedBufferSubData(ssbo.id(), 0, GLsizeiptr(shares.size() * sizeof(float)), shares.data());
    glUseProgram(0);

    for (size_t i = 0; i < elevations_deg.size(); ++i) {
        const double nu = std::tan(elevations_deg[i] * std::numbers::pi / 180.0) / std::sqrt(s2);
        const double expected = 1.0 / (1.0 + smithLambda(nu));
        // 1e-3: float arithmetic and the erfc approximation (1.5e-7 on its
        // own); dropping the erfc term moves the share by 0.01 to 0.5.
        EXPECT_NEAR(shares[i], expected, 1e-3) << elevations_deg[i] << " degrees up";
    }
    // Nearly every ray 0.1 degrees up meets another wave; nearly none 30 up.
    EXPECT_LT(shares.front(), 0.05);
    EXPECT_GT(shares.back(), 0.99);
}

} // namespace
