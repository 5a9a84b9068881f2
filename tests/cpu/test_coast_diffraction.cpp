// Waves diffracting into a breakwater's lee (swell/coast_field.h), held to
// Sommerfeld's (1896) solution for a semi-infinite screen as Penney & Price
// (1952) applied it to water waves, written out here from its Fresnel
// integrals; the integrals checked against Abramowitz & Stegun's table, and
// the solution against the diffraction diagrams' published value on the
// shadow line (Wiegel 1962, as the Coastal Engineering Manual, EM
// 1110-2-1100, Part II, ch. 7, 2002, sec. II-7-2.c(e), sums them up).
#include "swell/coast_field.h"
#include "ocean/coast/coast_reflection.h"
#include "support/numbers.h"
#include "swell/constants.h"
#include "swell/scene/waves.h"

#include <glm/geometric.hpp>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <complex>
#include <limits>

namespace {

using swell::CoastField;
using swell::DepthGrid;
using swell::Wave;
using swell::WaveSet;
using Complex = std::complex<double>;

using swell::test::kDeg;

// The Fresnel integrals C(x) + i S(x) = integral from 0 to x of
// exp(i pi u^2 / 2) du (Abramowitz & Stegun 1964, eqs. 7.3.1 and 7.3.2), by
// Simpson's rule on steps far finer than the integrand's oscillation.
Complex fresnel(double x)
{
    const int steps = 20000;
    const double h = x / steps;
    Complex sum = 0.0;
    for (int i = 0; i <= steps; ++i) {
        const double u = i * h;
        const double weight = (i == 0 || i == steps) ? 1.0 : (i % 2 ? 4.0 : 2.0);
        sum += weight * std::exp(Complex(0.0, swell::kPi * u * u / 2.0));
    }
    return sum * h / 3.0;
}

// Penney & Price's (1952) f(sigma) = (1 + i)/2 * integral from -infinity to
// sigma of exp(-i pi u^2 / 2) du, the integral being (1/2 + C) - i (1/2 + S).
Complex penneyPriceF(double sigma)
{
    const Complex cs = fresnel(sigma);
    return Complex(0.5, 0.5) * Complex(0.5 + cs.real(), -(0.5 + cs.imag()));
}

// Sommerfeld's solution for a semi-infinite breakwater along theta = 0
// with its tip at the origin, a wave arriving along theta0 (the angle
// between the wave's direction and the breakwater): the diffraction
// coefficient K = |H / H_incident| at polar (r, theta) in its lee (Penney &
// Price 1952, eq. 3.6; Dean & Dalrymple 1991, sec. 5.2.3):
//   F = f(sigma) exp(-i k r cos(theta - theta0)) + R f(sigma') exp(-i k r cos(theta + theta0)),
//   sigma = 2 sqrt(k r / pi) sin((theta - theta0) / 2), sigma' = -2 sqrt(k r / pi) sin((theta + theta0) / 2).
// The second term is the wave the breakwater's face reflects, diffracted
// in its turn: R = 1 for a rigid wall (Penney & Price's case, the
// published diagrams'), R = 0 for one that reflects nothing.
double sommerfeld(double rOverWavelength, double theta, double theta0, double reflected = 1.0)
{
    const double kr = swell::kTwoPi * rOverWavelength;
    const double sigma = 2.0 * std::sqrt(kr / swell::kPi) * std::sin((theta - theta0) / 2.0);
    const double sigmaReflected = -2.0 * std::sqrt(kr / swell::kPi) * std::sin((theta + theta0) / 2.0);
    return std::abs(penneyPriceF(sigma) * std::exp(Complex(0.0, -kr * std::cos(theta - theta0)))
                    + reflected * penneyPriceF(sigmaReflected) * std::exp(Complex(0.0, -kr * std::cos(theta + theta0))));
}

TEST(CoastField, TheSommerfeldSolutionMatchesItsPublishedValues)
{
    // Abramowitz & Stegun (1964), Table 7.7.
    EXPECT_NEAR(fresnel(1.0).real(), 0.7798934, 1e-6);
    EXPECT_NEAR(fresnel(1.0).imag(), 0.4382591, 1e-6);
    EXPECT_NEAR(fresnel(2.0).real(), 0.4882534, 1e-6);
    EXPECT_NEAR(fresnel(2.0).imag(), 0.3434157, 1e-6);
    // On the line from the tip along the wave's direction, K is about 0.5
    // for any approach angle (Wiegel 1962; CEM II-7-2.c(e)): exactly 0.5
    // without the reflected wave, a few hundredths more with it; deep in the
    // shadow it falls, and far out in the open it is the incident wave's 1.
    for (double theta0 : {60.0, 90.0, 120.0})
        for (double r : {2.0, 5.0, 10.0}) {
            EXPECT_NEAR(sommerfeld(r, theta0 * kDeg, theta0 * kDeg), 0.5, 0.05) << theta0 << " deg, r/L " << r;
            EXPECT_NEAR(sommerfeld(r, theta0 * kDeg, theta0 * kDeg, 0.0), 0.5, 1e-6);
            EXPECT_LT(sommerfeld(r, (theta0 - 45.0) * kDeg, theta0 * kDeg), 0.25);
        }
    EXPECT_NEAR(sommerfeld(20.0, 170.0 * kDeg, 90.0 * kDeg), 1.0, 0.1);
}

// A breakwater in water of one depth, its tip at the grid's middle, from
// the tip along `along` to the grid's edge: a wall of dry cells three wide,
// 2 m above the sea, with vertical faces; or, with a finite
// seawardSlope, its face towards the sea (+across) falling at that slope
// from the crest to the floor (a rubble or armoured face before a vertical
// lee, its end cut square at the tip).
struct Harbour {
    double cell_m = 2.0;
    int side = 400;
    double depth_m = 20.0;
    glm::dvec2 tip_m{400.0, 400.0};
    double seawardSlope = std::numeric_limits<double>::infinity();

