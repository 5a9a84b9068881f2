// The reflection and refraction passes (render/view_passes.h): the world
// drawn into the view's own targets at the reflection's resolution scale,
// clipped at the sea level (offset by reflection.clip_offset_m so the
// water's edge shows no gap), for the water to look up.
#include "render/view_passes.h"

#include "render/frame_uniforms.h"
#include "swell/gpu/bindings.h"
#include "swell/gpu/underwater.h"

#include <glm/gtc/matrix_transform.hpp>
#include <glm/matrix.hpp>

namespace swell::detail {

namespace {

// The pass's own frame uniforms: the mirrored camera and the clip plane
// keeping what lies above the surface (reflection), or the side beyond it
// from the eye (refraction: below, or above for an eye under the water).
FrameUniforms mirrorFrame(const FrameUniforms& base, PassKind kind, float clipOffset_m, glm::ivec2 size)
{
    FrameUniforms f = base;
    if (kind == PassKind::Reflection) {
        const glm::mat4 mirror = glm::scale(glm::mat4(1.0f), glm::vec3(1.0f, -1.0f, 1.0f));
        f.passViewProj = base.cameraViewProj * mirror;
        f.passInvViewProj = glm::inverse(f.passViewProj);
        f.clipPlane = glm::vec4(0.0f, 1.0f, 0.0f, clipOffset_m);
        f.eyePosition.y = -base.eyePosition.y;
    } else {
        const bool fromBelow = base.eyeUnderwater != 0;
        f.clipPlane = glm::vec4(0.0f, fromBelow ? 1.0f : -1.0f, 0.0f, clipOffset_m);
    }
    setViewport(f, size);
    return f;
}

} // namespace

void MirrorPass::draw(RenderContext& context, ViewState& state, const ViewFrame& v, const ViewRequest& request,
                      SceneWorld* own) const
{
    const bool reflection = kind == PassKind::Reflection;
    RenderTarget& target = reflection ? state.reflection : state.refraction;
    const glm::ivec2 size =
        glm::max(glm::ivec2(glm::dvec2(v.size) * context.scene.reflection.resolutionScale), glm::ivec2(1));
    target.resize(size);
    const ObservedPass observed(context.telemetry, reflection ? "reflection" : "refraction");
    PassState pass;
    pass.slot = reflection ? PassReflection : PassRefraction;
    pass.frame = mirrorFrame(v.base, kind, float(context.scene.reflection.clipOffset_m), size);
    pass.framebuffer = target.framebuffer();
    pass.viewport = glm::ivec4(0, 0, size);
    pass.depth = v.depth;
    pass.clipped = true;
    pass.mirrored = reflection;
    pass.begin(context.resources, context.telemetry, glm::vec4(0.0f));
    drawGeometry(context, pass, kind, own, request.options.geometry, request.view);
    glDisable(GL_CLIP_DISTANCE0);
    if (reflection)
        drawSky(context, true, v.depth);
}

void drawSky(RenderContext& context, bool inAir, const DepthConvention& depth)
{
    const Resources& resources = context.resources;
    (inAir ? resources.programs.skyInAir : resources.programs.sky).use();
    glBindTextureUnit(SWELL_UNIT_SKY, resources.world.skyCube.id());
    glDepthFunc(depth.testOrFar);
    glDepthMask(GL_FALSE);
    glBindVertexArray(resources.emptyVao.id());
    glDrawArrays(GL_TRIANGLES, 0, 3);
    ++context.telemetry.counters.drawCalls;
    glDepthMask(GL_TRUE);
    glDepthFunc(depth.test);
}

void WaterlinePass::draw(RenderContext& context, WaterlineMask& mask, const ViewFrame& v) const
{
    mask.resize(v.size);
    if (medium != NearPlaneMedium::Both) {
        mask.fill(medium);
        return;
    }
    const ObservedPass observed(context.telemetry, "waterline");
    PassState pass;
    pass.slot = PassWaterline;
    pass.frame = v.base;
    pass.frame.viewportOrigin = glm::vec2(0.0f);
    pass.framebuffer = mask.framebuffer();
    pass.viewport = glm::ivec4(0, 0, v.size);
    // The mask's own depth, whatever the frame's convention: waterline.frag
    // writes the distance to the eye, nearer passing (its clip control
    // stays the frame's, which its projection is for).
    pass.depth = v.depth;
    pass.depth.cleared = 1.0f;
    pass.depth.test = GL_LESS;
    pass.depth.testOrFar = GL_LEQUAL;
    pass.begin(context.resources, context.telemetry, glm::vec4(SWELL_WATERLINE_NO_HIT));
    glBindTextureUnit(SWELL_UNIT_WATERLINE, mask.allAbove()); // never the target itself
    const Resources& resources = context.resources;
    resources.programs.waterline.use();
    context.simulation.bindForWater();
    glBindVertexArray(resources.waterGrid.vertexArray());
    resources.waterGrid.draw();
    ++context.telemetry.counters.drawCalls;
}

} // namespace swell::detail
