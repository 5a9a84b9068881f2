// A host of the water for the tests: its own framebuffer, its own shader
// (not Swell's) and its own boxes, drawn into its frame and, through
// swell::PassGeometry, into Swell's reflection and refraction passes.
#pragma once

#include "swell/gl/handle.h"
#include "swell/view.h"

#include <epoxy/gl.h>
#include <glm/mat4x4.hpp>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include <cstdint>
#include <functional>
#include <vector>

namespace swell::test {

// An axis-aligned box of one flat colour (absolute world, m).
struct HostBox {
    glm::dvec3 min_m, max_m;
    glm::vec3 color;
};

// A framebuffer of the host's: RGBA8 (or RGBA16F) colour and a depth buffer
// (32-bit float for reversed-Z), or none.
class HostTarget {
public:
    HostTarget(glm::ivec2 size, GLenum colorFormat = GL_RGBA8, GLenum depthFormat = GL_DEPTH_COMPONENT32F);
    GLuint framebuffer() const { return framebuffer_.id(); }
    glm::ivec2 size() const { return size_; }
    // The colour, bottom row first, 4 bytes a pixel (or 4 floats for a float target).
    std::vector<std::uint8_t> pixels() const;
    std::vector<float> floatPixels() const;
    // The depth buffer's window depths, bottom row first.
    std::vector<float> depths() const;

private:
    glm::ivec2 size_;
    gl::Texture color_, depth_;
    gl::Framebuffer framebuffer_;
};

// Draws boxes with a shader of its own: flat colour, the clip plane written
// to gl_ClipDistance[0].
class HostScene final : public PassGeometry {
public:
    explicit HostScene(std::vector<HostBox> boxes);
    // The boxes through `viewProj` (absolute world to clip), keeping
    // dot(clip, (p, 1)) >= 0 when GL_CLIP_DISTANCE0 is on.
    void draw(const glm::dmat4& viewProj, glm::dvec4 clip = {0.0, 0.0, 0.0, 1.0}) const;
    void drawPass(const PassView& pass) override;
    // What drawPass() was called for, in order.
    std::vector<PassKind> passes;
    // Called at the end of drawPass() (to throw, or leave an error).
    std::function<void(const PassView&)> afterPass;

private:
    gl::Program program_;
    gl::VertexArray vao_;
    gl::Buffer vertices_;
    GLint viewProj_ = -1, clip_ = -1;
    int vertexCount_ = 0;
};

// The host's own frame: cleared to `clear` and the depth convention's far
// value, its boxes drawn, with the depth test and clip control of `depth`.
void drawHostFrame(const HostTarget& target, const HostScene& scene, const View& view, glm::vec4 clear);

} // namespace swell::test
