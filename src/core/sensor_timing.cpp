// When each row of the sensor gathers light (swell/dataset/sensor.h,
// SensorTiming).
#include "swell/dataset/sensor.h"

#include <algorithm>
#include <cmath>

namespace swell {

SensorTiming sensorTimingOf(const CameraSettings& camera, double time_s, int rows)
{
    SensorTiming timing;
    rows = std::max(rows, 0);
    const double shutter_s = std::max(camera.shutter_s, 0.0), readout_s = std::max(camera.readout_s, 0.0);
    const double span_s = shutter_s + readout_s;
    if (!(span_s > 0.0)) {
        timing.drawTimes_s = {time_s};
        timing.rowDraws.assign(std::size_t(rows), glm::ivec2(0, 0));
        return timing;
    }
    const int draws = std::max(camera.motionSamples, 2);
    const double spacing_s = span_s / draws;
    for (int j = 0; j < draws; ++j)
        // Nothing is simulated before time 0: a draw that would be is there.
        timing.drawTimes_s.push_back(std::max(time_s - 0.5 * span_s + (j + 0.5) * spacing_s, 0.0));
    // Draw j lies at offset (j + 0.5) spacing from the span's start; a row's
    // window, [t_y - shutter / 2, t_y + shutter / 2], starts at
    // readout (y + 0.5) / rows from it. Counted in units of the spacing so
    // that a window whose edge falls on a draw (shutter = spacing multiples)
    // takes it on one side only, whatever the rounding of the times.
    for (int y = 0; y < rows; ++y) {
        const double start = readout_s * ((y + 0.5) / rows) / spacing_s; // the window's start, in spacings
        const double end = start + shutter_s / spacing_s;
        // Draws with start <= j + 0.5 < end.
        const int first = int(std::ceil(start - 0.5 - 1e-9));
        const int last = int(std::ceil(end - 0.5 - 1e-9)) - 1;
        if (last >= first && first >= 0 && last < draws) {
            timing.rowDraws.emplace_back(first, last);
        } else {
            // No draw in the window: the one nearest the row's time.
            const double centre = start + 0.5 * shutter_s / spacing_s;
            const int nearest = std::clamp(int(std::floor(centre)), 0, draws - 1);
            timing.rowDraws.emplace_back(nearest, nearest);
        }
    }
    return timing;
}

double firstDrawTime_s(const CameraSettings& camera, double time_s)
{
    return sensorTimingOf(camera, time_s, 0).drawTimes_s.front();
}

} // namespace swell
