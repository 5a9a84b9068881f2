#include "render/host_colour.h"

namespace swell::detail {

GLuint HostColourCopy::copy(GLuint framebuffer, glm::ivec4 viewport, GLenum format)
{
    const glm::ivec2 size(viewport.z, viewport.w);
    if (!texture_ || format != format_ || size != size_) {
        texture_ = gl::Texture::create(GLenum(GL_TEXTURE_2D));
        glTextureStorage2D(texture_.id(), 1, format, size.x, size.y);
        glTextureParameteri(texture_.id(), GL_TEXTURE_MIN_FILTER, GL_LINEAR);
        glTextureParameteri(texture_.id(), GL_TEXTURE_MAG_FILTER, GL_LINEAR);
        glTextureParameteri(texture_.id(), GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
        glTextureParameteri(texture_.id(), GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
        framebuffer_ = gl::Framebuffer::create();
        glNamedFramebufferTexture(framebuffer_.id(), GL_COLOR_ATTACHMENT0, texture_.id(), 0);
        format_ = format;
        size_ = size;
    }
    // Blits obey the scissor test and the colour mask.
    glDisable(GL_SCISSOR_TEST);
    glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
    glBlitNamedFramebuffer(framebuffer, framebuffer_.id(), viewport.x, viewport.y, viewport.x + size.x,
                           viewport.y + size.y, 0, 0, size.x, size.y, GL_COLOR_BUFFER_BIT, GL_NEAREST);
    return texture_.id();
}

} // namespace swell::detail
