// The compute passes that build the spectral model's mip chains
// (gl/mip_downsample.h) against the box filter computed here: every texel
// of every level is the mean of the 2 x 2 below it, for the formats and
// sizes Swell uses, across layers and across the boundary between two
// dispatches (levels 4 and 5 by blocks, 5 and 6 from shared memory), where
// a wrong source level or block offset shows.
#include "support/gl_test.h"

#include "gl/mip_downsample.h"
#include "swell/error.h"
#include "swell/gpu/ocean.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <vector>

namespace {

using namespace swell;

class MipDownsample : public test::GlTest {};

struct MipDownsampleCase {
    GLenum format;
    int size, levels, layers, channels;
    double tolerance; // relative to the values' range (1): R16F keeps 11 bits
};

// A texture for the case whose level 0 holds values in [-1, 1] whose means
// differ from level to level (no constant or smooth field, which a wrong
// offset would reproduce); `seed` tells two textures apart.
gl::Texture filledTexture(const MipDownsampleCase& c, unsigned seed)
{
    gl::Texture texture = gl::Texture::create(GLenum(GL_TEXTURE_2D_ARRAY));
    glTextureStorage3D(texture.id(), c.levels, c.format, c.size, c.size, c.layers);
    std::mt19937 random(seed + unsigned(c.size));
    std::uniform_real_distribution<float> value(-1.0f, 1.0f);
    std::vector<float> base(size_t(c.size) * c.size * c.layers * 4);
    for (float& v : base)
        v = value(random);
    glTextureSubImage3D(texture.id(), 0, 0, 0, 0, c.size, c.size, c.layers, GL_RGBA, GL_FLOAT, base.data());
    glMemoryBarrier(GL_TEXTURE_FETCH_BARRIER_BIT);
    return texture;
}

// Every level of the texture's chain against the box filter of the level
// below as the texture holds it (the format's rounding at each level, as
// the GPU's chain has it). Returns the texels of levels 1 and up.
long long expectBoxFiltered(const gl::Texture& texture, const MipDownsampleCase& c)
{
    std::vector<float> level(size_t(c.size) * c.size * c.layers * 4);
    glGetTextureImage(texture.id(), 0, GL_RGBA, GL_FLOAT, GLsizei(level.size() * sizeof(float)), level.data());
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
        level = std::move(actual);
    }
    return texels;
}

void check(const MipDownsampleCase& c, gl::MipDownsampler::Path path)
{
    SCOPED_TRACE(testing::Message() << "size " << c.size << ", levels " << c.levels << ", layers " << c.layers
                                    << ", channels " << c.channels);
    const gl::Texture texture = filledTexture(c, 7u);
    const gl::MipDownsampler downsampler(gl::ShaderSources::embedded(), path);
    const gl::MipDownsampler::Work work = downsampler.run({&texture, c.format, c.size, c.levels, c.layers});
    if (path != gl::MipDownsampler::Path::Fastest) {
        EXPECT_EQ(downsampler.path(), path);
    }
    const int most = gl::MipDownsampler::levelsADispatch(downsampler.path());
    EXPECT_EQ(work.dispatches, (c.levels - 1 + most - 1) / most);
    EXPECT_EQ(work.barriers, work.dispatches);
    EXPECT_EQ(work.texelsWritten, expectBoxFiltered(texture, c));
}

// Both compute passes, and whichever this machine takes: the same filter.
TEST_F(MipDownsample, EveryLevelIsTheMeanOfTheTwoByTwoBelowIt)
{
    using Path = gl::MipDownsampler::Path;
    for (const auto path : {Path::SharedMemory, Path::Blocks, Path::Fastest}) {
        SCOPED_TRACE(path == Path::SharedMemory ? "shared memory" : path == Path::Blocks ? "blocks" : "this machine's path");
        // The spectral fields and moments, and the foam (swell/gpu/ocean.h).
        check({GL_RGBA32F, 1 << SWELL_FFT_LOG2_SIZE, SWELL_FFT_LOG2_SIZE + 1, SWELL_FFT_CASCADES, 4, 1e-6}, path);
        check({GL_R16F, 1 << SWELL_FOAM_LOG2_SIZE, SWELL_FOAM_LOG2_SIZE + 1, SWELL_FOAM_LEVELS, 1, 1e-3}, path);
        // Smaller chains: one dispatch, a dispatch's every level, one level
        // past it (for both passes' dispatches), and a texture of few levels.
        check({GL_RGBA32F, 2, 2, 1, 4, 1e-6}, path);
        check({GL_RGBA32F, 32, 6, 3, 4, 1e-6}, path);
        check({GL_RGBA32F, 64, 7, 1, 4, 1e-6}, path);
        check({GL_RGBA32F, 16, 5, 2, 4, 1e-6}, path);
        check({GL_RGBA32F, 32, 5, 1, 4, 1e-6}, path);
        check({GL_RGBA32F, 512, 4, 2, 4, 1e-6}, path);
    }
}

