#include "render/slope_statistics.h"

#include <cmath>

namespace swell::detail {

double meanSquareSlope(const SurfaceQuery& model)
{
    constexpr int kSamples = 4096;
    constexpr double kSide_m = 2000.0;
    // Roberts' R2 sequence: the plastic number's powers as increments; it
    // fills a square more evenly than random points, without a lattice that
    // could alias with a wave.
    constexpr double kPlastic = 1.32471795724474602596;
    constexpr double a1 = 1.0 / kPlastic, a2 = 1.0 / (kPlastic * kPlastic);
    double sum = 0.0;
    for (int i = 0; i < kSamples; ++i) {
        const double u = std::fmod(0.5 + a1 * i, 1.0), v = std::fmod(0.5 + a2 * i, 1.0);
        const glm::dvec3 n = model.surfaceAt({(u - 0.5) * kSide_m, (v - 0.5) * kSide_m}, 0.0).normal;
        sum += (n.x * n.x + n.z * n.z) / std::max(n.y * n.y, 1e-6);
    }
    return sum / kSamples;
}

} // namespace swell::detail
