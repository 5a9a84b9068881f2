// The built-in island's height function and the value noise (island_terrain.h).
#include "assets/island_terrain.h"

#include <algorithm>
#include <cmath>
#include <cstdint>

namespace swell::detail {

namespace {

double hash2(int x, int y)
{
    std::uint32_t h = std::uint32_t(x) * 374761393u + std::uint32_t(y) * 668265263u;
    h = (h ^ (h >> 13)) * 1274126177u;
    return double(h ^ (h >> 16)) / 4294967295.0;
}

double valueNoise(double x, double y)
{
    const int ix = int(std::floor(x)), iy = int(std::floor(y));
    const double fx = x - ix, fy = y - iy;
    const double sx = fx * fx * (3 - 2 * fx), sy = fy * fy * (3 - 2 * fy);
    const double a = hash2(ix, iy), b = hash2(ix + 1, iy), c = hash2(ix, iy + 1), d = hash2(ix + 1, iy + 1);
    return (a + (b - a) * sx) + ((c + (d - c) * sx) - (a + (b - a) * sx)) * sy;
}

} // namespace

double fractalNoise(double x, double y, int octaves)
{
    double sum = 0.0, amplitude = 0.5;
    for (int octave = 0; octave < octaves; ++octave) {
        sum += amplitude * (valueNoise(x, y) - 0.5);
        x *= 2.03;
        y *= 2.03;
        amplitude *= 0.5;
    }
    return sum;
}

double islandHeight_m(glm::dvec2 local_xz_m, double size_m, double peak_m)
{
    const double x = local_xz_m.x, z = local_xz_m.y;
    const double r = std::sqrt(x * x + z * z) / (0.5 * size_m);
    // A dome that dips below the water at r ~ 0.45, shallows to r ~ 0.75, then deep.
    const double dome = std::exp(-r * r * 9.0);
    const double relief = fractalNoise(x / 90.0 + 7.3, z / 90.0 - 2.1);
    const double h = peak_m * (dome + 0.9 * relief * dome) - 2.0 - 38.0 * std::min(r, 1.0) * std::min(r, 1.0);
    return std::max(h, -45.0);
}

} // namespace swell::detail
