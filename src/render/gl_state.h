// The host's GL state around Swell's work (docs/LIBRARY.md "The GL state";
// tests/gl/test_host_state.cpp, tests/gl/test_host_views.cpp hold it):
// SavedGlState captures everything Swell changes and everything that would
// change Swell's results if a host left it set, and puts it all back;
// setFixedState() sets the second kind, which Swell depends on but never
// changes itself (the stencil test, the logic op, sampler objects, the
// depth range, polygon offset, the provoking vertex, pixel-store
// parameters ...), to GL's defaults: at the start of each call of Swell's
// and again after each host callback, which may change any of it.
#pragma once

#include <epoxy/gl.h>

#include <array>
#include <cstddef>

namespace swell::detail {

// The texture units whose sampler bindings Swell clears: every
// SWELL_UNIT_* lies below it (swell/gpu/bindings.h).
inline constexpr int kSwellTextureUnits = 28;

// The capabilities Swell saves and puts back (kCapabilities in gl_state.cpp).
inline constexpr std::size_t kSavedCapabilities = 33;

class SavedGlState {
public:
    // Reads the state now current.
    SavedGlState();
    // Puts it back.
    void restore() const;

private:
    void readFixed();
    void restoreFixed() const;

    GLint drawFramebuffer_ = 0, readFramebuffer_ = 0, program_ = 0, vertexArray_ = 0, activeTexture_ = 0;
    std::array<GLint, 4> viewport_{}, scissorBox_{};
    std::array<GLboolean, 4> colorMask_{};
    GLboolean depthMask_ = GL_TRUE;
    GLint depthFunc_ = GL_LESS, frontFace_ = GL_CCW, clipOrigin_ = GL_LOWER_LEFT, clipDepth_ = GL_NEGATIVE_ONE_TO_ONE;
    std::array<GLint, 2> polygonMode_{};
    std::array<GLfloat, 4> clearColor_{};
    GLfloat clearDepth_ = 1.0f;
    std::array<GLint, 6> blend_{}; // source and destination factors (rgb, alpha), equations (rgb, alpha)
    // The capabilities a pass turns on or off, and those it needs off
    // (kCapabilities in gl_state.cpp).
    std::array<GLboolean, kSavedCapabilities> enabled_{};
    // The fixed state's values (setFixedState).
    std::array<GLdouble, 2> depthRange_{};
    GLfloat polygonOffsetFactor_ = 0.0f, polygonOffsetUnits_ = 0.0f, lineWidth_ = 1.0f, minSampleShading_ = 0.0f;
    GLint provokingVertex_ = GL_LAST_VERTEX_CONVENTION, logicOp_ = GL_COPY, sampleMask_ = -1;
    GLfloat sampleCoverage_ = 1.0f;
    GLboolean sampleCoverageInvert_ = GL_FALSE;
    std::array<GLint, kSwellTextureUnits> samplers_{};
    // Pixel-store parameters (kPixelStore in gl_state.cpp) and the buffers
    // bound to the generic binding points Swell's calls change or read.
    std::array<GLint, 16> pixelStore_{};
    std::array<GLint, 7> buffers_{};
};

// Sets the state Swell depends on but never changes itself to GL's defaults.
void setFixedState();

// Around one call of Swell's public API that draws or computes: the host's
// state saved and the fixed state set at the start, the host's state put
// back at the end, whatever happens.
class HostStateScope {
public:
    HostStateScope() { setFixedState(); }
    ~HostStateScope() { saved_.restore(); }
    HostStateScope(const HostStateScope&) = delete;
    HostStateScope& operator=(const HostStateScope&) = delete;

private:
    SavedGlState saved_;
};

// Call right after using a program that has a stage the next program used
// lacks: after a draw with a geometry stage, after compute dispatches
// followed by a draw (the caustics map's, the spray's). Mesa (22.3) keeps,
// per shader stage, a reference to the program that last changed that
// stage's code, so the next program used, lacking the stage, would stay
// referenced by it: deleted by a scene change that rebuilds the programs,
// it lived on in the driver until that stage was bound again (the soak's
// one program over its baseline; GlResources.AProgramDrawnAfterTheCausticsIsFreedWhenReplaced,
// 21 programs alive against 20 for the compute stage). Unbinding here
// clears every stage together with its reference.
inline void releaseProgramStages() { glUseProgram(0); }

} // namespace swell::detail
