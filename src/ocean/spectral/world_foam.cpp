#include "ocean/spectral/world_foam.h"

#include "ocean/spectral/whitecaps.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <vector>

namespace swell::spectral {

double foamTexel_m(const SpectralField& field, int level)
{
    return field.cascades[kFoamCascades - 1].patch_m / kSize * std::pow(SWELL_FOAM_LEVEL_RATIO, level);
}

namespace {

// An index far beyond int's range still gives the right differences.
int wrapped(double index) { return std::int32_t(std::uint32_t(std::int64_t(index))); }

} // namespace

std::vector<double> foamReplayOffsets_s(double lifetime_s)
{
    // In whole lattice steps, so every offset is exact.
    const auto span = std::int64_t(std::ceil(kFoamReplayLifetimes * lifetime_s / kFoamReplayStep_s));
    const auto fine = std::min(span, std::int64_t(std::ceil(kFoamFineReplay_s / kFoamReplayStep_s)));
    std::vector<std::int64_t> steps;
    for (std::int64_t i = 0; i <= fine; ++i)
        steps.push_back(i);
    const std::int64_t coarseSteps = kFoamReplayMostSteps - fine;
    if (span > fine && coarseSteps > 0) {
        // Step k of the coarse part is r^k lattice steps long (rounded, at
        // least one), r chosen (by bisection) so that coarseSteps of them
        // reach the span: sum r^k, k = 1..m, = span - fine.
        const double remaining = double(span - fine);
        auto reach = [&](double r) {
            double sum = 0.0, length = 1.0;
            for (std::int64_t k = 0; k < coarseSteps; ++k)
                sum += (length *= r);
            return sum;
        };
        double lo = 1.0, hi = 2.0;
        while (reach(hi) < remaining)
            hi *= 2.0;
        for (int i = 0; i < 60; ++i)
            (reach(0.5 * (lo + hi)) < remaining ? lo : hi) = 0.5 * (lo + hi);
        double length = 1.0, at = double(fine);
        for (std::int64_t k = 0; k < coarseSteps && steps.back() < span; ++k) {
            at += (length *= hi);
            steps.push_back(std::clamp(std::int64_t(std::llround(at)), steps.back() + 1, span));
        }
        steps.back() = span; // the whole span, whatever the rounding
    }
    std::vector<double> offsets;
    for (auto i = steps.rbegin(); i != steps.rend(); ++i)
        offsets.push_back(double(*i) * kFoamReplayStep_s);
    return offsets;
}

FoamWindow foamWindowAt(glm::dvec2 gridCenter_m, double texel_m)
{
    const glm::dvec2 texels = gridCenter_m / texel_m;
    const glm::dvec2 index = glm::floor(texels);
    FoamWindow w;
    w.centreIndex = {wrapped(index.x), wrapped(index.y)};
    w.centreFraction = glm::vec2(texels - index);
    w.origin = w.centreIndex - glm::ivec2(kFoamSize / 2);
    w.originTexels = glm::vec2(texels - double(kFoamSize) * glm::floor(texels / double(kFoamSize)));
    return w;
}

float foldThresholdFor(const CpuSurface& cpu, const SpectralField& field, double fraction)
{
    constexpr int kSamples = 256;
    // A spacing incommensurate with every patch, so no two samples see the
    // same place of a cascade.
    const double spacing_m = 1.37 * field.cascades[0].patch_m / kSamples;
    const SurfaceFilter filter{}; // unfiltered, as the shader's foldJacobian
    std::vector<float> j;
    j.reserve(size_t(kSamples) * kSamples);
    for (int row = 0; row < kSamples; ++row)
        for (int col = 0; col < kSamples; ++col)
            j.push_back(float(cpu.foldJacobianAt({col * spacing_m, row * spacing_m}, 0.0, filter, kFoamCascades)));
    return quantile(std::move(j), fraction);
}

} // namespace swell::spectral
