// Published sky measurements and fits that tests check the physical sky
// (swell/scene/atmosphere.h) against, and the published way to turn its radiance
// at three wavelengths into luminance and chromaticity.
#pragma once

#include <glm/vec3.hpp>

#include <array>
#include <cmath>
#include <numbers>
#include <vector>

namespace swell::test {

// The sun's spectral irradiance at the top of the atmosphere, W/(m^2 nm),
// in 10 nm bins from 360 to 830 nm: the ASTM G-173-03 extraterrestrial
// (ETR) column averaged over each bin, as Bruneton (2017, demo.cc,
// kSolarIrradiance) feeds it to the model this sky implements.
inline constexpr std::array<double, 48> kSolarIrradiance_W_per_m2_nm{
    1.11776, 1.14259, 1.01249, 1.14716, 1.72765, 1.73054, 1.6887,  1.61253, 1.91198, 2.03474, 2.02042, 2.02212,
    1.93377, 1.95809, 1.91686, 1.8298,  1.8685,  1.8931,  1.85149, 1.8504,  1.8341,  1.8345,  1.8147,  1.78158,
    1.7533,  1.6965,  1.68194, 1.64654, 1.6048,  1.52143, 1.55622, 1.5113,  1.474,   1.4482,  1.41018, 1.36775,
    1.34188, 1.31429, 1.28303, 1.26758, 1.2367,  1.2082,  1.18737, 1.14683, 1.12362, 1.1058,  1.07124, 1.04992};

// The table at any wavelength, linearly between bin starts, clamped.
inline double solarIrradiance(double lambda_nm)
{
    const double f = (lambda_nm - 360.0) / 10.0;
    if (f <= 0.0)
        return kSolarIrradiance_W_per_m2_nm.front();
    if (f >= 47.0)
        return kSolarIrradiance_W_per_m2_nm.back();
    const auto i = static_cast<std::size_t>(f);
    const double u = f - double(i);
    return kSolarIrradiance_W_per_m2_nm[i] * (1.0 - u) + kSolarIrradiance_W_per_m2_nm[i + 1] * u;
}

// The CIE 1931 2-degree colour matching functions x, y, z (y is the
// photopic luminous efficiency V), by the multi-lobe fit of Wyman, Sloan &
// Shirley (2013, JCGT 2(2), eq. 2), within a few percent of the tables.
inline glm::dvec3 cieColourMatching(double lambda_nm)
{
    auto g = [lambda_nm](double mean, double below, double above) {
        const double t = (lambda_nm - mean) / (lambda_nm < mean ? below : above);
        return std::exp(-0.5 * t * t);
    };
    return {1.056 * g(599.8, 37.9, 31.0) + 0.362 * g(442.0, 16.0, 26.7) - 0.065 * g(501.1, 20.4, 26.2),
            0.821 * g(568.8, 46.9, 40.5) + 0.286 * g(530.9, 16.3, 31.1),
            1.217 * g(437.0, 11.8, 36.0) + 0.681 * g(459.0, 26.0, 13.8)};
}

// The maximum luminous efficacy of radiation, lm/W (CIE; SI definition of the candela).
inline constexpr double kMaxLuminousEfficacy_lm_per_W = 683.0;

// CIE XYZ (Y: luminance, cd/m^2) of the sky whose radiance per unit solar
// irradiance at the top of the atmosphere is `ratio` (1/sr) at 680, 550
// and 440 nm, as the model computes it. Bruneton's (2016, "A qualitative
// and quantitative evaluation of 8 clear sky models", IEEE TVCG 23(12),
// sec. 14.3) conversion for three-wavelength models: around each sample
// the sky's spectrum is taken as the sun's times (lambda / lambda_c)^-3,
// each channel is projected on the linear sRGB colour matching functions
// (IEC 61966-2-1's XYZ to sRGB matrix), and the sRGB is turned back to XYZ.
inline glm::dvec3 skyXyz(glm::dvec3 ratio)
{
    const double lambdas[3] = {680.0, 550.0, 440.0};
    const double toSrgb[3][3] = {{3.2406, -1.5372, -0.4986}, {-0.9689, 1.8758, 0.0415}, {0.0557, -0.2040, 1.0570}};
    glm::dvec3 srgb(0.0);
    for (int c = 0; c < 3; ++c) {
        double k = 0.0; // lm nm / W
        for (double lambda = 360.0; lambda < 830.0; lambda += 1.0) {
            const glm::dvec3 xyz = cieColourMatching(lambda);
            const double bar = toSrgb[c][0] * xyz.x + toSrgb[c][1] * xyz.y + toSrgb[c][2] * xyz.z;
            k += bar * solarIrradiance(lambda) / solarIrradiance(lambdas[c]) * std::pow(lambda / lambdas[c], -3.0);
        }
        srgb[c] = kMaxLuminousEfficacy_lm_per_W * k * ratio[c] * solarIrradiance(lambdas[c]);
    }
    return {0.4124 * srgb.x + 0.3576 * srgb.y + 0.1805 * srgb.z, 0.2126 * srgb.x + 0.7152 * srgb.y + 0.0722 * srgb.z,
            0.0193 * srgb.x + 0.1192 * srgb.y + 0.9505 * srgb.z};
}

// The Preetham, Shirley & Smits (1999, "A practical analytic model for
// daylight", SIGGRAPH, appendix A.2) clear sky at turbidity T: luminance
// Y (cd/m^2) and chromaticity x, y of the sky at zenith angle theta and
// angle gamma from the sun, for the sun at zenith angle thetaSun (radians).
// Zenith values from their fits, the rest by the Perez et al. (1993)
// distribution with their coefficients, F(theta, gamma) / F(0, thetaSun).
struct SkyColour {
    double luminance_cd_per_m2, x, y;
};
inline SkyColour preethamSky(double theta, double gamma, double thetaSun, double T)
{
    auto perez = [&](double a, double b, double c, double d, double e) {
        auto f = [&](double th, double ga) {
            return (1.0 + a * std::exp(b / std::cos(th))) * (1.0 + c * std::exp(d * ga) + e * std::cos(ga) * std::cos(ga));
        };
        return f(theta, gamma) / f(0.0, thetaSun);
    };
    const double chi = (4.0 / 9.0 - T / 120.0) * (std::numbers::pi - 2.0 * thetaSun);
    const double zenithY_kcd = (4.0453 * T - 4.9710) * std::tan(chi) - 0.2155 * T + 2.4192;
    const double t = thetaSun, t2 = t * t, t3 = t2 * t;
    const double zenithX = T * T * (0.00166 * t3 - 0.00375 * t2 + 0.00209 * t)
        + T * (-0.02903 * t3 + 0.06377 * t2 - 0.03202 * t + 0.00394) + (0.11693 * t3 - 0.21196 * t2 + 0.06052 * t + 0.25886);
    const double zenithy = T * T * (0.00275 * t3 - 0.00610 * t2 + 0.00317 * t)
        + T * (-0.04214 * t3 + 0.08970 * t2 - 0.04153 * t + 0.00516) + (0.15346 * t3 - 0.26756 * t2 + 0.06670 * t + 0.26688);
    return {1000.0 * zenithY_kcd
                * perez(0.1787 * T - 1.4630, -0.3554 * T + 0.4275, -0.0227 * T + 5.3251, 0.1206 * T - 2.5771, -0.0670 * T + 0.3703),
            zenithX * perez(-0.0193 * T - 0.2592, -0.0665 * T + 0.0008, -0.0004 * T + 0.2125, -0.0641 * T - 0.8989, -0.0033 * T + 0.0452),
            zenithy * perez(-0.0167 * T - 0.2608, -0.0950 * T + 0.0092, -0.0079 * T + 0.2102, -0.0441 * T - 1.6537, -0.0109 * T + 0.0529)};
}

// Exact radiative transfer in a Rayleigh atmosphere: published radiances
// of the sky seen from the ground, by solvers of the polarised equation to
// five or more digits (the intensity I; the physical sky's model is scalar
// and approximates multiple scattering, which is what tests hold it to).
// Each row: the sun's zenith angle, the view's zenith angle and its azimuth
// from the sun's (0: towards the sun), all in degrees, and the radiance per
// unit of the sun's irradiance on a plane normal to its rays (1/sr).
struct RayleighSkyRow {
    double sunZenith_deg, viewZenith_deg, azimuthFromSun_deg, radiance_per_sr;
};
struct RayleighSkyCase {
    const char* source;
    double opticalDepth;   // the layer's Rayleigh optical thickness
    double groundAlbedo;   // Lambertian
    double depolarisation; // the molecules' depolarisation factor (the model has 0)
    std::vector<RayleighSkyRow> rows;
};

// The tables' units turned into radiance per unit irradiance normal to the
// sun's rays: IPRT's I / F0 is that already; Kokhanovsky et al. tabulate
// pi I / (mu0 F0); Natraj et al. tabulate I for an incident flux pi F0 = pi.
inline double fromKokhanovsky(double value, double sunZenith_deg)
{
    return value * std::cos(sunZenith_deg * std::numbers::pi / 180.0) / std::numbers::pi;
}
inline double fromNatraj(double value) { return value / std::numbers::pi; }
inline double zenithOfCosine(double mu) { return std::acos(mu) * 180.0 / std::numbers::pi; }

// The sun 30 to 90 degrees up, in layers as thick as the Earth's air at
// 440 nm (0.26) and thinner and thicker:
// - IPRT phase A (Emde et al. 2015, JQSRT 164, 8-36), the model PSTAR's
//   results: case A1 (one Rayleigh layer of optical thickness 0.5, black
//   ground; sun at the zenith with no depolarisation, and 30 degrees from it
//   with 0.03) and case A2 (optical thickness 0.1 over a Lambertian ground
//   of albedo 0.3, depolarisation 0.03, the sun 50 degrees from the zenith).
// - Kokhanovsky et al. 2010 (JQSRT 111, 1931-1946), the molecular layer's
//   transmitted light (Table A1): optical thickness 0.3262, the sun 60
//   degrees from the zenith, black ground.
// Views from the zenith to 10 degrees above the horizon.
inline std::vector<RayleighSkyCase> rayleighSkyBenchmarks()
{
    const double k = 60.0; // Kokhanovsky et al.'s sun
    return {
        {"IPRT A1, sun at the zenith", 0.5, 0.0, 0.0,
         {{0.0, 0.0, 0.0, 5.829094e-2}, {0.0, 20.0, 0.0, 5.794367e-2}, {0.0, 60.0, 0.0, 6.200341e-2}}},
        {"IPRT A1, sun 30 degrees from the zenith", 0.5, 0.0, 0.03,
         {{30.0, 0.0, 0.0, 4.944388e-2},
          {30.0, 20.0, 65.0, 5.300881e-2},
          {30.0, 20.0, 120.0, 4.650063e-2},
          {30.0, 20.0, 180.0, 4.345636e-2},
          {30.0, 60.0, 0.0, 8.061241e-2},
          {30.0, 60.0, 65.0, 6.691916e-2},
          {30.0, 60.0, 120.0, 5.409492e-2},
          {30.0, 60.0, 180.0, 5.179994e-2}}},
        {"IPRT A2", 0.1, 0.3, 0.03,
         {{50.0, 0.0, 0.0, 1.139551e-2},
          {50.0, 30.0, 0.0, 1.618379e-2},
          {50.0, 30.0, 45.0, 1.491217e-2},
          {50.0, 30.0, 90.0, 1.249049e-2},
          {50.0, 30.0, 135.0, 1.098560e-2},
          {50.0, 30.0, 180.0, 1.063078e-2},
          {50.0, 60.0, 45.0, 2.441616e-2},
          {50.0, 60.0, 90.0, 1.887249e-2},
          {50.0, 60.0, 135.0, 1.789589e-2},
          {50.0, 60.0, 180.0, 1.882903e-2},
          {50.0, 80.0, 0.0, 6.213985e-2},
          {50.0, 80.0, 45.0, 5.375838e-2},
          {50.0, 80.0, 90.0, 4.356350e-2},
          {50.0, 80.0, 135.0, 4.756701e-2},
          {50.0, 80.0, 180.0, 5.338393e-2}}},
        {"Kokhanovsky et al. 2010, molecular layer", 0.3262, 0.0, 0.0,
         {{k, 0.0, 0.0, fromKokhanovsky(0.1396923, k)},
          {k, 40.0, 0.0, fromKokhanovsky(0.2590920, k)},
          {k, 40.0, 90.0, fromKokhanovsky(0.1689676, k)},
          {k, 40.0, 180.0, fromKokhanovsky(0.1509949, k)}}},
    };
}

// Where a flat layer is not the round Earth, or the sun is low: the same
// molecular layer of Kokhanovsky et al. (2010, Table A1) seen 1 degree
// above the horizon, where a flat layer's line of sight crosses 57 times
// its thickness and a round atmosphere's about 27; and Natraj, Li & Yung
// (2009, ApJ 691, 1909; their corrected Coulson, Dave & Sekera tables),
// optical thickness 0.5, black ground, the sun at mu0 = 0.2 (11.5 degrees
// up), views from mu = 0.1 (5.7 degrees up) to the zenith.
inline std::vector<RayleighSkyCase> rayleighSkyHorizonAndLowSun()
{
    const double k = 60.0;
    const double sun = zenithOfCosine(0.2);
    auto row = [sun](double mu, double azimuth, double value) {
        return RayleighSkyRow{sun, zenithOfCosine(mu), azimuth, fromNatraj(value)};
    };
    return {
        {"Kokhanovsky et al. 2010, 1 degree above the horizon", 0.3262, 0.0, 0.0,
         {{k, 89.0, 0.0, fromKokhanovsky(0.5599639, k)},
          {k, 89.0, 90.0, fromKokhanovsky(0.3617355, k)},
          {k, 89.0, 180.0, fromKokhanovsky(0.5515021, k)}}},
        {"Natraj et al. 2009, sun 11.5 degrees up", 0.5, 0.0, 0.0,
         {row(0.10, 0.0, 0.13485741), row(0.10, 90.0, 0.08801144), row(0.10, 180.0, 0.13070302),
          row(0.20, 0.0, 0.15838610), row(0.20, 90.0, 0.10033646), row(0.20, 180.0, 0.14846675),
          row(0.52, 0.0, 0.12178394), row(0.52, 90.0, 0.07796226), row(0.52, 180.0, 0.10282324),
          row(0.84, 0.0, 0.07348081), row(0.84, 90.0, 0.05534670), row(0.84, 180.0, 0.05854240),
          row(1.00, 0.0, 0.04682203)}},
    };
}

} // namespace swell::test
