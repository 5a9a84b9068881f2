// The whitecaps' texture lattices (foam_texture.h).
#include "ocean/foam/foam_texture.h"

#include <algorithm>
#include <cmath>

namespace swell::foam {

namespace {

// The coarsest octave's cells, m: about the size of the gaps in a breaking
// crest's foam; each further octave's are kLacunarity times finer (6
// octaves: 3.3 m down to 3.4 cm, the bubbles' lace).
constexpr double kCoarsestCell_m = 1.0 / 0.3;
constexpr double kLacunarity = 2.5;
// The warp's cells are this many times the coarsest octave's.
constexpr double kWarpCells = 2.5;
// Each lattice is turned from the last by the golden angle, pi (3 - sqrt 5):
// the turns never line up again, so no two octaves share an axis.
constexpr double kGoldenAngle_rad = 2.39996322972865332;
constexpr double kPeriod = SWELL_FOAM_NOISE_PERIOD;

} // namespace

double foamShare(double amount, double breakingAmount)
{
    if (amount < SWELL_FOAM_LEAST_AMOUNT)
        return 0.0;
    const double breaking = std::clamp((amount - breakingAmount) / std::max(1.0 - breakingAmount, 1e-3), 0.0, 1.0);
    return SWELL_FOAM_LACE_SHARE * amount + (SWELL_FOAM_BREAKING_SHARE - SWELL_FOAM_LACE_SHARE * amount) * breaking;
}

std::array<FoamNoiseMap, kFoamNoiseMaps> foamNoiseMaps(glm::dvec2 gridCenter_m, glm::dvec2 windDirection,
                                                       double streak)
{
    std::array<FoamNoiseMap, kFoamNoiseMaps> maps{};
    const glm::dvec2 along = windDirection, across{-windDirection.y, windDirection.x};
    // x -> (along-wind / streak, across-wind): streaks drawn out along the wind.
    const glm::dmat2 streaked = glm::transpose(glm::dmat2(along / streak, across));
    for (int i = 0; i < kFoamNoiseMaps; ++i) {
        const bool warp = i == kFoamOctaves;
        const double cycles = warp ? 1.0 / (kCoarsestCell_m * kWarpCells)
                                   : std::pow(kLacunarity, double(i)) / kCoarsestCell_m;
        const double turn = kGoldenAngle_rad * double(i + 1);
        const glm::dmat2 rotation(std::cos(turn), std::sin(turn), -std::sin(turn), std::cos(turn));
        const glm::dmat2 map = cycles * rotation * streaked;
        const glm::dvec2 centre = map * gridCenter_m;
        maps[size_t(i)].map = glm::mat2(map);
        maps[size_t(i)].offset_cells = glm::vec2(centre - kPeriod * glm::floor(centre / kPeriod));
        maps[size_t(i)].cyclesPerMetre = float(cycles);
    }
    return maps;
}

} // namespace swell::foam
