#include "ocean/spectral/breaking.h"

#include "ocean/spectral/whitecaps.h"
#include "ocean/spectral/world_foam.h"

#include <vector>

namespace swell::spectral {

namespace {

BreakingRamp rampAtLevel(const CpuSurface& cpu, const SpectralField& field, double fraction, int level)
{
    constexpr int kBlocks = 8, kBlock = 32, kSpan = kBlock + 2 * kBreakingRadius;
    const double texel_m = foamTexel_m(field, level);
    // Blocks spaced incommensurately with every patch, so no two see the
    // same place of a cascade.
    const double spacing_m = 1.37 * field.cascades[0].patch_m / kBlocks;
    const SurfaceFilter filter{}; // unfiltered, as the shader's foldJacobian
    std::vector<float> jacobian(size_t(kSpan) * kSpan), scores;
    scores.reserve(size_t(kBlocks * kBlocks) * kBlock * kBlock);
    for (int row = 0; row < kBlocks; ++row)
        for (int col = 0; col < kBlocks; ++col) {
            for (int z = 0; z < kSpan; ++z)
                for (int x = 0; x < kSpan; ++x)
                    jacobian[size_t(z) * kSpan + size_t(x)] = float(cpu.foldJacobianAt(
                        {col * spacing_m + x * texel_m, row * spacing_m + z * texel_m}, 0.0, filter, kFoamCascades));
            for (int z = 0; z < kBlock; ++z)
                for (int x = 0; x < kBlock; ++x)
                    scores.push_back(breakingScore(&jacobian[size_t(z) * kSpan + size_t(x)], kSpan));
        }
    // Full foam where the score is among the lowest `fraction` of the
    // sea, none kBreakingSpan above.
    const float full = quantile(std::move(scores), fraction);
    return {full + kBreakingSpan, kBreakingSpan};
}

} // namespace

BreakingRamps breakingRampsFor(const CpuSurface& cpu, const SpectralField& field, double fraction)
{
    BreakingRamps ramps;
    for (int level = 0; level < kFoamLevels; ++level)
        ramps[size_t(level)] = rampAtLevel(cpu, field, fraction, level);
    return ramps;
}

BreakingRamps breakingRampsStartingAt(const std::array<float, kFoamLevels>& starts)
{
    BreakingRamps ramps;
    for (int level = 0; level < kFoamLevels; ++level)
        ramps[size_t(level)] = {starts[size_t(level)], kBreakingSpan};
    return ramps;
}

} // namespace swell::spectral
