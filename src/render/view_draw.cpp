// One view drawn (Renderer::draw, Renderer::render): what is asked of it,
// and its passes in order (render/view_passes.h).
#include "render/renderer_impl.h"

#include "render/contact_map.h"
#include "render/gl_state.h"
#include "render/scene_world.h"
#include "swell/gpu/bindings.h"

namespace swell {

void Renderer::Impl::drawView(const ViewRequest& request, ViewState& state)
{
    RenderContext c = context();
    ViewFrame v = prepareView(c, request.view, request.size, request.options.geometry != nullptr);
    ++telemetry.counters.views;
    SceneWorld own(resources.world, resources.programs.meshInAir, resources.programs.mesh, v.poses, v.island,
                   v.seabed, telemetry.counters);
    own.setIslandTolerance(settings.islandTolerance_px);
    SceneWorld* ownWorld = request.options.sceneWorld ? &own : nullptr;
    // Drawn for the temporal resolve below the output's size: the water's
    // detail filtered by the output pixel's footprint (frame.glsl).
    if (request.temporal() && request.size.x < request.outputSize().x)
        v.base.footprintScale = float(double(request.size.x) / double(request.outputSize().x));
    prepareViewMaps(c, v, ownWorld != nullptr);
    // Where the world meets the water, before every pass that shades it.
    drawContact(c, v, ownWorld, request.options.geometry, request.view);
    // Passes before the main one see nothing from below the water.
    state.waterline.resize(v.size);
    glBindTextureUnit(SWELL_UNIT_WATERLINE, state.waterline.allAbove());
    MirrorPass{PassKind::Reflection}.draw(c, state, v, request, ownWorld);
    MirrorPass{PassKind::Refraction}.draw(c, state, v, request, ownWorld);
    MainPass{}.draw(c, state, v, request, own);
    PresentPass{}.draw(c, state, v, request);
    if (request.options.motionVectors != 0 && !request.ownsFrame)
        motionVectors.draw(c, state, v, request);
}

void Renderer::Impl::drawRestoring(const ViewRequest& request, ViewState& state)
{
    const HostStateScope hostState;
    drawView(request, state);
}

namespace {

// Moves the request's projection by the view's jitter for this frame when
// it is resolved over time, keeping the unmoved one for the resolve; starts
// the history again when the resolve was just turned on or off.
void prepareTemporal(ViewRequest& request, ViewState& state, bool temporal, bool jitter)
{
    if (temporal != state.temporalOn)
        state.temporal.reset();
    state.temporalOn = temporal;
    if (!temporal)
        return;
    request.unjitteredViewProj = request.view.projection * request.view.view;
    state.temporal.setJitterEnabled(jitter);
    if (jitter)
        request.view.projection = jitteredProjection(request.view.projection, state.temporal.jitter_px(), request.size);
}

} // namespace

ViewRequest Renderer::Impl::renderRequest(const Camera& camera, glm::ivec2 outputSize, GLuint framebuffer)
{
    ViewRequest request;
    request.options.sceneWorld = true;
    request.options.sky = true;
    request.options.renderScale = settings.renderScale;
    request.options.antialiasing = settings.temporal ? Antialiasing::Off : scene.antialiasing;
    request.output = framebuffer;
    request.outputViewport = glm::ivec4(0, 0, outputSize);
    request.size = scaledFrameSize(outputSize, settings.renderScale);
    request.view = viewOf(camera, request.size);
    request.ownsFrame = true;
    prepareTemporal(request, views.own(), settings.temporal, settings.temporalJitter);
    return request;
}

ViewRequest Renderer::Impl::drawRequest(const View& view, GLuint framebuffer, const DrawOptions& options,
                                        ViewState& state)
{
    ViewRequest request;
    request.view = view;
    request.options = options;
    if (options.temporal)
        request.options.antialiasing = Antialiasing::Off; // the resolve brings its own
    request.output = framebuffer;
    request.outputViewport = view.viewport;
    request.size = scaledFrameSize(request.outputSize(), options.renderScale);
    prepareTemporal(request, state, options.temporal, settings.temporalJitter);
    return request;
}

void Renderer::Impl::render(const Camera& camera, double time_s, glm::ivec2 outputSize, GLuint framebuffer,
                            std::optional<glm::dvec3> simulatedAround_m)
{
    telemetry.counters = {};
    if (outputSize.x <= 0 || outputSize.y <= 0)
        return;
    advanceTo(time_s, simulatedAround_m.value_or(camera.position_m));
    drawRestoring(renderRequest(camera, outputSize, framebuffer), views.own());
}

} // namespace swell
