// The water's shading normal (oceanShading in each model's GLSL) adds to the
// grid's interpolated normal what the pixel's footprint resolves and the
// grid's does not. Evaluated at a vertex, that must be the normal the full
// per-pixel sum (oceanSurface at the pixel's footprint) gives: here both run
// side by side in one vertex shader, with transform feedback, at points,
// pixel footprints and grid footprints spread over what a frame draws.
#include "support/gl_test.h"

#include "../cpu/published_sea_laws.h"
#include "swell/gl/handle.h"
#include "swell/gl/shader.h"
#include "swell/scene/scene.h"
#include "swell/scene/waves.h"
#include "swell/wave_model.h"
#include "swell/wave_model_gpu.h"

#include <epoxy/gl.h>
#include <glm/geometric.hpp>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include <algorithm>
#include <cstdio>
#include <cmath>
#include <map>
#include <random>
#include <string>
#include <vector>

namespace {

class ShadingNormals : public swell::test::GlTest {};

// What every probe shader reads and writes (runProbes puts it first).
const char* kProbeInterface = R"(
#include "ocean.glsl"
layout(location = 0) in vec4 probe;
out vec3 fullNormal;
out vec3 shadedNormal;
out float shadedSlopeVariance;
)";

// xy: rest offset from the grid centre, m; z: pixel footprint, m; w: grid footprint, m.
const char* kShadingNormalsProbe = R"(
void main()
{
    SurfacePoint grid = oceanSurface(probe.xy, probe.w, 1.0);
    fullNormal = oceanSurface(probe.xy, probe.z, 1.0).normal;
    SurfacePoint shaded = oceanShading(probe.xy, probe.z, probe.w, grid.alongX, grid.alongZ, 1.0);
    shadedNormal = shaded.normal;
    shadedSlopeVariance = shaded.slopeVariance;
    gl_Position = vec4(0.0);
}
)";

// The largest angle between the two normals, over the probes whose pixel
// footprint is smaller than the grid's (the pixel adds waves), equal to it
// (nothing to add), or larger (the pixel takes out waves the grid summed).
struct Comparison {
    double worstFiner_rad = 0.0, worstEqual_rad = 0.0, worstCoarser_rad = 0.0;
};

// What the probe shader gives at one probe.
struct Probed {
    glm::dvec3 fullNormal, shadedNormal;
    double slopeVariance = 0.0;
};

