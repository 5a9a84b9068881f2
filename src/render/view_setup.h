// What a host's View (swell/view.h) means for the renderer's passes: its
// depth convention's numbers, and the checks that refuse a view or a
// framebuffer the water cannot be drawn with.
#pragma once

#include "render/gpu/blocks.h"
#include "swell/view.h"

#include <epoxy/gl.h>
#include <cstdint>
#include <glm/mat4x4.hpp>

namespace swell::detail {

struct DepthConvention {
    double nearNdcZ = -1.0, farNdcZ = 1.0; // NDC z of the near and far planes
    double ndcScale = 2.0, ndcOffset = -1.0; // NDC z = window depth * scale + offset
    float cleared = 1.0f;      // the window depth of nothing drawn (the far plane)
    GLenum test = GL_LESS;     // nearer passes
    GLenum testOrFar = GL_LEQUAL; // nearer, or at the far plane (the sky)
    GLenum clipDepth = GL_NEGATIVE_ONE_TO_ONE; // glClipControl's depth mode
    bool zeroToOne() const { return clipDepth == GL_ZERO_TO_ONE; }
};

DepthConvention depthConventionOf(DepthMode mode);

// Fills the Frame block's depth-convention fields for `mode`.
void setDepthConvention(FrameUniforms& f, DepthMode mode);

// Throws swell::Error naming what is wrong: an empty viewport, a view or
// projection matrix that is not finite or cannot be inverted, a
// framebuffer that is incomplete, or (for compositing) has no depth buffer.
void checkView(const View& view);
void checkFramebuffer(GLuint framebuffer, bool needsDepth);
// Throws swell::Error naming what is wrong with DrawOptions::motionVectors
// (not 0) for `framebuffer`: framebuffer 0, not a colour attachment,
// nothing attached there, not a float format of two channels or more, or a
// GL whose vertex shaders cannot use storage buffers.
void checkMotionVectors(GLuint framebuffer, std::uint32_t attachment);

} // namespace swell::detail
