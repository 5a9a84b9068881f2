// The spectral model's GPU fields against its CPU twin's, texel by texel:
// every cascade's displacement (Dx, Dy, Dz, dDx/dz) and derivatives
// (dDy/dx, dDy/dz, dDx/dx, dDz/dz) after the GPU's evolution and inverse
// FFT, at a time long after 0 (where the phases are large), and the
// shading's half-float copy of the derivatives with the slopes' second
// moments. Queries on the drawn surface (the displacement), the foam's
// folding (the derivatives) and the shading (their copy) stand on these
// fields; a difference in one field shows here by cascade and field,
// before any lookup, warp or filtering mixes them.
#include "support/gl_test.h"

#include "ocean/spectral/field_texels.h"
#include "ocean/spectral/spectral_cpu.h"
#include "ocean/spectral/spectral_field.h"
#include "swell/gl/context.h"
#include "swell/gl/handle.h"
#include "swell/gl/shader_sources.h"
#include "swell/gpu/bindings.h"
#include "swell/gpu/ocean.h"
#include "swell/scene/spectrum.h"
#include "swell/spectral_model.h"
#include "swell/wave_model_gpu.h"

#include <epoxy/gl.h>
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <glm/gtc/packing.hpp>

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <memory>
#include <string>
#include <tuple>
#include <vector>