// The probes run through `probeShader` (after kProbeInterface).
std::vector<Probed> runProbes(const swell::Scene& scene, double time_s, const std::vector<glm::vec4>& probes,
                              const char* probeShader = kShadingNormalsProbe)
{
    const swell::gl::ShaderSources embedded = swell::gl::ShaderSources::embedded();
    std::map<std::string, std::string> files;
    for (const std::string& name : embedded.fileNames())
        files[name] = embedded.file(name);
    files["shading_probe.vert"] = std::string(kProbeInterface) + probeShader;
    const swell::gl::ShaderSources sources = swell::gl::ShaderSources::fromMap(files);

    const std::unique_ptr<swell::WaveModel> model = swell::makeWaveModel(scene);
    const std::unique_ptr<swell::WaveModelGpu> gpu = model->createGpu(embedded);
    gpu->prepareFrame({12.5, -7.25}, time_s);
    const swell::gl::Program program = swell::gl::buildProgram(
        sources, {{GL_VERTEX_SHADER, "shading_probe.vert"}}, {"SWELL_OCEAN_FILE \"" + gpu->shaderFile() + "\""},
        {"fullNormal", "shadedNormal", "shadedSlopeVariance"});

    constexpr int kFloats = 7;
    swell::gl::Buffer input = swell::gl::Buffer::create(), output = swell::gl::Buffer::create();
    glNamedBufferStorage(input.id(), GLsizeiptr(probes.size() * sizeof(glm::vec4)), probes.data(), 0);
    glNamedBufferStorage(output.id(), GLsizeiptr(probes.size() * kFloats * sizeof(float)), nullptr, 0);
    swell::gl::VertexArray vao = swell::gl::VertexArray::create();
    glVertexArrayVertexBuffer(vao.id(), 0, input.id(), 0, sizeof(glm::vec4));
    glEnableVertexArrayAttrib(vao.id(), 0);
    glVertexArrayAttribFormat(vao.id(), 0, 4, GL_FLOAT, GL_FALSE, 0);
    glVertexArrayAttribBinding(vao.id(), 0, 0);

    // Drawing needs a complete framebuffer even with rasterisation discarded.
    swell::gl::Texture color = swell::gl::Texture::create(GLenum(GL_TEXTURE_2D));
    glTextureStorage2D(color.id(), 1, GL_RGBA8, 1, 1);
    swell::gl::Framebuffer target = swell::gl::Framebuffer::create();
    glNamedFramebufferTexture(target.id(), GL_COLOR_ATTACHMENT0, color.id(), 0);
    glBindFramebuffer(GL_FRAMEBUFFER, target.id());
    glUseProgram(program.id());
    gpu->bind();
    glBindVertexArray(vao.id());
    glBindBufferBase(GL_TRANSFORM_FEEDBACK_BUFFER, 0, output.id());
    glEnable(GL_RASTERIZER_DISCARD);
    glBeginTransformFeedback(GL_POINTS);
    glDrawArrays(GL_POINTS, 0, GLsizei(probes.size()));
    glEndTransformFeedback();
    glDisable(GL_RASTERIZER_DISCARD);
    glBindBufferBase(GL_TRANSFORM_FEEDBACK_BUFFER, 0, 0);
    glBindVertexArray(0);
    glUseProgram(0);
    glBindFramebuffer(GL_FRAMEBUFFER, 0);

    std::vector<float> values(probes.size() * kFloats);
    glGetNamedBufferSubData(output.id(), 0, GLsizeiptr(values.size() * sizeof(float)), values.data());
    std::vector<Probed> out(probes.size());
    for (size_t i = 0; i < probes.size(); ++i) {
        const float* v = &values[i * kFloats];
        out[i] = {glm::dvec3(v[0], v[1], v[2]), glm::dvec3(v[3], v[4], v[5]), double(v[6])};
    }
    return out;
}

Comparison compare(const swell::Scene& scene, double time_s)
{
    std::vector<glm::vec4> probes;
    std::mt19937 random(7);
    std::uniform_real_distribution<float> offset(-300.0f, 300.0f);
    for (const float grid_m : {0.05f, 0.25f, 1.0f, 4.0f, 16.0f})
        for (const float pixelOverGrid : {0.1f, 0.5f, 1.0f, 2.0f, 8.0f})
            for (int i = 0; i < 200; ++i)
                probes.push_back({offset(random), offset(random), grid_m * pixelOverGrid, grid_m});
    const std::vector<Probed> probed = runProbes(scene, time_s, probes);
    Comparison result;
    for (size_t i = 0; i < probes.size(); ++i) {
        const double angle = std::acos(std::clamp(
            glm::dot(glm::normalize(probed[i].fullNormal), glm::normalize(probed[i].shadedNormal)), -1.0, 1.0));
        double& worst = probes[i].z == probes[i].w ? result.worstEqual_rad
                        : probes[i].z < probes[i].w ? result.worstFiner_rad
                                                    : result.worstCoarser_rad;
        worst = std::max(worst, angle);
    }
    return result;
}

swell::Scene windScene(double speed_mps, swell::WaveModelKind kind)
{
    swell::Scene scene = swell::defaultScene();
    scene.sea.wind = swell::WindSettings{};
    scene.sea.wind->windSpeed_mps = speed_mps;
    scene.waves.model = kind;
    return scene;
}

// The sums are linear in the partial derivatives, so adding the band of
// waves between the two footprints to the grid's derivatives is the full sum
// up to float rounding, whether the pixel adds waves (finer than the grid:
// near the camera), takes them out (coarser: cells smaller than a pixel) or
// neither. Adding the band with the wrong sign, or leaving out the negative
// weights of the coarser pixels, is off by degrees.
void expectFullSum(const Comparison& c)
{
    constexpr double kRounding_rad = 2.0e-5;
    EXPECT_LT(c.worstFiner_rad, kRounding_rad);
    EXPECT_LT(c.worstEqual_rad, kRounding_rad);
    EXPECT_LT(c.worstCoarser_rad, kRounding_rad);
}

