// What follows the main pass when it drew into the view's own target
// (render/view_passes.h): the temporal resolve, or the MSAA resolve, FXAA
// and the render scale's filter, into the output's viewport; and for draw(),
// the host's picture brought into the target before and its depth after.
#include "render/view_passes.h"

#include "swell/gpu/bindings.h"

namespace swell::detail {

namespace {

// Draws host_copy.frag over `viewport` of the bound framebuffer from the
// colour and depth textures given, writing depth whatever was there.
void drawCopy(RenderContext& context, GLuint colour, GLuint depth, glm::ivec4 viewport)
{
    const HostCopyProgram& program = context.resources.programs.hostCopy;
    program.use();
    program.setViewport(viewport);
    glBindTextureUnit(SWELL_UNIT_POST_SOURCE, colour);
    glBindTextureUnit(SWELL_UNIT_HOST_DEPTH, depth);
    glDepthFunc(GL_ALWAYS);
    glBindVertexArray(context.resources.emptyVao.id());
    glDrawArrays(GL_TRIANGLES, 0, 3);
    ++context.telemetry.counters.drawCalls;
    glBindTextureUnit(SWELL_UNIT_POST_SOURCE, 0);
    glBindTextureUnit(SWELL_UNIT_HOST_DEPTH, 0);
}

} // namespace

void copyHostPictureIn(RenderContext& context, ViewState& state, const PassState& main, const ViewRequest& request)
{
    const ObservedPass observed(context.telemetry, "host picture");
    const GLenum format = request.options.encoding == OutputEncoding::Linear ? GL_RGBA16F : GL_RGBA8;
    const GLuint colour = state.hostPictureColour.copyColour(request.output, request.outputViewport, format);
    const GLuint depth = state.hostPictureDepth.copyDepth(request.output, request.outputViewport);
    glBindFramebuffer(GL_FRAMEBUFFER, main.framebuffer);
    setPassState(main.viewport, main.depth);
    drawCopy(context, colour, depth, main.viewport);
    main.restore(context);
}

void writeDepthBack(RenderContext& context, ViewState& state, const ViewFrame& v, const ViewRequest& request)
{
    const ObservedPass observed(context.telemetry, "host depth");
    glBindFramebuffer(GL_FRAMEBUFFER, request.output);
    setPassState(request.outputViewport, v.depth);
    glColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);
    drawCopy(context, state.mainTarget.drawnColor(), state.mainTarget.resolvedDepth(), request.outputViewport);
    glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
}

void PresentPass::draw(RenderContext& context, ViewState& state, const ViewFrame& v, const ViewRequest& request) const
{
    if (!request.throughTarget())
        return;
    Telemetry& telemetry = context.telemetry;
    const Resources& resources = context.resources;
    if (request.temporal()) {
        const ObservedPass observed(telemetry, "temporal resolve");
        glClipControl(GL_LOWER_LEFT, GL_NEGATIVE_ONE_TO_ONE);
        telemetry.counters.drawCalls += state.temporal.resolve(
            resources.programs.temporal, resources.emptyVao.id(), state.mainTarget.drawnColor(),
            state.mainTarget.drawnDepth(), request.size, request.outputViewport, request.output,
            *request.unjitteredViewProj, glm::dvec2(v.depth.ndcScale, v.depth.ndcOffset),
            context.simulation.require().time_s);
    } else {
        // The MSAA resolve, the FXAA filter and the render scale's filtering.
        const ObservedPass observed(telemetry, "present");
        glClipControl(GL_LOWER_LEFT, GL_NEGATIVE_ONE_TO_ONE);
        telemetry.counters.drawCalls += state.mainTarget.present(resources.programs.fxaa, resources.emptyVao.id());
    }
    if (!request.ownsFrame)
        writeDepthBack(context, state, v, request);
}

} // namespace swell::detail
