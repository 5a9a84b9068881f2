// GerstnerSurface: the Gerstner sum's CPU queries (swell/gerstner_model.h),
// the wave functions of swell/scene/waves.h over one wave set.
#include "swell/gerstner_model.h"

#include "swell/error.h"

#include <cmath>
#include <string>
#include <utility>

namespace swell {

GerstnerSurface::GerstnerSurface(WaveSet waves) : waves_(std::move(waves))
{
    if (const std::string problem = validate(waves_); !problem.empty())
        throw InputError({}, "waves: " + problem);
    reach_ = waveReach(waves_);
    double variance = 0.0;
    for (const Wave& w : waves_.waves)
        variance += 0.5 * w.amplitude_m * w.amplitude_m;
    heightDeviation_m_ = std::sqrt(variance);
}

SurfacePoint GerstnerSurface::surfaceAt(glm::dvec2 restPoint_m, double time_s, const SurfaceFilter& filter) const
{
    return swell::surfaceAt(waves_, restPoint_m, time_s, filter);
}

glm::dvec2 GerstnerSurface::restPointUnder(glm::dvec2 worldPoint_m, double time_s, const SurfaceFilter& filter) const
{
    const bool exact = filter.footprint_m <= 0.0 && filter.heightScale == 1.0;
    return swell::restPointUnder(exact ? waves_ : filteredWaves(waves_, filter), worldPoint_m, time_s);
}

} // namespace swell