    DepthGrid grid(glm::dvec2 along, bool withBreakwater) const
    {
        DepthGrid g;
        g.cell_m = cell_m;
        g.size = {side, side};
        g.outsideDepth_m = depth_m;
        g.depth_m.assign(std::size_t(side) * std::size_t(side), float(depth_m));
        const glm::dvec2 across(-along.y, along.x);
        for (int j = 0; j < side; ++j)
            for (int i = 0; i < side; ++i) {
                const glm::dvec2 p = cell_m * glm::dvec2(i, j) - tip_m;
                if (!withBreakwater || glm::dot(p, along) < 0.0)
                    continue;
                const double seaward_m = glm::dot(p, across) - 1.5 * cell_m; // from the crest's seaward edge
                const double lee_m = -glm::dot(p, across) - 1.5 * cell_m;
                float& depth = g.depth_m[std::size_t(j) * std::size_t(side) + std::size_t(i)];
                if (seaward_m <= 0.0 && lee_m <= 0.0)
                    depth = -2.0f;
                else if (seaward_m > 0.0 && !std::isinf(seawardSlope))
                    depth = float(std::min(depth_m, -2.0 + seawardSlope * seaward_m));
            }
        return g;
    }
};

// The field's wave height in the lee against Sommerfeld's with the
// reflected wave's term times `reflected` (Penney & Price's rigid
// breakwater: 1), at the shadow line and `into` degrees into the shadow, 4
// and 6 wavelengths from the tip, within 25%. The reflected wave is some
// of it: deep in the lee of a rigid wall at normal incidence a third of the
// height (60 degrees in, 4 wavelengths out: K 0.125 with it, 0.080
// without), nearer the shadow line a tenth or less.
void expectSommerfeldInTheLee(const Harbour& harbour, double amplitude_m, double reflected, double theta0_deg,
                              std::initializer_list<double> into_deg)
{
    const double wavelength = 40.0;
    // The breakwater runs along +z from the tip; the lee is on its +x side.
    const glm::dvec2 along(0.0, 1.0), lee(1.0, 0.0);
    const double theta0 = theta0_deg * kDeg;
    const glm::dvec2 direction = std::cos(theta0) * along + std::sin(theta0) * lee;
    WaveSet set;
    set.depth_m = harbour.depth_m;
    set.waves.push_back(Wave{direction, wavelength, amplitude_m, 0.0, 0.0});
    const CoastField field(set, harbour.grid(along, true));
    const glm::dvec2 open = swell::wavenumberVector(set.waves[0]);
    for (double r : {4.0, 6.0})
        for (double into : into_deg) {
            const double theta = theta0 - into * kDeg;
            const glm::dvec2 p = harbour.tip_m + r * wavelength * (std::cos(theta) * along + std::sin(theta) * lee);
            const double gain = field.waveAt(0, p, open).gain;
            const double expected = sommerfeld(r, theta, theta0, reflected);
            EXPECT_NEAR(gain / expected, 1.0, 0.25)
                << "incidence " << theta0_deg << " deg, " << into << " deg into the shadow, r/L " << r << ": gain "
                << gain << ", Sommerfeld " << expected << " with R " << reflected;
        }
}

TEST(CoastField, ABreakwatersLeeHoldsSommerfeldsWavesAtNormalIncidence)
{
    expectSommerfeldInTheLee(Harbour{}, 0.1, 1.0, 90.0, {0.0, 30.0, 60.0});
}

TEST(CoastField, ABreakwatersLeeHoldsSommerfeldsWavesAtAnAngle)
{
    expectSommerfeldInTheLee(Harbour{}, 0.1, 1.0, 60.0, {0.0, 20.0, 40.0});
}

// The deep water's wavelength L0 = 2 pi g / omega^2 of a wave `wavelength_m`
// long in water depth_m deep.
double deepWavelength(double wavelength_m, double depth_m)
{
    const double omega = swell::angularFrequency(swell::kTwoPi / wavelength_m, depth_m);
    return swell::kTwoPi * swell::kGravity / (omega * omega);
}

TEST(CoastField, TheReflectionCoefficientIsSeeligAndAhrenssForTheSurfSimilarity)
{
    using swell::coast::reflectionCoefficient;
    using swell::coast::surfSimilarity;
    // Battjes (1974): xi = tan(alpha) / sqrt(H / L0); a 1:10 slope under
    // waves of steepness 0.01 has xi = 1.
    EXPECT_NEAR(surfSimilarity(0.1, 1.0, 100.0), 1.0, 1e-12);
    // Seelig & Ahrens (1981), smooth slopes, a = 1.0, b = 5.5: half the
    // height where xi^2 = b, a vertical wall all of it, a 1:20 beach under
    // a swell of steepness 0.01 (xi = 0.5) 0.043, under the field's
    // threshold: a gentle beach sends nothing back.
    EXPECT_NEAR(reflectionCoefficient(std::sqrt(5.5) * 0.1, 1.0, 100.0), 0.5, 1e-12);
    EXPECT_DOUBLE_EQ(reflectionCoefficient(std::numeric_limits<double>::infinity(), 1.0, 100.0), 1.0);
    EXPECT_NEAR(reflectionCoefficient(0.05, 1.0, 100.0), 0.25 / 5.75, 1e-12);
    EXPECT_LT(reflectionCoefficient(0.05, 1.0, 100.0), swell::coast::kNegligibleReflection);
}

// The amplitude of waves 40 m long in 20 m of water that a face of 1:2
// reflects some 0.6 of (xi about 2.9; 0.86 m high).
constexpr double kSlopedFaceAmplitude = 0.43;

double slopedFaceReflection(double slope, double depth_m)
{
    return swell::coast::reflectionCoefficient(
        slope, 4.0 * std::sqrt(0.5 * kSlopedFaceAmplitude * kSlopedFaceAmplitude), deepWavelength(40.0, depth_m));
}

// A breakwater whose seaward face falls at 1:2: it sends back some 0.6 of
// the height, and its lee holds Sommerfeld's solution with that R.
TEST(CoastField, ASlopingFacedBreakwatersLeeHoldsSommerfeldsWavesWithItsOwnReflection)
{
    Harbour harbour;
    harbour.seawardSlope = 0.5;
    const double reflected = slopedFaceReflection(harbour.seawardSlope, harbour.depth_m);
    EXPECT_GT(reflected, 0.5);
    EXPECT_LT(reflected, 0.7);
    expectSommerfeldInTheLee(harbour, kSlopedFaceAmplitude, reflected, 90.0, {0.0, 30.0, 60.0});
}

// A shore across the grid at its middle, at normal incidence: a vertical
// wall (slope infinite; the land 20 m high) or a plane face at `slope`
// from the floor up to 2 m above the sea. The field's gain at the samples
// on the line through the grid's middle, from the waterline out, with
// their distance from the waterline (where the bilinear depth crosses zero).
struct ShoreLine {
    std::vector<double> fromWaterline_m, gain;
};

ShoreLine shoreLine(double slope, double amplitude_m, double out_m)
{
    const double wavelength = 40.0, depth = 20.0, cell = 2.0;
    const int side = 300;
    const double waterline_m = cell * 200.0 - 1.0; // between samples 199 and 200
    DepthGrid g;
    g.cell_m = cell;
    g.size = {side, side};
    g.outsideDepth_m = depth;
    g.depth_m.assign(std::size_t(side) * std::size_t(side), float(depth));
    for (int j = 0; j < side; ++j)
        for (int i = 0; i < side; ++i) {
            const double toWaterline_m = waterline_m - cell * i;
            const double h = std::isinf(slope) ? (toWaterline_m > 0.0 ? depth : -20.0)
                                               : std::clamp(slope * toWaterline_m, -2.0, depth);
            g.depth_m[std::size_t(j) * std::size_t(side) + std::size_t(i)] = float(h);
        }
    WaveSet set;
    set.depth_m = depth;
    set.waves.push_back(Wave{{1.0, 0.0}, wavelength, amplitude_m, 0.0, 0.0});
    const CoastField field(set, g);
    const glm::dvec2 open = swell::wavenumberVector(set.waves[0]);
    ShoreLine line;
    for (int i = 199; cell * i >= waterline_m - out_m; --i) {
        line.fromWaterline_m.push_back(waterline_m - cell * i);
        line.gain.push_back(field.waveAt(0, glm::dvec2(cell * i, cell * side / 2), open).gain);
    }
    return line;
}

// In front of a vertical wall at normal incidence the reflected wave stands
// with the incident one: the height |1 + R e^(2 i k x)| times the incident
// one's, x from the waterline, R the wall's (1): 2 at the antinodes, 0 at
// the nodes, half a wavelength apart (Dean & Dalrymple 1991, sec. 4.10).
// Held at the field's samples, out to 3 wavelengths, within 0.1.
TEST(CoastField, AVerticalWallStandsAClapotisInFrontOfIt)
{
    const double wavelength = 40.0;
    const double reflected = swell::coast::reflectionCoefficient(std::numeric_limits<double>::infinity(), 1.0, 1.0);
    const ShoreLine line = shoreLine(std::numeric_limits<double>::infinity(), 0.1, 3.0 * wavelength);
    double highest = 0.0, lowest = 2.0;
    for (std::size_t s = 0; s < line.gain.size(); ++s) {
        const double x = line.fromWaterline_m[s];
        const double expected = std::abs(1.0 + reflected * std::exp(Complex(0.0, 2.0 * swell::kTwoPi / wavelength * x)));
        EXPECT_NEAR(line.gain[s], expected, 0.1) << x << " m from the wall";
        highest = std::max(highest, line.gain[s]);
        lowest = std::min(lowest, line.gain[s]);
    }
    EXPECT_GT(highest, 1.9);
    EXPECT_LT(lowest, 0.35); // the nodes fall between the samples
}

// Before a face that reflects part of the height the wave stands in part:
// its envelope swings between 1 + R and 1 - R times the incident height
// (Dean & Dalrymple 1991, sec. 4.10), R the face's own. Held over the level
// floor before a 1:2 face's toe, out to 3 wavelengths, within 0.1.
TEST(CoastField, ASlopingFaceStandsAPartialClapotisOfItsOwnReflection)
{
    const double wavelength = 40.0, slope = 0.5;
    const double reflected = slopedFaceReflection(slope, 20.0);
    const ShoreLine line = shoreLine(slope, kSlopedFaceAmplitude, 20.0 / slope + 3.0 * wavelength);
    double highest = 0.0, lowest = 2.0;
    for (std::size_t s = 0; s < line.gain.size(); ++s)
        if (line.fromWaterline_m[s] > 20.0 / slope) {
            highest = std::max(highest, line.gain[s]);
            lowest = std::min(lowest, line.gain[s]);
        }
    EXPECT_NEAR(highest, 1.0 + reflected, 0.1) << "R " << reflected;
    EXPECT_NEAR(lowest, 1.0 - reflected, 0.1) << "R " << reflected;
}

} // namespace
