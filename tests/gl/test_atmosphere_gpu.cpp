// The physical sky's multiple-scattering lookups in GLSL (shaders/atmosphere.glsl)
// against their C++ twins (swell/scene/atmosphere.h), on the tables as the
// renderer uploads them (render/sky_cubemap.h): Psi_ms, and the air's
// order-2 part that depends on the view's direction. The baked sky's test
// (tests/golden/test_sky_physical.cpp) sees the order-2 part only through a
// few levels of 8-bit colour; this one sees it value by value.
#include "render/sky_cubemap.h"
#include "support/gl_test.h"
#include "support/shader_probe.h"
#include "swell/constants.h"
#include "swell/gl/handle.h"
#include "swell/gpu/bindings.h"
#include "swell/scene/atmosphere.h"

#include <glm/vec4.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <random>
#include <vector>

namespace {

class AtmosphereGpu : public swell::test::GlTest {};

const char* const kAtmosphereGpuProbe = R"(
#include "atmosphere.glsl"
layout(local_size_x = 64) in;
// Each: altitude (m), the sun's zenith cosine, the view's, the cosine between them.
layout(std430, binding = 0) readonly buffer Points { vec4 points[]; };
layout(std430, binding = 1) buffer Results { vec4 results[]; };
void main()
{
    uint i = gl_GlobalInvocationID.x;
    vec4 p = points[i];
    results[2u * i] = vec4(atmosphereMultipleScatteringAt(p.x, p.y), 0.0);
    results[2u * i + 1u] = vec4(atmosphereRayleighOrder2At(p.x, p.y, p.z, p.w), 0.0);
}
)";

// 64^2 points in the air: altitudes to 60 km, the sun from 10 degrees below
// the horizon to the zenith, views all round.
std::vector<glm::vec4> points()
{
    std::mt19937 rng(11);
    std::uniform_real_distribution<double> u(0.0, 1.0);
    std::vector<glm::vec4> p(64 * 64);
    for (glm::vec4& v : p) {
        const double altitude = 60000.0 * u(rng) * u(rng);
        const double muSun = -0.17 + 1.17 * u(rng), muView = 2.0 * u(rng) - 1.0;
        const double azimuth = 6.283185307 * u(rng);
        const double cosAngle =
            muSun * muView + std::sqrt(1.0 - muSun * muSun) * std::sqrt(1.0 - muView * muView) * std::cos(azimuth);
        v = glm::vec4(float(altitude), float(muSun), float(muView), float(cosAngle));
    }
    return p;
}

// Tolerance: the GPU filters the tables with fixed-point weights (8 bits
// on common hardware) and computes in float; both stay far below 0.5% of
// the largest Psi_ms (measured on llvmpipe: 4.1e-7 of it for Psi_ms and
// 3.4e-8 for the order-2 part). The order-2 part reaches 9% of the largest
// Psi_ms (6% in air four times as thick): leaving it out is off by that
// much, and its first and third layers read the other way round by 3.6e-2
// (measured).
TEST_F(AtmosphereGpu, MultipleScatteringLookupsAreTheCppModels)
{
    for (const double rayleighScale : {1.0, 4.0}) {
        swell::AtmosphereSettings settings;
        settings.rayleighScale = rayleighScale;
        const swell::Atmosphere atmosphere(settings);
        swell::detail::AtmosphereTextures textures;
        textures.upload(atmosphere);
        textures.bind();

        const std::vector<glm::vec4> in = points();
        const swell::gl::Program program = swell::test::buildShaderProbe(kAtmosphereGpuProbe);
        glProgramUniform1f(program.id(), glGetUniformLocation(program.id(), "atmosphereMieScale"), 1.0f);
        glProgramUniform1f(program.id(), glGetUniformLocation(program.id(), "atmosphereRayleighScale"), float(rayleighScale));
        const std::vector<glm::vec4> out =
            swell::test::runShaderProbe<glm::vec4, glm::vec4>(program, in, 2 * in.size(), GLuint(in.size() / 64));
        glBindTextureUnit(SWELL_UNIT_SKY_TRANSMITTANCE, 0);
        glBindTextureUnit(SWELL_UNIT_SKY_MULTISCATTER, 0);

        double largest = 0.0, worstPsi = 0.0, worstOrder2 = 0.0, largestOrder2 = 0.0;
        for (size_t i = 0; i < in.size(); ++i) {
            const double r = swell::kAtmosphereBottomRadius_m + double(in[i].x);
            const glm::dvec3 psi = atmosphere.multipleScattering(r, in[i].y);
            const glm::dvec3 order2 = atmosphere.rayleighMultipleScatteringOrder2(r, in[i].y, in[i].z, in[i].w);
            for (int c = 0; c < 3; ++c) {
                largest = std::max(largest, std::abs(psi[c]));
                largestOrder2 = std::max(largestOrder2, std::abs(order2[c]));
                worstPsi = std::max(worstPsi, std::abs(double(out[2 * i][c]) - psi[c]));
                worstOrder2 = std::max(worstOrder2, std::abs(double(out[2 * i + 1][c]) - order2[c]));
            }
        }
        std::printf("air x%.0f: largest Psi_ms %.3e, order-2 part up to %.3e; worst differences %.2e and %.2e of the "
                    "largest Psi_ms\n",
                    rayleighScale, largest, largestOrder2, worstPsi / largest, worstOrder2 / largest);
        EXPECT_GT(largestOrder2, 0.03 * largest) << "the order-2 part is too small to test";
        EXPECT_LT(worstPsi, 0.005 * largest);
        EXPECT_LT(worstOrder2, 0.005 * largest);
    }
}

} // namespace
