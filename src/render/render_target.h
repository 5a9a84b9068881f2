// An offscreen colour + depth target (reflection, refraction, headless output).
#pragma once

#include "swell/gl/handle.h"

#include <glm/vec2.hpp>

namespace swell::detail {

class RenderTarget {
public:
    // Recreates the textures when the size or format changes; a 0x0 size frees them.
    // colorFormat: GL_RGBA16F for linear intermediate images, GL_RGBA8 for output.
    void resize(glm::ivec2 size, GLenum colorFormat = GL_RGBA16F);
    glm::ivec2 size() const { return size_; }
    GLuint framebuffer() const { return framebuffer_.id(); }
    GLuint color() const { return color_.id(); }
    GLuint depth() const { return depth_.id(); }

private:
    glm::ivec2 size_{0, 0};
    GLenum colorFormat_ = 0;
    gl::Framebuffer framebuffer_;
    gl::Texture color_, depth_;
};

} // namespace swell::detail
