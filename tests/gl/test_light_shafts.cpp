// Shafts of light in the water column (issue 25): shaders/light_shafts.glsl
// run through a compute probe over a caustics map drawn for flat water and
// for ripples. Flat water scatters the closed-form single-scattering
// radiance of a homogeneous medium (render/light_shafts.h) and no pattern;
// ripples make shafts (contrast across neighbouring rays) about the same
// mean; the light falls with the eye's depth as the beam's absorption says.
#include "render/light_shafts.h"
#include "support/caustics_setup.h"
#include "swell/wave_model.h"
#include "support/fresnel_reference.h"
#include "support/gl_test.h"
#include "swell/flat_model.h"
#include "swell/gerstner_model.h"
#include "swell/gl/shader.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <vector>

namespace {

class LightShafts : public swell::test::GlTest {};

// A high sun, off to one side (as in tests/gl/test_caustics.cpp).
const glm::dvec3 kLightShaftsSun = glm::normalize(glm::dvec3(-0.3, 0.8, -0.5));
// The water's absorption in tests/golden's scenes, 1/m (r, g, b).
const glm::dvec3 kLightShaftsAbsorption_per_m(0.40, 0.07, 0.09);
const glm::dvec3 kSunIrradiance(1.0, 0.96, 0.9);
// A pixel's width over its distance: 540 rows over a 75-degree field.
const double kPixelSpread = 2.0 * std::tan(0.5 * 75.0 * 3.14159265358979 / 180.0) / 540.0;

using swell::test::fresnelAirToWater;

// Ripples 1.5 to 4 m long from three directions, slopes a k about 0.16
// (tests/golden/test_caustics_render.cpp's): foci between 3 and 8 m down.
swell::WaveSet ripples()
{
    swell::WaveSet set;
    set.waves = {{{1.0, 0.2}, 4.0, 0.10, 0.3, 0.0}, {{0.3, 1.0}, 2.5, 0.06, 0.3, 1.0}, {{-0.7, 0.6}, 1.5, 0.04, 0.3, 2.0}};
    return set;
}

// One ray: where it starts (relative to the render origin), where it
// goes (unit), how far, and the pixel's dither.
struct Ray {
    glm::vec4 start_path; // xyz start, m; w path, m
    glm::vec4 d_dither;   // xyz direction; w dither in [0, 1)
};

const char* const kLightShaftsProbe = R"(
#include "light_shafts.glsl"
layout(local_size_x = 1) in;
struct Ray { vec4 startPath; vec4 dDither; };
layout(std430, binding = 0) readonly buffer Rays { Ray rays[]; };
layout(std430, binding = 1) writeonly buffer Light { vec4 light[]; };
uniform vec3 absorption_per_m;
uniform vec3 sunIrradiance;
uniform float pixelSpread;
void main()
{
    Ray r = rays[gl_GlobalInvocationID.x];
    light[gl_GlobalInvocationID.x] = vec4(shaftsInscatter(r.startPath.xyz, r.dDither.xyz, r.startPath.w,
        absorption_per_m, sunIrradiance, pixelSpread, r.dDither.w), 0.0);
}
)";

// A caustics map for a wave model, and the shafts along rays through it.
class ShaftsRun {
public:
    explicit ShaftsRun(const swell::WaveModel& model)
        : drawn_(model.createGpu(swell::gl::ShaderSources::embedded()), glm::vec3(kLightShaftsSun))
    {
    }