namespace {

using namespace swell;

class SpectralFields : public test::GlTest {};

// The array texture bound to a texture unit, level 0, every layer
// (`layers` of them), as floats.
std::vector<float> boundArray(GLuint unit, int layers)
{
    GLint name = 0;
    glActiveTexture(GL_TEXTURE0 + unit);
    glGetIntegerv(GL_TEXTURE_BINDING_2D_ARRAY, &name);
    glActiveTexture(GL_TEXTURE0);
    EXPECT_NE(name, 0) << "nothing bound to unit " << unit;
    std::vector<float> texels(size_t(SWELL_FFT_SIZE) * SWELL_FFT_SIZE * size_t(layers) * 4);
    glGetTextureImage(GLuint(name), 0, GL_RGBA, GL_FLOAT, GLsizei(texels.size() * sizeof(float)), texels.data());
    return texels;
}

// The raw half floats of the array texture bound to a texture unit, level 0,
// every layer (`layers` of them): what the shading filters, bit for bit.
std::vector<std::uint16_t> boundHalves(GLuint unit, int layers)
{
    GLint name = 0;
    glActiveTexture(GL_TEXTURE0 + unit);
    glGetIntegerv(GL_TEXTURE_BINDING_2D_ARRAY, &name);
    glActiveTexture(GL_TEXTURE0);
    EXPECT_NE(name, 0) << "nothing bound to unit " << unit;
    std::vector<std::uint16_t> texels(size_t(SWELL_FFT_SIZE) * SWELL_FFT_SIZE * size_t(layers) * 4);
    glGetTextureImage(GLuint(name), 0, GL_RGBA, GL_HALF_FLOAT, GLsizei(texels.size() * sizeof(std::uint16_t)),
                      texels.data());
    return texels;
}

// One unit in the last place of a half float near |x| (its 11 significant
// bits; subnormal below 2^-14): what rounding a value to half moves it by,
// at most half of it, and two values a rounding apart, one of it.
double halfUlp(double x)
{
    const double magnitude = std::max(std::abs(x), std::ldexp(1.0, -14));
    return std::ldexp(1.0, std::ilogb(magnitude) - 10);
}

TEST_F(SpectralFields, TheGpusFieldsAreTheCpuTwins)
{
    SpectralSettings settings;
    settings.wind.windSpeed_mps = 10.0;
    const SpectralModel model(settings);
    const std::unique_ptr<WaveModelGpu> gpu = model.createGpu(gl::ShaderSources::embedded());
    constexpr double kTime_s = 1000.25;
    gpu->prepareFrame({0.0, 0.0}, kTime_s);
    gpu->bind();
    glMemoryBarrier(GL_TEXTURE_UPDATE_BARRIER_BIT);
    // The FFTs' full floats; the shading's half floats hold each cascade's
    // slope moments after its derivatives (shaders/ocean/spectral.glsl).
    const std::vector<float> displacement = boundArray(SWELL_UNIT_OCEAN0, SWELL_FFT_CASCADES),
                             derivatives = boundArray(SWELL_UNIT_OCEAN3, SWELL_FFT_CASCADES),
                             slopes = boundArray(SWELL_UNIT_OCEAN1, 2 * SWELL_FFT_CASCADES);

    // The twin, from the same field the model makes.
    const spectral::CpuSurface twin(std::make_shared<const spectral::SpectralField>(
        spectral::makeSpectralField(SeaSpectrum(settings.wind), settings.choppiness, settings.seed)));
    const spectral::CpuSurface::Fields& fields = twin.fieldsAt(kTime_s);
    const char* const names[8] = {"Dx", "Dy", "Dz", "dDx/dz", "dDy/dx", "dDy/dz", "dDx/dx", "dDz/dz"};
    const int n = SWELL_FFT_SIZE;
    for (int c = 0; c < SWELL_FFT_CASCADES; ++c)
        for (int f = 0; f < 8; ++f) {
            const std::vector<float>& gpuField = f < 4 ? displacement : derivatives;
            const std::vector<float>& cpu = fields.values[size_t(c)][size_t(f)];
            auto error = [&](int x, int z) {
                x &= n - 1, z &= n - 1;
                return double(gpuField[((size_t(c) * n + z) * n + x) * 4 + size_t(f % 4)]) - cpu[size_t(z) * n + x];
            };
            double worst = 0.0, sumSq = 0.0, errorSum = 0.0;
            int worstX = 0, worstZ = 0;
            for (int z = 0; z < n; ++z)
                for (int x = 0; x < n; ++x) {
                    const double v = cpu[size_t(z) * n + x];
                    errorSum += error(x, z);
                    if (std::abs(error(x, z)) > worst)
                        worst = std::abs(error(x, z)), worstX = x, worstZ = z;
                    sumSq += v * v;
                }
            const double rms = std::sqrt(sumSq / double(n * n));
            std::printf("cascade %d %-7s rms %.3e, worst difference %.3e (%.2e of rms)\n", c, names[f], rms, worst,
                        worst / std::max(rms, 1e-30));
            // float FFTs of 256^2 on both sides, in different orders: 1e-4 of
            // the field's rms covers their rounding many times over.
            // Where it differs: the mean difference (a wrong mean), and the
            // differences next to the worst along x and z (a wrong frequency's
            // pattern: the Nyquist alternates, one low frequency barely moves).
            std::string along;
            for (int i = 0; i < 4; ++i)
                along += fmt::format(" x+{}: {:.2e}, z+{}: {:.2e};", i, error(worstX + i, worstZ), i, error(worstX, worstZ + i));
            EXPECT_LE(worst, 1e-4 * rms + 1e-9) << "cascade " << c << ", " << names[f] << ": mean difference "
                                               << errorSum / double(n * n) << ", worst at " << worstX << ", " << worstZ
                                               << ";" << along;
        }
    // The shading's copy: the derivatives, then the slopes' second moments
    // ((dDy/dx)^2, (dDy/dz)^2 and their product), each texel the twin's
    // value rounded to a half float: within one half-float unit of it (the
    // GPU's float, 1e-4 of the rms off the twin's, may round the other way)
    // and the float FFTs' difference (1e-4 of the rms; 3e-4 for a product).
    for (int c = 0; c < SWELL_FFT_CASCADES; ++c) {
        const std::vector<float>& sx = fields.values[size_t(c)][4];
        const std::vector<float>& sz = fields.values[size_t(c)][5];
        for (int f = 0; f < 7; ++f) {
            const bool moment = f >= 4;
            const int m = f - 4;
            auto cpuAt = [&](size_t i) {
                if (!moment)
                    return double(fields.values[size_t(c)][size_t(4 + f)][i]);
                return m == 0 ? double(sx[i]) * sx[i] : m == 1 ? double(sz[i]) * sz[i] : double(sx[i]) * sz[i];
            };
            const size_t layer = moment ? size_t(c + SWELL_FFT_CASCADES) : size_t(c);
            double sumSq = 0.0;
            for (size_t i = 0; i < size_t(n) * n; ++i)
                sumSq += cpuAt(i) * cpuAt(i);
            const double rms = std::sqrt(sumSq / double(n * n));
            double worst = 0.0, worstOfUlp = 0.0;
            for (size_t i = 0; i < size_t(n) * n; ++i) {
                const double cpu = cpuAt(i), shaded = slopes[(layer * n * n + i) * 4 + size_t(moment ? m : f)];
                const double rounded = glm::unpackHalf1x16(glm::packHalf1x16(float(cpu)));
                const double error = std::abs(shaded - rounded);
                worst = std::max(worst, error);
                worstOfUlp = std::max(worstOfUlp, error / halfUlp(cpu));
                EXPECT_LE(error, halfUlp(cpu) + (moment ? 3e-4 : 1e-4) * rms + 1e-12)
                    << "cascade " << c << ", " << (moment ? "moment " : "derivative ") << (moment ? m : f) << " at texel "
                    << i << ": the twin's " << cpu << " (as a half " << rounded << "), the GPU's " << shaded;
                if (error > halfUlp(cpu) + (moment ? 3e-4 : 1e-4) * rms + 1e-12)
                    return; // one texel's message says it
            }
            std::printf("cascade %d shading %s %d: rms %.3e, worst difference from the rounded twin %.3e (%.2f of a "
                        "half's unit)\n",
                        c, moment ? "moment" : "derivative", moment ? m : f, rms, worst, worstOfUlp);
        }
    }
}

// A software rasteriser's interactive view takes the fields from the CPU's
// FFTs (src/ocean/spectral/field_texels.h) instead of the passes: every
// texel the passes write, within their float rounding of each other (1e-4
// of a field's rms, as above; for the half-float copy one half's unit more).
// On a GPU both views run the passes, and must be the same.
TEST_F(SpectralFields, AnInteractiveViewOnASoftwareRasteriserUploadsThePassesFields)
{
    SpectralSettings settings;
    settings.wind.windSpeed_mps = 14.0;
    const SpectralModel model(settings);
    constexpr double kTime_s = 731.5;
    struct Drawn {
        std::vector<float> displacement, derivatives, slopes;
        int dispatches = 0;
    };
    auto draw = [&](bool interactive) {
        const std::unique_ptr<WaveModelGpu> gpu = model.createGpu(gl::ShaderSources::embedded());
        gpu->setInteractive(interactive);
        gpu->prepareFrame({0.0, 0.0}, kTime_s);
        Drawn d;
        d.dispatches = gpu->takeWork().dispatches;
        gpu->bind();
        glMemoryBarrier(GL_TEXTURE_UPDATE_BARRIER_BIT);
        d.displacement = boundArray(SWELL_UNIT_OCEAN0, SWELL_FFT_CASCADES);
        d.derivatives = boundArray(SWELL_UNIT_OCEAN3, SWELL_FFT_CASCADES);
        d.slopes = boundArray(SWELL_UNIT_OCEAN1, 2 * SWELL_FFT_CASCADES);
        return d;
    };
    const Drawn passes = draw(false), uploaded = draw(true);
    // The FFTs' two passes are not run for the view that uploads.
    EXPECT_EQ(uploaded.dispatches, gl::isSoftwareRasterizer() ? passes.dispatches - 2 : passes.dispatches);

    const size_t layerFloats = size_t(SWELL_FFT_SIZE) * SWELL_FFT_SIZE * 4;
    auto expectClose = [&](const std::vector<float>& a, const std::vector<float>& b, int layers, bool half,
                           const char* name) {
        ASSERT_EQ(a.size(), b.size());
        for (int layer = 0; layer < layers; ++layer)
            for (size_t f = 0; f < 4; ++f) {
                // A slope moment is a product: 3e-4 of its rms, as above.
                const bool moments = half && layer >= SWELL_FFT_CASCADES;
                double sumSq = 0.0;
                for (size_t i = 0; i < layerFloats; i += 4)
                    sumSq += double(a[layer * layerFloats + i + f]) * a[layer * layerFloats + i + f];
                const double rms = std::sqrt(sumSq / double(layerFloats / 4));
                double worst = 0.0;
                for (size_t i = 0; i < layerFloats; i += 4) {
                    const double x = a[layer * layerFloats + i + f], y = b[layer * layerFloats + i + f];
                    const double allowed = (half ? halfUlp(x) : 0.0) + (moments ? 3e-4 : 1e-4) * rms + 1e-9;
                    worst = std::max(worst, std::abs(x - y) / allowed);
                }
                std::printf("%s layer %d component %zu: rms %.3e, worst difference %.2f of what is allowed\n", name,
                            layer, f, rms, worst);
                EXPECT_LE(worst, 1.0) << name << " layer " << layer << " component " << f;
            }
    };
    expectClose(passes.displacement, uploaded.displacement, SWELL_FFT_CASCADES, false, "displacement");
    expectClose(passes.derivatives, uploaded.derivatives, SWELL_FFT_CASCADES, false, "derivatives");
    expectClose(passes.slopes, uploaded.slopes, 2 * SWELL_FFT_CASCADES, true, "slopes");
}

// The interactive view's fields are made on two threads (the cascades
// shared with a worker) and their texels converted there; what it uploads
// must be, bit for bit, what one thread's twin makes and the old upload
// stored: the fields as floats, and the slopes' copy as the GL's own
// conversion of the same floats to half floats. Two frames, so the worker
// serves more than its first. Only a software rasteriser's view uploads.
TEST_F(SpectralFields, AnInteractiveViewUploadsTheOneThreadsTexelsBitForBit)
{
    if (!gl::isSoftwareRasterizer())
        GTEST_SKIP() << "a GPU runs the FFT passes in every view";
    SpectralSettings settings;
    settings.wind.windSpeed_mps = 20.0;
    const SpectralModel model(settings);
    const spectral::CpuSurface twin(std::make_shared<const spectral::SpectralField>(
        spectral::makeSpectralField(SeaSpectrum(settings.wind), settings.choppiness, settings.seed)));
    const std::unique_ptr<WaveModelGpu> gpu = model.createGpu(gl::ShaderSources::embedded());
    gpu->setInteractive(true);
    const int n = SWELL_FFT_SIZE, layers = SWELL_FFT_CASCADES;
    // The old upload's half floats: the single thread's floats through glTextureSubImage3D.
    gl::Texture reference = gl::Texture::create(GLenum(GL_TEXTURE_2D_ARRAY));
    glTextureStorage3D(reference.id(), 1, GL_RGBA16F, n, n, 2 * layers);
    for (double time_s : {731.5, 731.5 + 1.0 / 30.0}) {
        gpu->prepareFrame({12.0, -7.0}, time_s);
        gpu->bind();
        glMemoryBarrier(GL_TEXTURE_UPDATE_BARRIER_BIT);
        const std::vector<float> displacement = boundArray(SWELL_UNIT_OCEAN0, layers),
                                 derivatives = boundArray(SWELL_UNIT_OCEAN3, layers);
        const std::vector<std::uint16_t> slopes = boundHalves(SWELL_UNIT_OCEAN1, 2 * layers);

        spectral::FieldTexels expected;
        spectral::fieldTexels(twin.fieldsAt(time_s), layers, expected);
        glTextureSubImage3D(reference.id(), 0, 0, 0, 0, n, n, layers, GL_RGBA, GL_FLOAT, expected.derivatives.data());
        glTextureSubImage3D(reference.id(), 0, 0, 0, layers, n, n, layers, GL_RGBA, GL_FLOAT,
                            expected.slopeMoments.data());
        std::vector<std::uint16_t> expectedSlopes(slopes.size());
        glGetTextureImage(reference.id(), 0, GL_RGBA, GL_HALF_FLOAT,
                          GLsizei(expectedSlopes.size() * sizeof(std::uint16_t)), expectedSlopes.data());
        auto firstDifference = [](const auto& a, const auto& b) {
            size_t i = 0;
            while (i < a.size() && i < b.size() && a[i] == b[i])
                ++i;
            return i;
        };
        const size_t layerValues = size_t(n) * n * 4;
        // (Compared as whole vectors first: 8 million values; the message names the first that differs.)
        for (auto [name, got, want] : {std::tuple{"displacement", &displacement, &expected.displacement},
                                       std::tuple{"derivatives", &derivatives, &expected.derivatives}}) {
            ASSERT_EQ(got->size(), want->size());
            const size_t i = firstDifference(*got, *want);
            EXPECT_EQ(i, got->size()) << name << " at " << time_s << " s differs first in layer " << i / layerValues
                                      << ", value " << i % layerValues << ": " << (*got)[i] << " against "
                                      << (*want)[i];
        }
        ASSERT_EQ(slopes.size(), expectedSlopes.size());
        const size_t i = firstDifference(slopes, expectedSlopes);
        EXPECT_EQ(i, slopes.size()) << "slopes at " << time_s << " s differ first in layer " << i / layerValues
                                    << ", value " << i % layerValues << ": half 0x" << std::hex << slopes[i]
                                    << " against 0x" << expectedSlopes[i];
    }
}

} // namespace
