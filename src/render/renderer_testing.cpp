// The calls of swell/debug.h: what tests and the benchmark reach of a
// renderer beyond what a host needs.
#include "render/renderer_impl.h"

#include "render/gl_state.h"
#include "swell/debug.h"
#include "swell/error.h"

#include <fmt/format.h>

namespace swell {

std::unique_ptr<Renderer> RendererTesting::create(const Scene& scene, RendererOptions options,
                                                  unsigned omittedWaterTerms)
{
    return std::unique_ptr<Renderer>(new Renderer(scene, std::move(options), omittedWaterTerms));
}

int RendererTesting::waterVertexCount(const Renderer& renderer)
{
    return renderer.impl_->resources.waterVertexCount();
}

void RendererTesting::setTemporalJitter(Renderer& renderer, bool on) { renderer.impl_->settings.temporalJitter = on; }

void RendererTesting::setWaterInTwoPasses(Renderer& renderer, bool on)
{
    renderer.impl_->resources.waterInTwoPasses = on && vertexShadersStoreBuffers();
}

void RendererTesting::setIslandTolerance(Renderer& renderer, double tolerance_px)
{
    if (!(tolerance_px >= 0.0))
        throw InputError({"island tolerance"}, fmt::format("{} pixels is below 0", tolerance_px));
    renderer.impl_->settings.islandTolerance_px = tolerance_px;
}

void RendererTesting::setContactFoam(Renderer& renderer, bool on) { renderer.impl_->resources.contact.setEnabled(on); }

int RendererTesting::captureWaterVertices(Renderer& renderer, const Camera& camera, double time_s, unsigned buffer,
                                          glm::ivec2 size, std::vector<std::uint32_t>* drawnIndices)
{
    Renderer::Impl& s = *renderer.impl_;
    size = glm::max(size, glm::ivec2(1));
    s.advanceTo(time_s, camera.position_m);
    const HostStateScope hostState;
    RenderContext context = s.context();
    const ViewFrame v = prepareView(context, viewOf(camera, size), size, false);
    s.resources.bindFrame(PassMain, v.base);
    Resources& resources = s.resources;
    if (drawnIndices)
        *drawnIndices = resources.waterGrid.chosenIndices();
    // Drawing needs a complete framebuffer even with rasterisation discarded
    // (a headless context has no default one).
    if (s.output.size().x == 0)
        s.output.resize({1, 1}, GL_RGBA8);
    glBindFramebuffer(GL_FRAMEBUFFER, s.output.framebuffer());
    resources.programs.capture.use();
    glBindVertexArray(resources.emptyVao.id());
    glEnable(GL_RASTERIZER_DISCARD);
    glBindBufferBase(GL_TRANSFORM_FEEDBACK_BUFFER, 0, buffer);
    glBeginTransformFeedback(GL_POINTS);
    const int count = resources.waterVertexCount();
    glDrawArrays(GL_POINTS, 0, count);
    glEndTransformFeedback();
    glBindBufferBase(GL_TRANSFORM_FEEDBACK_BUFFER, 0, 0);
    return count;
}

} // namespace swell
