// The wake's modal step (objects/wake_field.h, WakeModes::turn), which
// turns each pair of modes k and -k once, against the plain formula turning
// every mode on its own (Tessendorf 2004, "Interactive Water Surfaces",
// eq. 3 solved over the step): the same numbers on a random spectrum, so
// no pair is missed, turned twice or given its mirror's wrong conjugate.
#include "objects/wake_field.h"

#include <gtest/gtest.h>

#include <complex>
#include <random>
#include <vector>

namespace {

using swell::detail::WakeFieldSettings;
using swell::detail::WakeModes;

// Every mode on its own: E^ and phi^ from C(k) and conj C(-k), turned, recombined.
std::vector<std::complex<float>> turnEachMode(const WakeModes& modes, const std::vector<std::complex<float>>& spectrum, float norm)
{
    const int n = modes.cells;
    std::vector<std::complex<float>> turned(spectrum.size());
    for (int q = 0; q < n; ++q)
        for (int p = 0; p < n; ++p) {
            const std::size_t m = std::size_t(p) + std::size_t(q) * n;
            const std::size_t mirror = std::size_t((n - p) % n) + std::size_t((n - q) % n) * n;
            const std::complex<float> c = spectrum[m], cm = std::conj(spectrum[mirror]);
            const std::complex<float> e = 0.5f * (c + cm);
            const std::complex<float> phi = std::complex<float>(0.0f, -0.5f) * (c - cm);
            const float cs = modes.cosStep[m], sn = modes.sinStep[m];
            const std::complex<float> e1 = e * cs + phi * (modes.kOverOmega[m] * sn);
            const std::complex<float> phi1 = m == 0 ? std::complex<float>(0.0f) : phi * cs - e * (modes.gOverOmega[m] * sn);
            turned[m] = norm * (e1 + std::complex<float>(0.0f, 1.0f) * phi1);
        }
    return turned;
}

TEST(WakeModes, PairsTurnAsEachModeOnItsOwn)
{
    WakeFieldSettings shallowAtOneSpeed;
    shallowAtOneSpeed.cells = 64;
    shallowAtOneSpeed.cellSize_m = 0.5;
    shallowAtOneSpeed.depth_m = 3.0;
    shallowAtOneSpeed.dispersive = false;
    for (const WakeFieldSettings& settings : {WakeFieldSettings{}, shallowAtOneSpeed}) {
        SCOPED_TRACE(testing::Message() << settings.cells << " cells");
        const WakeModes modes(settings);
        const int n = modes.cells;
        ASSERT_EQ(n, settings.cells);
        std::mt19937 rng(7);
        std::uniform_real_distribution<float> value(-1.0f, 1.0f);
        std::vector<std::complex<float>> spectrum(std::size_t(n) * n);
        for (auto& c : spectrum)
            c = {value(rng), value(rng)};
        const float norm = 1.0f / float(n) / float(n);
        const std::vector<std::complex<float>> expected = turnEachMode(modes, spectrum, norm);
        // Stale numbers where a mode is missed.
        std::vector<std::complex<float>> got(spectrum.size(), {1e3f, -1e3f});
        modes.turn(spectrum.data(), norm, got.data());
        int wrong = 0;
        for (std::size_t m = 0; m < got.size(); ++m)
            // The same floats (a zero's sign aside: the products differ only in that).
            if (!(got[m].real() == expected[m].real() && got[m].imag() == expected[m].imag()) && ++wrong <= 5)
                ADD_FAILURE() << "mode " << m % n << ", " << m / n << ": " << got[m] << " against " << expected[m];
        EXPECT_EQ(wrong, 0);
        // ...and the modes did turn: the step is not the identity.
        EXPECT_NE(expected[std::size_t(3) + std::size_t(5) * n], norm * spectrum[std::size_t(3) + std::size_t(5) * n]);
    }
}

} // namespace
