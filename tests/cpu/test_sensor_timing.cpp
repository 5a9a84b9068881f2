// When each row of the sensor gathers light (swell/dataset/sensor.h,
// SensorTiming): the draws spread over the span, each row's window centred
// on its readout time, a global shutter's rows all alike.
#include "swell/dataset/sensor.h"

#include <gtest/gtest.h>

#include <cmath>

namespace {

swell::CameraSettings sensor(double shutter_s, double readout_s, int samples)
{
    swell::CameraSettings c;
    c.shutter_s = shutter_s;
    c.readout_s = readout_s;
    c.motionSamples = samples;
    return c;
}

// The mean time of the draws a row averages.
double rowTime(const swell::SensorTiming& t, int y)
{
    const glm::ivec2 d = t.rowDraws[std::size_t(y)];
    double sum = 0.0;
    for (int j = d.x; j <= d.y; ++j)
        sum += t.drawTimes_s[std::size_t(j)];
    return sum / (d.y - d.x + 1);
}

TEST(SensorTiming, AnInstantIsOneDraw)
{
    const swell::SensorTiming t = swell::sensorTimingOf(sensor(0.0, 0.0, 16), 3.0, 10);
    ASSERT_EQ(t.drawTimes_s.size(), 1u);
    EXPECT_EQ(t.drawTimes_s[0], 3.0);
    for (const glm::ivec2 d : t.rowDraws)
        EXPECT_EQ(d, glm::ivec2(0, 0));
}

TEST(SensorTiming, AGlobalShutterAveragesEveryDrawOfItsWindowInEveryRow)
{
    const swell::SensorTiming t = swell::sensorTimingOf(sensor(0.04, 0.0, 8), 3.0, 100);
    ASSERT_EQ(t.drawTimes_s.size(), 8u);
    EXPECT_NEAR(t.drawTimes_s.front(), 3.0 - 0.02 + 0.0025, 1e-12);
    EXPECT_NEAR(t.drawTimes_s.back(), 3.0 + 0.02 - 0.0025, 1e-12);
    for (const glm::ivec2 d : t.rowDraws)
        EXPECT_EQ(d, glm::ivec2(0, 7));
}

TEST(SensorTiming, ARollingShuttersRowsAreReadFromTheTopEachOverItsOwnWindow)
{
    constexpr int kRows = 480;
    constexpr double kShutter_s = 0.01, kReadout_s = 0.03;
    const swell::SensorTiming t = swell::sensorTimingOf(sensor(kShutter_s, kReadout_s, 64), 5.0, kRows);
    const double spacing_s = (kShutter_s + kReadout_s) / 64;
    for (int y = 0; y < kRows; ++y) {
        const double readout_s = 5.0 + ((y + 0.5) / kRows - 0.5) * kReadout_s;
        // Its draws lie within its window and are all of them.
        const glm::ivec2 d = t.rowDraws[std::size_t(y)];
        EXPECT_GE(t.drawTimes_s[std::size_t(d.x)], readout_s - 0.5 * kShutter_s - 1e-12) << y;
        EXPECT_LT(t.drawTimes_s[std::size_t(d.y)], readout_s + 0.5 * kShutter_s + 1e-12) << y;
        EXPECT_EQ(d.y - d.x + 1, 16) << y; // the window holds shutter / spacing draws
        EXPECT_NEAR(rowTime(t, y), readout_s, 0.5 * spacing_s + 1e-12) << y;
    }
    // The middle of the frame is exposed around the frame's time.
    EXPECT_NEAR(0.5 * (rowTime(t, kRows / 2 - 1) + rowTime(t, kRows / 2)), 5.0, 0.5 * spacing_s);
}

TEST(SensorTiming, AReadoutWithoutShutterTakesTheDrawNearestEachRowsTime)
{
    constexpr int kRows = 100;
    const swell::SensorTiming t = swell::sensorTimingOf(sensor(0.0, 0.05, 10), 2.0, kRows);
    for (int y = 0; y < kRows; ++y) {
        const glm::ivec2 d = t.rowDraws[std::size_t(y)];
        EXPECT_EQ(d.x, d.y);
        const double readout_s = 2.0 + ((y + 0.5) / kRows - 0.5) * 0.05;
        EXPECT_LE(std::abs(t.drawTimes_s[std::size_t(d.x)] - readout_s), 0.5 * 0.005 + 1e-12) << y;
    }
    EXPECT_EQ(t.rowDraws.front().x, 0);
    EXPECT_EQ(t.rowDraws.back().x, 9);
}

TEST(SensorTiming, NothingIsDrawnBeforeTimeZero)
{
    const swell::SensorTiming t = swell::sensorTimingOf(sensor(0.1, 0.0, 4), 0.0, 4);
    EXPECT_EQ(t.drawTimes_s.front(), 0.0);
    EXPECT_NEAR(t.drawTimes_s.back(), 0.0375, 1e-12);
    EXPECT_NEAR(swell::firstDrawTime_s(sensor(0.1, 0.0, 4), 1.0), 1.0 - 0.0375, 1e-12);
}

} // namespace
