// The wake's Fourier modes and their turn over a step (wake_field.h).
#include "objects/wake_field.h"

#include "swell/constants.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace swell::detail {

namespace {

constexpr double kSlowestWake_rad_per_s = 1e-9;

} // namespace

int fastWakeCells(int cells)
{
    const auto fast = [](int n) {
        for (int p : {2, 3, 5})
            while (n > 1 && n % p == 0)
                n /= p;
        return n == 1;
    };
    int n = std::max(cells, 1);
    while (!fast(n))
        ++n;
    return n;
}

WakeModes::WakeModes(const WakeFieldSettings& settings)
{
    const int n = settings.cells;
    const std::size_t count = std::size_t(n) * std::size_t(n);
    cells = n;
    cosStep.resize(count);
    sinStep.resize(count);
    kOverOmega.resize(count);
    gOverOmega.resize(count);
    const double dk = 2.0 * std::numbers::pi / (n * settings.cellSize_m);
    for (int q = 0; q < n; ++q)
        for (int p = 0; p < n; ++p) {
            const double kx = dk * (p < n / 2 ? p : p - n), kz = dk * (q < n / 2 ? q : q - n);
            const double k = std::hypot(kx, kz);
            // Linear waves over depth d: omega^2 = g k tanh(k d) (Lamb 1932,
            // sec. 228); the dispersion-free stand-in: omega = c k.
            const double bigK = k > 0.0 ? k * std::tanh(k * settings.depth_m) : 0.0; // tanh(inf) = 1: deep water
            const double exact = settings.dispersive ? std::sqrt(kGravity * bigK) : settings.dispersionFreeSpeed_m_per_s * k;
            // In water so shallow that a mode hardly turns (a depth of 1e-300
            // m: omega ~ 1e-150), g / omega overflows a float and sin(omega
            // dt) underflows to 0, and their product, which tends to g dt,
            // came out NaN. Below kSlowestWake_rad_per_s (a period of two
            // centuries) the mode turns at that: the products are then their
            // limits, K dt and g dt, to float precision; faster modes as they are.
            const double omega = exact > 0.0 ? std::max(exact, kSlowestWake_rad_per_s) : 0.0;
            const std::size_t m = std::size_t(p) + std::size_t(q) * n;
            cosStep[m] = float(std::cos(omega * kWakeStep_s));
            sinStep[m] = float(std::sin(omega * kWakeStep_s));
            // The plain wave equation keeps d(phi)/dt = -g eta, so its K is omega^2 / g.
            const double kUsed = settings.dispersive ? bigK : omega * omega / kGravity;
            kOverOmega[m] = omega > 0.0 ? float(kUsed / omega) : 0.0f;
            gOverOmega[m] = omega > 0.0 ? float(kGravity / omega) : 0.0f;
        }
}

void WakeModes::turn(const std::complex<float>* spectrum, float norm, std::complex<float>* turned) const
{
    const int n = cells;
    // C = F(E + i phi): E^ = (C(k) + conj C(-k)) / 2, phi^ = (C(k) - conj C(-k)) / 2i.
    // Each mode turns as a free oscillator: E' = E cos + (K/w) phi sin,
    // phi' = phi cos - (g/w) E sin (Tessendorf 2004, eq. 3 solved over dt).
    // `norm` (1 / n^2 for the unnormalised inverse transform) goes in here too.
    // E and phi are real, so mode -k holds the conjugates of mode k's E^ and
    // phi^, and turns at the same frequency: each pair is turned once, the
    // mirror taking the conjugates (what a turn of its own gives). Written
    // out in reals: std::complex's product would check every result for NaN.
    auto turn = [&](std::size_t m, std::size_t mirror) {
        const std::complex<float> c = spectrum[m], cm = spectrum[mirror];
        // c + conj(cm) and c - conj(cm).
        const float sumRe = c.real() + cm.real(), sumIm = c.imag() - cm.imag();
        const float difRe = c.real() - cm.real(), difIm = c.imag() + cm.imag();
        const float eRe = 0.5f * sumRe, eIm = 0.5f * sumIm;       // E^ = (c + conj cm) / 2
        const float phiRe = 0.5f * difIm, phiIm = -0.5f * difRe;  // phi^ = (c - conj cm) / 2i
        const float cs = cosStep[m], sn = sinStep[m];
        const float toE = kOverOmega[m] * sn, toPhi = gOverOmega[m] * sn;
        const float e1Re = eRe * cs + phiRe * toE, e1Im = eIm * cs + phiIm * toE;
        // The mean potential has no effect on the waves; it is kept at 0.
        const float phi1Re = m == 0 ? 0.0f : phiRe * cs - eRe * toPhi;
        const float phi1Im = m == 0 ? 0.0f : phiIm * cs - eIm * toPhi;
        // E' + i phi' here, conj(E') + i conj(phi') at the mirror; the
        // mirror first, so a mode that is its own mirror keeps its own.
        turned[mirror] = {norm * (e1Re + phi1Im), norm * (phi1Re - e1Im)};
        turned[m] = {norm * (e1Re - phi1Im), norm * (e1Im + phi1Re)};
    };
    for (int q = 0; q <= n / 2; ++q) {
        const std::size_t row = std::size_t(q) * n, mirrorRow = std::size_t((n - q) % n) * n;
        // Rows 0 and n/2 are their own mirrors: half of each pairs with the other half.
        const int pLast = row == mirrorRow ? n / 2 : n - 1;
        turn(row, mirrorRow);
        for (int p = 1; p <= pLast; ++p)
            turn(row + std::size_t(p), mirrorRow + std::size_t(n - p));
    }
}

} // namespace swell::detail
