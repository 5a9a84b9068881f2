// The wake's texture and uniform block (wake_texture.h).
#include "render/wake_texture.h"

#include "swell/gpu/bindings.h"

namespace swell::detail {

void WakeTexture::upload(const WakeFrame* frame)
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
    hasWake_ = frame && frame->cells > 0;
    if (hasWake_) {
        GLint unpackAlignment = 4;
        glGetIntegerv(GL_UNPACK_ALIGNMENT, &unpackAlignment);
        glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
        glTextureSubImage2D(texture_.id(), 0, 0, 0, cells, cells, GL_RGBA, GL_FLOAT, frame->texels.data());
        glPixelStorei(GL_UNPACK_ALIGNMENT, unpackAlignment);
        corner_m_ = frame->corner_m();
        cellSize_m_ = frame->cellSize_m;
    }
}

void WakeTexture::place(glm::dvec3 origin)
{
    WakeUniforms u;
    if (hasWake_) {
        // The corner relative to the render origin, subtracted in double so
        // the float keeps centimetres however far from the world origin.
        u.corner_m = glm::vec2(corner_m_ - glm::dvec2(origin.x, origin.z));
        u.cellSize_m = float(cellSize_m_);
        u.cells = cells_;
    }
    glNamedBufferSubData(uniforms_.id(), 0, sizeof(u), &u);
}

void WakeTexture::bind() const
{
    glBindTextureUnit(SWELL_UNIT_WAKE, texture_.id());
    glBindBufferBase(GL_UNIFORM_BUFFER, SWELL_BINDING_WAKE, uniforms_.id());
}

} // namespace swell::detail
