// Frequency spectra of the sea: JONSWAP with the TMA depth factor, its
// parameters from the wind and fetch (growth laws, stopping at the fully
// developed Pierson-Moskowitz sea), a swell's from its height and period, and
// the dispersion relation both need.
#include "swell/scene/spectrum.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>

#include "ocean/clamped_settings.h"

namespace swell {

namespace {


// Pierson & Moskowitz 1964, S = alpha*g^2*omega^-5*exp(-0.74*(g/(U19.5*omega))^4)
// with alpha = 8.1e-3; its peak is where dS/domega = 0, omega_p = (4*0.74/5)^(1/4)*g/U19.5
// = 0.877*g/U19.5 (Stewart 2008, eq. 16.30), so 0.74*(g/(U*omega))^4 = 1.25*(omega_p/omega)^4.
constexpr double kPmAlpha = 8.1e-3;
constexpr double kPmPeak = 0.877;

// JONSWAP growth laws (Hasselmann et al. 1973), chi = g*F/U10^2: the energy
// g^2*m0/U^4 = 1.6e-7*chi, i.e. g*Hs/U^2 = 4*sqrt(1.6e-7*chi) = 1.6e-3*sqrt(chi),
// and the peak frequency f_p = 3.5*(g/U)*chi^-0.33, i.e. omega_p = 2*pi*3.5 = 22
// times (g/U)*chi^(-1/3) in the usual rounding (as in the Shore Protection Manual 1984).
constexpr double kFetchHeight = 1.6e-3;
constexpr double kFetchPeak = 22.0;

// The JONSWAP shape with alpha = 1 and omega_p = 1, g = 1, at x = omega/omega_p:
// x^-5*exp(-1.25*x^-4)*gamma^r, r = exp(-(x-1)^2/(2*sigma^2)), sigma = 0.07
// below the peak and 0.09 above: the mean JONSWAP spectrum of Hasselmann et
// al. 1973 (Dtsch. Hydrogr. Z. Suppl. A8(12)).
double jonswapShape(double x, double gamma)
{
    const double sigma = x <= 1.0 ? 0.07 : 0.09;
    const double offPeak = (x - 1.0) / sigma;
    const double enhancement = gamma == 1.0 ? 1.0 : std::pow(gamma, std::exp(-0.5 * offPeak * offPeak));
    return std::pow(x, -5.0) * std::exp(-1.25 * std::pow(x, -4.0)) * enhancement;
}

// Integral of jonswapShape over x in (0, inf): 1/5 for gamma = 1 (exactly,
// since the integral of x^-5*exp(-1.25*x^-4) is 1/(4*1.25)). Simpson's rule in
// log(x) from 0.25 (where exp(-1.25*256) is 0 in double) to 40, where the
// rest, about 1/(4*40^4), is added in closed form. 4000 intervals put 20
// points across the peak's width of 0.07.
double jonswapShapeIntegral(double gamma)
{
    constexpr double kLow = 0.25, kHigh = 40.0;
    constexpr int kIntervals = 4000;
    const double step = std::log(kHigh / kLow) / kIntervals;
    double sum = 0.0;
    for (int i = 0; i <= kIntervals; ++i) {
        const double x = kLow * std::exp(step * i);
        const double weight = (i == 0 || i == kIntervals) ? 1.0 : (i % 2 == 1 ? 4.0 : 2.0);
        sum += weight * jonswapShape(x, gamma) * x; // dx = x d(log x)
    }
    return sum * step / 3.0 + 1.0 / (4.0 * std::pow(kHigh, 4.0));
}

} // namespace

double windSpeedAt19_5m(double windSpeed10_mps)
{
    // Near-neutral power law over the open sea, U(z) = U10*(z/10)^0.11 (Hsu,
    // Meindl & Gilhousen 1994, J. Appl. Meteor. 33): 19.5 m gives 1.0762*U10.
    // (Stewart 2008, eq. 16.29, has 1.026*U10 from a logarithmic profile with
    // drag coefficient 1.3e-3; the power law gives the fully developed
    // g*Hs/U10^2 = 0.243 of the Shore Protection Manual 1984.)
    return windSpeed10_mps * std::pow(19.5 / 10.0, 0.11);
}

SpectrumParameters piersonMoskowitzParameters(double windSpeed10_mps)
{
    SpectrumParameters p;
    p.alpha = kPmAlpha;
    p.peakFrequency_radps = kPmPeak * kGravity / windSpeedAt19_5m(windSpeed10_mps);
    p.gamma = 1.0;
    return p;
}

double dnvPeakEnhancement(double peakPeriod_s, double significantHeight_m)
{
    // DNV-RP-C205 (2010), sec. 3.5.5.5, with Tp in s and Hs in m. It gives 1
    // for a fully developed sea (Tp/sqrt(Hs) = 4.99 s/sqrt(m) there) and rises
    // for young, steep seas.
    if (!(significantHeight_m > 0.0))
        return 1.0;
    const double ratio = peakPeriod_s / std::sqrt(significantHeight_m);
    if (ratio <= 3.6)
        return 5.0;
    if (ratio < 5.0)
        return std::exp(5.75 - 1.15 * ratio);
    return 1.0;
}

double jonswapAlphaFor(double significantHeight_m, double peakFrequency_radps, double gamma)
{
    // m0 = alpha*g^2/omega_p^4 * integral of the shape, and m0 = (Hs/4)^2.
    const double m0 = significantHeight_m * significantHeight_m / 16.0;
    const double wp2 = peakFrequency_radps * peakFrequency_radps;
    return m0 * wp2 * wp2 / (kGravity * kGravity * jonswapShapeIntegral(gamma));
}

SpectrumParameters jonswapParameters(const WindSettings& wind)
{
    const WindSettings w = detail::clampedWind(wind, "swell::jonswapParameters()");
    const double u = w.windSpeed_mps;
    const double chi = kGravity * w.fetch_km * 1000.0 / (u * u);

    SpectrumParameters pm = piersonMoskowitzParameters(u);
    pm.depth_m = w.depth_m;
    const double pmPeak2 = pm.peakFrequency_radps * pm.peakFrequency_radps;
    const double pmHeight_m = 4.0 * std::sqrt(pm.alpha * kGravity * kGravity / (5.0 * pmPeak2 * pmPeak2));

    const double height_m = kFetchHeight * std::sqrt(chi) * u * u / kGravity;
    if (height_m >= pmHeight_m)
        return pm; // fully developed: more fetch adds nothing (chi >= ~23000, 230 km at 10 m/s)

    SpectrumParameters p;
    p.peakFrequency_radps = std::max(kFetchPeak * kGravity / u * std::cbrt(1.0 / chi), pm.peakFrequency_radps);
    p.gamma = dnvPeakEnhancement(2.0 * kPi / p.peakFrequency_radps, height_m);
    p.alpha = jonswapAlphaFor(height_m, p.peakFrequency_radps, p.gamma);
    p.depth_m = w.depth_m;
    return p;
}

SpectrumParameters swellParameters(const SwellSettings& swell, double depth_m)
{
    const SwellSettings s = detail::clampedSwell(swell, "swell::swellParameters()");
    if (!(depth_m > 0.0))
        throw std::invalid_argument("swell::swellParameters(): depth_m must be > 0 or infinity");
    SpectrumParameters p;
    p.peakFrequency_radps = 2.0 * kPi / s.period_s;
    p.gamma = s.gamma;
    p.alpha = jonswapAlphaFor(s.height_m, p.peakFrequency_radps, p.gamma);
    p.depth_m = depth_m;
    return p;
}

double wavenumberOf(double omega_radps, double depth_m)
{
    // The root of g*k*tanh(k*h) = omega^2, which increases with k. It lies
    // between the larger of the deep (omega^2/g) and shallow (omega/sqrt(g*h))
    // answers, both lower bounds, and omega^2/(g*tanh(kLow*h)); bisection to the last bit.
    const double deep = omega_radps * omega_radps / kGravity;
    if (std::isinf(depth_m) || !(omega_radps > 0.0))
        return deep;
    double low = std::max(deep, omega_radps / std::sqrt(kGravity * depth_m));
    double high = deep / std::tanh(low * depth_m);
    for (int i = 0; i < 200; ++i) {
        const double mid = 0.5 * (low + high);
        if (mid <= low || mid >= high)
            break;
        (angularFrequency(mid, depth_m) < omega_radps ? low : high) = mid;
    }
    return 0.5 * (low + high);
}

double groupVelocity(double wavenumber_radpm, double depth_m)
{
    // d(omega)/dk of omega^2 = g*k*tanh(k*h): g*(tanh(kh) + kh*sech^2(kh))/(2*omega).
    if (!(wavenumber_radpm > 0.0))
        return std::isinf(depth_m) ? std::numeric_limits<double>::infinity() : std::sqrt(kGravity * depth_m);
    if (std::isinf(depth_m))
        return 0.5 * std::sqrt(kGravity / wavenumber_radpm);
    const double kh = wavenumber_radpm * depth_m;
    const double sech = 1.0 / std::cosh(kh); // 0 for kh past ~710: deep water
    const double omega = angularFrequency(wavenumber_radpm, depth_m);
    return kGravity * (std::tanh(kh) + kh * sech * sech) / (2.0 * omega);
}

double tmaFactor(double omega_radps, double depth_m)
{
    // Kitaigorodskii, Krasitskii & Zaslavskii 1975, the factor of the TMA
    // spectrum (Bouws et al. 1985, J. Geophys. Res. 90(C1)): in the saturation range the
    // spectrum goes as k^-3*dk/domega, so depth scales the deep-water
    // spectrum by [k^-3 dk/domega](h) / [k^-3 dk/domega](inf)
    // = omega^5 / (2*g^2*k^3*c_g), with k and c_g at depth h.
    if (std::isinf(depth_m) || !(omega_radps > 0.0))
        return 1.0;
    const double k = wavenumberOf(omega_radps, depth_m);
    const double cg = groupVelocity(k, depth_m);
    const double w2 = omega_radps * omega_radps;
    return w2 * w2 * omega_radps / (2.0 * kGravity * kGravity * k * k * k * cg);
}

double spectralDensity(const SpectrumParameters& spectrum, double omega_radps)
{
    if (!(omega_radps > 0.0))
        return 0.0;
    const double wp = spectrum.peakFrequency_radps;
    const double wp2 = wp * wp;
    // S = alpha*g^2*omega^-5*exp(-1.25*(omega_p/omega)^4)*gamma^r (Hasselmann
    // et al. 1973) = alpha*g^2/omega_p^5 * shape(omega/omega_p).
    const double deep = spectrum.alpha * kGravity * kGravity / (wp2 * wp2 * wp) * jonswapShape(omega_radps / wp, spectrum.gamma);
    return deep * tmaFactor(omega_radps, spectrum.depth_m);
}

} // namespace swell
