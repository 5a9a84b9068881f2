// Gerstner waves on the CPU, forward: dispersion, validation, the fold
// limit, the displacement and its derivatives. Everything works in double;
// phases are formed with exact products and reduced modulo 2*pi so that far
// from the world origin and late in time they stay accurate. The inverse
// (height under a world point) is gerstner_inverse.cpp, the fast sampler
// gerstner_sampler.cpp.
#include "ocean/gerstner/gerstner_terms.h"

#include "swell/coast_field.h"

#include <fmt/format.h>
#include <glm/common.hpp>
#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <limits>

namespace swell {

namespace gerstner {

// x reduced modulo 2*pi into [-pi, pi). The fma forms x - n*2pi exactly and
// rounds once, so the result is within a few 1e-16 rad of the true remainder
// of the double x, however large x is.
double wrapPi(double x)
{
    if (x >= -kPi && x < kPi)
        return x; // NaN fails this test and is returned below
    if (!std::isfinite(x))
        return x;
    // Adding and removing 1.5*2^52 rounds to the nearest integer inline, for
    // |x/2pi| < 2^51; the library call covers the rest.
    constexpr double kRound = 6755399441055744.0;
    const double turns = x * kInvTwoPi;
    const double n = std::abs(turns) < 2251799813685248.0 ? (turns + kRound) - kRound : std::nearbyint(turns);
    double r = std::fma(-n, kTwoPiHi, x);
    r = std::fma(-n, kTwoPiLo, r);
    // n came from a rounded quotient, so r can land just outside the range.
    if (r >= kPi)
        r = std::fma(-1.0, kTwoPiHi, r) - kTwoPiLo;
    else if (r < -kPi)
        r = (r + kTwoPiHi) + kTwoPiLo;
    return r;
}

// a*b modulo 2*pi, exact up to the final rounding: the product is split into
// hi + lo with an fma, and hi (which may be huge) is reduced on its own.
double productPhase(double a, double b)
{
    const double hi = a * b;
    const double lo = std::fma(a, b, -hi);
    return wrapPi(hi) + lo;
}

glm::dvec2 unitDirection(const Wave& wave)
{
    // Scaled first, so that no square overflows; cheaper than std::hypot.
    const double scale = std::max(std::abs(wave.direction.x), std::abs(wave.direction.y));
    const glm::dvec2 scaled = wave.direction / scale;
    return scaled / std::sqrt(glm::dot(scaled, scaled));
}

WaveTerms termsOf(const Wave& wave, double depth_m)
{
    WaveTerms t;
    t.d = unitDirection(wave);
    t.k = kTwoPi / wave.wavelength_m;
    t.kd = t.k * t.d;
    t.omega = angularFrequency(t.k, depth_m);
    return t;
}

// theta = kd.x*x + kd.z*z - omega*t + phase, wrapped, with every product exact.
double phaseAt(const WaveTerms& terms, double phase_rad, glm::dvec2 point_m, double time_s)
{
    const double sum = productPhase(terms.kd.x, point_m.x) + productPhase(terms.kd.y, point_m.y)
                     - productPhase(terms.omega, time_s) + wrapPi(phase_rad);
    return wrapPi(sum);
}

void accumulate(const Wave& wave, const WaveTerms& terms, double theta, Evaluation& e)
{
    const double s = std::sin(theta);
    const double c = std::cos(theta);
    const double a = wave.amplitude_m;
    const double qa = wave.steepness * a;
    e.displacement += glm::dvec3(-qa * terms.d.x * s, a * c, -qa * terms.d.y * s);
    const double ka = terms.k * a;
    const double qka = wave.steepness * ka;
    e.partials.alongX -= glm::dvec3(qka * terms.d.x * terms.d.x * c, ka * terms.d.x * s,
                                    qka * terms.d.x * terms.d.y * c);
    e.partials.alongZ -= glm::dvec3(qka * terms.d.x * terms.d.y * c, ka * terms.d.y * s,
                                    qka * terms.d.y * terms.d.y * c);
}

Evaluation evaluate(const WaveSet& set, glm::dvec2 restPoint_m, double time_s)
{
    Evaluation e;
    if (set.coast) {
        evaluateOverCoast(set, *set.coast, restPoint_m, time_s, e);
        return e;
    }
    for (const Wave& wave : set.waves) {
        const WaveTerms terms = termsOf(wave, set.depth_m);
        accumulate(wave, terms, phaseAt(terms, wave.phase_rad, restPoint_m, time_s), e);
    }
    return e;
}

void evaluateOverCoast(const WaveSet& set, const CoastField& coast, glm::dvec2 restPoint_m, double time_s,
                       Evaluation& e)
{
    const CoastCommonSample common = coast.commonAt(restPoint_m);
    for (std::size_t i = 0; i < set.waves.size(); ++i) {
        Wave wave = set.waves[i];
        WaveTerms terms = termsOf(wave, set.depth_m);
        double theta = phaseAt(terms, wave.phase_rad, restPoint_m, time_s);
        wave.steepness *= common.steepnessScale;
        if (const int layer = coast.layerOf(i); layer >= 0) {
            // The wave as the bottom has made it here: its phase, height,
            // direction and length (swell/coast_field.h).
            const CoastWaveSample local = coast.waveAt(layer, restPoint_m, terms.kd);
            theta = wrapPi(theta + local.phase_rad);
            wave.amplitude_m *= local.gain;
            const double k = std::sqrt(glm::dot(local.wavenumber_radpm, local.wavenumber_radpm));
            if (k > 0.0) {
                terms.k = k;
                terms.kd = local.wavenumber_radpm;
                terms.d = local.wavenumber_radpm / k;
            }
        } else {
            wave.amplitude_m *= common.gain;
        }
        accumulate(wave, terms, theta, e);
    }
}

} // namespace gerstner

using namespace gerstner;

glm::dvec2 wavenumberVector(const Wave& wave)
{
    return termsOf(wave, std::numeric_limits<double>::infinity()).kd;
}

double angularFrequency(double wavenumber_radpm, double depth_m)
{
    const double gk = kGravity * wavenumber_radpm;
    if (std::isinf(depth_m))
        return std::sqrt(gk);
    return std::sqrt(gk * std::tanh(wavenumber_radpm * depth_m));
}

WaveReach waveReach(const WaveSet& set)
{
    WaveReach reach;
    for (const Wave& w : set.waves) {
        reach.vertical_m += w.amplitude_m;
        reach.horizontal_m += w.steepness * w.amplitude_m;
    }
    // Shoaling raises a wave before it breaks.
    if (set.coast) {
        reach.vertical_m = std::max(reach.vertical_m, set.coast->reach().vertical_m);
        reach.horizontal_m = std::max(reach.horizontal_m, set.coast->reach().horizontal_m);
    }
    return reach;
}

double foldMeasure(const WaveSet& set)
{
    double sum = 0.0;
    for (const Wave& wave : set.waves)
        sum += wave.steepness * (kTwoPi / wave.wavelength_m) * wave.amplitude_m;
    return sum;
}

std::string validate(const WaveSet& set)
{
    if (set.waves.size() > SWELL_MAX_WAVES)
        return fmt::format("{} waves, at most {} (SWELL_MAX_WAVES) are supported", set.waves.size(),
                           SWELL_MAX_WAVES);
    if (!(set.depth_m > 0.0))
        return fmt::format("depth_m must be > 0 or infinity (got {})", set.depth_m);
    for (std::size_t i = 0; i < set.waves.size(); ++i) {
        const Wave& w = set.waves[i];
        const double length = std::hypot(w.direction.x, w.direction.y);
        if (!std::isfinite(length) || !(length > 0.0))
            return fmt::format("wave {}: direction must be finite and non-zero (got ({}, {}))", i,
                               w.direction.x, w.direction.y);
        if (!std::isfinite(w.wavelength_m))
            return fmt::format("wave {}: wavelength_m must be finite (got {})", i, w.wavelength_m);
        if (!(w.wavelength_m > 0.0))
            return fmt::format("wave {}: wavelength_m must be > 0 (got {})", i, w.wavelength_m);
        if (!std::isfinite(kTwoPi / w.wavelength_m))
            return fmt::format("wave {}: wavelength_m is too small, its wavenumber overflows (got {})", i,
                               w.wavelength_m);
        if (!std::isfinite(w.amplitude_m))
            return fmt::format("wave {}: amplitude_m must be finite (got {})", i, w.amplitude_m);
        if (!(w.amplitude_m >= 0.0))
            return fmt::format("wave {}: amplitude_m must be >= 0 (got {})", i, w.amplitude_m);
        if (!(w.steepness >= 0.0 && w.steepness <= 1.0))
            return fmt::format("wave {}: steepness must be in 0..1 (got {})", i, w.steepness);
        if (!std::isfinite(w.phase_rad))
            return fmt::format("wave {}: phase_rad must be finite (got {})", i, w.phase_rad);
    }
    return {};
}

std::string limitSteepness(WaveSet& set)
{
    const double measure = foldMeasure(set);
    if (std::isnan(measure))
        return "swell::limitSteepness(): the fold measure is NaN, left unchanged: " + validate(set);
    if (measure <= 1.0)
        return {};

    // Name the biggest contributors before scaling, as the user wrote them.
    std::vector<std::size_t> order(set.waves.size());
    for (std::size_t i = 0; i < order.size(); ++i)
        order[i] = i;
    auto contribution = [&](std::size_t i) {
        const Wave& w = set.waves[i];
        return w.steepness * (kTwoPi / w.wavelength_m) * w.amplitude_m;
    };
    std::stable_sort(order.begin(), order.end(),
                     [&](std::size_t a, std::size_t b) { return contribution(a) > contribution(b); });
    std::string names;
    for (std::size_t j = 0; j < std::min<std::size_t>(3, order.size()); ++j) {
        const Wave& w = set.waves[order[j]];
        names += fmt::format("{}wave {} (wavelength {:.4g} m, amplitude {:.4g} m, Q {:.3g})",
                             j == 0 ? "" : ", ", order[j], w.wavelength_m, w.amplitude_m, w.steepness);
    }

    // An infinite measure (amplitudes near the top of double) scales to 0.
    double scale = std::isinf(measure) ? 0.0 : 1.0 / measure;
    for (Wave& w : set.waves)
        w.steepness *= scale;
    // Rounding can leave the sum a hair above 1; nudge until it is not.
    for (int nudge = 0; nudge < 8 && foldMeasure(set) > 1.0; ++nudge) {
        for (Wave& w : set.waves)
            w.steepness *= 1.0 - 1e-15;
    }
    return fmt::format("swell::limitSteepness(): the waves would fold (sum of Q*k*A = {:.4g} > 1); "
                       "every steepness scaled by {:.4g}. Biggest contributors: {}",
                       measure, scale, names);
}

glm::dvec3 displacementAt(const WaveSet& set, glm::dvec2 restPoint_m, double time_s)
{
    return evaluate(set, restPoint_m, time_s).displacement;
}

SurfacePartials partialsAt(const WaveSet& set, glm::dvec2 restPoint_m, double time_s)
{
    return evaluate(set, restPoint_m, time_s).partials;
}

namespace {

glm::dvec3 normalOf(const SurfacePartials& p)
{
    glm::dvec3 n = glm::cross(p.alongZ, p.alongX);
    // Scale before normalising so that huge slopes do not overflow the square.
    const double largest = std::max({std::abs(n.x), std::abs(n.y), std::abs(n.z)});
    if (!(largest > 0.0) || !std::isfinite(largest))
        return {0.0, 1.0, 0.0};
    n /= largest;
    return n / std::sqrt(glm::dot(n, n));
}

} // namespace

glm::dvec3 normalAt(const WaveSet& set, glm::dvec2 restPoint_m, double time_s)
{
    return normalOf(partialsAt(set, restPoint_m, time_s));
}

double waveLodWeight(double wavelength_m, double footprint_m)
{
    if (!(footprint_m > 0.0))
        return 1.0;
    return glm::smoothstep(SWELL_MIN_CELLS_PER_WAVELENGTH * footprint_m, SWELL_FULL_CELLS_PER_WAVELENGTH * footprint_m,
                      wavelength_m);
}

WaveSet filteredWaves(const WaveSet& set, const SurfaceFilter& filter)
{
    WaveSet out = set;
    for (Wave& w : out.waves)
        w.amplitude_m *= filter.heightScale * waveLodWeight(w.wavelength_m, filter.footprint_m);
    return out;
}

SurfacePoint surfaceAt(const WaveSet& set, glm::dvec2 restPoint_m, double time_s, const SurfaceFilter& filter)
{
    const bool exact = filter.footprint_m <= 0.0 && filter.heightScale == 1.0;
    const Evaluation e = exact ? evaluate(set, restPoint_m, time_s) : evaluate(filteredWaves(set, filter), restPoint_m, time_s);
    return {e.displacement, normalOf(e.partials)};
}

double wrappedPhase(const Wave& wave, double depth_m, glm::dvec2 origin_m, double time_s)
{
    return phaseAt(termsOf(wave, depth_m), wave.phase_rad, origin_m, time_s);
}

} // namespace swell
