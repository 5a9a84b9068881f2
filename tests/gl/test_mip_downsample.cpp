// The compute pass that builds the spectral model's mip chains
// (gl/mip_downsample.h) against the box filter computed here: every texel
// of every level is the mean of the 2 x 2 below it, for the formats and
// sizes Swell uses, across layers and across the boundary between two
// dispatches (levels 5 and 6), where a wrong source level or block offset
// shows.
#include "support/gl_test.h"

#include "gl/mip_downsample.h"
#include "swell/error.h"
#include "swell/shader_constants.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <vector>

namespace {

using namespace swell;

class MipDownsample : public test::GlTest {};

struct Case {
    GLenum format;
    int size, levels, layers, channels;
    double tolerance; // relative to the values' range (1): R16F keeps 11 bits
};

void check(const Case& c, gl::MipDownsampler::Path path)
{
    SCOPED_TRACE(testing::Message() << "size " << c.size << ", levels " << c.levels << ", layers " << c.layers
                                    << ", channels " << c.channels);
    gl::Texture texture = gl::Texture::create(GLenum(GL_TEXTURE_2D_ARRAY));
    glTextureStorage3D(texture.id(), c.levels, c.format, c.size, c.size, c.layers);
    // Level 0: values in [-1, 1] whose means differ from level to level (no
    // constant or smooth field, which a wrong offset would reproduce).
    std::mt19937 random(7u + unsigned(c.size));
    std::uniform_real_distribution<float> value(-1.0f, 1.0f);
    std::vector<float> base(size_t(c.size) * c.size * c.layers * 4);
    for (float& v : base)
        v = value(random);
    glTextureSubImage3D(texture.id(), 0, 0, 0, 0, c.size, c.size, c.layers, GL_RGBA, GL_FLOAT, base.data());
    glMemoryBarrier(GL_TEXTURE_FETCH_BARRIER_BIT);
    // What level 0 holds after the format's rounding: the reference starts there.
    std::vector<float> level(base.size());
    glGetTextureImage(texture.id(), 0, GL_RGBA, GL_FLOAT, GLsizei(level.size() * sizeof(float)), level.data());

    const gl::MipDownsampler downsampler(gl::ShaderSources::embedded(), path);
    const gl::MipDownsampler::Work work = downsampler.run(texture, c.format, c.size, c.levels, c.layers);
    if (work.driverChains == 0) {
        EXPECT_EQ(work.dispatches, (c.levels - 1 + SWELL_DOWNSAMPLE_LEVELS - 1) / SWELL_DOWNSAMPLE_LEVELS);
        EXPECT_EQ(work.barriers, work.dispatches);
    } else {
        EXPECT_EQ(path, gl::MipDownsampler::Path::Fastest) << "the compute pass was asked for";
        EXPECT_EQ(work.driverChains, 1);
        EXPECT_EQ(work.dispatches, 0);
    }

    long long texels = 0;
    int side = c.size;
    for (int l = 1; l < c.levels; ++l) {
        const int below = side;
        side /= 2;
        texels += (long long)side * side * c.layers;
        std::vector<float> expected(size_t(side) * side * c.layers * 4);
        for (int layer = 0; layer < c.layers; ++layer)
            for (int y = 0; y < side; ++y)
                for (int x = 0; x < side; ++x)
                    for (int ch = 0; ch < 4; ++ch) {
                        auto at = [&](int xx, int yy) {
                            return level[((size_t(layer) * below + yy) * below + xx) * 4 + ch];
                        };
                        expected[((size_t(layer) * side + y) * side + x) * 4 + ch] =
                            0.25f * ((at(2 * x, 2 * y) + at(2 * x + 1, 2 * y)) + (at(2 * x, 2 * y + 1) + at(2 * x + 1, 2 * y + 1)));
                    }
        std::vector<float> actual(expected.size());
        glGetTextureImage(texture.id(), l, GL_RGBA, GL_FLOAT, GLsizei(actual.size() * sizeof(float)), actual.data());
        double worst = 0.0;
        int worstX = -1, worstY = -1, worstLayer = -1;
        for (int layer = 0; layer < c.layers; ++layer)
            for (int y = 0; y < side; ++y)
                for (int x = 0; x < side; ++x)
                    for (int ch = 0; ch < c.channels; ++ch) {
                        const size_t i = ((size_t(layer) * side + y) * side + x) * 4 + ch;
                        if (const double e = std::abs(double(actual[i]) - double(expected[i])); e > worst) {
                            worst = e;
                            worstX = x, worstY = y, worstLayer = layer;
                        }
                    }
        EXPECT_LE(worst, c.tolerance) << "level " << l << ", worst at texel " << worstX << ", " << worstY
                                      << " of layer " << worstLayer;
        // The next level's reference starts from what this level holds (the
        // format's rounding at each level, as the GPU's chain has it).
        level = std::move(actual);
    }
    EXPECT_EQ(work.texelsWritten, texels);
}

// The compute pass, and whichever path this machine takes (the driver's on
// llvmpipe): the same filter.
TEST_F(MipDownsample, EveryLevelIsTheMeanOfTheTwoByTwoBelowIt)
{
    for (const auto path : {gl::MipDownsampler::Path::Compute, gl::MipDownsampler::Path::Fastest}) {
        SCOPED_TRACE(path == gl::MipDownsampler::Path::Compute ? "compute pass" : "this machine's path");
        // The spectral fields and moments, and the foam (swell/shader_constants.h).
        check({GL_RGBA32F, 1 << SWELL_FFT_LOG2_SIZE, SWELL_FFT_LOG2_SIZE + 1, SWELL_FFT_CASCADES, 4, 1e-6}, path);
        check({GL_R16F, 1 << SWELL_FOAM_LOG2_SIZE, SWELL_FOAM_LOG2_SIZE + 1, SWELL_FOAM_LEVELS, 1, 1e-3}, path);
        // Smaller chains: one dispatch, a dispatch's every level, one level
        // past it, and a texture of few levels.
        check({GL_RGBA32F, 2, 2, 1, 4, 1e-6}, path);
        check({GL_RGBA32F, 32, 6, 3, 4, 1e-6}, path);
        check({GL_RGBA32F, 64, 7, 1, 4, 1e-6}, path);
        check({GL_RGBA32F, 512, 4, 2, 4, 1e-6}, path);
    }
}

TEST_F(MipDownsample, RefusesWhatItCannotBuild)
{
    gl::Texture texture = gl::Texture::create(GLenum(GL_TEXTURE_2D_ARRAY));
    glTextureStorage3D(texture.id(), 2, GL_RGBA32F, 24, 24, 1);
    const gl::MipDownsampler downsampler(gl::ShaderSources::embedded(), gl::MipDownsampler::Path::Compute);
    EXPECT_THROW(downsampler.run(texture, GL_RGBA32F, 24, 2, 1), Error) << "not a power of two";
    EXPECT_THROW(downsampler.run(texture, GL_RGBA32F, 4, 4, 1), Error) << "more levels than the size has";
}

} // namespace
