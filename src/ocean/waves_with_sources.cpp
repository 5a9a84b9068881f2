#include "ocean/waves_with_sources.h"

#include "swell/wave_model_gpu.h"

#include <fmt/format.h>
#include <glm/geometric.hpp>

namespace swell::detail {

WavesWithSources::WavesWithSources(std::shared_ptr<const WaveModel> waves,
                                   std::vector<std::shared_ptr<const SurfaceSource>> sources)
    : waves_(std::move(waves)), sources_(std::move(sources))
{
}

std::string_view WavesWithSources::name() const { return waves_->name(); }

std::string WavesWithSources::summary() const
{
    return fmt::format("{} with {} surface source{}", waves_->summary(), sources_.size(), sources_.size() == 1 ? "" : "s");
}

// The sources' reach depends on the time; the model's may not: the waves'
// alone (the renderer pads its culling by the sources' reach each frame).
WaveReach WavesWithSources::reach() const { return waves_->reach(); }
double WavesWithSources::heightDeviation_m() const { return waves_->heightDeviation_m(); }

SurfacePoint WavesWithSources::surfaceAt(glm::dvec2 rest, double time_s, const SurfaceFilter& filter) const
{
    SurfacePoint p = waves_->surfaceAt(rest, time_s, filter);
    // A height field's normal is (-dh/dx, 1, -dh/dz) normalised: the sources'
    // slopes add to the waves'.
    glm::dvec3 n = p.normal / std::max(p.normal.y, 1e-3);
    for (const std::shared_ptr<const SurfaceSource>& source : sources_) {
        const glm::dvec3 h = source->heightAt(rest, time_s);
        p.displacement_m.y += h.x;
        n.x -= h.y;
        n.z -= h.z;
    }
    p.normal = glm::normalize(n);
    return p;
}

glm::dvec3 WavesWithSources::displacementAt(glm::dvec2 rest, double time_s, const SurfaceFilter& filter) const
{
    glm::dvec3 d = waves_->displacementAt(rest, time_s, filter);
    for (const std::shared_ptr<const SurfaceSource>& source : sources_)
        d.y += source->heightAt(rest, time_s).x;
    return d;
}

glm::dvec2 WavesWithSources::restPointUnder(glm::dvec2 world, double time_s, const SurfaceFilter& filter) const
{
    return waves_->restPointUnder(world, time_s, filter);
}

std::unique_ptr<WaveModelGpu> WavesWithSources::createGpu(const gl::ShaderSources& shaders) const
{
    return waves_->createGpu(shaders);
}

} // namespace swell::detail
