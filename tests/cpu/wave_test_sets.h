// What the CPU wave tests share (test_waves.cpp, the Gerstner sum's math;
// test_wave_sampler.cpp, WaveSampler against it): hand-made and random wave
// sets, the displaced image of a rest point, and random points around a centre.
#pragma once

#include "swell/scene/waves.h"

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include <cmath>
#include <cstdint>
#include <limits>
#include <random>
#include <vector>

namespace swell::test::wave_sets {

inline constexpr double kInf = std::numeric_limits<double>::infinity();

// A small hand-made set: four waves in different directions, with un-normalised
// directions on purpose.
inline WaveSet handSet(double depth_m = kInf)
{
    WaveSet set;
    set.depth_m = depth_m;
    set.waves = {
        {{1.0, 0.0}, 40.0, 0.8, 0.7, 0.3},
        {{3.0, 4.0}, 17.0, 0.35, 0.5, -1.2},
        {{-1.0, 2.0}, 6.5, 0.12, 0.9, 2.9},
        {{0.2, -0.7}, 2.3, 0.03, 0.4, 0.0},
    };
    return set;
}

// n random waves, steepness then scaled to the fold limit (foldMeasure = 1).
// aligned: all within 0.3 rad of +x, which puts cusps on the crests.
inline WaveSet randomFoldLimitedSet(int n, std::uint32_t seed, bool aligned)
{
    std::mt19937 rng(seed);
    auto u = [&] { return rng() * (1.0 / 4294967296.0); };
    WaveSet set;
    for (int i = 0; i < n; ++i) {
        Wave w;
        const double angle = aligned ? 0.3 * u() : 2.0 * kPi * u();
        w.direction = {std::cos(angle), std::sin(angle)};
        w.wavelength_m = 1.0 + 99.0 * u();
        w.amplitude_m = w.wavelength_m / (2.0 * kPi) * u();
        w.steepness = 1.0;
        w.phase_rad = 2.0 * kPi * u() - kPi;
        set.waves.push_back(w);
    }
    // Make sure the sum is past the limit, so that limiting lands exactly on it.
    const double measure = swell::foldMeasure(set);
    if (measure < 1.5) {
        for (Wave& w : set.waves)
            w.amplitude_m *= 1.5 / measure;
    }
    swell::limitSteepness(set);
    return set;
}

// The world position the rest point x0 is displaced to at time t.
inline glm::dvec3 displacedPoint(const WaveSet& set, glm::dvec2 x0, double t)
{
    return glm::dvec3(x0.x, 0.0, x0.y) + swell::displacementAt(set, x0, t);
}

inline std::vector<glm::dvec2> randomPoints(int n, double halfWidth_m, glm::dvec2 centre, std::uint32_t seed)
{
    std::mt19937 rng(seed);
    std::vector<glm::dvec2> points;
    for (int i = 0; i < n; ++i) {
        const double x = (rng() * (2.0 / 4294967296.0) - 1.0) * halfWidth_m;
        const double z = (rng() * (2.0 / 4294967296.0) - 1.0) * halfWidth_m;
        points.push_back(centre + glm::dvec2(x, z));
    }
    return points;
}

} // namespace swell::test::wave_sets