    std::vector<glm::dvec3> shafts(const std::vector<Ray>& rays) const
    {
        const swell::gl::Program program = drawn_.probe(kLightShaftsProbe);
        swell::gl::Buffer in = swell::gl::Buffer::create(), out = swell::gl::Buffer::create();
        glNamedBufferData(in.id(), GLsizeiptr(rays.size() * sizeof(Ray)), rays.data(), GL_STATIC_DRAW);
        glNamedBufferData(out.id(), GLsizeiptr(rays.size() * sizeof(glm::vec4)), nullptr, GL_DYNAMIC_READ);
        glUseProgram(program.id());
        const GLuint id = program.id();
        glProgramUniform3f(id, glGetUniformLocation(id, "absorption_per_m"), float(kLightShaftsAbsorption_per_m.r),
                           float(kLightShaftsAbsorption_per_m.g), float(kLightShaftsAbsorption_per_m.b));
        glProgramUniform3f(id, glGetUniformLocation(id, "sunIrradiance"), float(kSunIrradiance.r),
                           float(kSunIrradiance.g), float(kSunIrradiance.b));
        glProgramUniform1f(id, glGetUniformLocation(id, "pixelSpread"), float(kPixelSpread));
        drawn_.map().bind();
        glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 0, in.id());
        glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 1, out.id());
        glDispatchCompute(GLuint(rays.size()), 1, 1);
        glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
        std::vector<glm::vec4> values(rays.size());
        glGetNamedBufferSubData(out.id(), 0, GLsizeiptr(values.size() * sizeof(glm::vec4)), values.data());
        glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 0, 0);
        glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 1, 0);
        glUseProgram(0);
        std::vector<glm::dvec3> light;
        for (const glm::vec4& v : values)
            light.emplace_back(v);
        return light;
    }

private:
    swell::test::DrawnCausticsMap drawn_;
};

glm::dvec3 expected(const Ray& r)
{
    return swell::detail::levelShaftsRadiance(kLightShaftsSun, kSunIrradiance, kLightShaftsAbsorption_per_m, 1.0 - fresnelAirToWater(kLightShaftsSun.y),
                                              glm::dvec3(r.start_path), glm::dvec3(r.d_dither), double(r.start_path.w));
}

// Directions from the eye: towards the sun's refracted light (up into the
// beam, where the phase function's forward lobe shows the shafts), 25
// degrees off it, level towards the sun's side, and down and away.
std::vector<glm::dvec3> directions()
{
    const glm::dvec3 towardsSun = -swell::detail::levelRefractedRay(kLightShaftsSun);
    const glm::dvec3 side = glm::normalize(glm::dvec3(towardsSun.x, 0.0, towardsSun.z));
    const double off = 25.0 * 3.14159265358979 / 180.0;
    return {towardsSun, glm::normalize(towardsSun * std::cos(off) + side * std::sin(off)), side,
            glm::normalize(glm::dvec3(-side.x, -0.5, -side.z))};
}

// A line of rays starting `depth_m` down, 16 m long across the sun's
// azimuth, along d, the dither varying as a screen's would.
std::vector<Ray> line(double depth_m, glm::dvec3 d, double path_m)
{
    std::vector<Ray> rays;
    const glm::dvec3 across = glm::normalize(glm::cross(d, glm::dvec3(0.0, 1.0, 0.0)) + glm::dvec3(1e-3, 0.0, 0.0));
    for (int i = 0; i < 256; ++i) {
        const glm::dvec3 start = glm::dvec3(0.0, -depth_m, 0.0) + across * (-8.0 + 16.0 * i / 255.0);
        rays.push_back({glm::vec4(glm::vec3(start), float(path_m)), glm::vec4(glm::vec3(d), float((i * 37 % 64) / 64.0))});
    }
    return rays;
}

struct LineStats {
    double mean = 0.0;     // of the rays' green light
    double contrast = 0.0; // its standard deviation over the mean
};

LineStats stats(const std::vector<glm::dvec3>& light)
{
    double sum = 0.0, squares = 0.0;
    for (const glm::dvec3& l : light) {
        sum += l.g;
        squares += l.g * l.g;
    }
    LineStats s;
    s.mean = sum / double(light.size());
    s.contrast = std::sqrt(std::max(squares / double(light.size()) - s.mean * s.mean, 0.0)) / s.mean;
    return s;
}

