// Caustics conserve the sun's light (issue 25): the caustics map
// (render/caustics_map.h) under flat water holds Fresnel's transmittance
// everywhere, a level floor under it receives the direct light times the
// water's transmittance (Fresnel and absorption along the refracted ray),
// and waves move the light about without changing its mean while the
// pattern's contrast grows with their slope.
#include "support/caustics_setup.h"
#include "swell/wave_model.h"
#include "support/fresnel_reference.h"
#include "support/gl_test.h"
#include "swell/constants.h"
#include "swell/flat_model.h"
#include "swell/gerstner_model.h"
#include "swell/gl/shader.h"
#include "swell/gpu/underwater.h"

#include <glm/geometric.hpp>

#include <cmath>
#include <cstdio>
#include <vector>

namespace {

class Caustics : public swell::test::GlTest {};

// A high sun, off to one side: its rays reach the slices drifted.
const glm::vec3 kCausticsSun = glm::normalize(glm::vec3(-0.3f, 0.8f, -0.5f));
// A low one, 10 degrees up: the level surface reflects a third of its light.
const glm::vec3 kLowSun = glm::normalize(glm::vec3(0.98f, 0.17f, 0.0f));
// The water's absorption in tests/golden's scenes, 1/m (r, g, b).
const glm::vec3 kCausticsAbsorption_per_m(0.40f, 0.07f, 0.09f);

using swell::test::fresnelAirToWater;

// The cosine of the sun's refracted ray from the vertical (Snell's law).
double refractedCosine(double cosI)
{
    const double sinT = std::sqrt(1.0 - cosI * cosI) / swell::kWaterIor;
    return std::sqrt(1.0 - sinT * sinT);
}

// Waves 1.5 to 4 m long from three directions, their heights times `scale`
// (slopes a k of 0.08 at scale 1).
swell::WaveSet ripples(double scale)
{
    swell::WaveSet set;
    set.waves = {{{1.0, 0.2}, 4.0, 0.05 * scale, 0.3, 0.0},
                 {{0.3, 1.0}, 2.5, 0.03 * scale, 0.3, 1.0},
                 {{-0.7, 0.6}, 1.5, 0.02 * scale, 0.3, 2.0}};
    return set;
}

struct SliceStats {
    double mean = 0.0;     // over the map, of the irradiance over the air's E sun.y
    double contrast = 0.0; // standard deviation over mean
};

// The light on a level floor at each depth, through causticsSunlight()
// (caustics.glsl) at a lattice of points well inside the map, over the
// air's E sun.y, per channel.
const char* const kFloorProbe = R"(
#include "caustics.glsl"
layout(local_size_x = 64) in;
layout(std430, binding = 0) buffer Probe { vec4 data[]; };
uniform float depth_m;
uniform vec3 absorption_per_m;
void main()
{
    uint i = gl_GlobalInvocationID.x;
    vec2 uv = 0.15 + 0.7 * vec2(i % 64u, i / 64u) / 63.0;
    vec3 p = vec3(causticsMapCorner_m.x + uv.x * causticsMapSize_m, -depth_m,
                  causticsMapCorner_m.y + uv.y * causticsMapSize_m);
    data[i] = vec4(causticsSunlight(vec3(0.0, 1.0, 0.0), p, absorption_per_m, 0.0) / causticsSun.y, 0.0);
}
)";

class CausticsRun {
public:
    explicit CausticsRun(const swell::WaveModel& model, glm::vec3 sun = kCausticsSun)
        : drawn_(model.createGpu(swell::gl::ShaderSources::embedded()), sun)
    {
    }

    long long triangles() const { return drawn_.triangles(); }

    std::vector<SliceStats> slices() const
    {
        const int n = SWELL_CAUSTICS_SIZE;
        std::vector<float> texels(std::size_t(n) * n * SWELL_CAUSTICS_SLICES);
        glGetTextureImage(drawn_.map().texture(), 0, GL_RED, GL_FLOAT, GLsizei(texels.size() * sizeof(float)), texels.data());
        std::vector<SliceStats> stats;
        for (int k = 0; k < SWELL_CAUSTICS_SLICES; ++k) {
            double sum = 0.0, squares = 0.0;
            for (std::size_t t = 0; t < std::size_t(n) * n; ++t) {
                const double v = texels[std::size_t(k) * n * n + t];
                sum += v;
                squares += v * v;
            }
            const double count = double(n) * n;
            SliceStats s;
            s.mean = sum / count;
            s.contrast = std::sqrt(std::max(squares / count - s.mean * s.mean, 0.0)) / s.mean;
            stats.push_back(s);
        }
        return stats;
    }

    // The mean light on a level floor at depth_m, per channel (kFloorProbe).
    glm::dvec3 floorMean(float depth_m) const
    {
        const swell::gl::Program program = drawn_.probe(kFloorProbe);
        constexpr int kPoints = 64 * 64;
        swell::gl::Buffer buffer = swell::gl::Buffer::create();
        glNamedBufferData(buffer.id(), kPoints * sizeof(glm::vec4), nullptr, GL_DYNAMIC_READ);
        glUseProgram(program.id());
        glProgramUniform1f(program.id(), glGetUniformLocation(program.id(), "depth_m"), depth_m);
        glProgramUniform3f(program.id(), glGetUniformLocation(program.id(), "absorption_per_m"), kCausticsAbsorption_per_m.r,
                           kCausticsAbsorption_per_m.g, kCausticsAbsorption_per_m.b);
        drawn_.map().bind();
        glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 0, buffer.id());
        glDispatchCompute(kPoints / 64, 1, 1);
        glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
        std::vector<glm::vec4> values(kPoints);
        glGetNamedBufferSubData(buffer.id(), 0, kPoints * sizeof(glm::vec4), values.data());
        glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 0, 0);
        glUseProgram(0);
        glm::dvec3 sum(0.0);
        for (const glm::vec4& v : values)
            sum += glm::dvec3(v);
        return sum / double(kPoints);
    }

