// Copies of the host's framebuffer under a view's viewport, as textures of
// the viewport's size, for draw(): its depth, for the pass that fogs the
// host's geometry seen from under the water (shaders/underwater_host.frag);
// and its colour and depth, brought into a view's own target when draw()
// draws the view through it (a render scale, antialiasing or the temporal
// resolve; render/view_passes.h). A pass cannot sample the buffer it draws
// into, nor a host's renderbuffer or default framebuffer at all. A depth
// copy has the host's depth format (a blit copies depth only between equal
// formats); a multisampled framebuffer is resolved on the way.
#pragma once

#include "swell/gl/handle.h"

#include <glm/vec2.hpp>
#include <glm/vec4.hpp>

namespace swell::detail {

class HostCopy {
public:
    // Copies `framebuffer`'s depth under `viewport` and returns the copy's
    // texture. Leaves no framebuffer bound.
    GLuint copyDepth(GLuint framebuffer, glm::ivec4 viewport);
    // Copies its colour (its read buffer) into a texture of `format`
    // (GL_RGBA8, or GL_RGBA16F for a linear output), filtered bilinearly.
    GLuint copyColour(GLuint framebuffer, glm::ivec4 viewport, GLenum format);
    // The last copy's texture (0 before the first).
    GLuint texture() const { return texture_.id(); }

private:
    GLuint copy(GLuint framebuffer, glm::ivec4 viewport, GLenum format, bool depth);

    gl::Texture texture_;
    gl::Framebuffer framebuffer_;
    glm::ivec2 size_{0};
    GLenum format_ = 0;
};

} // namespace swell::detail
