// The spectral ocean's far geometry keeps the waves its vertices can carry
// (issue #47, item 9: the storm from a bridge read as a rough plain). A
// vertex whose cell is too coarse for a cascade's shortest wave used to drop
// the whole cascade, and with it the long waves it also holds: the storm's
// first cascade holds everything from 94 m up, its 300 m swell included, and
// went flat where the grid's cells pass 47 m (about 470 m from a 10 m eye).
// Now the cascade's filtered field (its displacement averaged over texels
// as wide as the cell, spectral_cpu.h) takes over where its exact one fades.
//
// The bound is the sampling theorem's, not today's output: at cells f m
// apart, the drawn height's variance holds at least half of the waves 4 f
// and longer (which 4 or more cells a wavelength draw; the average over a
// cell and the cubic B-spline through the chain's texels keep 0.35 of a
// 4 f wave's variance, 0.77 of an 8 f wave's and more of longer ones, and
// a sea's variance lies mostly in its waves well above 4 f) and no more
// than the waves 2 f and longer (the shortest the cells can carry: what is
// shorter would alias).
#include "ocean/spectral/spectral_cpu.h"
#include "ocean/spectral/spectral_field.h"
#include "swell/scene/spectrum.h"
#include "swell/scene/waves.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <memory>
#include <numbers>
#include <random>
#include <vector>

namespace {

using namespace swell::spectral;

// The storm preset's sea (scenes/storm.toml): 20 m/s over 600 km, a 60
// degree spread, choppiness 1.2, seed 13.
std::shared_ptr<const SpectralField> stormField()
{
    swell::WindSettings wind;
    wind.windSpeed_mps = 20.0;
    wind.fetch_km = 600.0;
    wind.spread_deg = 60.0;
    return std::make_shared<const SpectralField>(makeSpectralField(swell::SeaSpectrum(wind), 1.2, 13));
}

// The height variance of the field's waves of wavelength_m or longer, m^2
// (Parseval: each held sample k adds |h0(k)|^2 + |h0(-k)|^2 over time).
double varianceOfWavesLongerThan(const SpectralField& field, double wavelength_m)
{
    double variance = 0.0;
    for (int c = 0; c < kCascades; ++c) {
        const double dk = 2.0 * std::numbers::pi / field.cascades[size_t(c)].patch_m;
        for (int row = 0; row < kSize; ++row)
            for (int col = 0; col < kSize; ++col) {
                const double k = dk * std::hypot(double(frequencyOf(row)), double(frequencyOf(col)));
                if (k == 0.0 || 2.0 * std::numbers::pi / k < wavelength_m)
                    continue;
                const size_t i = size_t(row) * kSize + size_t(col);
                variance += std::norm(field.h0[size_t(c)][i]) + std::norm(field.h0MinusConj[size_t(c)][i]);
            }
    }
    return variance;
}

// The variance of the drawn height at cells footprint_m apart, m^2: over
// 1500 rest points spread over two of the first cascade's patches, at three
// times.
double drawnHeightVariance(const CpuSurface& surface, double footprint_m)
{
    std::mt19937 rng(7);
    std::uniform_real_distribution<double> along(0.0, 6000.0);
    const swell::SurfaceFilter filter{footprint_m, 1.0};
    double sum = 0.0, sumSquares = 0.0;
    int n = 0;
    for (double time_s : {0.0, 7.3, 19.1})
        for (int i = 0; i < 500; ++i) {
            const double y = surface.displacementAt({along(rng), along(rng)}, time_s, filter).y;
            sum += y;
            sumSquares += y * y;
            ++n;
        }
    const double mean = sum / n;
    return sumSquares / n - mean * mean;
}

TEST(SpectralFarField, TheStormsFarVerticesCarryTheWavesTheirCellsCan)
{
    const auto field = stormField();
    const CpuSurface surface(field);
    const double all = varianceOfWavesLongerThan(*field, 0.0);
    std::printf("storm: Hs from the spectrum %.2f m, the drawn at 1 m cells %.2f m\n", 4.0 * std::sqrt(all),
                4.0 * std::sqrt(drawnHeightVariance(surface, 1.0)));
    for (double footprint_m : {30.0, 60.0, 100.0}) {
        const double drawn = drawnHeightVariance(surface, footprint_m);
        const double resolved = varianceOfWavesLongerThan(*field, 4.0 * footprint_m);
        const double carried = varianceOfWavesLongerThan(*field, 2.0 * footprint_m);
        std::printf("cells %.0f m: drawn %.3f m^2, waves of 4 cells and longer %.3f, of 2 cells and longer %.3f "
                    "(all %.3f)\n",
                    footprint_m, drawn, resolved, carried, all);
        EXPECT_GE(drawn, 0.5 * resolved) << "cells " << footprint_m << " m apart drop waves they can draw";
        EXPECT_LE(drawn, carried) << "cells " << footprint_m << " m apart draw waves shorter than two cells";
    }
}

} // namespace
