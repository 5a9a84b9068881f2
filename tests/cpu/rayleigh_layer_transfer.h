// A reference solver for the physical sky's tests: the radiance of the sky
// seen from under a plane-parallel layer of air that scatters by Rayleigh's
// law and absorbs nothing, over a black ground, lit by the sun at the top.
//
// Why the tests need it: the published exact solutions (published_sky.h)
// solve the polarised equation of transfer, and the model (swell/scene/atmosphere.h)
// is scalar, like every real-time sky. For the same Rayleigh layer the two
// differ by up to about 10% at a low sun (Mishchenko, Lacis & Travis 1994,
// JQSRT 51, 491). This solver does both: polarised, it must reproduce the
// published tables, which checks its geometry, normalisation and sampling;
// with the one switch turned, it gives the scalar radiance the model is
// meant to approximate.
//
// The method: forward Monte Carlo with the local estimate (Marchuk et al.
// 1980, "The Monte Carlo Methods in Atmospheric Optics", ch. 2; the
// polarised form with Stokes vectors rotated into each scattering plane, as
// in Hovenier, van der Mee & Domke 2004, "Transfer of Polarized Light in
// Planetary Atmospheres", sec. 2.4 and 3.2). Deterministic for a seed.
#pragma once

#include <cstdint>
#include <vector>

namespace swell::test {

struct LayerView {
    double viewZenith_deg;     // from the zenith, looking up (0..90)
    double azimuthFromSun_deg; // 0: towards the sun
};

// The radiance at the ground along each view, per unit of the sun's
// irradiance on a plane normal to its rays (1/sr): the same unit as
// published_sky.h's rows. Its relative standard error is about
// 1 / sqrt(photons) times a few.
std::vector<double> rayleighLayerRadiance(double opticalDepth, double sunZenith_deg, const std::vector<LayerView>& views,
                                          bool polarised, long photons, std::uint64_t seed = 1);

} // namespace swell::test
