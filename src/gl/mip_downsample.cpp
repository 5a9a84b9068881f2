#include "gl/mip_downsample.h"

#include "gl/uniform_location.h"

#include "swell/error.h"
#include "swell/gl/context.h"
#include "swell/gl/shader.h"
#include "swell/gpu/bindings.h"

#include <fmt/format.h>

#include <algorithm>
#include <bit>

namespace swell::gl {

namespace {
// The shared-memory pass's workgroup side (one invocation a texel of the
// first level written); the blocks pass's (one invocation a block).
constexpr int kSharedGroupSide = 1 << (SWELL_DOWNSAMPLE_LEVELS - 1);
constexpr int kBlocksGroupSide = SWELL_DOWNSAMPLE_BLOCKS_GROUP;

void check(const MipDownsampler::Chain& c)
{
    if (c.texture == nullptr || c.size < 1 || !std::has_single_bit(unsigned(c.size)) || c.levels < 1 ||
        (1 << (c.levels - 1)) > c.size || c.layers < 1)
        throw Error(fmt::format("swell::gl::MipDownsampler::run(): {} levels of a {}^2 texture ({} layers): the "
                                "size must be a power of two with that many levels",
                                c.levels, c.size, c.layers));
}
} // namespace

int MipDownsampler::levelsADispatch(Path path)
{
    return path == Path::Blocks ? SWELL_DOWNSAMPLE_BLOCK_LEVELS : SWELL_DOWNSAMPLE_LEVELS;
}

MipDownsampler::MipDownsampler(const ShaderSources& shaders, Path path)
    : path_(path != Path::Fastest ? path : isSoftwareRasterizer() ? Path::Blocks : Path::SharedMemory)
{
    const char* file = path_ == Path::Blocks ? "mip_blocks.comp" : "mip_downsample.comp";
    program_ = buildProgram(shaders, {{GL_COMPUTE_SHADER, file}});
    sourceLevelLocation_ = requiredUniform(program_, "sourceLevel", file);
    levelsLocation_ = requiredUniform(program_, "levels", file);
    // Only the blocks pass builds two chains in one dispatch.
    if (path_ == Path::Blocks)
        layersALocation_ = requiredUniform(program_, "layersA", file);
}

MipDownsampler::Work MipDownsampler::run(const Chain& chain) const
{
    check(chain);
    return runTogether(chain, nullptr);
}

MipDownsampler::Work MipDownsampler::run(const Chain& a, const Chain& b) const
{
    check(a);
    check(b);
    if (path_ == Path::Blocks && a.size == b.size && a.levels == b.levels)
        return runTogether(a, &b);
    Work work = runTogether(a, nullptr);
    const Work second = runTogether(b, nullptr);
    work.dispatches += second.dispatches;
    work.barriers += second.barriers;
    work.texelsWritten += second.texelsWritten;
    return work;
}

MipDownsampler::Work MipDownsampler::runTogether(const Chain& a, const Chain* b) const
{
    Work work;
    // Image units 0 .. most - 1 hold the levels a dispatch writes, and
    // most .. 2 most - 1 chain b's.
    const int most = levelsADispatch(path_);
    const int layers = a.layers + (b ? b->layers : 0);
    glUseProgram(program_.id());
    glBindTextureUnit(SWELL_UNIT_DOWNSAMPLE_SOURCE, a.texture->id());
    if (b)
        glBindTextureUnit(SWELL_UNIT_DOWNSAMPLE_SOURCE_B, b->texture->id());
    if (layersALocation_ >= 0)
        glUniform1i(layersALocation_, a.layers);
    for (int source = 0; source + 1 < a.levels; source += most) {
        const int count = std::min(most, a.levels - 1 - source);
        for (const Chain* chain : {&a, b}) {
            if (chain == nullptr)
                continue;
            const GLuint first = chain == &a ? 0 : GLuint(most);
            for (int k = 0; k < most; ++k) {
                if (k < count)
                    glBindImageTexture(first + GLuint(k), chain->texture->id(), source + 1 + k, GL_TRUE, 0,
                                       GL_WRITE_ONLY, chain->format);
                else
                    glBindImageTexture(first + GLuint(k), 0, 0, GL_FALSE, 0, GL_WRITE_ONLY, GL_RGBA32F);
            }
        }
        glUniform1i(sourceLevelLocation_, source);
        glUniform1i(levelsLocation_, count);
        const int first = std::max(a.size >> (source + 1), 1); // the first level written's side
        // Shared memory: an invocation a texel of that level; blocks: an
        // invocation a block of it, 2^(count - 1) texels on a side.
        const int invocations = path_ == Path::Blocks ? first >> (count - 1) : first;
        const int groupSide = path_ == Path::Blocks ? kBlocksGroupSide : kSharedGroupSide;
        const GLuint groups = GLuint((invocations + groupSide - 1) / groupSide);
        glDispatchCompute(groups, groups, GLuint(layers));
        ++work.dispatches;
        glMemoryBarrier(GL_TEXTURE_FETCH_BARRIER_BIT | GL_SHADER_IMAGE_ACCESS_BARRIER_BIT);
        ++work.barriers;
        for (int k = 0; k < count; ++k) {
            const long long side = std::max(a.size >> (source + 1 + k), 1);
            work.texelsWritten += side * side * layers;
        }
    }
    for (int k = 0; k < (b ? 2 : 1) * most; ++k)
        glBindImageTexture(GLuint(k), 0, 0, GL_FALSE, 0, GL_WRITE_ONLY, GL_RGBA32F);
    glBindTextureUnit(SWELL_UNIT_DOWNSAMPLE_SOURCE, 0);
    if (b)
        glBindTextureUnit(SWELL_UNIT_DOWNSAMPLE_SOURCE_B, 0);
    glUseProgram(0);
    return work;
}

} // namespace swell::gl
