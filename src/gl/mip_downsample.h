// The mip chain of a square, power-of-two 2D array texture, by a compute
// pass rather than glGenerateMipmap. On a GPU, shaders/mip_downsample.comp
// reduces blocks in shared memory: NVIDIA's driver took 0.18 to 0.36 ms of
// GPU time for each of the spectral model's chains on an H200, most of the
// simulation's 1.2 ms; the pass 0.035 ms (docs/design/performance-log.md). On a
// software rasteriser, shaders/mip_blocks.comp: each invocation reduces its
// own block, without the barriers llvmpipe emulates slowly (the
// shared-memory pass took about 25 ms a 4-layer 256^2 chain there) and
// without the driver's draw per level and layer, which cost the calling
// thread about 0.5 ms of CPU a chain. All are the same box filter.
#pragma once

#include "swell/gl/handle.h"
#include "swell/gl/shader_sources.h"

#include <epoxy/gl.h>

namespace swell::gl {

class MipDownsampler {
public:
    enum class Path {
        Fastest,      // shared memory on a GPU, blocks on a software rasteriser
        SharedMemory, // shaders/mip_downsample.comp (its tests)
        Blocks,       // shaders/mip_blocks.comp (its tests)
    };
    explicit MipDownsampler(const ShaderSources& shaders, Path path = Path::Fastest);

    // What one chain asked of the GPU (the frame counters' figures).
    struct Work {
        int dispatches = 0;
        int barriers = 0;
        long long texelsWritten = 0; // every layer's, every level's
    };

    // A texture whose chain is built: size x size at level 0, `layers`
    // layers, internal format `format`, `levels` levels (all it has).
    struct Chain {
        const Texture* texture = nullptr;
        GLenum format = 0;
        int size = 0, levels = 0, layers = 0;
    };

    // Levels 1 .. levels - 1 of the chain's texture from level 0, each
    // texel the mean of the 2 x 2 below it. Level 0 must be visible to
    // texture fetches (a GL_TEXTURE_FETCH_BARRIER_BIT after the writes that
    // made it); the levels written are, on return, for fetches and image
    // loads alike.
    Work run(const Chain& chain) const;
    // Two chains: in the same dispatches on the blocks path when they have
    // the same size and levels, one after the other otherwise.
    Work run(const Chain& a, const Chain& b) const;

    // Which pass this one runs (Fastest resolved for this machine).
    Path path() const { return path_; }

    // How many levels one dispatch of `path` writes.
    static int levelsADispatch(Path path);

private:
    // Both chains' levels in the same dispatches (b: none, or one of a's
    // size and levels; the blocks path only when given b).
    Work runTogether(const Chain& a, const Chain* b) const;

    Path path_;
    Program program_;
    GLint sourceLevelLocation_ = -1, levelsLocation_ = -1, layersALocation_ = -1;
};

} // namespace swell::gl
