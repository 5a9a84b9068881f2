// The temporal resolve (swell/renderer.h setTemporalResolve, docs/RENDERING.md
// "Temporal resolve"): each frame's projection jittered by a sub-pixel
// offset from a Halton (2, 3) sequence, and the frame, drawn at the render
// scale, blended into a history kept at the output's size: the clip box of
// each drawn pixel's neighbourhood gathered at the drawn size
// (shaders/temporal_neighbourhood.frag), then the history resolved at the
// output's (shaders/temporal_resolve.frag). Library-internal.
#pragma once

#include "swell/gl/handle.h"

#include <epoxy/gl.h>
#include <glm/mat4x4.hpp>
#include <glm/vec2.hpp>

#include <cstdint>
#include <optional>

namespace swell::detail {

// The i-th point (i >= 1) of the van der Corput sequence in `base`, in 0..1.
double radicalInverse(std::uint32_t i, std::uint32_t base);

// The jitter of frame `frame` of the cycle, in drawn pixels, in -0.5..0.5 on
// each axis: Halton (2, 3) points 1..SWELL_TEMPORAL_JITTER_PHASES, less 0.5.
glm::dvec2 temporalJitter_px(std::uint64_t frame);

// `projection` moved by `jitter_px` drawn pixels of a target `size` pixels:
// the image moves by that much (clip x, y += offset * w).
glm::dmat4 jitteredProjection(const glm::dmat4& projection, glm::dvec2 jitter_px, glm::ivec2 size);

// temporal_resolve.frag built one way and its uniforms.
struct TemporalResolveProgram {
    TemporalResolveProgram() = default;
    explicit TemporalResolveProgram(gl::Program built);
    gl::Program program;
    GLint reprojection = -1, jitter = -1, depthToNdc = -1, historyValid = -1, waterMaxWeight = -1;
};

// The resolve's programs. The resolve comes built twice: for frames drawn
// at half the output's size or less (2x2 samples a pixel) and above.
class TemporalPrograms {
public:
    TemporalPrograms() = default;
    TemporalPrograms(gl::Program neighbourhood, gl::Program resolveHalfOrLess, gl::Program resolveAboveHalf,
                     gl::Program present);
    explicit operator bool() const { return bool(neighbourhood_); }

private:
    friend class TemporalResolve;
    gl::Program neighbourhood_;
    TemporalResolveProgram halfOrLess_, aboveHalf_;
    // The history into an output the blit does not suit
    // (temporal_present.frag; outputTakesTheBlit in temporal_resolve.cpp).
    gl::Program present_;
    GLint presentOrigin_ = -1;
};

class TemporalResolve {
public:
    // Forgets the history: the next frame starts again from itself alone.
    void reset() { previous_.reset(); }
    // The jitter of the frame about to be drawn, drawn pixels.
    glm::dvec2 jitter_px() const { return temporalJitter_px(frame_); }
    // Turns the jitter off (a frame drawn at the pixels' centres), for tests
    // that show what the jitter brings.
    void setJitterEnabled(bool enabled) { jitterEnabled_ = enabled; }
    bool jitterEnabled() const { return jitterEnabled_; }

    // Resolves the frame just drawn (its colour and depth textures, their
    // size `drawnSize`) into the history and draws the result into `output`
    // (its framebuffer, over `outputViewport`: its lower-left corner and
    // size, pixels): a blit where the output is one
    // single-sampled 8-bit colour buffer (a window's, most hosts'), else a
    // full-screen pass. viewProj: the frame's unjittered view and
    // projection, absolute world to clip (double, so kilometres from the
    // origin keep their precision in the reprojection); depthToNdc: the
    // depth convention's scale and offset; time_s: the simulated time drawn
    // (the water keeps a short history when it changed). Leaves `output`
    // bound with a viewport over it. Returns the draw calls made.
    int resolve(const TemporalPrograms& programs, GLuint emptyVao, GLuint frameColor, GLuint frameDepth,
                glm::ivec2 drawnSize, glm::ivec4 outputViewport, GLuint output, const glm::dmat4& viewProj,
                glm::dvec2 depthToNdc, double time_s);

private:
    struct Target {
        gl::Texture texture;
        gl::Framebuffer framebuffer;
    };
    void resize(glm::ivec2 size);
    void resizeBoxes(glm::ivec2 drawnSize);

    Target history_[2];
    // The output's colour, 8 bits, opaque: the resolve's second output,
    // blitted into the output.
    gl::Texture display_;
    gl::Framebuffer displayFramebuffer_;
    // Per drawn pixel: the clip box's centre and half extent
    // (temporal_neighbourhood.frag's two outputs), one framebuffer.
    gl::Texture boxCentre_, boxExtent_;
    gl::Framebuffer boxes_;
    glm::ivec2 drawnSize_{0};
    int current_ = 0; // the history written last
    glm::ivec2 size_{0};
    std::uint64_t frame_ = 0;
    bool jitterEnabled_ = true;
    // The last frame's unjittered view and projection, while its history is good.
    std::optional<glm::dmat4> previous_;
    double previousTime_s_ = 0.0;
};

} // namespace swell::detail
