// Waves over a varying bottom (swell/coast_field.h), held to linear wave
// theory as Dean & Dalrymple (1991) state it, each law written out here
// from spectrum.h's own dispersion solver (a bisection, not the field's
// Newton): the drawn crests' phase speed over a flat bottom, shoaling on a
// 1:50 beach (with the shoaling coefficient's published minimum of 0.913
// as a check of the law itself), Snell's law on straight parallel contours,
// McCowan's breaker index, and dry land.
#include "ocean/coast/coast_march.h"
#include "support/numbers.h"

#include "swell/coast_field.h"
#include "swell/constants.h"
#include "swell/error.h"
#include "swell/scene/spectrum.h"
#include "swell/scene/waves.h"

#include <glm/geometric.hpp>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <memory>

namespace {

using swell::CoastField;
using swell::DepthGrid;
using swell::Wave;
using swell::WaveSet;

using swell::test::kDeg;
using swell::test::kInf;

// A grid whose depth is a function of x alone: straight contours along z.
DepthGrid contoursAlongZ(int nx, int nz, double cell_m, const std::function<double(double)>& depthAtX)
{
    DepthGrid g;
    g.cell_m = cell_m;
    g.size = {nx, nz};
    g.depth_m.resize(std::size_t(nx) * std::size_t(nz));
    for (int j = 0; j < nz; ++j)
        for (int i = 0; i < nx; ++i)
            g.depth_m[std::size_t(j) * std::size_t(nx) + std::size_t(i)] = float(depthAtX(i * cell_m));
    return g;
}

WaveSet oneWave(glm::dvec2 direction, double wavelength_m, double amplitude_m)
{
    WaveSet set;
    set.waves.push_back(Wave{direction, wavelength_m, amplitude_m, 0.0, 0.0});
    return set;
}

double deepOmega(double wavelength_m) { return std::sqrt(swell::kGravity * swell::kTwoPi / wavelength_m); }

// Linear theory's wavenumber and group velocity at depth h for angular
// frequency omega (Dean & Dalrymple 1991, eqs. 4.20 and 4.33).
double theoryWavenumber(double omega, double h) { return swell::wavenumberOf(omega, h); }
double theoryGroupVelocity(double omega, double h) { return swell::groupVelocity(theoryWavenumber(omega, h), h); }

// The shoaling coefficient K_s = sqrt(C_g0 / C_g) (eq. 4.104).
double shoaling(double omega, double h)
{
    return std::sqrt(swell::groupVelocity(omega * omega / swell::kGravity, kInf) / theoryGroupVelocity(omega, h));
}

// The position of the crest of the surface nearest x_m along z = z_m,
// within half a local wavelength: the largest height on a fine walk,
// refined by a parabola through it and its neighbours.
double crestNear(const WaveSet& set, double x_m, double z_m, double halfWindow_m, double time_s)
{
    const double step = halfWindow_m / 400.0;
    auto height = [&](double x) { return swell::displacementAt(set, {x, z_m}, time_s).y; };
    double best = x_m - halfWindow_m, bestHeight = -kInf;
    for (double x = x_m - halfWindow_m; x <= x_m + halfWindow_m; x += step)
        if (const double h = height(x); h > bestHeight) {
            bestHeight = h;
            best = x;
        }
    const double a = height(best - step), b = height(best), c = height(best + step);
    const double curvature = a - 2.0 * b + c;
    return curvature < 0.0 ? best + 0.5 * step * (a - c) / curvature : best;
}

TEST(CoastField, LocalWavenumberSolvesTheDispersionRelation)
{
    for (double omega : {0.2, 0.63, 1.5, 4.0})
        for (double h : {0.05, 0.3, 2.0, 10.0, 80.0, 500.0, kInf}) {
            const double k = swell::coast::localWavenumber(omega, h);
            EXPECT_NEAR(k, theoryWavenumber(omega, h), 1e-9 * k) << "omega " << omega << ", h " << h;
        }
}

TEST(CoastField, TheShoalingLawHasItsPublishedMinimum)
{
    // The law the tests below hold the field to, checked against a published
    // number: K_s dips to 0.913 at kh of about 1.2 before it rises
    // (Dean & Dalrymple 1991, fig. 4.10 and sec. 4.4.2).
    const double omega = deepOmega(100.0);
    double lowest = kInf;
    for (double h = 1.0; h < 100.0; h += 0.01)
        lowest = std::min(lowest, shoaling(omega, h));
    EXPECT_NEAR(lowest, 0.913, 0.001);
}

// Over a flat bottom of depth h, the drawn crests run at the phase speed
// c = sqrt(g / k tanh(kh)) of linear theory (eq. 4.20 as c = omega / k),
// within 1%, at kh = 0.3, 1 and 3.
TEST(CoastField, CrestsRunAtThePhaseSpeedOfTheirDepth)
{
    const double h = 10.0;
    for (double kh : {0.3, 1.0, 3.0}) {
        const double k = kh / h;
        const double omega = std::sqrt(swell::kGravity * k * std::tanh(kh));
        const double deepWavelength = swell::kTwoPi * swell::kGravity / (omega * omega);
        WaveSet set = oneWave({1.0, 0.0}, deepWavelength, 0.05);
        const double length = 2.0 * swell::kPi / k;
        const int nx = int(std::ceil(8.0 * length / 2.0)) + 1;
        set.coast = std::make_shared<const CoastField>(set, contoursAlongZ(nx, 24, 2.0, [&](double) { return h; }));
        const double x = 4.0 * length, z = 24.0; // the grid's middle row, half way along
        const double period = swell::kTwoPi / omega, dt = period / 8.0;
        const double start = crestNear(set, x, z, 0.5 * length, 0.0);
        const double later = crestNear(set, start + omega / k * dt, z, 0.25 * length, dt);
        const double speed = (later - start) / dt;
        const double theory = std::sqrt(swell::kGravity / theoryWavenumber(omega, h) * std::tanh(theoryWavenumber(omega, h) * h));
        EXPECT_NEAR(speed / theory, 1.0, 0.01) << "kh " << kh << ": " << speed << " m/s against " << theory;
    }
}

// A long-crested swell at normal incidence on a 1:50 plane beach: its
// height follows linear shoaling H/H0 = sqrt(C_g0 / C_g) within 5% from
// deep water to the break point, where H/h is McCowan's 0.78, and inside
// the surf zone H <= 0.78 h.
struct Beach {
    double cell_m = 5.0;
    double deepest_m = 100.0;
    double depthAt(double x) const { return deepest_m - x / 50.0; }
    // The swell run onto it at normal incidence: T = 10 s, H0 = 1 m.
    double wavelength_m = 156.0, amplitude_m = 0.5;
    WaveSet swell() const { return oneWave({1.0, 0.0}, wavelength_m, amplitude_m); }
    // Samples across the beach, from its deepest to a little up the land.
    int samples() const { return int(deepest_m * 50.0 / cell_m) + 20; }
    // The field of `set` over it, 12 samples along the shore.
    CoastField fieldFor(const WaveSet& set) const
    {
        return CoastField(set, contoursAlongZ(samples(), 12, cell_m, [this](double x) { return depthAt(x); }));
    }
};

TEST(CoastField, ASwellShoalsOnAPlaneBeachAsLinearTheorySays)
{
    const Beach beach;
    const double wavelength = beach.wavelength_m, amplitude = beach.amplitude_m;
    const WaveSet set = beach.swell();
    const int nx = beach.samples();
    const CoastField field = beach.fieldFor(set);
    const double omega = deepOmega(wavelength);
    const glm::dvec2 open = swell::wavenumberVector(set.waves[0]);
    double worst = 0.0, lowest = kInf, highest = 0.0;
    int compared = 0;
    for (int i = 4; i < nx; ++i) {
        const double x = i * beach.cell_m, h = beach.depthAt(x);
        const double gain = field.waveAt(0, {x, 6 * beach.cell_m}, open).gain;
        if (2.0 * amplitude * gain >= swell::kBreakerIndex * h * 0.999)
            break; // the break point
        const double law = shoaling(omega, h);
        worst = std::max(worst, std::abs(gain / law - 1.0));
        lowest = std::min(lowest, gain);
        highest = std::max(highest, gain);
        ++compared;
    }
    EXPECT_LT(worst, 0.05);
    // The transect saw the dip below 1 and the rise above it.
    EXPECT_LT(lowest, 0.93);
    EXPECT_GT(highest, 1.2);
    EXPECT_GT(compared, 900);
}

TEST(CoastField, WavesBreakAtMcCowansIndexAndStayUnderItInTheSurf)
{
    const Beach beach;
    const double amplitude = beach.amplitude_m;
    const WaveSet set = beach.swell();
    const int nx = beach.samples();
    const CoastField field = beach.fieldFor(set);
    const glm::dvec2 open = swell::wavenumberVector(set.waves[0]);
    double breakRatio = 0.0, previousRatio = 0.0;
    bool broken = false;
    for (int i = 4; i < nx; ++i) {
        const double x = i * beach.cell_m, h = beach.depthAt(x);
        if (h <= 0.05)
            break;
        const double height = 2.0 * amplitude * field.waveAt(0, {x, 6 * beach.cell_m}, open).gain;
        const double ratio = height / h;
        if (!broken && ratio < previousRatio - 1e-9) {
            // H/h stops rising once the cut holds it.
            broken = true;
            breakRatio = previousRatio;
        }
        if (broken) {
            EXPECT_LE(ratio, swell::kBreakerIndex * (1.0 + 1e-6)) << "h " << h;
        }
        previousRatio = std::max(previousRatio, ratio);
    }
    ASSERT_TRUE(broken);
    EXPECT_NEAR(breakRatio, 0.78, 0.1);
}

// The surf's measure (the common texel's fourth channel): none where the
// waves do not break, and inside the surf zone the share of the shoaled
// height the cut took, 1 - gamma h / (H0 K_s) with K_s linear shoaling's
// (eq. 4.104), growing towards the shore; none on dry land.
TEST(CoastField, TheSurfMeasureIsTheShareOfTheShoaledHeightTheCutTook)
{
    const Beach beach;
    const CoastField field = beach.fieldFor(beach.swell());
    int offshore = 0, surf = 0;
    double previous = 0.0;
    for (int i = 4; i < beach.samples() - 4; ++i) {
        const double x = i * beach.cell_m, h = beach.depthAt(x);
        const swell::CoastCommonSample common = field.commonAt({x, 6 * beach.cell_m});
        if (h <= 0.0) {
            EXPECT_EQ(common.breaking, 0.0) << "h " << h;
            continue;
        }
        const double shoaled = 2.0 * beach.amplitude_m * shoaling(deepOmega(beach.wavelength_m), h);
        if (shoaled < swell::kBreakerIndex * h * 0.95) {
            EXPECT_EQ(common.breaking, 0.0) << "h " << h;
            ++offshore;
        } else if (shoaled > swell::kBreakerIndex * h * 1.05 && h > 2.0 * beach.cell_m / 50.0) {
            EXPECT_NEAR(1.0 - common.breaking, swell::kBreakerIndex * h / shoaled, 0.05) << "h " << h;
            EXPECT_GE(common.breaking, previous - 1e-6) << "h " << h;
            previous = common.breaking;
            ++surf;
        }
    }
    EXPECT_GT(offshore, 900);
    EXPECT_GT(surf, 10);
    EXPECT_GT(previous, 0.5); // near the shore the cut takes most of the height
}

// A sea of many waves breaks as a random sea does: not where its waves'
// heights summed (its highest possible crest-to-trough) would reach 0.78 h,
// a third of the way in, but where its significant height 4 sigma reaches
// Thornton & Guza's (1983) saturated surf zone, rms height 0.42 h
// (significant height 0.59 h with Rayleigh heights), and under it after.
TEST(CoastField, ASeaOfManyWavesBreaksAtItsSignificantHeight)
{
    const Beach beach;
    WaveSet set;
    for (int i = 0; i < 12; ++i) // 12 waves of 130 to 174 m, within 6 degrees of the normal
        set.waves.push_back({{std::cos((i - 5.5) * kDeg), std::sin((i - 5.5) * kDeg)}, 130.0 + 4.0 * i, 0.12, 0.0, 0.7 * i});
    const int nx = beach.samples();
    const CoastField field = beach.fieldFor(set);
    double onset = 0.0;
    for (int i = 4; i < nx; ++i) {
        const double x = i * beach.cell_m, h = beach.depthAt(x);
        if (h <= 0.05)
            break;
        double variance = 0.0;
        for (std::size_t w = 0; w < set.waves.size(); ++w) {
            const double a = set.waves[w].amplitude_m
                           * field.waveAt(field.layerOf(w), {x, 6 * beach.cell_m}, swell::wavenumberVector(set.waves[w])).gain;
            variance += 0.5 * a * a;
        }
        const double significant = 4.0 * std::sqrt(variance);
        if (onset == 0.0 && field.commonAt({x, 6 * beach.cell_m}).gain < 1.0)
            onset = significant / h;
        if (onset > 0.0) {
            EXPECT_LE(significant / h, 0.42 * std::sqrt(2.0) * (1.0 + 1e-3)) << "h " << h;
        }
    }
    EXPECT_NEAR(onset, 0.42 * std::sqrt(2.0), 0.05);
}

// A swell arriving at 30 degrees on straight parallel contours turns as
// Snell's law for waves says, sin(theta) / c constant (eq. 4.115), within
// 2 degrees at three depths.
TEST(CoastField, CrestsTurnToTheContoursAsSnellsLawSays)
{
    const double cell = 5.0, wavelength = 100.0;
    const double theta0 = 30.0 * kDeg;
    WaveSet set = oneWave({std::cos(theta0), std::sin(theta0)}, wavelength, 0.2);
    auto depthAt = [](double x) { return std::max(60.0 - x / 50.0, -2.0); };
    const CoastField field(set, contoursAlongZ(620, 520, cell, depthAt));
    const double omega = deepOmega(wavelength);
    const double c0 = omega / theoryWavenumber(omega, kInf);
    const glm::dvec2 open = swell::wavenumberVector(set.waves[0]);
    for (double h : {20.0, 8.0, 3.0}) {
        const double x = (60.0 - h) * 50.0, z = 2200.0;
        const glm::dvec2 k = field.waveAt(0, {x, z}, open).wavenumber_radpm;
        const double theta = std::atan2(k.y, k.x);
        const double snell = std::asin(std::sin(theta0) * (omega / theoryWavenumber(omega, h)) / c0);
        EXPECT_NEAR(theta / kDeg, snell / kDeg, 2.0) << "h " << h;
        // Its length is the depth's too.
        EXPECT_NEAR(std::sqrt(glm::dot(k, k)), theoryWavenumber(omega, h), 0.01 * theoryWavenumber(omega, h)) << "h " << h;
    }
}

TEST(CoastField, NoWaveOnDryLand)
{
    WaveSet set = oneWave({1.0, 0.0}, 60.0, 0.4);
    set.waves.push_back(Wave{{0.8, 0.6}, 7.0, 0.1, 0.5, 1.0}); // a short wave, without a field of its own
    auto depthAt = [](double x) { return 30.0 - x / 20.0; }; // dry beyond x = 600 m
    set.coast = std::make_shared<const CoastField>(set, contoursAlongZ(200, 40, 4.0, depthAt));
    for (double x : {610.0, 650.0, 700.0})
        for (double t : {0.0, 1.3, 7.7}) {
            const glm::dvec3 d = swell::displacementAt(set, {x, 80.0}, t);
            EXPECT_EQ(d.y, 0.0) << "x " << x << ", t " << t;
            EXPECT_EQ(d.x, 0.0);
        }
    // And waves where it is wet.
    double largest = 0.0;
    for (double t = 0.0; t < 10.0; t += 0.5)
        largest = std::max(largest, std::abs(swell::displacementAt(set, {200.0, 80.0}, t).y));
    EXPECT_GT(largest, 0.2);
}

TEST(CoastField, TheSurfaceNeverLoopsOverItselfWhereTheWavesSteepen)
{
    // Steep waves shoaling: shorter and higher, Q k A would pass 1; the
    // field's steepness scale keeps the Jacobian of the rest-to-world map
    // positive everywhere.
    WaveSet set = oneWave({1.0, 0.0}, 60.0, 0.8);
    set.waves[0].steepness = 1.0 / (swell::kTwoPi / 60.0 * 0.8) * 0.95;
    auto depthAt = [](double x) { return 40.0 - x / 30.0; };
    set.coast = std::make_shared<const CoastField>(set, contoursAlongZ(300, 16, 4.0, depthAt));
    for (double x = 20.0; x < 1190.0; x += 0.7)
        for (double t : {0.0, 2.1}) {
            const swell::SurfacePartials p = swell::partialsAt(set, {x, 32.0}, t);
            EXPECT_GT(p.alongX.x * p.alongZ.z - p.alongX.z * p.alongZ.x, 0.0) << "x " << x << ", t " << t;
        }
}

TEST(CoastField, RefusesAGridItCannotUse)
{
    const WaveSet set = oneWave({1.0, 0.0}, 60.0, 0.4);
    DepthGrid tiny = contoursAlongZ(1, 8, 1.0, [](double) { return 5.0; });
    EXPECT_THROW(CoastField field(set, tiny), swell::Error);
    DepthGrid nan = contoursAlongZ(8, 8, 1.0, [](double) { return 5.0; });
    nan.depth_m[9] = std::numeric_limits<float>::quiet_NaN();
    EXPECT_THROW(CoastField field(set, nan), swell::Error);
    DepthGrid mismatched = contoursAlongZ(8, 8, 1.0, [](double) { return 5.0; });
    mismatched.depth_m.pop_back();
    EXPECT_THROW(CoastField field(set, mismatched), swell::Error);
}

} // namespace
