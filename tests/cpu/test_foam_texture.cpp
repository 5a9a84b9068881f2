// The lattices of the whitecaps' texture (src/ocean/foam/foam_texture.h).
#include "ocean/foam/foam_texture.h"
#include "swell/gpu/ocean.h"

#include <gtest/gtest.h>

#include <glm/glm.hpp>

#include <cmath>

namespace {

using namespace swell;
using namespace swell::foam;

// A lattice cell index modulo the noise's period, in 0..period.
double wrapped(double cells)
{
    const double period = SWELL_FOAM_NOISE_PERIOD;
    return cells - period * std::floor(cells / period);
}

// The cells a world point falls in are the same whichever grid centre the
// frame has (the texture stays on the water as the camera moves), also a
// thousand kilometres from the origin, within 1e-3 cells (the shader's
// floats hold the offset to about 5e-4 cells at the period).
TEST(FoamLattices, LatticesAreAnchoredToTheWorld)
{
    const glm::dvec2 wind = glm::normalize(glm::dvec2(-0.94, -0.34));
    for (const glm::dvec2 world : {glm::dvec2(3.7, -12.2), glm::dvec2(1.0e6 + 0.31, -2.0e6 + 7.9)}) {
        const glm::dvec2 centres[] = {world + glm::dvec2(-40.0, 25.0), world + glm::dvec2(0.37, 0.11),
                                      world + glm::dvec2(133.0, -71.5)};
        const auto first = foamNoiseMaps(centres[0], wind, 2.5);
        for (const glm::dvec2 centre : centres) {
            const auto maps = foamNoiseMaps(centre, wind, 2.5);
            for (int i = 0; i < kFoamNoiseMaps; ++i) {
                const glm::dvec2 a = glm::dmat2(first[size_t(i)].map) * (world - centres[0]) +
                                     glm::dvec2(first[size_t(i)].offset_cells);
                const glm::dvec2 b = glm::dmat2(maps[size_t(i)].map) * (world - centre) +
                                     glm::dvec2(maps[size_t(i)].offset_cells);
                for (int k = 0; k < 2; ++k) {
                    const double d = std::abs(wrapped(a[k]) - wrapped(b[k]));
                    EXPECT_LT(std::min(d, SWELL_FOAM_NOISE_PERIOD - d), 1e-3)
                        << "lattice " << i << " at (" << world.x << ", " << world.y << ")";
                }
            }
        }
    }
}

// No two lattices share an axis (else their cells would add up): without
// streaks, every pair's axes are at least 5 degrees apart (modulo a quarter
// turn); and each octave's cells are finer than the last's.
TEST(FoamLattices, LatticesAreTurnedAndNested)
{
    const auto maps = foamNoiseMaps({0.0, 0.0}, {1.0, 0.0}, 1.0);
    const double quarter = 3.14159265358979 / 2.0;
    for (int i = 0; i < kFoamNoiseMaps; ++i) {
        const double ai = std::atan2(double(maps[size_t(i)].map[0][1]), double(maps[size_t(i)].map[0][0]));
        for (int j = 0; j < i; ++j) {
            const double aj = std::atan2(double(maps[size_t(j)].map[0][1]), double(maps[size_t(j)].map[0][0]));
            const double d = std::abs(std::remainder(ai - aj, quarter));
            EXPECT_GT(d, 5.0 * 3.14159265358979 / 180.0) << "lattices " << i << " and " << j;
        }
    }
    for (int i = 1; i < kFoamOctaves; ++i)
        EXPECT_GT(maps[size_t(i)].cyclesPerMetre, 2.0f * maps[size_t(i - 1)].cyclesPerMetre);
}

} // namespace