TEST_F(LightShafts, FlatWaterScattersTheClosedFormAndNoShafts)
{
    const swell::FlatModel flat;
    const ShaftsRun run(flat);
    for (const glm::dvec3& d : directions())
        for (double path_m : {6.0, 1.0e6})
            for (double depth_m : {1.5, 4.0, 10.0}) {
                const std::vector<Ray> rays = line(depth_m, d, path_m);
                const std::vector<glm::dvec3> light = run.shafts(rays);
                // Each ray against the homogeneous medium's closed form: the
                // map holds Fresnel's transmittance everywhere (to float
                // rounding), so the march about it adds nothing, whatever
                // the dither; 0.5% is float's exp and the map's rounding.
                for (std::size_t i = 0; i < rays.size(); i += 51)
                    for (int c = 0; c < 3; ++c) {
                        const double want = expected(rays[i])[c];
                        EXPECT_NEAR(light[i][c], want, 0.005 * want + 1e-9)
                            << "depth " << depth_m << " m, path " << path_m << " m, direction " << d.x << " " << d.y
                            << " " << d.z << ", channel " << c;
                    }
                // Smooth: neighbouring rays see the same light.
                EXPECT_LT(stats(light).contrast, 0.002) << "flat water makes no shafts";
            }
}

TEST_F(LightShafts, RipplesMakeShaftsAboutTheFlatMean)
{
    const swell::FlatModel flat;
    const ShaftsRun level(flat);
    const swell::GerstnerModel waves(ripples());
    const ShaftsRun rippled(waves);
    const std::vector<glm::dvec3> ds = directions();
    // Looking up into the beam and 25 degrees off it, 3 m down, out to the
    // surface (or the depths for the level ray).
    for (std::size_t k = 0; k < 3; ++k) {
        const std::vector<Ray> rays = line(3.0, ds[k], 1.0e6);
        const LineStats f = stats(level.shafts(rays)), r = stats(rippled.shafts(rays));
        std::printf("direction %zu: flat mean %.5f contrast %.4f; ripples mean %.5f contrast %.4f\n", k, f.mean,
                    f.contrast, r.mean, r.contrast);
        // Shafts: bright and dim rays side by side where flat water has none
        // (measured 0.33 up the beam, 0.26 at 25 degrees off it and 0.05
        // level, where each ray crosses the pattern at 1 m per metre).
        EXPECT_GT(r.contrast, 0.03) << "direction " << k;
        EXPECT_GT(r.contrast, 20.0 * f.contrast) << "direction " << k;
        // The waves move the light about; its mean over the line stays
        // (the map keeps its mean within 5%; a line of rays samples a
        // band of it: 15%; measured 2% apart).
        EXPECT_NEAR(r.mean, f.mean, 0.15 * f.mean) << "direction " << k;
    }
}

TEST_F(LightShafts, TheLightFallsWithDepthAsTheBeamIsAbsorbed)
{
    // A level ray's light, z down: exp(-a z / cosT) (the beam's slant path
    // from the surface), per channel, under flat water exactly and under
    // ripples on the line's mean.
    const double cosT = -swell::detail::levelRefractedRay(kLightShaftsSun).y;
    const glm::dvec3 level = directions()[2];
    const swell::FlatModel flat;
    const ShaftsRun calm(flat);
    const swell::GerstnerModel waves(ripples());
    const ShaftsRun rippled(waves);
    const std::vector<glm::dvec3> calm2 = calm.shafts(line(2.0, level, 1.0e6));
    const std::vector<glm::dvec3> calm8 = calm.shafts(line(8.0, level, 1.0e6));
    const glm::dvec3 fall = glm::exp(-kLightShaftsAbsorption_per_m * 6.0 / cosT);
    for (int c = 0; c < 3; ++c)
        EXPECT_NEAR(calm8[0][c] / calm2[0][c], fall[c], 0.005 * fall[c]) << "flat water, channel " << c;
    const LineStats r2 = stats(rippled.shafts(line(2.0, level, 1.0e6)));
    const LineStats r8 = stats(rippled.shafts(line(8.0, level, 1.0e6)));
    std::printf("ripples, level ray: 2 m down %.5f, 8 m down %.5f, ratio %.4f (exp %.4f)\n", r2.mean, r8.mean,
                r8.mean / r2.mean, fall.g);
    // Measured 0.627 against 0.626: the map keeps its mean at every depth.
    EXPECT_NEAR(r8.mean / r2.mean, fall.g, 0.15 * fall.g) << "ripples, green";
}

} // namespace
