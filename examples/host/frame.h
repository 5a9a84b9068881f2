// The example host's frame: its render target (colour + depth), the
// reversed-Z projection with an infinite far plane a modern engine uses,
// and its own tone mapping from the linear HDR target to the display.
#pragma once

#include <GL/glcorearb.h>
#include <glm/mat4x4.hpp>
#include <glm/vec2.hpp>

#include <cstdint>
#include <vector>

namespace host {

// A framebuffer with one colour texture (GL_RGBA16F for the linear HDR
// frame, GL_RGBA8 for display colours) and a depth texture (32-bit float:
// reversed-Z needs it to keep its precision).
class Target {
public:
    Target(glm::ivec2 size, GLenum colorFormat);
    ~Target();
    Target(const Target&) = delete;
    Target& operator=(const Target&) = delete;

    GLuint framebuffer() const { return framebuffer_; }
    GLuint colorTexture() const { return color_; }
    glm::ivec2 size() const { return size_; }
    // The colour as 8-bit RGBA, bottom row first.
    std::vector<std::uint8_t> pixels() const;

private:
    glm::ivec2 size_;
    GLuint color_ = 0, depth_ = 0, framebuffer_ = 0;
};

// Reversed-Z with the far plane at infinity (clip z = near, w = -z_eye):
// depth 1 at the near plane falling towards 0 with distance, for
// glClipControl(GL_LOWER_LEFT, GL_ZERO_TO_ONE) and GL_GREATER.
glm::dmat4 reversedInfiniteProjection(double fovY_deg, double aspect, double near_m);

// Starts a frame into `target`: its viewport, colour cleared to `clear`;
// reversed-Z (the host's own way): glClipControl(GL_LOWER_LEFT,
// GL_ZERO_TO_ONE), GL_GREATER, depth cleared to 0 (the far plane);
// otherwise GL's default convention, GL_LESS, depth cleared to 1.
void beginFrame(const Target& target, const float clear[4], bool reversedZ = true);

// The host's post-process: the linear HDR colour, exposed and tone-mapped
// (ACES, Narkowicz 2015's fit), sRGB-encoded into a display framebuffer.
class ToneMapper {
public:
    ToneMapper();
    ~ToneMapper();
    ToneMapper(const ToneMapper&) = delete;
    ToneMapper& operator=(const ToneMapper&) = delete;

    // Draws `hdr` over the whole of `framebuffer` (0: the window) of `size`.
    void apply(GLuint hdr, GLuint framebuffer, glm::ivec2 size, float exposure) const;

private:
    GLuint program_ = 0, vertexArray_ = 0;
    GLint exposure_ = -1;
};

} // namespace host
