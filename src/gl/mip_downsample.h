// The mip chain of a square, power-of-two 2D array texture. On a GPU, a
// compute pass (shaders/mip_downsample.comp) instead of glGenerateMipmap:
// NVIDIA's driver took 0.18 to 0.36 ms of GPU time for each of the spectral
// model's chains on an H200, most of the simulation's 1.2 ms; the compute
// pass 0.035 ms (docs/PERFORMANCE.md). Each dispatch writes up to
// SWELL_DOWNSAMPLE_LEVELS levels from shared memory. On a software
// rasteriser the driver's own: llvmpipe ran the compute pass's barriers
// about 4 times slower than its mipmap generation (about 25 ms against 6
// for a 256^2 chain of 4 layers). Both are the same box filter.
#pragma once

#include "swell/gl/handle.h"
#include "swell/gl/shader_sources.h"

#include <epoxy/gl.h>

namespace swell::gl {

class MipDownsampler {
public:
    enum class Path {
        Fastest, // the compute pass on a GPU, the driver's on a software rasteriser
        Compute, // the compute pass everywhere (its tests)
    };
    explicit MipDownsampler(const ShaderSources& shaders, Path path = Path::Fastest);

    // What one chain asked of the GPU (the frame counters' figures).
    struct Work {
        int dispatches = 0;
        int barriers = 0;
        int driverChains = 0;        // glGenerateTextureMipmap calls
        long long texelsWritten = 0; // every layer's, every level's
    };

    // Levels 1 .. levels - 1 of `texture` (size x size at level 0, `layers`
    // layers, internal format `format`, `levels` levels: all it has) from
    // level 0, each texel the mean of the 2 x 2 below it. Level 0 must be visible to texture fetches (a
    // GL_TEXTURE_FETCH_BARRIER_BIT after the writes that made it); the
    // levels written are, on return, for fetches and image loads alike.
    Work run(const Texture& texture, GLenum format, int size, int levels, int layers) const;

private:
    bool compute_ = true;
    Program program_;
    GLint sourceLevelLocation_ = -1, levelsLocation_ = -1;
};

} // namespace swell::gl
