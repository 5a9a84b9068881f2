// The ocean renderer's public calls (swell/renderer.h): each hands its work
// to the part of Renderer::Impl that owns it (render/renderer_impl.h).
#include "render/renderer_impl.h"

#include "render/gl_state.h"
#include "swell/error.h"
#include "swell/gpu/bindings.h"
#include "swell/gpu/limits.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

namespace swell {

Renderer::Renderer(const Scene& scene, RendererOptions options) : Renderer(scene, std::move(options), 0u) {}

Renderer::Renderer(const Scene& scene, RendererOptions options, unsigned omittedWaterTerms)
    : impl_(std::make_unique<Impl>(std::move(options), omittedWaterTerms))
{
    std::shared_ptr<const Seabed> seabed = impl_->seabedOf(scene);
    impl_->apply(scene, ParameterEffect::Frame, Impl::waveModelOf(scene, *seabed), nullptr, {}, true, seabed);
}

Renderer::~Renderer() = default;

void Renderer::setScene(const Scene& scene)
{
    Impl& s = *impl_;
    const ParameterEffect effects = sceneChanges(s.scene, scene);
    // The waves are generated again only when a wave parameter or the sea
    // floor they run over changed; the floor is built once, for the model
    // and the drawn mesh.
    const bool floorChanged = hasEffect(effects, ParameterEffect::Seabed) || hasEffect(effects, ParameterEffect::World);
    std::shared_ptr<const Seabed> seabed = floorChanged ? s.seabedOf(scene) : nullptr;
    std::shared_ptr<const WaveModel> sceneModel = s.simulation.sceneModel();
    if (hasEffect(effects, ParameterEffect::Waves) || floorChanged)
        sceneModel = Impl::waveModelOf(scene, seabed ? *seabed : *s.resources.seabed);
    s.apply(scene, effects, std::move(sceneModel), s.simulation.overrideModel(), s.simulation.hostSources(), false,
            std::move(seabed));
}

const Scene& Renderer::scene() const { return impl_->scene; }
const WaveModel& Renderer::waveModel() const { return impl_->simulation.model(); }

void Renderer::setWaveModel(std::shared_ptr<const WaveModel> model)
{
    Impl& s = *impl_;
    s.apply(s.scene, ParameterEffect::Frame, s.simulation.sceneModel(), std::move(model), s.simulation.hostSources());
}

void Renderer::addSurfaceSource(std::shared_ptr<const SurfaceSource> source)
{
    Impl& s = *impl_;
    if (!source)
        throw Error("addSurfaceSource: no source (null)");
    std::vector<std::shared_ptr<const SurfaceSource>> next = s.simulation.hostSources();
    if (std::find(next.begin(), next.end(), source) != next.end())
        throw Error("addSurfaceSource: the source was added already");
    next.push_back(std::move(source));
    const std::size_t drawn = next.size() + (s.scene.wake.enabled ? 1 : 0);
    if (drawn > SWELL_MAX_SURFACE_SOURCES)
        throw Error(fmt::format("addSurfaceSource: at most {} surface sources are drawn{}", SWELL_MAX_SURFACE_SOURCES,
                                s.scene.wake.enabled ? ", the wake's included" : ""));
    s.apply(s.scene, ParameterEffect::Frame, s.simulation.sceneModel(), s.simulation.overrideModel(), std::move(next));
}

void Renderer::removeSurfaceSource(const std::shared_ptr<const SurfaceSource>& source)
{
    Impl& s = *impl_;
    std::vector<std::shared_ptr<const SurfaceSource>> next = s.simulation.hostSources();
    next.erase(std::remove(next.begin(), next.end(), source), next.end());
    s.apply(s.scene, ParameterEffect::Frame, s.simulation.sceneModel(), s.simulation.overrideModel(), std::move(next));
}

void Renderer::setSeabedHeights(const SeabedHeights& heights)
{
    Impl& s = *impl_;
    checkSeabedHeights(heights, "Renderer::setSeabedHeights()");
    s.simulation.settle();
    // Built before anything changes: a failure leaves the heights as they were.
    auto seabed = std::make_shared<const Seabed>(s.scene, &heights);
    std::shared_ptr<const WaveModel> model = makeWaveModel(s.scene, *seabed);
    // The waves run over the host's floor too.
    s.apply(s.scene, ParameterEffect::Frame, std::move(model), s.simulation.overrideModel(), s.simulation.hostSources());
    s.hostSeabed = heights;
    s.resources.seabed = std::move(seabed);
}

void Renderer::clearSeabedHeights()
{
    Impl& s = *impl_;
    s.simulation.settle();
    auto seabed = std::make_shared<const Seabed>(s.scene);
    std::shared_ptr<const WaveModel> model = makeWaveModel(s.scene, *seabed);
    s.apply(s.scene, ParameterEffect::Frame, std::move(model), s.simulation.overrideModel(), s.simulation.hostSources());
    s.resources.seabed = std::move(seabed);
    s.hostSeabed.reset();
}

const Seabed& Renderer::seabed() const { return *impl_->resources.seabed; }

namespace {

void checkRenderScale(double scale)
{
    if (!(scale >= kMinRenderScale && scale <= kMaxRenderScale))
        throw InputError({"render scale"}, fmt::format("{} is outside {}..{}", scale, kMinRenderScale, kMaxRenderScale));
}

} // namespace

void Renderer::setRenderScale(double scale)
{
    checkRenderScale(scale);
    impl_->settings.renderScale = scale;
}

double Renderer::renderScale() const { return impl_->settings.renderScale; }
void Renderer::setTemporalResolve(bool on) { impl_->settings.temporal = on; }
bool Renderer::temporalResolve() const { return impl_->settings.temporal; }
void Renderer::resetTemporalHistory() { impl_->views.resetHistories(); }
void Renderer::releaseView(std::uint32_t viewId) { impl_->views.release(viewId); }

const FrameCounters& Renderer::counters() const { return impl_->telemetry.counters; }
void Renderer::setPassObserver(PassObserver* observer) { impl_->telemetry.setObserver(observer); }

void Renderer::setInteractive(bool interactive)
{
    impl_->settings.interactive = interactive;
    impl_->simulation.setInteractive(interactive);
}

void Renderer::reloadShaders()
{
    Impl& s = *impl_;
    s.resources.sources.forgetCachedFiles();
    s.resources.programs = buildChangedPrograms(s.resources.sources, Programs{}, s.resources.programs.flags);
    s.labels.forgetPrograms(); // built again from the new sources when next asked for
    s.sky.forgetPrograms();
}

void Renderer::advanceTo(double time_s, glm::dvec3 viewpoint_m)
{
    if (!std::isfinite(time_s) || !std::isfinite(viewpoint_m.x + viewpoint_m.y + viewpoint_m.z))
        throw Error(fmt::format("advanceTo: the time ({}) and the viewpoint must be finite", time_s));
    impl_->advanceTo(time_s, viewpoint_m);
}

void Renderer::anticipate(double nextTime_s) { impl_->simulation.anticipate(nextTime_s); }

std::optional<double> Renderer::simulatedTime_s() const
{
    const std::optional<Simulated>& simulated = impl_->simulation.simulated();
    return simulated ? std::optional<double>(simulated->time_s) : std::nullopt;
}

void Renderer::draw(const View& view, unsigned framebuffer, const DrawOptions& options)
{
    Impl& s = *impl_;
    s.simulation.require();
    // A callback's error is told by the flag it leaves: one pending already
    // would be blamed on it, and clearing it would hide the host's own.
    if (const GLenum pending = glGetError(); pending != GL_NO_ERROR)
        throw Error(fmt::format("GL error 0x{:04x} was pending when draw() was called (draw() tells its "
                                "callbacks' errors by the flag they leave, so it needs none pending)",
                                pending));
    checkView(view);
    checkFramebuffer(framebuffer, true);
    checkRenderScale(options.renderScale);
    if (options.motionVectors != 0)
        checkMotionVectors(framebuffer, options.motionVectors);
    ViewState& state = s.views.host(options.viewId);
    s.drawRestoring(s.drawRequest(view, framebuffer, options, state), state);
}

void Renderer::render(const Camera& camera, double time_s, glm::ivec2 size, unsigned framebuffer)
{
    impl_->render(camera, time_s, size, framebuffer);
}

Image Renderer::renderImage(const Camera& camera, double time_s, glm::ivec2 size,
                            std::optional<glm::dvec3> simulatedAround_m)
{
    Image image;
    if (size.x <= 0 || size.y <= 0)
        return image;
    RenderTarget& output = impl_->output;
    output.resize(size, GL_RGBA8);
    impl_->render(camera, time_s, size, output.framebuffer(), simulatedAround_m);
    image.width = size.x;
    image.height = size.y;
    image.rgba.resize(size_t(size.x) * size_t(size.y) * 4);
    std::vector<std::uint8_t> bottomUp(image.rgba.size());
    {
        // A pixel buffer or pack parameters the host left would change the read-back.
        const HostStateScope hostState;
        glPixelStorei(GL_PACK_ALIGNMENT, 1);
        glGetTextureImage(output.color(), 0, GL_RGBA, GL_UNSIGNED_BYTE, GLsizei(bottomUp.size()), bottomUp.data());
    }
    const size_t row = size_t(size.x) * 4;
    for (int y = 0; y < size.y; ++y)
        std::copy_n(&bottomUp[size_t(size.y - 1 - y) * row], row, &image.rgba[size_t(y) * row]);
    return image;
}

FrameLabels Renderer::renderLabels(const Camera& camera, glm::ivec2 size)
{
    RenderContext context = impl_->context();
    return impl_->labels.draw(context, camera, size);
}

Camera Renderer::sceneCameraAt(double time_s) { return impl_->simulation.sceneCameraAt(impl_->scene, time_s); }

PlatformMotion Renderer::platformAt(double time_s) { return impl_->simulation.platformAt(impl_->scene, time_s); }
std::vector<glm::dmat4> Renderer::objectTransforms() const { return impl_->simulation.objectTransforms(); }

DrawnSurface Renderer::drawnSurface(const Camera& camera, double time_s) const
{
    return impl_->simulation.drawnSurface(camera.position_m, time_s, impl_->resources.shapes);
}

DrawnSurface Renderer::drawnSurface(glm::dvec3 lodViewpoint_m) const
{
    return impl_->simulation.drawnSurface(lodViewpoint_m);
}

} // namespace swell
