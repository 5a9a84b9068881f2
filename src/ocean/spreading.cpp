// Directional spreading D(theta; omega): how a component's energy at one
// frequency is shared among directions. Each form is normalised in closed
// form over the full circle, and numerically when it is cut narrower.
#include "swell/scene/spectrum.h"

#include <cmath>
#include <numbers>

namespace swell {

namespace {


// theta wrapped into (-pi, pi].
double wrapAngle(double theta_rad)
{
    double t = std::remainder(theta_rad, 2.0 * kPi);
    return t <= -kPi ? t + 2.0 * kPi : t;
}

// The uncut D at |theta| <= pi, normalised over (-pi, pi].
double fullCircleDensity(const Spreading& spreading, double omega_radps, double theta_rad)
{
    if (spreading.swellPeakExponent > 0.0 || spreading.model == SpreadingModel::Mitsuyasu) {
        // Mitsuyasu et al. 1975: D = Q(s)*cos^2s(theta/2). Its integral over
        // the circle is 2*sqrt(pi)*Gamma(s+1/2)/Gamma(s+1), so
        // Q(s) = Gamma(s+1)/(2*sqrt(pi)*Gamma(s+1/2)).
        const double s = spreadingExponent(spreading, omega_radps);
        const double q = std::exp(std::lgamma(s + 1.0) - std::lgamma(s + 0.5)) / (2.0 * std::sqrt(kPi));
        return q * std::pow(std::abs(std::cos(0.5 * theta_rad)), 2.0 * s);
    }
    // Donelan et al. 1985: D = beta/2 * sech^2(beta*theta) on the whole line;
    // on the circle the integral of sech^2(beta*theta) is 2*tanh(beta*pi)/beta.
    const double beta = donelanBannerBeta(omega_radps / spreading.peakFrequency_radps);
    const double sech = 1.0 / std::cosh(beta * theta_rad);
    return beta / (2.0 * std::tanh(beta * kPi)) * sech * sech;
}

// The integral of the uncut D over [-cut, cut]: Simpson's rule on [0, cut]
// (D is even), 128 intervals, enough for the narrowest swell (s = 200, a
// width of about 0.1 rad) over any cut.
double massInside(const Spreading& spreading, double omega_radps, double cut_rad)
{
    constexpr int kIntervals = 128;
    const double h = cut_rad / kIntervals;
    double sum = fullCircleDensity(spreading, omega_radps, 0.0) + fullCircleDensity(spreading, omega_radps, cut_rad);
    for (int i = 1; i < kIntervals; ++i)
        sum += (i % 2 == 1 ? 4.0 : 2.0) * fullCircleDensity(spreading, omega_radps, i * h);
    return 2.0 * sum * h / 3.0;
}

} // namespace

double spreadingExponent(const Spreading& spreading, double omega_radps)
{
    const double ratio = omega_radps / spreading.peakFrequency_radps;
    if (spreading.swellPeakExponent > 0.0) {
        // Mitsuyasu et al. 1975 (J. Phys. Oceanogr. 5): s = s_max*(f/f_p)^5 up
        // to the peak and s_max*(f/f_p)^-2.5 above; s_max for swell after
        // Goda & Suzuki 1975 (Goda 1985: 25 for swell from nearby, 75 from afar).
        return spreading.swellPeakExponent * (ratio <= 1.0 ? std::pow(ratio, 5.0) : std::pow(ratio, -2.5));
    }
    // Hasselmann, Dunckel & Ewing 1980 (J. Phys. Oceanogr. 10), the JONSWAP
    // fit: s = 6.97*(f/f_m)^4.06 below 1.05*f_m, and above it
    // s = 9.77*(f/f_m)^mu with mu = -2.33 - 1.45*(U/c_m - 1.17), c_m the phase
    // speed at the peak: the younger the sea, the faster it widens.
    if (ratio < 1.05)
        return 6.97 * std::pow(ratio, 4.06);
    const double mu = -2.33 - 1.45 * (spreading.windOverPeakSpeed - 1.17);
    return 9.77 * std::pow(ratio, mu);
}

double donelanBannerBeta(double omegaOverPeak)
{
    // Donelan, Hamilton & Hui 1985 (Phil. Trans. R. Soc. A 315), their fit of beta:
    // beta = 2.61*r^1.3 for 0.56 < r < 0.95, 2.28*r^-1.3 for 0.95 <= r < 1.6,
    // and 1.24 outside; above 1.6 Banner 1990 (J. Phys. Oceanogr. 20) measured
    // beta = 10^(-0.4 + 0.8393*exp(-0.567*ln(r^2))), which joins at 1.6.
    const double r = omegaOverPeak;
    if (r >= 1.6)
        return std::pow(10.0, -0.4 + 0.8393 * std::exp(-0.567 * std::log(r * r)));
    if (r >= 0.95)
        return 2.28 * std::pow(r, -1.3);
    if (r > 0.56)
        return 2.61 * std::pow(r, 1.3);
    return 1.24;
}

double spreadingDensity(const Spreading& spreading, double omega_radps, double theta_rad)
{
    if (!(spreading.cut_rad > 0.0) || !(omega_radps > 0.0))
        return 0.0; // all energy on one line: no density
    const double theta = wrapAngle(theta_rad);
    if (std::abs(theta) > spreading.cut_rad)
        return 0.0;
    const double density = fullCircleDensity(spreading, omega_radps, theta);
    if (spreading.cut_rad >= kPi)
        return density;
    return density / massInside(spreading, omega_radps, spreading.cut_rad);
}

} // namespace swell
