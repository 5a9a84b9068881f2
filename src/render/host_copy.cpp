#include "render/host_copy.h"

#include "swell/error.h"

#include <fmt/format.h>

namespace swell::detail {

namespace {

// The sized internal format of a framebuffer's depth buffer, from its bits
// and component type (the default framebuffer has no texture to ask).
GLenum depthFormatOf(GLuint framebuffer)
{
    const GLenum attachment = framebuffer == 0 ? GL_DEPTH : GL_DEPTH_ATTACHMENT;
    GLint depthBits = 0, stencilBits = 0, type = GL_NONE;
    glGetNamedFramebufferAttachmentParameteriv(framebuffer, attachment, GL_FRAMEBUFFER_ATTACHMENT_DEPTH_SIZE, &depthBits);
    glGetNamedFramebufferAttachmentParameteriv(framebuffer, attachment, GL_FRAMEBUFFER_ATTACHMENT_COMPONENT_TYPE, &type);
    // Sizes may only be asked of an attachment that is there.
    const GLenum stencil = framebuffer == 0 ? GL_STENCIL : GL_STENCIL_ATTACHMENT;
    GLint stencilType = GL_NONE;
    glGetNamedFramebufferAttachmentParameteriv(framebuffer, stencil, GL_FRAMEBUFFER_ATTACHMENT_OBJECT_TYPE, &stencilType);
    if (stencilType != GL_NONE)
        glGetNamedFramebufferAttachmentParameteriv(framebuffer, stencil, GL_FRAMEBUFFER_ATTACHMENT_STENCIL_SIZE, &stencilBits);
    // A stencil attachment that is not the depth buffer's own does not make it a depth-stencil format.
    if (framebuffer != 0 && stencilType != GL_NONE) {
        GLint depthName = 0, stencilName = 0;
        glGetNamedFramebufferAttachmentParameteriv(framebuffer, GL_DEPTH_ATTACHMENT, GL_FRAMEBUFFER_ATTACHMENT_OBJECT_NAME, &depthName);
        glGetNamedFramebufferAttachmentParameteriv(framebuffer, GL_STENCIL_ATTACHMENT, GL_FRAMEBUFFER_ATTACHMENT_OBJECT_NAME, &stencilName);
        if (stencilName != depthName)
            stencilBits = 0;
    }
    const bool floating = type == GL_FLOAT;
    if (depthBits == 32 && floating)
        return stencilBits > 0 ? GL_DEPTH32F_STENCIL8 : GL_DEPTH_COMPONENT32F;
    if (depthBits == 24)
        return stencilBits > 0 ? GL_DEPTH24_STENCIL8 : GL_DEPTH_COMPONENT24;
    if (depthBits == 16)
        return GL_DEPTH_COMPONENT16;
    if (depthBits == 32)
        return GL_DEPTH_COMPONENT32;
    throw Error(fmt::format("framebuffer {}'s depth buffer ({} bits) has a format the water cannot copy", framebuffer,
                            depthBits));
}

bool hasStencil(GLenum format) { return format == GL_DEPTH24_STENCIL8 || format == GL_DEPTH32F_STENCIL8; }

} // namespace

GLuint HostCopy::copyDepth(GLuint framebuffer, glm::ivec4 viewport)
{
    return copy(framebuffer, viewport, depthFormatOf(framebuffer), true);
}

GLuint HostCopy::copyColour(GLuint framebuffer, glm::ivec4 viewport, GLenum format)
{
    return copy(framebuffer, viewport, format, false);
}

GLuint HostCopy::copy(GLuint framebuffer, glm::ivec4 viewport, GLenum format, bool depth)
{
    const glm::ivec2 size(viewport.z, viewport.w);
    if (!texture_ || format != format_ || size != size_) {
        texture_ = gl::Texture::create(GLenum(GL_TEXTURE_2D));
        glTextureStorage2D(texture_.id(), 1, format, size.x, size.y);
        // Depths are never blended; the colour is filtered into another size.
        const GLint filter = depth ? GL_NEAREST : GL_LINEAR;
        glTextureParameteri(texture_.id(), GL_TEXTURE_MIN_FILTER, filter);
        glTextureParameteri(texture_.id(), GL_TEXTURE_MAG_FILTER, filter);
        glTextureParameteri(texture_.id(), GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
        glTextureParameteri(texture_.id(), GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
        framebuffer_ = gl::Framebuffer::create();
        const GLenum attachment = !depth ? GL_COLOR_ATTACHMENT0
                                  : hasStencil(format) ? GL_DEPTH_STENCIL_ATTACHMENT
                                                       : GL_DEPTH_ATTACHMENT;
        glNamedFramebufferTexture(framebuffer_.id(), attachment, texture_.id(), 0);
        format_ = format;
        size_ = size;
    }
    // Colour blits obey the scissor test and the colour mask.
    glDisable(GL_SCISSOR_TEST);
    glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
    glBlitNamedFramebuffer(framebuffer, framebuffer_.id(), viewport.x, viewport.y, viewport.x + size.x,
                           viewport.y + size.y, 0, 0, size.x, size.y,
                           depth ? GL_DEPTH_BUFFER_BIT : GL_COLOR_BUFFER_BIT, GL_NEAREST);
    return texture_.id();
}

} // namespace swell::detail
