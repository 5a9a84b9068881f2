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
    const auto steps = std::int64_t(std::ceil(kFoamReplayLifetimes * lifetime_s / kFoamReplayStep_s));
    std::vector<double> offsets;
    for (std::int64_t i = steps; i >= 0; --i)
        offsets.push_back(double(i) * kFoamReplayStep_s);
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

} // namespace swell::spectral
