// Waves diffracting into a breakwater's lee (swell/coast_field.h), held to
// Sommerfeld's (1896) solution for a semi-infinite screen as Penney & Price
// (1952) applied it to water waves, written out here from its Fresnel
// integrals; the integrals checked against Abramowitz & Stegun's table, and
// the solution against the diffraction diagrams' published value on the
// shadow line (Wiegel 1962, as the Coastal Engineering Manual, EM
// 1110-2-1100, Part II, ch. 7, 2002, sec. II-7-2.c(e), sums them up).
#include "swell/coast_field.h"
#include "support/numbers.h"
#include "swell/constants.h"
#include "swell/scene/waves.h"

#include <glm/geometric.hpp>
#include <gtest/gtest.h>

#include <cmath>
#include <complex>

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

// A breakwater in water of one depth, its tip at the grid's middle: a wall
// of dry cells three wide from the tip along `along` to the grid's edge.
struct Harbour {
    double cell_m = 2.0;
    int side = 400;
    double depth_m = 20.0;
    glm::dvec2 tip_m{400.0, 400.0};

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
                if (withBreakwater && glm::dot(p, along) >= 0.0 && std::abs(glm::dot(p, across)) <= 1.5 * cell_m)
                    g.depth_m[std::size_t(j) * std::size_t(side) + std::size_t(i)] = -2.0f;
            }
        return g;
    }
};

// The field's wave height in the lee against Sommerfeld's, at the shadow
// line and `into` degrees into the shadow, 4 and 6 wavelengths from the
// tip. The field reflects nothing from the breakwater's face (coast_field.h),
// so its reference is the solution without the reflected wave: deep in the
// lee of a rigid wall at normal incidence that wave is a third of the
// height (60 degrees in, 4 wavelengths out: K 0.125 with it, 0.080
// without), nearer the shadow line a tenth or less.
void expectSommerfeldInTheLee(double theta0_deg, std::initializer_list<double> into_deg, bool withBreakwater = true)
{
    const Harbour harbour;
    const double wavelength = 40.0, amplitude = 0.1;
    // The breakwater runs along +z from the tip; the lee is on its +x side.
    const glm::dvec2 along(0.0, 1.0), lee(1.0, 0.0);
    const double theta0 = theta0_deg * kDeg;
    const glm::dvec2 direction = std::cos(theta0) * along + std::sin(theta0) * lee;
    WaveSet set;
    set.depth_m = harbour.depth_m;
    set.waves.push_back(Wave{direction, wavelength, amplitude, 0.0, 0.0});
    const CoastField field(set, harbour.grid(along, withBreakwater));
    const glm::dvec2 open = swell::wavenumberVector(set.waves[0]);
    for (double r : {4.0, 6.0})
        for (double into : into_deg) {
            const double theta = theta0 - into * kDeg;
            const glm::dvec2 p = harbour.tip_m + r * wavelength * (std::cos(theta) * along + std::sin(theta) * lee);
            const double gain = field.waveAt(0, p, open).gain;
            const double expected = sommerfeld(r, theta, theta0, 0.0);
            EXPECT_NEAR(gain / expected, 1.0, 0.25)
                << "incidence " << theta0_deg << " deg, " << into << " deg into the shadow, r/L " << r << ": gain "
                << gain << ", Sommerfeld " << expected;
        }
}

TEST(CoastField, ABreakwatersLeeHoldsSommerfeldsWavesAtNormalIncidence) { expectSommerfeldInTheLee(90.0, {0.0, 30.0, 60.0}); }

TEST(CoastField, ABreakwatersLeeHoldsSommerfeldsWavesAtAnAngle) { expectSommerfeldInTheLee(60.0, {0.0, 20.0, 40.0}); }

} // namespace
