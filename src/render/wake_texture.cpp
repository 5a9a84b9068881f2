// The wake's texture and uniform block (wake_texture.h).
#include "render/wake_texture.h"

#include "swell/shader_constants.h"

namespace swell::detail {

void WakeTexture::upload(const WakeFrame* frame, glm::dvec3 origin)
{
    if (!uniforms_) {
        uniforms_ = gl::Buffer::create();
        glNamedBufferStorage(uniforms_.id(), sizeof(WakeUniforms), nullptr, GL_DYNAMIC_STORAGE_BIT);
    }
    const int cells = frame && frame->cells > 0 ? frame->cells : 1;
    if (!texture_ || cells != cells_) {
        // A 1x1 texture when there is no wake, so the unit is never empty.
        texture_ = gl::Texture::create(GLenum(GL_TEXTURE_2D));
        glTextureStorage2D(texture_.id(), 1, GL_RGBA32F, cells, cells);
        glTextureParameteri(texture_.id(), GL_TEXTURE_MIN_FILTER, GL_NEAREST);
        glTextureParameteri(texture_.id(), GL_TEXTURE_MAG_FILTER, GL_NEAREST);
        cells_ = cells;
        const float zero[4] = {0.0f, 0.0f, 0.0f, 0.0f};
        glClearTexImage(texture_.id(), 0, GL_RGBA, GL_FLOAT, zero);
    }
    WakeUniforms u;
    if (frame && frame->cells > 0) {
        glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
        glTextureSubImage2D(texture_.id(), 0, 0, 0, cells, cells, GL_RGBA, GL_FLOAT, frame->texels.data());
        // The corner relative to the render origin, subtracted in double so
        // the float keeps centimetres however far from the world origin.
        const glm::dvec2 corner = frame->corner_m() - glm::dvec2(origin.x, origin.z);
        u.corner_m = glm::vec2(corner);
        u.cellSize_m = float(frame->cellSize_m);
        u.cells = frame->cells;
        const glm::ivec2 period(SWELL_WAKE_NOISE_PERIOD);
        u.cornerCell = ((frame->cornerCell % period) + period) % period;
    }
    glNamedBufferSubData(uniforms_.id(), 0, sizeof(u), &u);
}

void WakeTexture::bind() const
{
    glBindTextureUnit(SWELL_UNIT_WAKE, texture_.id());
    glBindBufferBase(GL_UNIFORM_BUFFER, SWELL_BINDING_WAKE, uniforms_.id());
}

} // namespace swell::detail
