// Offscreen targets: RenderTarget is one colour + depth pair (reflection,
// refraction, headless output, the main pass's own target); MainTarget is
// where the main pass draws when the frame is anti-aliased or drawn at a
// render scale, and how that image reaches the output framebuffer.
#pragma once

#include "swell/gl/handle.h"
#include "swell/scene/scene.h"

#include <glm/vec2.hpp>

namespace swell::detail {

class FxaaProgram;

class RenderTarget {
public:
    // Recreates the textures when the size, format or sample count changes;
    // a 0x0 size frees them. colorFormat: GL_RGBA16F for linear intermediate
    // images, GL_RGBA8 for display-ready ones. samples > 1: multisampled
    // textures (read them only by a resolving blit).
    void resize(glm::ivec2 size, GLenum colorFormat = GL_RGBA16F, int samples = 1);
    glm::ivec2 size() const { return size_; }
    int samples() const { return samples_; }
    GLuint framebuffer() const { return framebuffer_.id(); }
    GLuint color() const { return color_.id(); }
    GLuint depth() const { return depth_.id(); }

private:
    glm::ivec2 size_{0, 0};
    GLenum colorFormat_ = 0;
    int samples_ = 1;
    gl::Framebuffer framebuffer_;
    gl::Texture color_, depth_;
};

// The samples a pixel of an MSAA main pass has. 4 is what every GL 4.5
// implementation must support for RGBA8 and depth (GL_MAX_SAMPLES >= 4), and
// llvmpipe's only multisample count.
inline constexpr int kMsaaSamples = 4;

// The main pass's target. Without anti-aliasing at scale 1 the main pass
// draws straight into the output; otherwise into its own target here, which
// present() then resolves (MSAA), filters (FXAA) and scales (render scale,
// bilinear) into the output.
class MainTarget {
public:
    // Sets up the targets for a frame drawn at `drawSize` (see
    // scaledFrameSize) and shown in `output` over `outputViewport` (its
    // lower-left corner and size, pixels), and returns the framebuffer the
    // main pass draws into. ownTarget: draw into the target even when
    // nothing would present it (the temporal resolve reads it instead:
    // drawnColor(), drawnDepth()). colorFormat: GL_RGBA8 for display-ready
    // colour, GL_RGBA16F for linear.
    GLuint begin(glm::ivec2 drawSize, glm::ivec4 outputViewport, GLuint output, Antialiasing antialiasing,
                 bool ownTarget = false, GLenum colorFormat = GL_RGBA8);
    // The main pass's own single-sampled image and depth (not MSAA).
    GLuint drawnColor() const { return single_.color(); }
    GLuint drawnDepth() const { return single_.depth(); }
    // The main pass's depth, single-sampled: an MSAA pass's samples
    // resolved into drawnDepth() first (one sample each).
    GLuint resolvedDepth();
    // Whether present() has work to do for the frame begun last.
    bool presents() const { return !direct_; }
    // Brings the main pass's image to the output. `fxaa` draws the FXAA
    // filter with `emptyVao`. Leaves the output framebuffer bound with its
    // viewport set. Returns the draw calls it made (the filter's; blits are
    // not draws).
    int present(const FxaaProgram& fxaa, GLuint emptyVao);

private:
    // Copies `from`'s colour into the output, bilinear where sizes differ.
    void blitToOutput(const RenderTarget& from) const;

    RenderTarget multisampled_; // MSAA: the main pass's samples
    RenderTarget single_;       // the main pass (off, FXAA) or MSAA's resolve
    RenderTarget filtered_;     // FXAA's result when it must still be scaled or moved
    bool direct_ = true;        // the main pass draws into the output itself
    GLuint output_ = 0;
    glm::ivec2 drawSize_{0};
    glm::ivec4 outputViewport_{0};
    Antialiasing antialiasing_ = Antialiasing::Off;
};

} // namespace swell::detail