private:
    swell::test::DrawnCausticsMap drawn_;
};

// The direct light on a level floor depth_m under flat water over the air's
// E sun.y: Fresnel's transmittance, then Beer-Lambert along the refracted ray.
glm::dvec3 expectedFloor(double depth_m)
{
    const double cosI = kCausticsSun.y;
    const double path_m = depth_m / refractedCosine(cosI);
    return (1.0 - fresnelAirToWater(cosI)) * glm::exp(-glm::dvec3(kCausticsAbsorption_per_m) * path_m);
}

TEST_F(Caustics, FlatWaterLetsTheSunsTransmittedLightDownEverywhere)
{
    const swell::FlatModel flat;
    const CausticsRun run(flat);
    EXPECT_EQ(run.triangles(), 2LL * SWELL_CAUSTICS_CELLS * SWELL_CAUSTICS_CELLS);
    const double transmittance = 1.0 - fresnelAirToWater(kCausticsSun.y);
    for (const SliceStats& s : run.slices()) {
        // The issue's bound: the mean within 5% of the transmitted light.
        EXPECT_NEAR(s.mean, transmittance, 0.05 * transmittance);
        // Each texel is covered by exactly one cell's image, of the same area.
        EXPECT_LT(s.contrast, 0.01) << "flat water focuses nothing";
    }
    // The floor between and below the slices, with the water's absorption.
    for (float depth_m : {0.5f, 2.0f, 5.0f, 12.0f}) {
        const glm::dvec3 floor = run.floorMean(depth_m);
        const glm::dvec3 expected = expectedFloor(depth_m);
        for (int c = 0; c < 3; ++c)
            EXPECT_NEAR(floor[c], expected[c], 0.05 * expected[c]) << "depth " << depth_m << " m, channel " << c;
    }
    // A low sun: 1 - R is 0.65, far from the high sun's 0.98 (whose 2% of
    // reflection alone lies within the 5%), so Fresnel's part is held too.
    const CausticsRun low(flat, kLowSun);
    const double lowTransmittance = 1.0 - fresnelAirToWater(kLowSun.y);
    for (const SliceStats& s : low.slices()) {
        EXPECT_NEAR(s.mean, lowTransmittance, 0.05 * lowTransmittance);
        EXPECT_LT(s.contrast, 0.01);
    }
}

TEST_F(Caustics, WavesMoveTheLightAboutKeepingItsMeanAndSharpenWithSlope)
{
    const double transmittance = 1.0 - fresnelAirToWater(kCausticsSun.y);
    std::vector<std::vector<SliceStats>> byScale;
    std::vector<glm::dvec3> floors;
    for (double scale : {1.0, 2.0}) {
        const swell::GerstnerModel waves(ripples(scale));
        const CausticsRun run(waves);
        byScale.push_back(run.slices());
        floors.push_back(run.floorMean(2.0f));
        for (int k = 0; k < SWELL_CAUSTICS_SLICES; ++k)
            std::printf("heights x%.0f, slice at %.0f m: mean %.4f (level %.4f), contrast %.3f\n", scale,
                        double(swell::detail::kCausticsSliceDepths_m[std::size_t(k)]), byScale.back()[std::size_t(k)].mean,
                        transmittance, byScale.back()[std::size_t(k)].contrast);
        std::printf("heights x%.0f, floor at 2 m: %.4f %.4f %.4f (expected %.4f %.4f %.4f)\n", scale, floors.back().r,
                    floors.back().g, floors.back().b, expectedFloor(2.0).r, expectedFloor(2.0).g, expectedFloor(2.0).b);
    }
    for (std::size_t w = 0; w < byScale.size(); ++w)
        for (int k = 0; k < SWELL_CAUSTICS_SLICES; ++k) {
            const SliceStats& s = byScale[w][std::size_t(k)];
            // The mean unchanged within the issue's 5% (Fresnel's
            // transmittance on tilted facets and the map's edges move it
            // by less than that).
            EXPECT_NEAR(s.mean, transmittance, 0.05 * transmittance) << "scale " << w << ", slice " << k;
            // Waves focus the light: a pattern, not a level wash.
            EXPECT_GT(s.contrast, 0.05) << "scale " << w << ", slice " << k;
        }
    // Steeper waves focus harder, at every depth. Well above every focus
    // (a wave of height a and wavenumber k focuses about n / (n - 1) / (a k^2)
    // down: 11 m for the shortest at these heights, 5.7 m at twice them), the
    // contrast grows with the slope, nearly twice for twice the heights
    // (measured 0.103 and 0.219 at 1 m); past a focus the sun's disc holds it
    // (1.62 and 1.79 at 8 m).
    for (int k = 0; k < SWELL_CAUSTICS_SLICES; ++k)
        EXPECT_GT(byScale[1][std::size_t(k)].contrast, 1.05 * byScale[0][std::size_t(k)].contrast) << "slice " << k;
    EXPECT_GT(byScale[1][0].contrast, 1.6 * byScale[0][0].contrast) << "the first slice, 1 m down";
    // The floor's mean light through the look-up, absorption included.
    const glm::dvec3 expected = expectedFloor(2.0);
    for (const glm::dvec3& floor : floors)
        for (int c = 0; c < 3; ++c)
            EXPECT_NEAR(floor[c], expected[c], 0.05 * expected[c]) << "channel " << c;
}

} // namespace
