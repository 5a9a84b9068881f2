// A copy of the host's depth under a view's viewport, for the pass that
// fogs the host's geometry seen from under the water (shaders/
// underwater_host.frag): a pass cannot sample the depth buffer it draws
// into. The copy has the host's depth format (a blit copies depth only
// between equal formats) and the viewport's size.
#pragma once

#include "swell/gl/handle.h"

#include <glm/vec2.hpp>
#include <glm/vec4.hpp>

namespace swell::detail {

class HostDepthCopy {
public:
    // Copies `framebuffer`'s depth under `viewport` and returns the copy's
    // texture. Leaves no framebuffer bound.
    GLuint copy(GLuint framebuffer, glm::ivec4 viewport);

private:
    gl::Texture texture_;
    gl::Framebuffer framebuffer_;
    glm::ivec2 size_{0};
    GLenum format_ = 0;
};

} // namespace swell::detail
