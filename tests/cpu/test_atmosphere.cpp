// The physical sky's model (swell/scene/atmosphere.h): its numerics (the tables
// against direct integration, the ray march's steps, the spherical
// harmonics against the irradiance integral), what it must do to light (the
// sun reddens and dims towards the horizon; at sunset the sky away from the
// sun is dim and bluish, issue 28 item 11), and published reference values.
#include "swell/scene/atmosphere.h"

#include "published_sky.h"
#include "rayleigh_layer_transfer.h"
#include "swell/constants.h"

#include <gtest/gtest.h>

#include <glm/geometric.hpp>

#include <cmath>
#include <cstdio>
#include <numbers>
#include <vector>

namespace {

using swell::Atmosphere;

using swell::kPi;
constexpr double kBottom_m = swell::kAtmosphereBottomRadius_m;

const Atmosphere& clearAir()
{
    static const Atmosphere atmosphere{swell::AtmosphereSettings{}};
    return atmosphere;
}

glm::dvec3 sunAt(double elevation_deg)
{
    const double e = elevation_deg * kPi / 180.0;
    return {0.0, std::sin(e), -std::cos(e)};
}

// A direction at an elevation and an azimuth from the sun's (which is at -z).
glm::dvec3 skyAt(double elevation_deg, double azimuthFromSun_deg)
{
    const double e = elevation_deg * kPi / 180.0, a = azimuthFromSun_deg * kPi / 180.0;
    return {std::sin(a) * std::cos(e), std::sin(e), -std::cos(a) * std::cos(e)};
}

// The model's radiance at 440 nm along each of a benchmark's rows
// (published_sky.h), for the model's air made the benchmark's layer: its
// density scaled to the layer's optical thickness, no aerosols, the
// benchmark's ground.
std::vector<double> modelRadiances(const swell::test::RayleighSkyCase& c)
{
    const double column440 = swell::kRayleighScatteringBlue_per_m * swell::kRayleighScaleHeight_m
        * (1.0 - std::exp(-(swell::kAtmosphereTopRadius_m - kBottom_m) / swell::kRayleighScaleHeight_m));
    swell::AtmosphereSettings settings;
    settings.rayleighScale = c.opticalDepth / column440;
    settings.mieScale = 0.0;
    settings.groundAlbedo = c.groundAlbedo;
    const Atmosphere air(settings);
    std::vector<double> radiances;
    for (const swell::test::RayleighSkyRow& row : c.rows) {
        const glm::dvec3 sun = sunAt(90.0 - row.sunZenith_deg);
        const glm::dvec3 view = skyAt(90.0 - row.viewZenith_deg, row.azimuthFromSun_deg);
        radiances.push_back(air.skyRadiance(view, sun, 400).z);
    }
    return radiances;
}

// The model over a reference along each row, printed for the figures
// quoted below.
std::vector<double> ratiosTo(const swell::test::RayleighSkyCase& c, const std::vector<double>& references,
                             const char* reference)
{
    const std::vector<double> model = modelRadiances(c);
    std::vector<double> ratios;
    for (size_t i = 0; i < model.size(); ++i) {
        ratios.push_back(model[i] / references[i]);
        std::printf("%s: sun %.1f, view %.1f at %.0f from the sun: model / %s %.3f\n", c.source, c.rows[i].sunZenith_deg,
                    c.rows[i].viewZenith_deg, c.rows[i].azimuthFromSun_deg, reference, ratios.back());
    }
    return ratios;
}

std::vector<double> rayleighSkyRatios(const swell::test::RayleighSkyCase& c)
{
    std::vector<double> published;
    for (const swell::test::RayleighSkyRow& row : c.rows)
        published.push_back(row.radiance_per_sr);
    return ratiosTo(c, published, "published");
}

double relativeError(double value, double reference) { return std::abs(value / reference - 1.0); }

// The table, read bilinearly, against the transmittance integrated directly
// along the same rays: within 1% of the value (or 1e-4 where it is smaller
// than 1e-2: it falls towards 0 along grazing rays, where the parametrisation
// packs its texels). A wrong parametrisation (x_mu and x_r swapped) is off by
// far more.
TEST(Atmosphere, TransmittanceTableMatchesDirectIntegration)
{
    const Atmosphere& air = clearAir();
    for (double altitude_m : {0.0, 10.0, 500.0, 3000.0, 12000.0, 40000.0})
        for (double mu : {1.0, 0.7, 0.3, 0.1, 0.03, 0.01, 0.0, -0.02}) {
            const double r = kBottom_m + altitude_m;
            const glm::dvec3 exact = swell::transmittanceToTop(r, mu, air.settings(), 4096);
            const glm::dvec3 table = air.transmittance(r, mu);
            for (int c = 0; c < 3; ++c) {
                const double tolerance = std::max(0.01 * exact[c], 1.0e-4);
                EXPECT_NEAR(table[c], exact[c], tolerance) << "altitude " << altitude_m << " m, mu " << mu << ", channel " << c;
            }
        }
}

// The ray march's SWELL_SKY_MARCH_STEPS quadratic steps against 4000: within
// 1% everywhere above the horizon, for the sun high and at sunset.
TEST(Atmosphere, SkyMarchStepsConverge)
{
    const Atmosphere& air = clearAir();
    for (double sunElevation : {60.0, 4.0})
        for (double elevation : {0.0, 2.0, 10.0, 45.0, 90.0})
            for (double azimuth : {0.0, 90.0, 180.0}) {
                const glm::dvec3 coarse = air.skyRadiance(skyAt(elevation, azimuth), sunAt(sunElevation));
                const glm::dvec3 fine = air.skyRadiance(skyAt(elevation, azimuth), sunAt(sunElevation), 4000);
                for (int c = 0; c < 3; ++c)
                    EXPECT_LT(relativeError(coarse[c], fine[c]), 0.01)
                        << "sun " << sunElevation << ", view elevation " << elevation << ", azimuth " << azimuth;
            }
}

// The order-2 harmonics against the cosine-weighted integral of the sky's and
// the ground's radiance: Ramamoorthi & Hanrahan (2001) bound the error of
// order 2 at a few percent of the mean for any lighting; 10% of the
// up-facing irradiance here. Leaving the A_l convolution out, or a harmonic's
// sign wrong, is off by tens of percent.
TEST(Atmosphere, IrradianceHarmonicsMatchTheIntegral)
{
    const Atmosphere& air = clearAir();
    for (double sunElevation : {40.0, 4.0}) {
        const glm::dvec3 sun = sunAt(sunElevation);
        const std::array<glm::dvec3, 9> sh = air.irradianceSh(sun);
        // The ground's radiance, as irradianceSh() defines it.
        glm::dvec3 skyDown(0.0);
        constexpr int kRings = 64, kSectors = 128;
        const double cell = 2.0 * kPi / (kRings * kSectors);
        for (int i = 0; i < kRings; ++i)
            for (int j = 0; j < kSectors; ++j) {
                const double ct = (i + 0.5) / kRings, st = std::sqrt(1.0 - ct * ct), phi = 2.0 * kPi * (j + 0.5) / kSectors;
                const glm::dvec3 d(st * std::cos(phi), ct, st * std::sin(phi));
                skyDown += air.skyRadiance(d, sun, 24) * ct * cell;
            }
        const glm::dvec3 ground = air.settings().groundAlbedo / kPi * (air.sunTransmittance(sun) * sun.y + skyDown);
        const double scale = swell::evaluateSh(sh, {0.0, 1.0, 0.0}).y;
        for (const glm::dvec3 n : {glm::dvec3(0, 1, 0), glm::dvec3(0, 0, -1), glm::dvec3(0, 0, 1), glm::dvec3(1, 0, 0),
                                   glm::dvec3(0, -1, 0), glm::normalize(glm::dvec3(0, 1, 1))}) {
            glm::dvec3 exact(0.0);
            constexpr int kR = 48, kS = 96;
            const double dw = 4.0 * kPi / (kR * kS);
            for (int i = 0; i < kR; ++i)
                for (int j = 0; j < kS; ++j) {
                    const double ct = 1.0 - 2.0 * (i + 0.5) / kR, st = std::sqrt(1.0 - ct * ct);
                    const double phi = 2.0 * kPi * (j + 0.5) / kS;
                    const glm::dvec3 d(st * std::cos(phi), ct, st * std::sin(phi));
                    const double c = glm::dot(d, n);
                    if (c <= 0.0)
                        continue;
                    exact += (d.y >= 0.0 ? air.skyRadiance(d, sun, 24) : ground) * c * dw;
                }
            const glm::dvec3 fit = swell::evaluateSh(sh, n);
            for (int c = 0; c < 3; ++c)
                EXPECT_NEAR(fit[c], exact[c], 0.1 * scale)
                    << "sun " << sunElevation << " deg, normal " << n.x << " " << n.y << " " << n.z << ", channel " << c;
        }
    }
}

// The sun's light at the sea reddens and dims as it sinks: blue over red
// falls at every step down, and at 4 degrees (the sunset preset) red is at
// least five times blue while at 60 degrees they are within 25%.
TEST(Atmosphere, TheSunReddensAndDimsTowardsTheHorizon)
{
    const Atmosphere& air = clearAir();
    double lastRatio = 2.0, lastGreen = 2.0;
    for (double elevation : {90.0, 60.0, 30.0, 15.0, 8.0, 4.0, 2.0}) {
        const glm::dvec3 t = air.sunTransmittance(sunAt(elevation));
        EXPECT_LT(t.z / t.x, lastRatio) << elevation;
        EXPECT_LT(t.y, lastGreen) << elevation;
        lastRatio = t.z / t.x;
        lastGreen = t.y;
        if (elevation == 60.0) {
            EXPECT_GT(t.z / t.x, 0.75);
        }
        if (elevation == 4.0) {
            EXPECT_LT(t.z / t.x, 0.2);
        }
    }
    EXPECT_EQ(air.sunTransmittance(sunAt(-1.0)), glm::dvec3(0.0)) << "the sun below the horizon";
}

// Issue 28 item 11 at its root: with the sun 4 degrees up, the light on a
// surface turned away from the sun is bluish (blue above red; the gradient
// sky's ambient there was orange, red 1.6 times blue) and dim, under a
// quarter of what a surface facing the sun gets from the sky alone.
TEST(Atmosphere, AtSunsetTheSkyAwayFromTheSunIsDimAndBluish)
{
    const Atmosphere& air = clearAir();
    const glm::dvec3 sun = sunAt(4.0);
    const std::array<glm::dvec3, 9> sh = air.irradianceSh(sun);
    const glm::dvec3 away = swell::evaluateSh(sh, {0.0, 0.0, 1.0});
    const glm::dvec3 towards = swell::evaluateSh(sh, {0.0, 0.0, -1.0});
    EXPECT_GT(away.z, away.x) << "the light on the side away from the sun is not bluish";
    EXPECT_LT(towards.z, towards.x) << "the light on the side facing the sun is not warm";
    // The sky's radiance itself: the horizon opposite the sun is dimmer
    // than the one under the sun by a factor of five or more.
    const glm::dvec3 opposite = air.skyRadiance(skyAt(1.0, 180.0), sun);
    const glm::dvec3 under = air.skyRadiance(skyAt(1.0, 0.0), sun);
    EXPECT_LT(opposite.x + opposite.y + opposite.z, 0.2 * (under.x + under.y + under.z));
    // Lit by the sun too, the side facing it takes several times the light
    // of the side away from it.
    const glm::dvec3 direct = air.sunTransmittance(sun) * 1.0; // cosine 1 facing the sun horizontally, nearly
    const double lit = glm::dot(towards + direct * std::cos(4.0 * kPi / 180.0), glm::dvec3(0.2126, 0.7152, 0.0722));
    const double shade = glm::dot(away, glm::dvec3(0.2126, 0.7152, 0.0722));
    EXPECT_LT(shade, 0.25 * lit);
}

// Published reference: the Rayleigh optical depth of the whole atmosphere
// at sea level, the model's beta_R(0) H_R, against Hansen & Travis's (1974,
// Space Sci. Rev. 16, sec. 2) fit for the standard atmosphere at 1013.25 hPa,
// tau(lambda) = 0.008569 lambda^-4 (1 + 0.0113 lambda^-2 + 0.00013 lambda^-4),
// lambda in um. Bruneton 2017's coefficients (1.24062e-6 / lambda^4 per m)
// with an 8 km scale height are denser: +9.1% at 440 nm, +11.5% at 550 nm
// and +13.0% at 680 nm (measured). The test holds the blue within 10%, the
// published tolerance, and the others within the 14% they reach, so a change
// of constants that makes them worse turns it red.
TEST(Atmosphere, RayleighOpticalDepthAgainstHansenAndTravis1974)
{
    struct Case {
        double lambda_um, beta_per_m, tolerance;
    };
    const Case cases[] = {{0.44, swell::kRayleighScatteringBlue_per_m, 0.10},
                          {0.55, swell::kRayleighScatteringGreen_per_m, 0.14},
                          {0.68, swell::kRayleighScatteringRed_per_m, 0.14}};
    for (const Case& c : cases) {
        const double l = c.lambda_um;
        const double published = 0.008569 * std::pow(l, -4.0) * (1.0 + 0.0113 * std::pow(l, -2.0) + 0.00013 * std::pow(l, -4.0));
        // The column integral of the model's own profile, 0 to the top.
        double column = 0.0;
        const double dh = 10.0;
        for (double h = 0.5 * dh; h < swell::kAtmosphereTopRadius_m - kBottom_m; h += dh)
            column += swell::atmosphereAt(h, {}).rayleighScattering[l < 0.5 ? 2 : l < 0.6 ? 1 : 0] * dh;
        EXPECT_NEAR(column, c.beta_per_m * swell::kRayleighScaleHeight_m, 1.0e-3 * column);
        EXPECT_LT(relativeError(column, published), c.tolerance)
            << l * 1000.0 << " nm: model " << column << ", Hansen & Travis " << published;
    }
}

// Published reference: the CIE standard clear sky, type 12 (CIE S 011/E:2003,
// ISO 15469:2004): luminance relative to the zenith's,
// L / Lz = f(chi) phi(Z) / (f(Zs) phi(0)), phi(Z) = 1 + a exp(b / cos Z),
// f(chi) = 1 + c (exp(d chi) - exp(d pi / 2)) + e cos^2 chi, with a = -1,
// b = -0.32, c = 10, d = -3, e = 0.45 (Z: the point's zenith angle, Zs the
// sun's, chi the angle between them). The model's luminance is
// 0.2126 R + 0.7152 G + 0.0722 B of its radiance. It meets the standard
// within 10% high in the sky across from the sun (60 degrees up, 90 degrees
// in azimuth from it) for the sun 10 to 30 degrees up: +3%, +4%, +6%
// (measured). Elsewhere it does not (docs/RENDERING.md lists the figures):
// the clear air of Bruneton 2017 has less aerosol than the standard's
// clear sky, so its glow round the sun is weaker and its horizon brighter.
TEST(Atmosphere, RelativeLuminanceAgainstTheCieStandardClearSky)
{
    const Atmosphere& air = clearAir();
    auto luminance = [](glm::dvec3 c) { return 0.2126 * c.x + 0.7152 * c.y + 0.0722 * c.z; };
    auto cie = [](double zenithAngle, double chi, double sunZenithAngle) {
        auto phi = [](double z) { return 1.0 - std::exp(-0.32 / std::cos(z)); };
        auto f = [](double x) { return 1.0 + 10.0 * (std::exp(-3.0 * x) - std::exp(-3.0 * kPi / 2.0)) + 0.45 * std::cos(x) * std::cos(x); };
        return f(chi) * phi(zenithAngle) / (f(sunZenithAngle) * phi(0.0));
    };
    for (double sunElevation : {10.0, 20.0, 30.0}) {
        const glm::dvec3 sun = sunAt(sunElevation);
        const glm::dvec3 point = skyAt(60.0, 90.0);
        const double model = luminance(air.skyRadiance(point, sun)) / luminance(air.skyRadiance({0.0, 1.0, 0.0}, sun));
        const double chi = std::acos(glm::dot(point, sun));
        const double standard = cie(30.0 * kPi / 180.0, chi, (90.0 - sunElevation) * kPi / 180.0);
        EXPECT_LT(relativeError(model, standard), 0.10) << "sun " << sunElevation << " deg: model " << model << ", CIE " << standard;
    }
}

// Published reference: the colour of the clear sky, as chromaticity x, y,
// against Preetham, Shirley & Smits (1999, appendix A.2: the zenith's fits
// and the Perez distribution's coefficients for x and y) at turbidity 2,
// at the zenith and 5 degrees above the horizon 90 degrees in azimuth from
// the sun, for the sun 10 to 60 degrees up. The model's radiance at its
// three wavelengths becomes XYZ by Bruneton's (2016, sec. 14.3) conversion
// over the ASTM G-173 solar spectrum that Bruneton 2017 uses
// (published_sky.h). Within 10% everywhere; measured, x then y: zenith
// -4.7% -9.3% (sun 10), -2.7% -6.2% (20), -1.2% -3.7% (30), -2.2% -4.0%
// (45), -4.5% -6.8% (60); horizon -7.8% -7.7%, -7.5% -6.0%, -6.0% -3.8%,
// -5.7% -3.6%, -7.0% -5.7%: the model's sky is a little bluer than
// Preetham's hazier one. Air without its 440 nm Rayleigh scattering, or
// the channels swapped, is off by far more.
TEST(Atmosphere, ChromaticityAgainstPreetham1999)
{
    const Atmosphere& air = clearAir();
    for (double sunElevation : {10.0, 20.0, 30.0, 45.0, 60.0}) {
        const glm::dvec3 sun = sunAt(sunElevation);
        const double thetaSun = (90.0 - sunElevation) * kPi / 180.0;
        for (const glm::dvec3 view : {glm::dvec3(0.0, 1.0, 0.0), skyAt(5.0, 90.0)}) {
            const glm::dvec3 xyz = swell::test::skyXyz(air.skyRadiance(view, sun, 400));
            const double x = xyz.x / (xyz.x + xyz.y + xyz.z), y = xyz.y / (xyz.x + xyz.y + xyz.z);
            const swell::test::SkyColour reference =
                swell::test::preethamSky(std::acos(view.y), std::acos(glm::dot(view, sun)), thetaSun, 2.0);
            EXPECT_LT(relativeError(x, reference.x), 0.10)
                << "sun " << sunElevation << ", view elevation " << std::asin(view.y) * 180.0 / kPi << ": x " << x
                << ", Preetham " << reference.x;
            EXPECT_LT(relativeError(y, reference.y), 0.10)
                << "sun " << sunElevation << ", view elevation " << std::asin(view.y) * 180.0 / kPi << ": y " << y
                << ", Preetham " << reference.y;
        }
    }
}

// Published reference, out of reach: the absolute luminance of the clear
// sky from Preetham et al.'s (1999, appendix A.2) zenith fit and Perez
// distribution at turbidity 2: 2.46, 2.95, 3.49, 4.47, 5.89 kcd/m^2 at the
// zenith for the sun 10, 20, 30, 45, 60 degrees up, and 13.3 to 15.1 kcd/m^2
// 5 degrees above the horizon 90 degrees from the sun. The model reaches
// 0.67, 0.90, 1.07, 1.34, 1.66 kcd/m^2 at the zenith (27 to 31% of
// Preetham's) and 3.9 to 6.1 kcd/m^2 at that horizon (29 to 42%), by
// Bruneton's (2016) conversion with 683 lm/W and the CIE colour matching
// functions (published_sky.h; the solar spectrum there gives 132.6 klx
// above the atmosphere). That conversion is not what falls short: the
// sRGB weights times 133.3 klx, used before, give the same within
// 1.2% at the zenith and 2.8% at the horizon.
// The atmospheres differ: Preetham's turbidity 2 holds an aerosol optical
// depth of about 0.10 at 550 nm (their Angstrom beta = 0.04608 T - 0.04586
// with alpha 1.3), Bruneton 2017's clear air 0.005. With its aerosols
// raised to that depth (sky.mie_scale 18.9) the model reaches 34 to 67% at
// the zenith and 20 to 37% at the horizon (measured): Bruneton's aerosols
// scatter forward (g = 0.8) and absorb (albedo 0.9), so they dim the
// horizon away from the sun. The test holds the figures reached, at
// least 27% of Preetham's everywhere, so the sky cannot get dimmer unseen,
// and no more than 110%.
TEST(Atmosphere, AbsoluteLuminanceAgainstPreetham1999IsHeldWhereItIs)
{
    const Atmosphere& air = clearAir();
    for (double sunElevation : {10.0, 20.0, 30.0, 45.0, 60.0}) {
        const glm::dvec3 sun = sunAt(sunElevation);
        const double thetaSun = (90.0 - sunElevation) * kPi / 180.0;
        for (const glm::dvec3 view : {glm::dvec3(0.0, 1.0, 0.0), skyAt(5.0, 90.0)}) {
            const double luminance = swell::test::skyXyz(air.skyRadiance(view, sun, 400)).y;
            const double reference =
                swell::test::preethamSky(std::acos(view.y), std::acos(glm::dot(view, sun)), thetaSun, 2.0).luminance_cd_per_m2;
            EXPECT_GT(luminance / reference, 0.27) << "sun " << sunElevation << ", view " << view.y << ": " << luminance
                                                   << " cd/m2, Preetham " << reference;
            EXPECT_LT(luminance / reference, 1.10) << "sun " << sunElevation << ", view " << view.y;
        }
    }
}

// Published reference: the radiance of a Rayleigh sky from exact solutions
// of radiative transfer (published_sky.h: IPRT phase A's cases A1 and A2,
// Kokhanovsky et al. 2010's molecular layer), the sun 30 to 90 degrees up,
// views from the zenith to 10 degrees above the horizon, layers 0.1 to 0.5
// thick (the Earth's air is 0.26 at 440 nm, 0.11 at 550 nm). The model's
// air is made the benchmark's (modelRadiances). Within 10% everywhere;
// measured, model over published: A1 with the sun at the zenith 0.902 to
// 1.015, 30 degrees from it 0.938 to 1.048; A2 0.916 to 0.963 (lowest 10
// degrees up); Kokhanovsky et al. 0.928 to 1.047.
// The model differs from the benchmarks where it approximates: light
// scattered twice or more is estimated (Hillaire 2020, with the air's
// order-2 part; atmosphere.cpp), the molecules do not depolarise (0.03 in
// two of the cases), and the Earth is round where the benchmarks' layer is
// flat; and where it does not try to be the same: its radiance is scalar,
// the benchmarks' the intensity of the polarised equation. For A1 with the
// sun at the zenith the exact scalar radiance is itself 0.909 to 1.041 of
// the polarised (rayleigh_layer_transfer.h). Broken on purpose: without the
// multiple scattering the model reaches 0.34 to 0.70; with A2's ground black,
// 0.66 to 0.77 there; with an isotropic phase function for the air,
// 0.69 to 1.26.
// At the horizon and under a low sun (rayleighSkyHorizonAndLowSun) the
// model is further from the polarised tables, held within 17%: 1 degree
// above the horizon 0.921 to 0.967; the sun 11.5 degrees up (Natraj et al.)
// 0.841 to 1.094, lowest near the horizon towards and away from the sun
// and highest at the zenith. That is polarisation's pattern: the exact
// scalar radiance there is 0.882 to 1.108 of the polarised. Against the
// scalar (the next test) the model is within 8%.
TEST(Atmosphere, SkyRadianceAgainstExactRayleighTransfer)
{
    for (const swell::test::RayleighSkyCase& c : swell::test::rayleighSkyBenchmarks()) {
        const std::vector<double> ratios = rayleighSkyRatios(c);
        for (size_t i = 0; i < ratios.size(); ++i)
            EXPECT_LT(std::abs(ratios[i] - 1.0), 0.10)
                << c.source << ": sun " << c.rows[i].sunZenith_deg << ", view " << c.rows[i].viewZenith_deg << " at "
                << c.rows[i].azimuthFromSun_deg << " degrees from the sun: model / published " << ratios[i];
    }
}

TEST(Atmosphere, SkyRadianceAgainstExactRayleighTransferAtTheHorizonAndALowSun)
{
    for (const swell::test::RayleighSkyCase& c : swell::test::rayleighSkyHorizonAndLowSun()) {
        const std::vector<double> ratios = rayleighSkyRatios(c);
        for (size_t i = 0; i < ratios.size(); ++i)
            EXPECT_LT(std::abs(ratios[i] - 1.0), 0.17)
                << c.source << ": sun " << c.rows[i].sunZenith_deg << ", view " << c.rows[i].viewZenith_deg << " at "
                << c.rows[i].azimuthFromSun_deg << " degrees from the sun: model / published " << ratios[i];
    }
}

// The reference for a scalar model: the same layers' exact scalar radiance
// (rayleigh_layer_transfer.h), from the solver that reproduces the
// published polarised tables within 1% (RayleighLayerTransfer.*), with the
// polarisation left out. Every published case of a black ground and
// molecules that do not depolarise: IPRT A1 with the sun at the zenith,
// Kokhanovsky et al.'s layer from the zenith to 1 degree above the horizon,
// Natraj et al.'s sun 11.5 degrees up. The issue asks for 10%; the test
// holds 8%, which only the air's order-2 part of the multiple scattering
// reaches. Measured, model over scalar: A1 0.971 to 0.989; Kokhanovsky et
// al. 0.973 to 0.987, and 0.952 to 0.978 at 1 degree; Natraj et al. 0.923
// (5.7 degrees up, 90 degrees from the sun) to 1.002. Broken on purpose:
// Hillaire's isotropic estimate as published reaches 0.900 to 1.035; with
// the phase functions along the rays but no order-2 part, 0.911 to 1.041;
// without the multiple scattering, 0.34 to 0.72.
TEST(Atmosphere, SkyRadianceAgainstScalarRayleighTransfer)
{
    std::vector<swell::test::RayleighSkyCase> cases;
    for (const auto& set : {swell::test::rayleighSkyBenchmarks(), swell::test::rayleighSkyHorizonAndLowSun()})
        for (const swell::test::RayleighSkyCase& c : set)
            if (c.groundAlbedo == 0.0 && c.depolarisation == 0.0)
                cases.push_back(c);
    ASSERT_EQ(cases.size(), 4u);
    for (const swell::test::RayleighSkyCase& c : cases) {
        std::vector<swell::test::LayerView> views;
        for (const swell::test::RayleighSkyRow& row : c.rows) {
            ASSERT_EQ(row.sunZenith_deg, c.rows.front().sunZenith_deg);
            views.push_back({row.viewZenith_deg, row.azimuthFromSun_deg});
        }
        const std::vector<double> scalar =
            swell::test::rayleighLayerRadiance(c.opticalDepth, c.rows.front().sunZenith_deg, views, false, 400000);
        const std::vector<double> ratios = ratiosTo(c, scalar, "scalar");
        for (size_t i = 0; i < ratios.size(); ++i)
            EXPECT_LT(std::abs(ratios[i] - 1.0), 0.08)
                << c.source << ": sun " << c.rows[i].sunZenith_deg << ", view " << c.rows[i].viewZenith_deg << " at "
                << c.rows[i].azimuthFromSun_deg << " degrees from the sun: model / scalar " << ratios[i];
    }
}

} // namespace
