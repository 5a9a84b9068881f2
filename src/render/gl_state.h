// The GL state a draw of the water changes, captured before it and put back
// after it, so a host's own passes find their state as they left it
// (docs/LIBRARY.md lists what is restored and what is left bound;
// tests/gl/test_host_composite.cpp holds it).
#pragma once

#include <epoxy/gl.h>

#include <array>

namespace swell::detail {

class SavedGlState {
public:
    // Reads the state now current.
    SavedGlState();
    // Puts it back.
    void restore() const;

private:
    GLint drawFramebuffer_ = 0, readFramebuffer_ = 0, program_ = 0, vertexArray_ = 0, activeTexture_ = 0;
    std::array<GLint, 4> viewport_{}, scissorBox_{};
    std::array<GLboolean, 4> colorMask_{};
    GLboolean depthMask_ = GL_TRUE;
    GLint depthFunc_ = GL_LESS, frontFace_ = GL_CCW, clipOrigin_ = GL_LOWER_LEFT, clipDepth_ = GL_NEGATIVE_ONE_TO_ONE;
    std::array<GLint, 2> polygonMode_{};
    std::array<GLfloat, 4> clearColor_{};
    GLfloat clearDepth_ = 1.0f;
    GLint packAlignment_ = 4, unpackAlignment_ = 4;
    std::array<GLint, 6> blend_{}; // source and destination factors (rgb, alpha), equations (rgb, alpha)
    // The capabilities it turns on or off (kCapabilities in gl_state.cpp).
    std::array<GLboolean, 9> enabled_{};
};

// The current program, put back when it goes out of scope (or 0 when the
// host deleted it meanwhile): advanceTo()'s compute passes change nothing
// else a host's passes find.
class SavedProgram {
public:
    SavedProgram();
    ~SavedProgram();
    SavedProgram(const SavedProgram&) = delete;
    SavedProgram& operator=(const SavedProgram&) = delete;

private:
    GLint program_ = 0;
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