TEST_F(ShadingNormals, GerstnerAddsToTheGridNormalWhatThePixelResolves)
{
    for (const double t : {0.0, 1.0e3}) {
        SCOPED_TRACE("t = " + std::to_string(t));
        expectFullSum(compare(swell::defaultScene(), t));
    }
}

// The same in a 15 m/s wind: steeper short waves.
TEST_F(ShadingNormals, GerstnerInAStrongWind)
{
    expectFullSum(compare(windScene(15.0, swell::WaveModelKind::Gerstner), 10.0));
}

// The spectral model's slope textures hold every wave: its shading normal is
// the full sum's whatever the grid's.
TEST_F(ShadingNormals, SpectralShadingIsTheFullSum)
{
    expectFullSum(compare(windScene(10.0, swell::WaveModelKind::Spectral), 10.0));
}

// At a footprint finer than every cascade's texel (level 0 of every slope
// mip chain, every cascade weighed 1) the GPU's normal is the CPU twin's:
// both look each cascade up at its anti-tiling warp's point and carry its
// slopes to the rest point through the warp's Jacobian. The GPU filters with
// the hardware's bilinear weights (8 bits on llvmpipe), off by up to 1/256
// of the slope between two texels: measured 8.2e-5 rad rms, 5.7e-4 at worst
// (rms slope 0.18 at 10 m/s). Reading the cross derivative dDx/dz from the
// displacement's texture, which is sampled nearest (a texel's value over the
// whole texel), as the shading did before it moved beside the slopes'
// moments, gave 1.4e-3 rms and 8.8e-3 at worst; leaving the Jacobian out of
// the GPU's sum, 1.1e-2 rms and 7.1e-2 at worst.
TEST_F(ShadingNormals, SpectralNormalAtAFineFootprintIsTheCpuTwins)
{
    const swell::Scene scene = windScene(10.0, swell::WaveModelKind::Spectral);
    constexpr float kFootprint_m = 0.002f;
    std::vector<glm::vec4> probes;
    std::mt19937 random(5);
    std::uniform_real_distribution<float> offset(-300.0f, 300.0f);
    for (int i = 0; i < 2000; ++i)
        probes.push_back({offset(random), offset(random), kFootprint_m, kFootprint_m});
    const double time_s = 10.0;
    const std::vector<Probed> probed = runProbes(scene, time_s, probes);
    const std::unique_ptr<swell::WaveModel> model = swell::makeWaveModel(scene);
    const glm::dvec2 gridCenter(12.5, -7.25); // runProbes' frame
    double worst_rad = 0.0, sumSq = 0.0, slopeSq = 0.0;
    for (size_t i = 0; i < probes.size(); ++i) {
        const glm::dvec3 cpu = model->surfaceAt(gridCenter + glm::dvec2(probes[i].x, probes[i].y), time_s,
                                                {double(kFootprint_m), 1.0}).normal;
        const double a = std::acos(std::clamp(glm::dot(cpu, glm::normalize(probed[i].shadedNormal)), -1.0, 1.0));
        worst_rad = std::max(worst_rad, a);
        sumSq += a * a;
        slopeSq += (cpu.x * cpu.x + cpu.z * cpu.z) / (cpu.y * cpu.y);
    }
    const double rms_rad = std::sqrt(sumSq / double(probes.size()));
    std::printf("angle between the GPU's shading normal and the CPU twin's: rms %.2e rad, worst %.2e rad (rms slope %.3f)\n",
                rms_rad, worst_rad, std::sqrt(slopeSq / double(probes.size())));
    EXPECT_LT(rms_rad, 3.0e-4);
    EXPECT_LT(worst_rad, 2.0e-3);
}

