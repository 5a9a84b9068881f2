#include "gl/mip_downsample.h"

#include "swell/error.h"
#include "swell/gl/context.h"
#include "swell/gl/shader.h"
#include "swell/shader_constants.h"

#include <fmt/format.h>

#include <algorithm>
#include <bit>

namespace swell::gl {

namespace {
constexpr int kLevelsADispatch = SWELL_DOWNSAMPLE_LEVELS;
constexpr int kGroupSide = 1 << (kLevelsADispatch - 1);
} // namespace

MipDownsampler::MipDownsampler(const ShaderSources& shaders, Path path)
    : compute_(path == Path::Compute || !isSoftwareRasterizer())
{
    // Built only where it runs: a software rasteriser keeps the driver's.
    if (!compute_)
        return;
    program_ = buildProgram(shaders, {{GL_COMPUTE_SHADER, "mip_downsample.comp"}});
    sourceLevelLocation_ = glGetUniformLocation(program_.id(), "sourceLevel");
    levelsLocation_ = glGetUniformLocation(program_.id(), "levels");
}

MipDownsampler::Work MipDownsampler::run(const Texture& texture, GLenum format, int size, int levels, int layers) const
{
    if (size < 1 || !std::has_single_bit(unsigned(size)) || levels < 1 || (1 << (levels - 1)) > size || layers < 1)
        throw Error(fmt::format("swell::gl::MipDownsampler::run(): {} levels of a {}^2 texture ({} layers): the "
                                "size must be a power of two with that many levels",
                                levels, size, layers));
    Work work;
    if (!compute_) {
        glGenerateTextureMipmap(texture.id());
        ++work.driverChains;
        for (int l = 1; l < levels; ++l)
            work.texelsWritten += (long long)(size >> l) * (size >> l) * layers;
        return work;
    }
    glUseProgram(program_.id());
    glBindTextureUnit(SWELL_UNIT_DOWNSAMPLE_SOURCE, texture.id());
    for (int source = 0; source + 1 < levels; source += kLevelsADispatch) {
        const int count = std::min(kLevelsADispatch, levels - 1 - source);
        for (int k = 0; k < kLevelsADispatch; ++k) {
            if (k < count)
                glBindImageTexture(GLuint(k), texture.id(), source + 1 + k, GL_TRUE, 0, GL_WRITE_ONLY, format);
            else
                glBindImageTexture(GLuint(k), 0, 0, GL_FALSE, 0, GL_WRITE_ONLY, GL_RGBA32F);
        }
        glUniform1i(sourceLevelLocation_, source);
        glUniform1i(levelsLocation_, count);
        const int first = std::max(size >> (source + 1), 1); // the first level written's side
        const GLuint groups = GLuint((first + kGroupSide - 1) / kGroupSide);
        glDispatchCompute(groups, groups, GLuint(layers));
        ++work.dispatches;
        glMemoryBarrier(GL_TEXTURE_FETCH_BARRIER_BIT | GL_SHADER_IMAGE_ACCESS_BARRIER_BIT);
        ++work.barriers;
        for (int k = 0; k < count; ++k) {
            const long long side = std::max(size >> (source + 1 + k), 1);
            work.texelsWritten += side * side * layers;
        }
    }
    for (int k = 0; k < kLevelsADispatch; ++k)
        glBindImageTexture(GLuint(k), 0, 0, GL_FALSE, 0, GL_WRITE_ONLY, GL_RGBA32F);
    glBindTextureUnit(SWELL_UNIT_DOWNSAMPLE_SOURCE, 0);
    glUseProgram(0);
    return work;
}

} // namespace swell::gl
