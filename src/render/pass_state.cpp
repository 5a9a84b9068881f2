#include "render/pass_state.h"

#include "render/gl_state.h"
#include "render/scene_world.h"
#include "render/simulation.h"
#include "render/view_frame.h"
#include "swell/error.h"
#include "swell/gpu/bindings.h"

#include <fmt/format.h>

namespace swell::detail {

namespace {

const char* passName(PassKind pass)
{
    switch (pass) {
    case PassKind::Reflection: return "reflection";
    case PassKind::Refraction: return "refraction";
    case PassKind::Main: return "main";
    case PassKind::WaterMask: return "water mask";
    case PassKind::Contact: return "contact";
    }
    return "?";
}

} // namespace

void setPassState(glm::ivec4 viewport, const DepthConvention& depth)
{
    glViewport(viewport.x, viewport.y, viewport.z, viewport.w);
    glDisable(GL_BLEND);
    glDisable(GL_CULL_FACE);
    glDisable(GL_SCISSOR_TEST);
    glDisable(GL_RASTERIZER_DISCARD);
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(depth.test);
    glDepthMask(GL_TRUE);
    glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
    glClipControl(GL_LOWER_LEFT, depth.clipDepth);
    glPolygonMode(GL_FRONT_AND_BACK, GL_FILL);
    // The shaders write display-ready (sRGB-encoded) colour, or linear
    // colour for a linear target: never encoded again on the way.
    glDisable(GL_FRAMEBUFFER_SRGB);
    // Filter across cubemap face edges (off by default even in core profiles).
    glEnable(GL_TEXTURE_CUBE_MAP_SEAMLESS);
}

void PassState::begin(const Resources& resources, Telemetry& telemetry, std::optional<glm::vec4> clear) const
{
    {
        const CpuPartScope part(telemetry.cpu, telemetry.counters.simulationCpu.views_ms);
        resources.bindFrame(slot, frame);
    }
    glBindFramebuffer(GL_FRAMEBUFFER, framebuffer);
    setPassState(viewport, depth);
    if (clear) {
        glClearColor(clear->r, clear->g, clear->b, clear->a);
        glClearDepth(depth.cleared);
        glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    }
    clipped ? glEnable(GL_CLIP_DISTANCE0) : glDisable(GL_CLIP_DISTANCE0);
}

void PassState::restore(RenderContext& context) const
{
    setFixedState();
    glBindFramebuffer(GL_FRAMEBUFFER, framebuffer);
    setPassState(viewport, depth);
    glFrontFace(mirrored ? GL_CW : GL_CCW);
    if (clipped)
        glEnable(GL_CLIP_DISTANCE0);
    {
        const CpuPartScope part(context.telemetry.cpu, context.telemetry.counters.simulationCpu.views_ms);
        context.resources.bindFrame(slot, frame);
    }
    context.resources.caustics.bind();
    context.resources.contact.bind();
    context.simulation.bindForWater();
}

void drawGeometry(RenderContext& context, const PassState& state, PassKind kind, SceneWorld* own, PassGeometry* host,
                  const View& view)
{
    const SeaFrame& sea = context.simulation.sea();
    PassView pass;
    pass.pass = kind;
    pass.view = state.mirrored ? view.view * sea.mirror() : view.view;
    pass.projection = view.projection;
    pass.viewport = state.viewport;
    pass.depth = view.depth;
    pass.eye_m = state.mirrored ? sea.mirrored(view.eye_m()) : view.eye_m();
    // The pass's clip plane, relative to the render origin, is the sea
    // frame's plane moved by the origin (its y at the sea level).
    pass.clipPlane_m = sea.planeInWorld(glm::dvec4(state.frame.clipPlane));
    // The mirror turns every triangle's winding around on screen: without
    // the front face turned too, the faces seen would count as back faces,
    // and mesh.frag, which turns a back face's normal round, would light
    // each object's reflection from the wrong side.
    glFrontFace(state.mirrored ? GL_CW : GL_CCW);
    drawGeometryAs(context, state, pass, own, host);
    glFrontFace(GL_CCW);
}

void drawGeometryAs(RenderContext& context, const PassState& state, const PassView& pass, SceneWorld* own,
                    PassGeometry* host)
{
    // The world is drawn before the sky and the water, which bind the sky
    // cubemap for themselves; its fog looks the sky up too (fog.glsl's
    // aerial perspective), and the unit may hold nothing yet (a bake leaves
    // it empty) or what another frame left there.
    glBindTextureUnit(SWELL_UNIT_SKY, context.resources.world.skyCube.id());
    if (own)
        own->drawPass(pass);
    if (host) {
        host->drawPass(pass);
        if (const GLenum error = glGetError(); error != GL_NO_ERROR)
            throw Error(fmt::format("the host's geometry left GL error 0x{:04x} in the {} pass", error,
                                    passName(pass.pass)));
        state.restore(context);
    }
}

} // namespace swell::detail

