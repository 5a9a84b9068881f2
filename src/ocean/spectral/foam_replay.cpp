#include "ocean/spectral/foam_replay.h"

#include "ocean/spectral/spectral_warp.h"
#include "swell/constants.h"

#include <kiss_fftnd.h>

#include <algorithm>
#include <cmath>
#include <cstring>

namespace swell::spectral {

// One packed transform carries both folding cascades' dDx/dz.
static_assert(kFoamCascades == 2);
static_assert(sizeof(kiss_fft_cpx) == sizeof(std::complex<float>));

namespace {

// A foam value as llvmpipe stores it in the R16F texture: rounded toward
// zero to a half (measured: rounding to nearest instead left this replay's
// foam above the GPU's by up to 0.002, its mean by 0.0004, after 20 steps;
// toward zero, within one half's step of it, the mean 1e-6). The foam is
// 0..1, so no half overflows.
float toHalfTowardZero(float v)
{
    constexpr float kSmallestNormalHalf = 6.103515625e-05f; // 2^-14
    if (v < kSmallestNormalHalf) // a subnormal half: a multiple of 2^-24
        return std::ldexp(std::floor(std::ldexp(v, 24)), -24);
    std::uint32_t bits;
    std::memcpy(&bits, &v, sizeof bits);
    bits &= 0xffffe000u; // a half keeps 10 of the float's 23 mantissa bits
    std::memcpy(&v, &bits, sizeof bits);
    return v;
}

// How much higher than computed this replay takes each breaking score: the
// GPU's steps compute J from other transforms (and llvmpipe's float
// arithmetic), and a still must show no foam a sequence of the GPU's steps
// would not. Their J's agree within one half's step (1.5e-5; measured over
// one step's 131072 texels at three times of the storm); a score divides
// the differences of a box's J by its deviation, so it moves by up to
// about 3 * 1.5e-5 / 0.05 = 0.001 where a box breaks (deviations of 0.05
// and more; a glassier box scores near 0, far above the ramp). The margin
// is three times that and takes 0.003 / kBreakingSpan = 0.02 off a
// texel's new foam: 0.01 took so much that the still's cover fell short of
// the sequence's by more than the first frame's carried foam allows
// (Whitecaps.AStillShowsTheFoamItsHistoryMade: 0.0048 against 0.0045).
constexpr float kScoreMargin = 0.003f;

} // namespace

FoamReplay::FoamReplay(std::shared_ptr<const SpectralField> field, const BreakingRamps& ramps)
    : field_(std::move(field)), ramps_(ramps)
{
    const int dims[2] = {kSize, kSize};
    fft_ = kiss_fftnd_alloc(dims, 2, 1, nullptr, nullptr);
    const size_t n = size_t(kSize) * kSize;
    const float lambda = float(field_->choppiness);
    // As evolve() in spectral_field.cpp: the derivatives of the horizontal
    // displacement i lambda k/|k| h are -lambda k_a k_b / |k| h.
    for (int c = 0; c < kFoamCascades; ++c) {
        const double dk = kTwoPi / field_->cascades[size_t(c)].patch_m;
        cxx_[size_t(c)].assign(n, 0.0f);
        czz_[size_t(c)].assign(n, 0.0f);
        cxz_[size_t(c)].assign(n, 0.0f);
        for (int row = 0; row < kSize; ++row)
            for (int col = 0; col < kSize; ++col) {
                const size_t s = size_t(row) * kSize + size_t(col);
                if (field_->omega_radps[size_t(c)][s] == 0.0)
                    continue;
                const float kx = float(dk * frequencyOf(col)), kz = float(dk * frequencyOf(row));
                const float k = std::sqrt(kx * kx + kz * kz);
                cxx_[size_t(c)][s] = -(lambda * kx * kx / k);
                czz_[size_t(c)][s] = -(lambda * kz * kz / k);
                cxz_[size_t(c)][s] = -(lambda * kx * kz / k);
            }
        phasor_[size_t(c)].assign(n, {});
        alongSpectrum_[size_t(c)].assign(n, {});
        along_[size_t(c)].assign(n, {});
    }
    crossSpectrum_.assign(n, {});
    cross_.assign(n, {});
    for (auto& f : foam_)
        f.assign(size_t(kFoamSize) * kFoamSize, 0.0f);
    jacobian_.assign(size_t(kSpan) * kSpan * kFoamLevels, 0.0f);
    score_.assign(size_t(kMadeSpan) * kMadeSpan, 0.0f);
    lowest_.assign(size_t(kFoamSize) * kFoamSize, 0.0f);
}

FoamReplay::~FoamReplay() { kiss_fft_free(fft_); }

void FoamReplay::placeTaps(glm::dvec2 gridCenter_m, const std::array<FoamWindow, kFoamLevels>& windows)
{
    const size_t texels = size_t(kSpan) * kSpan;
    for (auto& t : taps_)
        t.resize(texels * kFoamLevels);
    for (int level = 0; level < kFoamLevels; ++level) {
        const FoamWindow& w = windows[size_t(level)];
        const double texel_m = foamTexel_m(*field_, level);
        for (int y = 0; y < kSpan; ++y)
            for (int x = 0; x < kSpan; ++x) {
                // The world texel of the span, as the shader finds its tile's.
                const glm::ivec2 world = w.origin + glm::ivec2(x, y) - kMargin;
                const glm::dvec2 restOffset_m =
                    (glm::dvec2(world - w.centreIndex) + 0.5 - glm::dvec2(w.centreFraction)) * texel_m;
                const glm::dvec2 point_m = gridCenter_m + restOffset_m;
                const size_t texel = size_t(level) * texels + size_t(y) * kSpan + size_t(x);
                for (int c = 0; c < kFoamCascades; ++c) {
                    const WarpSample warp = warpAt(field_->warps[size_t(c)], point_m);
                    const double scale = kSize / field_->cascades[size_t(c)].patch_m;
                    const glm::dvec2 s = (point_m + warp.offset_m) * scale;
                    const double x0 = std::floor(s.x), z0 = std::floor(s.y);
                    auto wrap = [](double v) { return std::uint32_t(v - kSize * std::floor(v / kSize)); };
                    const std::uint32_t c0 = wrap(x0), c1 = (c0 + 1) % kSize, r0 = wrap(z0), r1 = (r0 + 1) % kSize;
                    Tap& t = taps_[size_t(c)][texel];
                    t.i00 = r0 * kSize + c0;
                    t.i01 = r0 * kSize + c1;
                    t.i10 = r1 * kSize + c0;
                    t.i11 = r1 * kSize + c1;
                    t.fx = float(s.x - x0);
                    t.fz = float(s.y - z0);
                    t.j00 = float(warp.jacobian[0].x);
                    t.j01 = float(warp.jacobian[0].y);
                    t.j10 = float(warp.jacobian[1].x);
                    t.j11 = float(warp.jacobian[1].y);
                }
            }
    }
}

void FoamReplay::evolveTo(double time_s)
{
    const size_t n = size_t(kSize) * kSize;
    // exp(i w t) for every sample: from its phase (reduced in double, as
    // evolve() and the GPU reduce it) at the first step, then turned by
    // exp(i w dt) in double at each next (the replay's steps are equal, so
    // one rotation serves them all; a double's rounding over hundreds of
    // turns stays far below a float's).
    const bool fresh = !phasorSet_;
    const double dt_s = time_s - phasorTime_s_;
    for (int c = 0; c < kFoamCascades; ++c) {
        const auto& omega = field_->omega_radps[size_t(c)];
        auto& phasor = phasor_[size_t(c)];
        if (fresh) {
            for (size_t s = 0; s < n; ++s) {
                const double phase = std::fmod(omega[s] * time_s, kTwoPi);
                phasor[s] = {std::cos(phase), std::sin(phase)};
            }
        } else if (dt_s != 0.0) {
            if (dt_s != lastStep_s_ || rotation_[size_t(c)].empty()) {
                rotation_[size_t(c)].resize(n);
                for (size_t s = 0; s < n; ++s)
                    rotation_[size_t(c)][s] = std::polar(1.0, std::fmod(omega[s] * dt_s, kTwoPi));
            }
            for (size_t s = 0; s < n; ++s)
                phasor[s] *= rotation_[size_t(c)][s];
        }
    }
    if (!fresh)
        lastStep_s_ = dt_s;
    phasorSet_ = true;
    phasorTime_s_ = time_s;

    using C = std::complex<float>;
    for (int c = 0; c < kFoamCascades; ++c) {
        const auto& h0 = field_->h0[size_t(c)];
        const auto& h0mc = field_->h0MinusConj[size_t(c)];
        const auto& phasor = phasor_[size_t(c)];
        const auto& cxx = cxx_[size_t(c)];
        const auto& czz = czz_[size_t(c)];
        const auto& cxz = cxz_[size_t(c)];
        auto& along = alongSpectrum_[size_t(c)];
        for (size_t s = 0; s < n; ++s) {
            const C e(float(phasor[s].real()), float(phasor[s].imag()));
            // hhat = h0 exp(-i w t) + conj(h0(-k)) exp(i w t); the
            // coefficients are 0 where w is (the mean).
            const C h = h0[s] * std::conj(e) + h0mc[s] * e;
            along[s] = C(cxx[s] * h.real() - czz[s] * h.imag(), cxx[s] * h.imag() + czz[s] * h.real());
            const C xz = cxz[s] * h;
            // Cascade 0's dDx/dz as the real part, cascade 1's as the imaginary.
            crossSpectrum_[s] = c == 0 ? xz : crossSpectrum_[s] + C(-xz.imag(), xz.real());
        }
    }
    auto inverse = [this](const std::vector<C>& in, std::vector<C>& out) {
        kiss_fftnd(static_cast<kiss_fftnd_cfg>(fft_), reinterpret_cast<const kiss_fft_cpx*>(in.data()),
                   reinterpret_cast<kiss_fft_cpx*>(out.data()));
    };
    for (int c = 0; c < kFoamCascades; ++c)
        inverse(alongSpectrum_[size_t(c)], along_[size_t(c)]);
    inverse(crossSpectrum_, cross_);
}

float FoamReplay::jacobianAt(size_t texel) const
{
    // As foldJacobian() in shaders/ocean/spectral.glsl.
    float gxx = 0.0f, gxz = 0.0f, gzx = 0.0f, gzz = 0.0f; // d Dx/dx, dDx/dz, dDz/dx, dDz/dz at the rest point
    for (int c = 0; c < kFoamCascades; ++c) {
        const Tap& t = taps_[size_t(c)][texel];
        const auto& a = along_[size_t(c)];
        auto bilinear = [&t](auto v00, auto v01, auto v10, auto v11) {
            const auto top = v00 + (v01 - v00) * t.fx;
            const auto bottom = v10 + (v11 - v10) * t.fx;
            return top + (bottom - top) * t.fz;
        };
        const std::complex<float> d = bilinear(a[t.i00], a[t.i01], a[t.i10], a[t.i11]);
        const std::complex<float> x = bilinear(cross_[t.i00], cross_[t.i01], cross_[t.i10], cross_[t.i11]);
        const float dxx = d.real(), dzz = d.imag(), dxz = c == 0 ? x.real() : x.imag();
        // In the patch: grad Dx = (dxx, dxz), grad Dz = (dxz, dzz); at the
        // rest point through the warp: d/dx_j = grad . jacobian[j].
        gxx += dxx * t.j00 + dxz * t.j01;
        gxz += dxx * t.j10 + dxz * t.j11;
        gzx += dxz * t.j00 + dzz * t.j01;
        gzz += dxz * t.j10 + dzz * t.j11;
    }
    return (1.0f + gxx) * (1.0f + gzz) - gxz * gzx;
}

size_t FoamReplay::spanIndexOf(int level, int x, int z) const
{
    // The world texel a stored texel holds, from its window's origin.
    const glm::ivec2 fromOrigin = (glm::ivec2(x, z) - windows_[size_t(level)].origin) & (kFoamSize - 1);
    return size_t(level) * kSpan * kSpan + size_t(fromOrigin.y + kBreakingSpread) * kSpan +
           size_t(fromOrigin.x + kBreakingSpread);
}

void FoamReplay::lowestScoresOf(int level, float* lowest)
{
    // The score of each texel of the span's inner part: the box whose
    // first texel is scored texel m's index in the span is m's.
    const float* jacobian = &jacobian_[size_t(level) * kSpan * kSpan];
    for (int z = 0; z < kMadeSpan; ++z)
        for (int x = 0; x < kMadeSpan; ++x)
            score_[size_t(z) * kMadeSpan + size_t(x)] = breakingScore(&jacobian[size_t(z) * kSpan + size_t(x)], kSpan);
    const int spread = breakingSpreadAt(level);
    const glm::ivec2 origin = windows_[size_t(level)].origin;
    for (int z = 0; z < kFoamSize; ++z)
        for (int x = 0; x < kFoamSize; ++x) {
            // The world texel this stored texel holds, from the window's
            // origin, and the lowest score within its spread: the most foam
            // made there is that score's (the ramp falls), as
            // spectral_foam.comp keeps the most made.
            const glm::ivec2 f = (glm::ivec2(x, z) - origin) & (kFoamSize - 1);
            float least = score_[size_t(f.y + kBreakingSpread) * kMadeSpan + size_t(f.x + kBreakingSpread)];
            for (int dz = -spread; dz <= spread; ++dz)
                for (int dx = -spread; dx <= spread; ++dx)
                    least = std::min(least, score_[size_t(f.y + kBreakingSpread + dz) * kMadeSpan +
                                                   size_t(f.x + kBreakingSpread + dx)]);
            lowest[size_t(z) * kFoamSize + size_t(x)] = least;
        }
}

void FoamReplay::stepJacobians(double time_s)
{
    evolveTo(time_s);
    for (size_t t = 0; t < jacobian_.size(); ++t)
        jacobian_[t] = jacobianAt(t);
}

std::array<std::vector<std::vector<float>>, kFoamLevels> FoamReplay::lowestScores(
    glm::dvec2 gridCenter_m, const std::array<FoamWindow, kFoamLevels>& windows, const std::vector<double>& times_s)
{
    windows_ = windows;
    placeTaps(gridCenter_m, windows);
    phasorSet_ = false;
    std::array<std::vector<std::vector<float>>, kFoamLevels> scores;
    for (const double t : times_s) {
        stepJacobians(t);
        for (int level = 0; level < kFoamLevels; ++level) {
            scores[size_t(level)].emplace_back(size_t(kFoamSize) * kFoamSize);
            lowestScoresOf(level, scores[size_t(level)].back().data());
        }
    }
    return scores;
}

const std::array<std::vector<float>, kFoamLevels>& FoamReplay::run(glm::dvec2 gridCenter_m,
                                                                    const std::array<FoamWindow, kFoamLevels>& windows,
                                                                    const std::vector<double>& times_s,
                                                                    double lifetime_s)
{
    windows_ = windows;
    placeTaps(gridCenter_m, windows);
    phasorSet_ = false;
    for (size_t i = 0; i < times_s.size(); ++i) {
        stepJacobians(times_s[i]);
        const float decay = i == 0 ? 0.0f : float(std::exp(-(times_s[i] - times_s[i - 1]) / lifetime_s));
        for (int level = 0; level < kFoamLevels; ++level) {
            lowestScoresOf(level, lowest_.data());
            float* foam = foam_[size_t(level)].data();
            const BreakingRamp& ramp = ramps_[size_t(level)];
            for (size_t p = 0; p < lowest_.size(); ++p)
                // Stored as the GPU's R16F texture stores it at every
                // step, so the foam decays through the same roundings.
                foam[p] = toHalfTowardZero(
                    std::max(foam[p] * decay, foamMadeAt(lowest_[p] + kScoreMargin, ramp.start, ramp.span)));
        }
    }
    return foam_;
}

float FoamReplay::lastJacobian(int level, int x, int z) const
{
    return jacobian_[spanIndexOf(level, x, z) + size_t(kBreakingRadius) * kSpan + kBreakingRadius];
}

} // namespace swell::spectral
