#include "render/gl_state.h"

namespace swell::detail {

namespace {

// Every capability a pass of the renderer sets (renderer.cpp's beginPass
// and its passes); their order is enabled_'s.
constexpr std::array<GLenum, 9> kCapabilities = {
    GL_BLEND,        GL_CULL_FACE,         GL_SCISSOR_TEST,       GL_DEPTH_TEST,
    GL_FRAMEBUFFER_SRGB, GL_CLIP_DISTANCE0, GL_TEXTURE_CUBE_MAP_SEAMLESS, GL_RASTERIZER_DISCARD,
    GL_MULTISAMPLE,
};

} // namespace

SavedGlState::SavedGlState()
{
    glGetIntegerv(GL_DRAW_FRAMEBUFFER_BINDING, &drawFramebuffer_);
    glGetIntegerv(GL_READ_FRAMEBUFFER_BINDING, &readFramebuffer_);
    glGetIntegerv(GL_CURRENT_PROGRAM, &program_);
    glGetIntegerv(GL_VERTEX_ARRAY_BINDING, &vertexArray_);
    glGetIntegerv(GL_ACTIVE_TEXTURE, &activeTexture_);
    glGetIntegerv(GL_VIEWPORT, viewport_.data());
    glGetIntegerv(GL_SCISSOR_BOX, scissorBox_.data());
    glGetBooleanv(GL_COLOR_WRITEMASK, colorMask_.data());
    glGetBooleanv(GL_DEPTH_WRITEMASK, &depthMask_);
    glGetIntegerv(GL_DEPTH_FUNC, &depthFunc_);
    glGetIntegerv(GL_FRONT_FACE, &frontFace_);
    glGetIntegerv(GL_CLIP_ORIGIN, &clipOrigin_);
    glGetIntegerv(GL_CLIP_DEPTH_MODE, &clipDepth_);
    glGetIntegerv(GL_POLYGON_MODE, polygonMode_.data());
    glGetFloatv(GL_COLOR_CLEAR_VALUE, clearColor_.data());
    glGetFloatv(GL_DEPTH_CLEAR_VALUE, &clearDepth_);
    glGetIntegerv(GL_PACK_ALIGNMENT, &packAlignment_);
    glGetIntegerv(GL_UNPACK_ALIGNMENT, &unpackAlignment_);
    glGetIntegerv(GL_BLEND_SRC_RGB, &blend_[0]);
    glGetIntegerv(GL_BLEND_DST_RGB, &blend_[1]);
    glGetIntegerv(GL_BLEND_SRC_ALPHA, &blend_[2]);
    glGetIntegerv(GL_BLEND_DST_ALPHA, &blend_[3]);
    glGetIntegerv(GL_BLEND_EQUATION_RGB, &blend_[4]);
    glGetIntegerv(GL_BLEND_EQUATION_ALPHA, &blend_[5]);
    for (std::size_t i = 0; i < kCapabilities.size(); ++i)
        enabled_[i] = glIsEnabled(kCapabilities[i]);
}

void SavedGlState::restore() const
{
    // A name that died meanwhile is not bound again: a program the host
    // deleted while it was current lives until another is bound (ours), and
    // binding its name then would be an error; the others unbind at deletion.
    auto alive = [](GLint name, GLboolean (*is)(GLuint)) { return name == 0 || is(GLuint(name)) ? GLuint(name) : 0u; };
    glBindFramebuffer(GL_DRAW_FRAMEBUFFER, alive(drawFramebuffer_, glIsFramebuffer));
    glBindFramebuffer(GL_READ_FRAMEBUFFER, alive(readFramebuffer_, glIsFramebuffer));
    glUseProgram(alive(program_, glIsProgram));
    glBindVertexArray(alive(vertexArray_, glIsVertexArray));
    glActiveTexture(GLenum(activeTexture_));
    glViewport(viewport_[0], viewport_[1], viewport_[2], viewport_[3]);
    glScissor(scissorBox_[0], scissorBox_[1], scissorBox_[2], scissorBox_[3]);
    glColorMask(colorMask_[0], colorMask_[1], colorMask_[2], colorMask_[3]);
    glDepthMask(depthMask_);
    glDepthFunc(GLenum(depthFunc_));
    glFrontFace(GLenum(frontFace_));
    glClipControl(GLenum(clipOrigin_), GLenum(clipDepth_));
    // Core profiles keep one mode for both faces (GL_POLYGON_MODE reads it twice).
    glPolygonMode(GL_FRONT_AND_BACK, GLenum(polygonMode_[0]));
    glClearColor(clearColor_[0], clearColor_[1], clearColor_[2], clearColor_[3]);
    glClearDepth(clearDepth_);
    glPixelStorei(GL_PACK_ALIGNMENT, packAlignment_);
    glPixelStorei(GL_UNPACK_ALIGNMENT, unpackAlignment_);
    glBlendFuncSeparate(GLenum(blend_[0]), GLenum(blend_[1]), GLenum(blend_[2]), GLenum(blend_[3]));
    glBlendEquationSeparate(GLenum(blend_[4]), GLenum(blend_[5]));
    for (std::size_t i = 0; i < kCapabilities.size(); ++i)
        enabled_[i] ? glEnable(kCapabilities[i]) : glDisable(kCapabilities[i]);
}

SavedProgram::SavedProgram() { glGetIntegerv(GL_CURRENT_PROGRAM, &program_); }

SavedProgram::~SavedProgram()
{
    // A program the host deleted while it was current is gone once another
    // was bound: nothing to bind back.
    glUseProgram(program_ != 0 && glIsProgram(GLuint(program_)) ? GLuint(program_) : 0u);
}

} // namespace swell::detail
