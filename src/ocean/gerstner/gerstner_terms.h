// Internal to the Gerstner model: the exact per-wave terms and the phase
// arithmetic shared by the forward sum (gerstner_waves.cpp), its inverse
// (gerstner_inverse.cpp) and the fast sampler (gerstner_sampler.cpp).
#pragma once

#include "swell/constants.h"
#include "swell/scene/waves.h"

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

namespace swell::gerstner {

// 2*pi as an unevaluated sum hi + lo, so that n*2*pi for n up to 2^53 can be
// subtracted with an error far below one ulp of the remainder.
inline constexpr double kTwoPiHi = kTwoPi;
inline constexpr double kTwoPiLo = 2.4492935982947064e-16;
inline constexpr double kInvTwoPi = 1.0 / kTwoPi;

// x reduced modulo 2*pi into [-pi, pi). The fma forms x - n*2pi exactly and
// rounds once, so the result is within a few 1e-16 rad of the true remainder
// of the double x, however large x is.
double wrapPi(double x);

// a*b modulo 2*pi, exact up to the final rounding.
double productPhase(double a, double b);

// What every evaluation needs of one wave, derived once per call.
struct WaveTerms {
    glm::dvec2 d;  // unit direction
    double k;      // wavenumber, rad/m
    glm::dvec2 kd; // k*d, rad/m
    double omega;  // angular frequency, rad/s
};

glm::dvec2 unitDirection(const Wave& wave);
WaveTerms termsOf(const Wave& wave, double depth_m);

// theta = kd.x*x + kd.z*z - omega*t + phase, wrapped, with every product exact.
double phaseAt(const WaveTerms& terms, double phase_rad, glm::dvec2 point_m, double time_s);

// The sum of all waves and its rest-space derivatives at one rest point.
struct Evaluation {
    glm::dvec3 displacement{0.0};
    SurfacePartials partials;
};

void accumulate(const Wave& wave, const WaveTerms& terms, double theta, Evaluation& e);
Evaluation evaluate(const WaveSet& set, glm::dvec2 restPoint_m, double time_s);
// The sum over a coast field (swell/coast_field.h): each coast wave with the
// phase, gain and wavenumber the field gives it at the rest point, the others
// with its common gain, every steepness times its steepness scale.
void evaluateOverCoast(const WaveSet& set, const CoastField& coast, glm::dvec2 restPoint_m, double time_s,
                       Evaluation& e);

} // namespace swell::gerstner
