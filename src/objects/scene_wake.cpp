// A scene's wake and the surface bodies float on (scene_wake.h).
#include "objects/scene_wake.h"

#include "swell/wave_model_gpu.h" // the waves' GPU half, handed on


#include <fmt/format.h>

#include <algorithm>
#include <cmath>

namespace swell::detail {

namespace {

// The wave model plus the wake, as heights added at the rest point: the
// grid's vertex at rest point x0 rises by the wake there (shaders/wake.glsl),
// so the rest point under a world point is the waves' own.
class WavesWithWake final : public WaveModel {
public:
    WavesWithWake(const WaveModel& waves, const SceneWake& wake) : waves_(waves), wake_(wake) {}
    std::string_view name() const override { return waves_.name(); }
    std::string summary() const override { return fmt::format("{} with a wake", waves_.summary()); }
    WaveReach reach() const override { return waves_.reach(); }
    double heightDeviation_m() const override { return waves_.heightDeviation_m(); }
    SurfacePoint surfaceAt(glm::dvec2 rest, double time_s, const SurfaceFilter& filter) const override
    {
        SurfacePoint p = waves_.surfaceAt(rest, time_s, filter);
        p.displacement_m.y += wake_.heightAt(rest, time_s);
        return p;
    }
    glm::dvec3 displacementAt(glm::dvec2 rest, double time_s, const SurfaceFilter& filter) const override
    {
        return waves_.displacementAt(rest, time_s, filter) + glm::dvec3(0.0, wake_.heightAt(rest, time_s), 0.0);
    }
    glm::dvec2 restPointUnder(glm::dvec2 world, double time_s, const SurfaceFilter& filter) const override
    {
        return waves_.restPointUnder(world, time_s, filter);
    }
    std::unique_ptr<WaveModelGpu> createGpu(const gl::ShaderSources& shaders) const override
    {
        return waves_.createGpu(shaders);
    }

private:
    const WaveModel& waves_;
    const SceneWake& wake_;
};

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

} // namespace

SceneWake::SceneWake(const WakeSettings& settings, double depth_m, const WaveModel& waves)
    : field_(fieldSettings(settings, depth_m)), surface_(std::make_unique<WavesWithWake>(waves, *this))
{
    reset(glm::dvec2(0.0));
}

SceneWake::~SceneWake() = default;

void SceneWake::reset(glm::dvec2 focus_m)
{
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

} // namespace swell::detail
