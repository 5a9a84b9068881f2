// SpectralSurface: the spectral field behind swell::SurfaceQuery, queried
// through its CPU twin (spectral_cpu.h); the breaking score's ramp its
// whitecaps are made on (breaking.h), from the field itself.
#include "swell/spectral_model.h"

#include "ocean/coast/coast_grid.h"
#include "ocean/spectral/breaking.h"
#include "ocean/spectral/spectral_coast.h"
#include "ocean/spectral/spectral_cpu.h"
#include "ocean/spectral/whitecaps.h"
#include "ocean/spectral/world_foam.h"

#include <algorithm>
#include <cmath>

namespace swell {

using namespace spectral;

namespace {

// The trains of the field's longest band over the floor's coast field; null
// where the floor is flat everywhere.
std::shared_ptr<const CoastTrains> coastOf(const SpectralField& field, double depth_m, const Seabed* seabed)
{
    if (!seabed)
        return nullptr;
    WaveSet trains = coastTrainsOf(field, depth_m);
    trains.coast = coast::coastFieldOf(*seabed, trains);
    if (!trains.coast)
        return nullptr;
    const CoastTrainDepths depths = coastTrainDepthsOf(trains);
    return std::make_shared<const CoastTrains>(CoastTrains{std::move(trains), depths});
}

} // namespace

SpectralSurface::SpectralSurface(const SpectralSettings& settings) : SpectralSurface(settings, nullptr) {}

SpectralSurface::SpectralSurface(const SpectralSettings& settings, const Seabed& seabed)
    : SpectralSurface(settings, &seabed)
{
}

SpectralSurface::SpectralSurface(const SpectralSettings& settings, const Seabed* seabed)
    : settings_(settings),
      field_(std::make_shared<const SpectralField>(
          makeSpectralField(SeaSpectrum(settings.wind), settings.choppiness, settings.seed))),
      coast_(coastOf(*field_, settings.wind.depth_m, seabed)),
      cpu_(std::make_unique<CpuSurface>(field_, coast_))
{
    // (fieldsAt is not thread-safe; nothing else can reach cpu_ while it is
    // being built.)
    const CpuSurface::Fields& fields = cpu_->fieldsAt(0.0);
    // The cascades' bands are disjoint, so their height variances add.
    double variance = 0.0;
    for (int c = 0; c < kCascades; ++c) {
        double sum = 0.0;
        for (const float h : fields.values[size_t(c)][1])
            sum += double(h) * double(h);
        variance += sum / double(fields.values[size_t(c)][1].size());
    }
    heightDeviation_m_ = std::sqrt(variance);
    // The breaking ramps from the field itself: a still's foam on this sea
    // covers Monahan's share of it at this wind. A sea without foam takes
    // no foam steps, so it needs none (and saves the replay's 0.4 s).
    if (settings.foamLifetime_s > 0.0) {
        const BreakingRamps ramps = calibratedBreakingRamps(field_, settings.wind.windSpeed_mps);
        for (int level = 0; level < kFoamLevels; ++level)
            breakingStart_[size_t(level)] = ramps[size_t(level)].start;
    }
}

SpectralSurface::~SpectralSurface() = default;

WaveReach SpectralSurface::reach() const
{
    WaveReach reach{field_->verticalReach_m, field_->horizontalReach_m};
    // Over a coast the trains add to the band they share, shoaled before
    // they break (CoastField::reach): bounded by the sum of both.
    if (coast_) {
        const WaveReach trains = coast_->trains.coast->reach();
        reach.vertical_m += trains.vertical_m;
        reach.horizontal_m += trains.horizontal_m;
    }
    return reach;
}

SurfacePoint SpectralSurface::surfaceAt(glm::dvec2 restPoint_m, double time_s, const SurfaceFilter& filter) const
{
    return cpu_->surfaceAt(restPoint_m, time_s, filter);
}

glm::dvec3 SpectralSurface::displacementAt(glm::dvec2 restPoint_m, double time_s, const SurfaceFilter& filter) const
{
    return cpu_->displacementAt(restPoint_m, time_s, filter);
}

} // namespace swell
