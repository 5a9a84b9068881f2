// The main pass (render/view_passes.h): into the output directly, or into
// the view's own target when it is anti-aliased, scaled or resolved over
// time; draw()'s picture is copied into that target first.
#include "render/view_passes.h"

#include "render/scene_world.h"
#include "render/spray_renderer.h"
#include "swell/gpu/bindings.h"
#include "swell/scene/scene.h"

#include <glm/matrix.hpp>

#include <tuple>

namespace swell::detail {

namespace {

// The underwater pass over the host's geometry (underwater_host.frag): on a
// copy of its depth, blending in-scattering and transmittance.
void fogHostUnderwater(RenderContext& context, ViewState& state, const PassState& main)
{
    const ObservedPass observed(context.telemetry, "underwater host");
    const GLuint copy = state.hostDepth.copyDepth(main.framebuffer, main.viewport);
    glBindFramebuffer(GL_FRAMEBUFFER, main.framebuffer);
    setPassState(main.viewport, main.depth);
    glDisable(GL_DEPTH_TEST);
    glDepthMask(GL_FALSE);
    glEnable(GL_BLEND);
    glBlendEquation(GL_FUNC_ADD);
    glBlendFunc(GL_ONE, GL_SRC1_COLOR);
    context.resources.programs.underwaterHost.use();
    glBindTextureUnit(SWELL_UNIT_HOST_DEPTH, copy);
    glBindVertexArray(context.resources.emptyVao.id());
    glDrawArrays(GL_TRIANGLES, 0, 3);
    ++context.telemetry.counters.drawCalls;
    glDisable(GL_BLEND);
    setPassState(main.viewport, main.depth);
}

} // namespace

std::pair<GLuint, glm::ivec4> MainPass::target(ViewState& state, const ViewRequest& request) const
{
    // The temporal resolve brings its own anti-aliasing (the jitter): the
    // main pass draws into its target, plain, and the resolve reads it.
    const Antialiasing antialiasing = request.temporal() ? Antialiasing::Off : request.options.antialiasing;
    // A linear output keeps the sun's highlight above 1 and its precision.
    const GLenum format = request.options.encoding == OutputEncoding::Linear ? GL_RGBA16F : GL_RGBA8;
    // Drawn straight into the output, the target gives its buffers back.
    const GLuint framebuffer = state.mainTarget.begin(request.size, request.outputViewport, request.output,
                                                      antialiasing, request.temporal(), format);
    if (!state.mainTarget.presents())
        return {framebuffer, request.outputViewport};
    return {framebuffer, glm::ivec4(0, 0, request.size)};
}

void MainPass::draw(RenderContext& context, ViewState& state, const ViewFrame& v, const ViewRequest& request,
                    SceneWorld& own) const
{
    PassState pass;
    pass.slot = PassMain;
    pass.frame = v.base;
    pass.frame.passEncodesSrgb = request.options.encoding == OutputEncoding::Srgb ? 1 : 0;
    pass.frame.passMarksWater = request.temporal() ? 1 : 0;
    // The waterline mask is drawn at the main pass's size, so the main pass
    // (multisampled or not) reads it on the same pixel grid.
    const NearPlaneMedium medium =
        nearPlaneMedium(nearPlaneCorners(glm::inverse(v.viewProj), v.depth.nearNdcZ), context.simulation.reach());
    WaterlinePass{medium}.draw(context, state.waterline, v);
    glBindTextureUnit(SWELL_UNIT_WATERLINE, state.waterline.texture());
    const bool inAir = medium == NearPlaneMedium::Air;
    own.setMainPassInAir(inAir);
    const ObservedPass observed(context.telemetry, "main");
    std::tie(pass.framebuffer, pass.viewport) = target(state, request);
    pass.depth = v.depth;
    pass.frame.viewportOrigin = glm::vec2(pass.viewport.x, pass.viewport.y);
    pass.begin(context.resources, context.telemetry,
               request.ownsFrame ? std::optional<glm::vec4>(glm::vec4(0.0f, 0.0f, 0.0f, 1.0f)) : std::nullopt);
    if (!request.ownsFrame && request.throughTarget())
        copyHostPictureIn(context, state, pass, request);
    // The host's geometry seen from below the water is fogged by it, as
    // Swell's own is, before Swell's own is drawn in (draw() only: in
    // render() there is no host's frame).
    if (!request.ownsFrame && medium != NearPlaneMedium::Air)
        fogHostUnderwater(context, state, pass);
    // The world, then the closed volumes the water must not show inside.
    // In draw() the host drew its own opaque scene and volumes already:
    // only Swell's own world joins them.
    PassGeometry* host = request.ownsFrame ? request.options.geometry : nullptr;
    SceneWorld* ownWorld = request.options.sceneWorld ? &own : nullptr;
    if (ownWorld || host) {
        drawGeometry(context, pass, PassKind::Main, ownWorld, host, request.view);
        glColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);
        drawGeometry(context, pass, PassKind::WaterMask, ownWorld, host, request.view);
        glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
    }
    {
        const ObservedPass water(context.telemetry, "water");
        drawWater(context, state, pass, inAir);
    }
    if (request.ownsFrame || request.options.sky)
        drawSky(context, inAir, v.depth);
    // From under the water the surface hides the spray (and the depth
    // test hides a particle's part below the surface from above).
    if (v.base.eyeUnderwater == 0)
        context.spray.draw(context, v, request.view);
}

} // namespace swell::detail
