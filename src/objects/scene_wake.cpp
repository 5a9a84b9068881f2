// A scene's wake, and the source that adds it to the surface bodies float on (scene_wake.h).
#include "objects/scene_wake.h"

#include "objects/wake_surface.h"

#include <algorithm>
#include <cmath>

namespace swell::detail {

namespace {

WakeFieldSettings fieldSettings(const WakeSettings& s, double depth_m)
{
    WakeFieldSettings f;
    f.cells = fastWakeCells(s.cells);
    f.cellSize_m = s.cellSize_m;
    f.depth_m = depth_m;
    // An eighth of the grid each side: room for the waves to die out, and
    // three quarters of it left for the wake.
    f.spongeCells = std::max(4, f.cells / 8);
    return f;
}

// The shallowest water the wake takes, m: on the beach's last metres (and
// over dry land, where it draws nothing the water shows) it keeps this.
constexpr double kShallowestWake_m = 0.3;
// How far the depth under the grid must move before its modes are made
// again (a few milliseconds for 256 x 256): 3%, which changes the
// shallow-water speed sqrt(g h) by 1.5%.
constexpr double kDepthStep = 0.03;

} // namespace

SceneWake::SceneWake(const WakeSettings& settings, double depth_m, std::shared_ptr<const Seabed> seabed)
    : field_(fieldSettings(settings, depth_m)), seaDepth_m_(depth_m), seabed_(std::move(seabed))
{
    reset(glm::dvec2(0.0));
}

double SceneWake::depthAt(glm::dvec2 focus_m) const
{
    if (!seabed_)
        return seaDepth_m_;
    const double below = -seabed_->elevation_m(focus_m); // -inf..inf; inf off every shape in deep water
    return std::clamp(std::isnan(below) ? seaDepth_m_ : below, kShallowestWake_m, seaDepth_m_);
}

void SceneWake::reset(glm::dvec2 focus_m)
{
    field_.setDepth(depthAt(focus_m));
    field_.reset(focus_m);
    previousHeights_.assign(field_.heights().size(), 0.0f);
    previousFoam_ = previousHeights_;
    previousCorner_ = field_.cornerCell();
}

void SceneWake::step(const std::vector<WakeSource>& sources, glm::dvec2 focus_m)
{
    field_.heightsInto(previousHeights_); // into the storage it had: no allocation a step
    previousFoam_ = field_.foam();
    previousCorner_ = field_.cornerCell();
    field_.recentre(focus_m);
    const double depth_m = depthAt(focus_m), now_m = field_.settings().depth_m;
    if (depth_m != now_m && !(std::abs(depth_m - now_m) <= kDepthStep * std::min(depth_m, now_m)))
        field_.setDepth(depth_m);
    field_.step(sources);
}

double SceneWake::blendAt(double time_s) const
{
    // 1 at the current state's time and later, 0 at the previous one's and
    // earlier; whole steps are snapped, so a body's sample at k dt reads a
    // state exactly, whatever rounding k * dt had.
    const double u = time_s * kWakeStepsPerSecond - double(field_.steps() - 1);
    if (std::abs(u - std::round(u)) < 1e-6)
        return std::clamp(std::round(u), 0.0, 1.0);
    return std::clamp(u, 0.0, 1.0);
}

double SceneWake::heightAt(glm::dvec2 world_m, double time_s) const
{
    const double f = blendAt(time_s);
    const int n = field_.cells();
    const double h = field_.cellSize_m();
    const double current = f > 0.0 ? field_.heightAt(world_m) : 0.0;
    const double previous =
        f < 1.0 ? bilinearOverCells(world_m / h - glm::dvec2(previousCorner_), n,
                                             [&](int i, int j) { return previousHeights_[std::size_t(i) + std::size_t(j) * n]; }) : 0.0;
    return f >= 1.0 ? current : f <= 0.0 ? previous : (1.0 - f) * previous + f * current;
}

WakeFrame SceneWake::frameAt(double time_s) const
{
    WakeFrame frame;
    const int n = field_.cells();
    frame.cells = n;
    frame.cellSize_m = field_.cellSize_m();
    frame.cornerCell = field_.cornerCell();
    const float f = float(blendAt(time_s));
    const std::vector<float>& currentFoam = field_.foam();
    const glm::ivec2 shift = frame.cornerCell - previousCorner_;
    // The blended heights and foam go straight into the texels (x and w),
    // the slopes from those heights after.
    frame.texels.resize(currentFoam.size());
    for (int j = 0; j < n; ++j)
        for (int i = 0; i < n; ++i) {
            const std::size_t m = std::size_t(i) + std::size_t(j) * n;
            const int pi = i + shift.x, pj = j + shift.y;
            const bool inPrevious = pi >= 0 && pj >= 0 && pi < n && pj < n;
            const std::size_t pm = inPrevious ? std::size_t(pi) + std::size_t(pj) * n : 0;
            const float hp = inPrevious ? previousHeights_[pm] : 0.0f, fp = inPrevious ? previousFoam_[pm] : 0.0f;
            const float current = field_.heightOfCell(m);
            glm::vec4& texel = frame.texels[m];
            texel.x = f >= 1.0f ? current : f <= 0.0f ? hp : (1.0f - f) * hp + f * current;
            texel.w = f >= 1.0f ? currentFoam[m] : f <= 0.0f ? fp : (1.0f - f) * fp + f * currentFoam[m];
        }
    const float toSlope = float(0.5 / frame.cellSize_m);
    auto at = [&](int i, int j) { return frame.texels[std::size_t(std::clamp(i, 0, n - 1)) + std::size_t(std::clamp(j, 0, n - 1)) * n].x; };
    float reach_m = 0.0f;
    for (int j = 0; j < n; ++j)
        for (int i = 0; i < n; ++i) {
            glm::vec4& texel = frame.texels[std::size_t(i) + std::size_t(j) * n];
            texel.y = (at(i + 1, j) - at(i - 1, j)) * toSlope;
            texel.z = (at(i, j + 1) - at(i, j - 1)) * toSlope;
            reach_m = std::max(reach_m, std::abs(texel.x));
        }
    frame.reach_m = double(reach_m);
    return frame;
}

double SceneWake::reach_m() const
{
    double reach_m = 0.0;
    for (const float h : previousHeights_)
        reach_m = std::max(reach_m, std::abs(double(h)));
    for (std::size_t m = 0; m < previousHeights_.size(); ++m)
        reach_m = std::max(reach_m, std::abs(double(field_.heightOfCell(m))));
    return reach_m;
}

glm::dvec3 SceneWakeSource::heightAt(glm::dvec2 restPoint_m, double time_s) const
{
    return {wake_.heightAt(restPoint_m, time_s), 0.0, 0.0};
}

double SceneWakeSource::reach_m(double) const { return wake_.reach_m(); }

std::string SceneWakeSource::glsl() const { return WakeSurfaceSource::code(); }

SurfaceSourceParameters SceneWakeSource::gpuParameters(double, glm::dvec3) const { return {}; }

} // namespace swell::detail
