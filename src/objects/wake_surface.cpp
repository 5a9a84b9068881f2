#include "objects/wake_surface.h"

#include <algorithm>
#include <cmath>

namespace swell::detail {

WakeSurfaceSource::WakeSurfaceSource(std::shared_ptr<const WakeFrame> frame) : frame_(std::move(frame))
{
    if (frame_)
        reach_m_ = frame_->reach_m;
}

glm::dvec3 WakeSurfaceSource::heightAt(glm::dvec2 restPoint_m, double) const
{
    if (!frame_ || frame_->cells <= 0)
        return glm::dvec3(0.0);
    // The slopes as the GPU blends them: the cells' own, bilinearly.
    const glm::dvec2 g = (restPoint_m - frame_->corner_m()) / frame_->cellSize_m;
    auto slope = [&](int component) {
        return bilinearOverCells(g, frame_->cells, [&](int i, int j) {
            return frame_->texels[std::size_t(i) + std::size_t(j) * std::size_t(frame_->cells)][component];
        });
    };
    return {frame_->heightAt(restPoint_m), slope(1), slope(2)};
}

double WakeSurfaceSource::reach_m(double) const { return reach_m_; }

std::string WakeSurfaceSource::code()
{
    // The cells come from the Wake block and texture (shaders/wake.glsl),
    // not from the parameters; the foam's amount is the cells' own, given
    // its look where water.frag draws every source's foam.
    return R"(#include "wake.glsl"
vec4 SWELL_SOURCE_FUNCTION(vec2 p_m, vec4 parameters[4]) { return wakeAt(p_m); }
)";
}

std::string WakeSurfaceSource::glsl() const { return code(); }

SurfaceSourceParameters WakeSurfaceSource::gpuParameters(double, glm::dvec3) const { return {}; }

} // namespace swell::detail