// Two chains in one call, as the spectral model builds its slopes' and its
// foam's (two textures, two formats): on the blocks path in the same
// dispatches, chain B's layers after chain A's, where a wrong layer offset,
// source or image unit shows; chains of different sizes one after the other.
TEST_F(MipDownsample, TwoChainsInOneCall)
{
    using Path = gl::MipDownsampler::Path;
    const MipDownsampleCase slopes{GL_RGBA32F, 1 << SWELL_FFT_LOG2_SIZE, SWELL_FFT_LOG2_SIZE + 1, 2 * SWELL_FFT_CASCADES, 4, 1e-6};
    const MipDownsampleCase foam{GL_R16F, 1 << SWELL_FOAM_LOG2_SIZE, SWELL_FOAM_LOG2_SIZE + 1, SWELL_FOAM_LEVELS, 1, 1e-3};
    const MipDownsampleCase smaller{GL_RGBA32F, 64, 7, 3, 4, 1e-6};
    for (const auto path : {Path::SharedMemory, Path::Blocks}) {
        SCOPED_TRACE(path == Path::SharedMemory ? "shared memory" : "blocks");
        const gl::MipDownsampler downsampler(gl::ShaderSources::embedded(), path);
        const int most = gl::MipDownsampler::levelsADispatch(path);
        const gl::Texture a = filledTexture(slopes, 11u), b = filledTexture(foam, 13u);
        const gl::MipDownsampler::Work work = downsampler.run({&a, slopes.format, slopes.size, slopes.levels, slopes.layers},
                                                              {&b, foam.format, foam.size, foam.levels, foam.layers});
        const int chainDispatches = (slopes.levels - 1 + most - 1) / most;
        EXPECT_EQ(work.dispatches, path == Path::Blocks ? chainDispatches : 2 * chainDispatches);
        EXPECT_EQ(work.barriers, work.dispatches);
        {
            SCOPED_TRACE("chain A");
            const long long texelsA = expectBoxFiltered(a, slopes);
            SCOPED_TRACE("chain B");
            EXPECT_EQ(work.texelsWritten, texelsA + expectBoxFiltered(b, foam));
        }
        // Another size: one chain after the other.
        const gl::Texture c = filledTexture(smaller, 17u), d = filledTexture(foam, 19u);
        const gl::MipDownsampler::Work apart = downsampler.run({&c, smaller.format, smaller.size, smaller.levels, smaller.layers},
                                                               {&d, foam.format, foam.size, foam.levels, foam.layers});
        EXPECT_EQ(apart.dispatches, (smaller.levels - 1 + most - 1) / most + chainDispatches);
        SCOPED_TRACE("apart");
        const long long texelsC = expectBoxFiltered(c, smaller);
        EXPECT_EQ(apart.texelsWritten, texelsC + expectBoxFiltered(d, foam));
    }
}

TEST_F(MipDownsample, RefusesWhatItCannotBuild)
{
    gl::Texture texture = gl::Texture::create(GLenum(GL_TEXTURE_2D_ARRAY));
    glTextureStorage3D(texture.id(), 2, GL_RGBA32F, 24, 24, 1);
    const gl::MipDownsampler downsampler(gl::ShaderSources::embedded(), gl::MipDownsampler::Path::SharedMemory);
    EXPECT_THROW(downsampler.run({&texture, GL_RGBA32F, 24, 2, 1}), Error) << "not a power of two";
    EXPECT_THROW(downsampler.run({&texture, GL_RGBA32F, 4, 4, 1}), Error) << "more levels than the size has";
    EXPECT_THROW(downsampler.run({nullptr, GL_RGBA32F, 4, 3, 1}), Error) << "no texture";
}

} // namespace
