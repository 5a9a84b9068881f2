// Clamping of WindSettings and SwellSettings into their documented ranges.
#include "ocean/clamped_settings.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace swell::detail {

namespace {

double requireFinite(double value, const char* function, const char* field)
{
    if (!std::isfinite(value))
        throw std::invalid_argument(fmt::format("{}: {} must be finite (got {})", function, field, value));
    return value;
}

} // namespace

SwellSettings clampedSwell(const SwellSettings& swell, const char* function)
{
    SwellSettings s = swell;
    s.height_m = std::clamp(requireFinite(swell.height_m, function, "swell.height_m"), 0.0, 15.0);
    s.period_s = std::clamp(requireFinite(swell.period_s, function, "swell.period_s"), 3.0, 25.0);
    s.direction_deg = requireFinite(swell.direction_deg, function, "swell.direction_deg");
    s.gamma = std::clamp(requireFinite(swell.gamma, function, "swell.gamma"), 1.0, 10.0);
    s.sMax = std::clamp(requireFinite(swell.sMax, function, "swell.sMax"), 1.0, 200.0);
    s.waveCount = std::clamp(swell.waveCount, 1, SWELL_MAX_WAVES - 1);
    return s;
}

WindSettings clampedWind(const WindSettings& wind, const char* function)
{
    WindSettings w = wind;
    w.windSpeed_mps = std::clamp(requireFinite(wind.windSpeed_mps, function, "windSpeed_mps"), 0.5, 40.0);
    w.windDirection_deg = requireFinite(wind.windDirection_deg, function, "windDirection_deg");
    w.spread_deg = std::clamp(requireFinite(wind.spread_deg, function, "spread_deg"), 0.0, 180.0);
    w.fetch_km = std::clamp(requireFinite(wind.fetch_km, function, "fetch_km"), 1.0, 10000.0);
    // The swell's waves come out of the same budget of SWELL_MAX_WAVES.
    if (wind.swell)
        w.swell = clampedSwell(*wind.swell, function);
    const int swellCount = w.swell ? w.swell->waveCount : 0;
    w.waveCount = std::clamp(wind.waveCount, 1, SWELL_MAX_WAVES - swellCount);
    // Below ~2 cm surface tension, not gravity, sets the speed of a wave.
    w.minWavelength_m = std::clamp(requireFinite(wind.minWavelength_m, function, "minWavelength_m"), 0.05, 1000.0);
    w.steepness = std::clamp(requireFinite(wind.steepness, function, "steepness"), 0.0, 1.0);
    if (!(wind.depth_m > 0.0)) // also NaN
        throw std::invalid_argument(fmt::format("{}: depth_m must be > 0 or infinity (got {})", function, wind.depth_m));
    w.depth_m = std::max(wind.depth_m, 0.1);
    if (w.spreading != SpreadingModel::Mitsuyasu && w.spreading != SpreadingModel::DonelanBanner)
        throw std::invalid_argument(fmt::format("{}: spreading is not a SpreadingModel", function));
    return w;
}

} // namespace swell::detail
