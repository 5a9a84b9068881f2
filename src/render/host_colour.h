// A copy of the host's colour under a view's viewport, for a view that
// draw() draws through its own main target (a render scale, antialiasing or
// the temporal resolve): the host's picture is brought into the target
// before the water is drawn over it, and the result filtered back into the
// viewport. A pass cannot sample the buffer it draws into, nor a host's
// renderbuffer or default framebuffer at all: the copy is a texture, of the
// viewport's size.
#pragma once

#include "swell/gl/handle.h"

#include <glm/vec2.hpp>
#include <glm/vec4.hpp>

namespace swell::detail {

class HostColourCopy {
public:
    // Copies `framebuffer`'s colour (its first draw buffer) under `viewport`
    // into a texture of `format` (GL_RGBA8, or GL_RGBA16F for a linear
    // output) and returns it. A multisampled framebuffer is resolved on the
    // way. Leaves no framebuffer bound.
    GLuint copy(GLuint framebuffer, glm::ivec4 viewport, GLenum format);

private:
    gl::Texture texture_;
    gl::Framebuffer framebuffer_;
    glm::ivec2 size_{0};
    GLenum format_ = 0;
};

} // namespace swell::detail
