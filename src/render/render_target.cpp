#include "render/render_target.h"

#include "swell/error.h"

namespace swell::detail {

void RenderTarget::resize(glm::ivec2 size, GLenum colorFormat)
{
    if (size == size_ && colorFormat == colorFormat_)
        return;
    colorFormat_ = colorFormat;
    framebuffer_.reset();
    color_.reset();
    depth_.reset();
    size_ = size;
    if (size.x <= 0 || size.y <= 0) {
        size_ = {0, 0};
        return;
    }
    color_ = gl::Texture::create(GLenum(GL_TEXTURE_2D));
    // Half floats for intermediate images: the sun's highlight exceeds 1.
    glTextureStorage2D(color_.id(), 1, colorFormat, size.x, size.y);
    glTextureParameteri(color_.id(), GL_TEXTURE_MIN_FILTER, GL_LINEAR);
    glTextureParameteri(color_.id(), GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    glTextureParameteri(color_.id(), GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
    glTextureParameteri(color_.id(), GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
    depth_ = gl::Texture::create(GLenum(GL_TEXTURE_2D));
    glTextureStorage2D(depth_.id(), 1, GL_DEPTH_COMPONENT32F, size.x, size.y);
    glTextureParameteri(depth_.id(), GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTextureParameteri(depth_.id(), GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    glTextureParameteri(depth_.id(), GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
    glTextureParameteri(depth_.id(), GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
    framebuffer_ = gl::Framebuffer::create();
    glNamedFramebufferTexture(framebuffer_.id(), GL_COLOR_ATTACHMENT0, color_.id(), 0);
    glNamedFramebufferTexture(framebuffer_.id(), GL_DEPTH_ATTACHMENT, depth_.id(), 0);
    if (glCheckNamedFramebufferStatus(framebuffer_.id(), GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE)
        throw Error("swell::RenderTarget::resize(): framebuffer incomplete");
}

} // namespace swell::detail