// The mean square slope the water is shaded with at each pixel footprint:
// that of the shading normals (as height slopes, -n.x/n.y and -n.z/n.y) plus
// the slope variance the shading spreads the highlight by, over probes spread
// evenly across +-halfSpan_m.
std::vector<double> renderedMeanSquareSlopes(const swell::Scene& scene, const std::vector<double>& footprints_m,
                                             float halfSpan_m)
{
    constexpr int kPerFootprint = 20000;
    std::vector<glm::vec4> probes;
    std::mt19937 random(11);
    std::uniform_real_distribution<float> offset(-halfSpan_m, halfSpan_m);
    for (const double f : footprints_m)
        for (int i = 0; i < kPerFootprint; ++i)
            probes.push_back({offset(random), offset(random), float(f), float(f)});
    const std::vector<Probed> probed = runProbes(scene, 10.0, probes);
    std::vector<double> out(footprints_m.size(), 0.0);
    for (size_t i = 0; i < probed.size(); ++i) {
        const glm::dvec3 n = glm::normalize(probed[i].shadedNormal);
        out[i / kPerFootprint] += ((n.x * n.x + n.z * n.z) / (n.y * n.y) + probed[i].slopeVariance) / kPerFootprint;
    }
    return out;
}

// The rendered surface's slopes are Cox & Munk's (1954: 0.003 + 5.12e-3*U12.5)
// within 15%, from a pixel of 5 mm to one of 2 m: what the mipmaps average out
// of the slopes (their second moments) and the waves no cascade holds
// (Elfouhaily et al. 1997) come back as the highlight's spread. Without the
// moments a 2 m pixel is 33-82% short; without the unresolved waves a 10 m/s
// sea is 43-47% short at every footprint.
TEST_F(ShadingNormals, SpectralSlopesAreCoxAndMunksAtEveryFootprint)
{
    for (const double wind_mps : {5.0, 10.0, 15.0}) {
        const double published = swell::test::coxMunkSlopeVariance(wind_mps);
        const std::vector<double> footprints{0.005, 0.05, 0.5, 2.0};
        const std::vector<double> rendered =
            renderedMeanSquareSlopes(windScene(wind_mps, swell::WaveModelKind::Spectral), footprints, 400.0f);
        for (size_t f = 0; f < footprints.size(); ++f) {
            const double footprint_m = footprints[f], mss = rendered[f];
            std::printf("U10 %4.1f m/s, pixel %5.3f m: rendered mean square slope %.4f, Cox & Munk %.4f (%+.0f%%)\n",
                        wind_mps, footprint_m, mss, published, 100.0 * (mss / published - 1.0));
            EXPECT_NEAR(mss / published, 1.0, 0.15) << wind_mps << " m/s, pixel " << footprint_m << " m";
        }
    }
}

// The Gerstner model keeps its waves' slope variance, sum (k*a)^2/2, at every
// footprint: what the pixel no longer resolves goes to the highlight's spread.
TEST_F(ShadingNormals, GerstnerKeepsItsSlopeVarianceAtEveryFootprint)
{
    const swell::Scene scene = windScene(10.0, swell::WaveModelKind::Gerstner);
    const swell::WaveSet waves = swell::resolveWaves(scene);
    double expected = 0.0;
    for (const swell::Wave& w : waves.waves) {
        const double ka = glm::length(swell::wavenumberVector(w)) * w.amplitude_m;
        expected += 0.5 * ka * ka;
    }
    const std::vector<double> footprints{0.005, 0.2, 1.0, 5.0};
    const std::vector<double> rendered = renderedMeanSquareSlopes(scene, footprints, 2000.0f);
    for (size_t f = 0; f < footprints.size(); ++f) {
        const double footprint_m = footprints[f], mss = rendered[f];
        std::printf("pixel %5.3f m: rendered mean square slope %.5f, the waves' %.5f\n", footprint_m, mss, expected);
        EXPECT_NEAR(mss / expected, 1.0, 0.1) << "pixel " << footprint_m << " m";
    }
}

