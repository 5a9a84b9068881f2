// The main pass's water (render/view_passes.h): in two passes where it can
// be, a visibility pass and one shading run per water pixel
// (render/water_visibility.h), else the grid shaded in its own fragments.
#include "render/view_passes.h"

#include "swell/gpu/bindings.h"
#include "swell/scene/scene.h"

namespace swell::detail {

namespace {

// Whether `framebuffer` holds more than one sample a pixel (Swell's MSAA
// target, or a host's multisampled framebuffer drawn into directly).
bool multisampled(GLuint framebuffer)
{
    GLint samples = 0;
    if (framebuffer == 0)
        glGetIntegerv(GL_SAMPLES, &samples);
    else
        glGetNamedFramebufferParameteriv(framebuffer, GL_SAMPLES, &samples);
    return samples > 1;
}

} // namespace

void MainPass::drawWater(RenderContext& context, ViewState& state, const PassState& pass, bool inAir) const
{
    // The visibility pass keeps one triangle a pixel: a multisampled pass
    // needs a triangle a sample, and the wireframe view draws lines.
    const bool twoPasses = context.resources.waterInTwoPasses && context.scene.debugView != DebugView::Wireframe &&
                           !multisampled(pass.framebuffer);
    if (twoPasses)
        drawWaterInTwoPasses(context, state, pass, inAir);
    else
        drawWaterInOnePass(context, state, inAir);
}

void MainPass::bindWaterShading(const RenderContext& context, const ViewState& state, bool deferred, bool inAir) const
{
    const Programs& programs = context.resources.programs;
    if (deferred)
        (inAir ? programs.waterDeferredInAir : programs.waterDeferred).use();
    else
        (inAir ? programs.waterInAir : programs.water).use();
    glBindTextureUnit(SWELL_UNIT_SKY, context.resources.world.skyCube.id());
    glBindTextureUnit(SWELL_UNIT_REFLECTION_COLOR, state.reflection.color());
    glBindTextureUnit(SWELL_UNIT_REFLECTION_DEPTH, state.reflection.depth());
    glBindTextureUnit(SWELL_UNIT_REFRACTION_COLOR, state.refraction.color());
    glBindTextureUnit(SWELL_UNIT_REFRACTION_DEPTH, state.refraction.depth());
    context.simulation.bindForWater();
}

void MainPass::drawWaterInOnePass(RenderContext& context, const ViewState& state, bool inAir) const
{
    const Resources& resources = context.resources;
    bindWaterShading(context, state, false, inAir);
    glBindVertexArray(resources.waterGrid.vertexArray());
    if (context.scene.debugView == DebugView::Wireframe)
        glPolygonMode(GL_FRONT_AND_BACK, GL_LINE);
    context.telemetry.counters.waterTriangles += resources.waterGrid.draw();
    glPolygonMode(GL_FRONT_AND_BACK, GL_FILL);
    ++context.telemetry.counters.drawCalls;
}

void MainPass::drawWaterInTwoPasses(RenderContext& context, ViewState& state, const PassState& pass, bool inAir) const
{
    Resources& resources = context.resources;
    const glm::ivec2 size(pass.viewport.z, pass.viewport.w);
    {
        const ObservedPass observed(context.telemetry, "water visibility");
        glBindFramebuffer(GL_FRAMEBUFFER, state.waterVisibility.begin(pass.framebuffer, pass.viewport));
        setPassState(glm::ivec4(0, 0, size), pass.depth);
        const WaterVisibilityProgram& program = resources.programs.waterVisibility;
        program.use();
        context.simulation.bindForWater();
        resources.waterVertexCache.bind(std::size_t(resources.waterVertexCount()), program.cachedVertexBytes());
        glBindVertexArray(resources.waterGrid.vertexArray());
        context.telemetry.counters.waterTriangles +=
            resources.waterGrid.drawRanges([&](std::uint32_t first) { program.setFirstTriangle(first); });
        context.telemetry.counters.drawCalls += resources.waterGrid.rangeCount();
        glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT | GL_TEXTURE_FETCH_BARRIER_BIT);
        // The tiles that show water, for the shading pass's draw.
        resources.programs.waterTiles.use();
        glBindTextureUnit(SWELL_UNIT_WATER_VISIBILITY, state.waterVisibility.triangles());
        glBindBufferBase(GL_SHADER_STORAGE_BUFFER, SWELL_STORAGE_WATER_TILES, state.waterVisibility.tiles());
        const glm::ivec2 tiles = state.waterVisibility.tileGrid();
        glDispatchCompute(GLuint(tiles.x), GLuint(tiles.y), 1);
        // No program, before the next: Mesa keeps a reference to the first
        // program made current after a compute program (as the compute
        // stage's), which would keep the shading pass's program alive past
        // its deletion until the next compute dispatch (the soak's GL
        // objects left after the renderer was destroyed).
        glUseProgram(0);
        glMemoryBarrier(GL_COMMAND_BARRIER_BIT | GL_SHADER_STORAGE_BARRIER_BIT);
        Telemetry::addWork(state.waterVisibility.passWork(), context.telemetry.counters.viewsGpu);
    }
    const ObservedPass observed(context.telemetry, "water shading");
    glBindFramebuffer(GL_FRAMEBUFFER, pass.framebuffer);
    setPassState(pass.viewport, pass.depth);
    // Each water pixel's depth is the visibility pass's, written as it is.
    glDepthFunc(GL_ALWAYS);
    bindWaterShading(context, state, true, inAir);
    glBindTextureUnit(SWELL_UNIT_WATER_VISIBILITY, state.waterVisibility.triangles());
    glBindTextureUnit(SWELL_UNIT_WATER_DEPTH, state.waterVisibility.depth());
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, SWELL_STORAGE_WATER_INDICES, resources.waterGrid.indexBuffer());
    glBindVertexArray(resources.emptyVao.id());
    glBindBuffer(GL_DRAW_INDIRECT_BUFFER, state.waterVisibility.tiles());
    // A point whose centre leaves the viewport is not drawn at all: the
    // viewport is widened to whole tiles (the pixels keep their places: same
    // corner, same pixel size) and the scissor keeps the pass's own.
    const glm::ivec2 tiled = state.waterVisibility.tileGrid() * SWELL_WATER_TILE;
    glViewport(pass.viewport.x, pass.viewport.y, tiled.x, tiled.y);
    glEnable(GL_SCISSOR_TEST);
    glScissor(pass.viewport.x, pass.viewport.y, pass.viewport.z, pass.viewport.w);
    glEnable(GL_PROGRAM_POINT_SIZE);
    glDrawArraysIndirect(GL_POINTS, nullptr);
    glDisable(GL_PROGRAM_POINT_SIZE);
    glBindBuffer(GL_DRAW_INDIRECT_BUFFER, 0);
    ++context.telemetry.counters.drawCalls;
    setPassState(pass.viewport, pass.depth);
}

} // namespace swell::detail
