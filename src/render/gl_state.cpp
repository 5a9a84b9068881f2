#include "render/gl_state.h"

namespace swell::detail {

namespace {

// Every capability a pass of the renderer sets (pass_state.cpp's
// setPassState and the passes), then those it needs at GL's defaults
// (setFixedState), with their default, in enabled_'s order.
struct Capability {
    GLenum name;
    bool fixed;        // set by setFixedState, never by a pass
    bool defaultValue; // GL's initial value (setFixedState's)
};
constexpr std::array<Capability, kSavedCapabilities> kCapabilities = {{
    {GL_BLEND, false, false},
    {GL_CULL_FACE, false, false},
    {GL_SCISSOR_TEST, false, false},
    {GL_DEPTH_TEST, false, false},
    {GL_FRAMEBUFFER_SRGB, false, false},
    {GL_CLIP_DISTANCE0, false, false},
    {GL_TEXTURE_CUBE_MAP_SEAMLESS, false, false},
    {GL_RASTERIZER_DISCARD, false, false},
    {GL_MULTISAMPLE, true, true},
    {GL_STENCIL_TEST, true, false},
    {GL_COLOR_LOGIC_OP, true, false},
    {GL_POLYGON_OFFSET_FILL, true, false},
    {GL_POLYGON_OFFSET_LINE, true, false},
    {GL_POLYGON_OFFSET_POINT, true, false},
    {GL_DEPTH_CLAMP, true, false},
    {GL_PRIMITIVE_RESTART, true, false},
    {GL_PRIMITIVE_RESTART_FIXED_INDEX, true, false},
    {GL_SAMPLE_ALPHA_TO_COVERAGE, true, false},
    {GL_SAMPLE_ALPHA_TO_ONE, true, false},
    {GL_SAMPLE_COVERAGE, true, false},
    {GL_SAMPLE_MASK, true, false},
    {GL_SAMPLE_SHADING, true, false},
    {GL_LINE_SMOOTH, true, false},
    {GL_POLYGON_SMOOTH, true, false},
    {GL_DITHER, true, true},
    {GL_CLIP_DISTANCE1, true, false},
    {GL_CLIP_DISTANCE2, true, false},
    {GL_CLIP_DISTANCE3, true, false},
    {GL_CLIP_DISTANCE4, true, false},
    {GL_CLIP_DISTANCE5, true, false},
    {GL_CLIP_DISTANCE6, true, false},
    {GL_CLIP_DISTANCE7, true, false},
    // Off: the points Swell draws without a size in their shaders (the
    // water's shading pass turns it on for its tiles' points).
    {GL_PROGRAM_POINT_SIZE, true, false},
}};

// The pixel-store parameters, with GL's defaults: Swell's uploads and
// read-backs assume them (alignment 4 save where a call sets its own).
struct PixelStore {
    GLenum name;
    GLint defaultValue;
};
constexpr std::array<PixelStore, 16> kPixelStore = {{
    {GL_PACK_ALIGNMENT, 4},       {GL_PACK_ROW_LENGTH, 0},     {GL_PACK_IMAGE_HEIGHT, 0},
    {GL_PACK_SKIP_PIXELS, 0},     {GL_PACK_SKIP_ROWS, 0},      {GL_PACK_SKIP_IMAGES, 0},
    {GL_PACK_SWAP_BYTES, 0},      {GL_PACK_LSB_FIRST, 0},      {GL_UNPACK_ALIGNMENT, 4},
    {GL_UNPACK_ROW_LENGTH, 0},    {GL_UNPACK_IMAGE_HEIGHT, 0}, {GL_UNPACK_SKIP_PIXELS, 0},
    {GL_UNPACK_SKIP_ROWS, 0},     {GL_UNPACK_SKIP_IMAGES, 0},  {GL_UNPACK_SWAP_BYTES, 0},
    {GL_UNPACK_LSB_FIRST, 0},
}};

// The generic buffer binding points: those Swell's calls change
// (glBindBufferBase sets the generic one too) and the pixel buffers, which
// would turn its uploads and read-backs into copies from and to them.
struct BufferTarget {
    GLenum target, binding;
};
constexpr std::array<BufferTarget, 7> kBuffers = {{
    {GL_UNIFORM_BUFFER, GL_UNIFORM_BUFFER_BINDING},
    {GL_SHADER_STORAGE_BUFFER, GL_SHADER_STORAGE_BUFFER_BINDING},
    {GL_TRANSFORM_FEEDBACK_BUFFER, GL_TRANSFORM_FEEDBACK_BUFFER_BINDING},
    {GL_DRAW_INDIRECT_BUFFER, GL_DRAW_INDIRECT_BUFFER_BINDING},
    {GL_DISPATCH_INDIRECT_BUFFER, GL_DISPATCH_INDIRECT_BUFFER_BINDING},
    {GL_PIXEL_PACK_BUFFER, GL_PIXEL_PACK_BUFFER_BINDING},
    {GL_PIXEL_UNPACK_BUFFER, GL_PIXEL_UNPACK_BUFFER_BINDING},
}};

// A name that died meanwhile is not bound again: a program the host deleted
// while it was current lives until another is bound (ours), and binding
// its name then would be an error; the others unbind at deletion.
GLuint alive(GLint name, GLboolean (*is)(GLuint)) { return name == 0 || is(GLuint(name)) ? GLuint(name) : 0u; }

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
    glGetIntegerv(GL_BLEND_SRC_RGB, &blend_[0]);
    glGetIntegerv(GL_BLEND_DST_RGB, &blend_[1]);
    glGetIntegerv(GL_BLEND_SRC_ALPHA, &blend_[2]);
    glGetIntegerv(GL_BLEND_DST_ALPHA, &blend_[3]);
    glGetIntegerv(GL_BLEND_EQUATION_RGB, &blend_[4]);
    glGetIntegerv(GL_BLEND_EQUATION_ALPHA, &blend_[5]);
    for (std::size_t i = 0; i < kCapabilities.size(); ++i)
        enabled_[i] = glIsEnabled(kCapabilities[i].name);
    readFixed();
}

void SavedGlState::readFixed()
{
    glGetDoublev(GL_DEPTH_RANGE, depthRange_.data());
    glGetFloatv(GL_POLYGON_OFFSET_FACTOR, &polygonOffsetFactor_);
    glGetFloatv(GL_POLYGON_OFFSET_UNITS, &polygonOffsetUnits_);
    glGetFloatv(GL_LINE_WIDTH, &lineWidth_);
    glGetFloatv(GL_MIN_SAMPLE_SHADING_VALUE, &minSampleShading_);
    glGetIntegerv(GL_PROVOKING_VERTEX, &provokingVertex_);
    glGetIntegerv(GL_LOGIC_OP_MODE, &logicOp_);
    glGetIntegeri_v(GL_SAMPLE_MASK_VALUE, 0, &sampleMask_);
    glGetFloatv(GL_SAMPLE_COVERAGE_VALUE, &sampleCoverage_);
    glGetBooleanv(GL_SAMPLE_COVERAGE_INVERT, &sampleCoverageInvert_);
    for (int unit = 0; unit < kSwellTextureUnits; ++unit) {
        glActiveTexture(GLenum(GL_TEXTURE0 + unit));
        glGetIntegerv(GL_SAMPLER_BINDING, &samplers_[std::size_t(unit)]);
    }
    glActiveTexture(GLenum(activeTexture_));
    for (std::size_t i = 0; i < kPixelStore.size(); ++i)
        glGetIntegerv(kPixelStore[i].name, &pixelStore_[i]);
    for (std::size_t i = 0; i < kBuffers.size(); ++i)
        glGetIntegerv(kBuffers[i].binding, &buffers_[i]);
}

void SavedGlState::restore() const
{
    glBindFramebuffer(GL_DRAW_FRAMEBUFFER, alive(drawFramebuffer_, glIsFramebuffer));
    glBindFramebuffer(GL_READ_FRAMEBUFFER, alive(readFramebuffer_, glIsFramebuffer));
    glUseProgram(alive(program_, glIsProgram));
    glBindVertexArray(alive(vertexArray_, glIsVertexArray));
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
    glBlendFuncSeparate(GLenum(blend_[0]), GLenum(blend_[1]), GLenum(blend_[2]), GLenum(blend_[3]));
    glBlendEquationSeparate(GLenum(blend_[4]), GLenum(blend_[5]));
    for (std::size_t i = 0; i < kCapabilities.size(); ++i)
        enabled_[i] ? glEnable(kCapabilities[i].name) : glDisable(kCapabilities[i].name);
    restoreFixed();
    glActiveTexture(GLenum(activeTexture_));
}

void SavedGlState::restoreFixed() const
{
    glDepthRange(depthRange_[0], depthRange_[1]);
    glPolygonOffset(polygonOffsetFactor_, polygonOffsetUnits_);
    glLineWidth(lineWidth_);
    glMinSampleShading(minSampleShading_);
    glProvokingVertex(GLenum(provokingVertex_));
    glLogicOp(GLenum(logicOp_));
    glSampleMaski(0, GLbitfield(sampleMask_));
    glSampleCoverage(sampleCoverage_, sampleCoverageInvert_);
    for (int unit = 0; unit < kSwellTextureUnits; ++unit)
        glBindSampler(GLuint(unit), alive(samplers_[std::size_t(unit)], glIsSampler));
    for (std::size_t i = 0; i < kPixelStore.size(); ++i)
        glPixelStorei(kPixelStore[i].name, pixelStore_[i]);
    for (std::size_t i = 0; i < kBuffers.size(); ++i)
        glBindBuffer(kBuffers[i].target, alive(buffers_[i], glIsBuffer));
}

void setFixedState()
{
    for (const Capability& c : kCapabilities)
        if (c.fixed)
            c.defaultValue ? glEnable(c.name) : glDisable(c.name);
    glDepthRange(0.0, 1.0);
    glPolygonOffset(0.0f, 0.0f);
    glLineWidth(1.0f);
    glMinSampleShading(0.0f);
    glProvokingVertex(GL_LAST_VERTEX_CONVENTION);
    glLogicOp(GL_COPY);
    glSampleMaski(0, ~0u);
    glSampleCoverage(1.0f, GL_FALSE);
    // Sampler objects would replace the filtering and wrapping Swell's
    // textures were made with.
    glBindSamplers(0, kSwellTextureUnits, nullptr);
    for (const PixelStore& p : kPixelStore)
        glPixelStorei(p.name, p.defaultValue);
    glBindBuffer(GL_PIXEL_PACK_BUFFER, 0);
    glBindBuffer(GL_PIXEL_UNPACK_BUFFER, 0);
}

} // namespace swell::detail