// The spectral model's pixels take each cascade's warped lookup
// interpolated from their triangle's vertices where the grid's cell is at
// most 1/SWELL_FFT_WARP_CELLS_PER_WAVELENGTH of the warp's shortest
// sinusoid, and evaluate it themselves on larger cells
// (oceanShadingFromVertices). Here a point at barycentric (0.2, 0.5, 0.3) of
// a grid triangle with legs of the cell size: its normal from the three
// vertices' oceanVertexData, interpolated as the rasteriser does, against
// the per-pixel warp's (fullNormal), at pixel footprints of the cell and a
// tenth of it (level 0 of the finest cascades).
const char* kVertexWarpProbe = R"(
void main()
{
    float cell_m = probe.z;
    vec2 p = probe.xy;
    vec2 v0 = p - cell_m * vec2(0.5, 0.3);
    vec4 d0[SWELL_OCEAN_VERTEX_DATA], d1[SWELL_OCEAN_VERTEX_DATA], d2[SWELL_OCEAN_VERTEX_DATA];
    vec4 d[SWELL_OCEAN_VERTEX_DATA];
    oceanVertexData(v0, d0);
    oceanVertexData(v0 + vec2(cell_m, 0.0), d1);
    oceanVertexData(v0 + vec2(0.0, cell_m), d2);
    for (int i = 0; i < SWELL_OCEAN_VERTEX_DATA; ++i)
        d[i] = 0.2 * d0[i] + 0.5 * d1[i] + 0.3 * d2[i];
    SurfacePoint grid = oceanSurface(p, cell_m, 1.0);
    fullNormal = oceanShading(p, probe.w, cell_m, grid.alongX, grid.alongZ, 1.0).normal;
    SurfacePoint shaded = oceanShadingFromVertices(p, probe.w, cell_m, grid.alongX, grid.alongZ, 1.0, d, cell_m);
    shadedNormal = shaded.normal;
    shadedSlopeVariance = shaded.slopeVariance;
    gl_Position = vec4(0.0);
}
)";

// At 20 m/s (the storm's sea; its cascades' warps are 99 m to 14 km long,
// interpolated on cells up to 4.9 m to 740 m), on every cell size the two
// normals differ by half what the GPU's shading normal may differ from the
// CPU twin's (SpectralNormalAtAFineFootprintIsTheCpuTwins: 3e-3 rad rms,
// 2e-2 at worst, the 8-bit filter weights' share), and on cells too large
// for any cascade to take the vertices' lookup, by float rounding alone.
// Measured: 1.2e-4 to 1.3e-3 rad rms, 6.9e-4 to 5.8e-3 at worst (the
// same filter weights' rounding of lookups a fraction of a texel apart).
// Interpolating on cells 16 times too large went red.
TEST_F(ShadingNormals, SpectralPixelsInterpolateTheWarpOnlyWhereItIsNearlyLinear)
{
    const swell::Scene scene = windScene(20.0, swell::WaveModelKind::Spectral);
    std::vector<glm::vec4> probes;
    std::mt19937 random(11);
    std::uniform_real_distribution<float> offset(-1500.0f, 1500.0f);
    const std::vector<float> cells_m = {0.05f, 0.5f, 2.0f, 4.0f, 16.0f, 64.0f, 256.0f, 1024.0f};
    for (const float cell_m : cells_m)
        for (const float pixelOverCell : {0.1f, 1.0f})
            for (int i = 0; i < 200; ++i)
                probes.push_back({offset(random), offset(random), cell_m, cell_m * pixelOverCell});
    const std::vector<Probed> probed = runProbes(scene, 1.0e3, probes, kVertexWarpProbe);
    constexpr double kRms_rad = 1.5e-3, kWorst_rad = 1.0e-2;
    for (size_t k = 0; k < cells_m.size(); ++k) {
        double worst = 0.0, sumSq = 0.0;
        const size_t first = k * 400, last = first + 400;
        for (size_t i = first; i < last; ++i) {
            const double angle = std::acos(std::clamp(
                glm::dot(glm::normalize(probed[i].fullNormal), glm::normalize(probed[i].shadedNormal)), -1.0, 1.0));
            worst = std::max(worst, angle);
            sumSq += angle * angle;
        }
        std::printf("cell %7.2f m: the interpolated warp's normal off the pixel's by %.2e rad rms, %.2e at worst\n",
                    cells_m[k], std::sqrt(sumSq / 400.0), worst);
        EXPECT_LT(std::sqrt(sumSq / 400.0), kRms_rad) << "cells of " << cells_m[k] << " m";
        EXPECT_LT(worst, kWorst_rad) << "cells of " << cells_m[k] << " m";
        if (cells_m[k] >= 1024.0f) {
            EXPECT_LT(worst, 2.0e-5) << "cells too large for any cascade's vertex warp took it";
        }
    }
}

} // namespace
