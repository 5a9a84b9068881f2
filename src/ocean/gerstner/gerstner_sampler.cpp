// WaveSampler: many Gerstner height queries at one time, in float with
// SIMD (see swell/scene/waves.h).
#include "ocean/gerstner/gerstner_terms.h"

#include <fmt/format.h>
#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <stdexcept>

namespace swell {

using namespace gerstner;

// ---------------------------------------------------------------------------
// WaveSampler
//
// The query kernel is written once over GCC/Clang vector extensions and
// compiled twice: for the baseline ISA with four floats per vector, and, on
// x86-64, for AVX2 with FMA with eight, chosen at run time. Plain arithmetic on
// these types compiles to packed instructions without any target flags.

#if (defined(__x86_64__) || defined(_M_X64)) && (defined(__GNUC__) || defined(__clang__))
#define SWELL_SAMPLER_AVX2 1
#else
#define SWELL_SAMPLER_AVX2 0
#endif

namespace {

using Float2 = float __attribute__((vector_size(8)));
using Float4 = float __attribute__((vector_size(16)));
using Float8 = float __attribute__((vector_size(32)));
using Int4 = std::int32_t __attribute__((vector_size(16)));
using Int8 = std::int32_t __attribute__((vector_size(32)));
using Double2 = double __attribute__((vector_size(16)));
using Double4 = double __attribute__((vector_size(32)));

// Vector types of one kernel: F for the solve, D for the phase prologue
// (half as many lanes), and the float vector D narrows to.
struct Narrow {
    using F = Float4;
    using I = Int4;
    using D = Double2;
    using FromD = Float2;
};
struct Wide {
    using F = Float8;
    using I = Int8;
    using D = Double4;
    using FromD = Float4;
};

static_assert(SWELL_MAX_WAVES % WaveSampler::kLanes == 0, "the wave arrays are padded to whole vectors");
static_assert(WaveSampler::kLanes * sizeof(float) == sizeof(Float8), "kLanes is the widest vector");

// Everything below takes and returns vectors by reference or is inlined, so
// that no 32-byte vector crosses a call in code built for the baseline ISA.
#define SWELL_INLINE [[gnu::always_inline]] inline

template <class V, class T>
SWELL_INLINE void load(V& v, const T* p)
{
    std::memcpy(&v, p, sizeof v);
}

// The sum of four lanes of each of a, b, c, d, as one vector.
SWELL_INLINE Float4 laneSums(Float4 a, Float4 b, Float4 c, Float4 d)
{
    const Float4 ab = __builtin_shufflevector(a, b, 0, 4, 1, 5) + __builtin_shufflevector(a, b, 2, 6, 3, 7);
    const Float4 cd = __builtin_shufflevector(c, d, 0, 4, 1, 5) + __builtin_shufflevector(c, d, 2, 6, 3, 7);
    return __builtin_shufflevector(ab, cd, 0, 1, 4, 5) + __builtin_shufflevector(ab, cd, 2, 3, 6, 7);
}

// The lane sums of eight vectors: out[j] = sum of the lanes of the j-th.
SWELL_INLINE void laneSums(const Float4& a, const Float4& b, const Float4& c, const Float4& d, const Float4& e,
                           const Float4& f, const Float4& g, const Float4& h, float out[8])
{
    const Float4 abcd = laneSums(a, b, c, d);
    const Float4 efgh = laneSums(e, f, g, h);
    std::memcpy(out, &abcd, sizeof abcd);
    std::memcpy(out + 4, &efgh, sizeof efgh);
}

// The same for eight lanes: pairs within each 128-bit half first, the
// halves last, 14 shuffles and 7 additions in all.
SWELL_INLINE void laneSums(const Float8& a, const Float8& b, const Float8& c, const Float8& d, const Float8& e,
                           const Float8& f, const Float8& g, const Float8& h, float out[8])
{
#define SWELL_PAIRS(x, y)                                             \
    (__builtin_shufflevector(x, y, 0, 8, 1, 9, 4, 12, 5, 13)          \
     + __builtin_shufflevector(x, y, 2, 10, 3, 11, 6, 14, 7, 15))
#define SWELL_QUADS(x, y)                                             \
    (__builtin_shufflevector(x, y, 0, 1, 8, 9, 4, 5, 12, 13)          \
     + __builtin_shufflevector(x, y, 2, 3, 10, 11, 6, 7, 14, 15))
    const Float8 ab = SWELL_PAIRS(a, b);
    const Float8 cd = SWELL_PAIRS(c, d);
    const Float8 ef = SWELL_PAIRS(e, f);
    const Float8 gh = SWELL_PAIRS(g, h);
    const Float8 abcd = SWELL_QUADS(ab, cd);
    const Float8 efgh = SWELL_QUADS(ef, gh);
#undef SWELL_PAIRS
#undef SWELL_QUADS
    const Float8 all = __builtin_shufflevector(abcd, efgh, 0, 1, 2, 3, 8, 9, 10, 11)
                     + __builtin_shufflevector(abcd, efgh, 4, 5, 6, 7, 12, 13, 14, 15);
    std::memcpy(out, &all, sizeof all);
}

// sin and cos of every lane, absolute error below 3e-7 for |x| < 1e4 rad
// (measured; the solves stay far inside that).
// The angle is reduced by a multiple n of pi into [-pi/2, pi/2] (pi split in
// two so that n*pi comes off exactly), the sine and cosine there come from
// minimax polynomials (errors 5e-9 and 3e-10 before float rounding), and the
// sign (-1)^n is flipped in with the low bit of n.
template <class F, class I>
SWELL_INLINE void sinCos(const F& x, F& s, F& c)
{
    // Adding 1.5*2^23 rounds to an integer and leaves it in the low mantissa
    // bits; needs IEEE arithmetic, i.e. no -ffast-math.
    const F shifted = x * 0.318309886183790672f + 12582912.0f;
    const F n = shifted - 12582912.0f;
    const I signBits = __builtin_bit_cast(I, shifted) << 31;
    const F r = (x - n * 3.140625f) - n * 9.67653589793116e-4f;
    const F r2 = r * r;
    F ps = r2 * 2.600054767808503e-06f - 1.9806615201304982e-04f;
    ps = ps * r2 + 8.333017291561384e-03f;
    ps = ps * r2 - 0.16666657096504653f;
    const F sinR = r + r * r2 * ps;
    F pc = r2 * -2.60771053520008e-07f + 2.476188624832763e-05f;
    pc = pc * r2 - 1.3888403508218697e-03f;
    pc = pc * r2 + 4.166664072805985e-02f;
    pc = pc * r2 - 0.49999999549557245f;
    const F cosR = pc * r2 + 1.0f;
    s = __builtin_bit_cast(F, __builtin_bit_cast(I, sinR) ^ signBits);
    c = __builtin_bit_cast(F, __builtin_bit_cast(I, cosR) ^ signBits);
}

// Added to the diagonal of J in the float solves. Where J is singular to
// float precision (about 1e-7: next to a cusp of a set at the fold limit) it
// keeps the Newton step finite and pointing against the residual, and the
// halving finds its length; elsewhere it changes the step by 1e-5 of itself,
// which costs nothing in convergence and saves a select on the critical path.
constexpr float kRidge = 1e-5f;

bool cpuHasAvx2Fma()
{
#if SWELL_SAMPLER_AVX2
    __builtin_cpu_init();
    return __builtin_cpu_supports("avx2") && __builtin_cpu_supports("fma");
#else
    return false;
#endif
}

} // namespace

// Two kernels: one query with the waves across the lanes (latency), and a
// batch with the queries across the lanes (throughput, no horizontal sums).
struct WaveSamplerKernel {
    template <class P>
    SWELL_INLINE static double height(const WaveSampler& w, glm::dvec2 worldPoint_m);
    template <class P>
    SWELL_INLINE static void heights(const WaveSampler& w, const glm::dvec2* points, double* heights, std::size_t count);

    static double baseline(const WaveSampler& w, glm::dvec2 worldPoint_m) { return height<Narrow>(w, worldPoint_m); }
    static void baselineBatch(const WaveSampler& w, const glm::dvec2* points, double* out, std::size_t count)
    {
        heights<Narrow>(w, points, out, count);
    }
#if SWELL_SAMPLER_AVX2
    [[gnu::target("avx2,fma")]] static double avx2(const WaveSampler& w, glm::dvec2 worldPoint_m)
    {
        return height<Wide>(w, worldPoint_m);
    }
    [[gnu::target("avx2,fma")]] static void avx2Batch(const WaveSampler& w, const glm::dvec2* points, double* out,
                                                      std::size_t count)
    {
        heights<Wide>(w, points, out, count);
    }
#endif
};

template <class P>
SWELL_INLINE double WaveSamplerKernel::height(const WaveSampler& w, glm::dvec2 worldPoint_m)
{
    using F = typename P::F;
    using I = typename P::I;
    using D = typename P::D;
    using FromD = typename P::FromD;
    constexpr int kFloatLanes = sizeof(F) / sizeof(float);
    constexpr int kDoubleLanes = sizeof(D) / sizeof(double);

    // Phase of every wave at the query point, in double relative to the
    // origin, reduced to [-pi, pi] and only then narrowed to float. At 10 km
    // a 0.5 m wave is 1.3e5 rad in, which float could not hold to 0.01 rad.
    // The arrays are padded to kLanes; this path needs only whole vectors.
    const int padded = (w.waveCount_ + kFloatLanes - 1) / kFloatLanes * kFloatLanes;
    alignas(32) float theta0[SWELL_MAX_WAVES];
    const double rx = worldPoint_m.x - w.origin_m_.x;
    const double rz = worldPoint_m.y - w.origin_m_.y;
    for (int i = 0; i < padded; i += kDoubleLanes) {
        D kx, kz, p0;
        load(kx, w.kxD_ + i);
        load(kz, w.kzD_ + i);
        load(p0, w.phase0_ + i);
        D t = kx * rx + kz * rz + p0;
        const D n = (t * kInvTwoPi + 6755399441055744.0) - 6755399441055744.0; // 1.5*2^52 rounds
        t = (t - n * kTwoPiHi) - n * kTwoPiLo;
        const FromD narrowed = __builtin_convertvector(t, FromD);
        std::memcpy(theta0 + i, &narrowed, sizeof narrowed);
    }

    // Newton on the rest point's offset from the query point, as in
    // solveInverse but in float, and with the halving folded into the
    // iteration: an evaluation that did not shrink the residual is rejected
    // and the next one tries half the step from the last accepted point.
    //
    // The bookkeeping is written as selects, so that the only branches on
    // the data are the exit tests. At least kFirstExit evaluations run: the
    // step from the query point itself is rarely within tolerance.
    constexpr int kFirstExit = 2;
    constexpr int kMaxEvaluations = 12;
    constexpr float kTolerance2 = WaveSampler::kStepTolerance_m * WaveSampler::kStepTolerance_m;
    const float radius2 = w.maxOffset_m_ * w.maxOffset_m_;
    float tryX = 0.0f, tryZ = 0.0f;                        // offset evaluated next, m
    float baseX = 0.0f, baseZ = 0.0f;                      // last accepted offset, m
    float stepX = 0.0f, stepZ = 0.0f;                      // step from it, m
    float baseResidual2 = std::numeric_limits<float>::infinity(); // its |r|^2, m^2
    float baseHeight = 0.0f, baseGx = 0.0f, baseGz = 0.0f; // its height, m, and dh/dx0
    for (int evaluation = 0;; ++evaluation) {
        F sx{}, sz{}, sjxx{}, sjxz{}, sjzz{}, sh{}, sgx{}, sgz{};
        for (int i = 0; i < padded; i += kFloatLanes) {
            F th, kx, kz, s, c, a;
            load(th, theta0 + i);
            load(kx, w.kx_ + i);
            load(kz, w.kz_ + i);
            sinCos<F, I>(th + kx * tryX + kz * tryZ, s, c);
            load(a, w.qax_ + i);
            sx -= a * s;
            load(a, w.qaz_ + i);
            sz -= a * s;
            load(a, w.jxx_ + i);
            sjxx -= a * c;
            load(a, w.jxz_ + i);
            sjxz -= a * c;
            load(a, w.jzz_ + i);
            sjzz -= a * c;
            load(a, w.amp_ + i);
            sh += a * c;
            load(a, w.akx_ + i);
            sgx -= a * s;
            load(a, w.akz_ + i);
            sgz -= a * s;
        }
        float sums[8];
        laneSums(sx, sz, sjxx, sjxz, sjzz, sh, sgx, sgz, sums);
        const float resX = tryX + sums[0];
        const float resZ = tryZ + sums[1];
        const float residual2 = resX * resX + resZ * resZ;

        // Newton step from this point, with a ridge of kRidge on J as in
        // solveInverse; the fixed-point step if J is not even semi-definite
        // (a set past the fold limit).
        const float jxx = 1.0f + kRidge + sums[2];
        const float jxz = sums[3];
        const float jzz = 1.0f + kRidge + sums[4];
        const float det = jxx * jzz - jxz * jxz;
        const float invDet = det > 0.0f ? 1.0f / det : 0.0f;
        const float newtonX = det > 0.0f ? (jxz * resZ - jzz * resX) * invDet : -resX;
        const float newtonZ = det > 0.0f ? (jxz * resX - jxx * resZ) * invDet : -resZ;

        const bool accept = residual2 < baseResidual2;
        baseX = accept ? tryX : baseX;
        baseZ = accept ? tryZ : baseZ;
        baseResidual2 = accept ? residual2 : baseResidual2;
        baseHeight = accept ? sums[5] : baseHeight;
        baseGx = accept ? sums[6] : baseGx;
        baseGz = accept ? sums[7] : baseGz;
        stepX = accept ? newtonX : 0.5f * stepX;
        stepZ = accept ? newtonZ : 0.5f * stepZ;

        // Converged: the last step, to first order.
        const bool converged = accept && stepX * stepX + stepZ * stepZ <= kTolerance2;
        if (evaluation + 1 >= kFirstExit && converged)
            return static_cast<double>(baseHeight + baseGx * stepX + baseGz * stepZ);
        // Out of evaluations (only next to a cusp of a set at the fold
        // limit, where the height is flat along x0): the best point found.
        if (evaluation + 1 == kMaxEvaluations)
            return static_cast<double>(baseHeight);

        tryX = baseX + stepX;
        tryZ = baseZ + stepZ;
        // The answer lies within sum(Q*A) of the query point. A branch, not a
        // select: it is rarely taken, and so stays off the critical path.
        const float length2 = tryX * tryX + tryZ * tryZ;
        if (length2 > radius2) [[unlikely]] {
            const float scale = std::sqrt(radius2 / length2);
            tryX *= scale;
            tryZ *= scale;
            stepX = tryX - baseX;
            stepZ = tryZ - baseZ;
        }
    }
}

// b = a in the lanes where mask is set. Comparisons of vectors give masks of
// all ones or all zeros per lane.
template <class F, class I>
SWELL_INLINE void select(const I& mask, const F& a, F& b)
{
    b = __builtin_bit_cast(F, (mask & __builtin_bit_cast(I, a)) | (~mask & __builtin_bit_cast(I, b)));
}

template <class P>
SWELL_INLINE void WaveSamplerKernel::heights(const WaveSampler& w, const glm::dvec2* points, double* out,
                                             std::size_t count)
{
    using F = typename P::F;
    using I = typename P::I;
    using D = typename P::D;
    using FromD = typename P::FromD;
    constexpr int kLanes = sizeof(F) / sizeof(float);
    constexpr int kHalf = sizeof(D) / sizeof(double);
    static_assert(2 * kHalf == kLanes);

    for (std::size_t first = 0; first < count; first += kLanes) {
        // Up to kLanes queries, the last lanes repeating the last point.
        alignas(32) double rx[kLanes];
        alignas(32) double rz[kLanes];
        const std::size_t n = std::min<std::size_t>(kLanes, count - first);
        for (int l = 0; l < kLanes; ++l) {
            const glm::dvec2 p = points[first + std::min<std::size_t>(static_cast<std::size_t>(l), n - 1)];
            rx[l] = p.x - w.origin_m_.x;
            rz[l] = p.y - w.origin_m_.y;
        }

        // Phase of every wave at every query point, reduced in double, as in
        // height(): theta0[wave] holds the lanes.
        F theta0[SWELL_MAX_WAVES];
        D rxLo, rxHi, rzLo, rzHi;
        load(rxLo, rx);
        load(rxHi, rx + kHalf);
        load(rzLo, rz);
        load(rzHi, rz + kHalf);
        for (int i = 0; i < w.waveCount_; ++i) {
            const double kx = w.kxD_[i];
            const double kz = w.kzD_[i];
            const double p0 = w.phase0_[i];
            D lo = rxLo * kx + rzLo * kz + p0;
            D hi = rxHi * kx + rzHi * kz + p0;
            const D nLo = (lo * kInvTwoPi + 6755399441055744.0) - 6755399441055744.0;
            const D nHi = (hi * kInvTwoPi + 6755399441055744.0) - 6755399441055744.0;
            lo = (lo - nLo * kTwoPiHi) - nLo * kTwoPiLo;
            hi = (hi - nHi * kTwoPiHi) - nHi * kTwoPiLo;
            const FromD narrowLo = __builtin_convertvector(lo, FromD);
            const FromD narrowHi = __builtin_convertvector(hi, FromD);
            std::memcpy(&theta0[i], &narrowLo, sizeof narrowLo);
            std::memcpy(reinterpret_cast<char*>(&theta0[i]) + sizeof narrowLo, &narrowHi, sizeof narrowHi);
        }

        // The solve of height(), lane by lane: every lane runs until all have
        // converged, a lane's answer frozen when it converges.
        constexpr int kFirstExit = 2;
        constexpr int kMaxEvaluations = 12;
        constexpr float kTolerance2 = WaveSampler::kStepTolerance_m * WaveSampler::kStepTolerance_m;
        const float radius2 = w.maxOffset_m_ * w.maxOffset_m_;
        F tryX{}, tryZ{}, baseX{}, baseZ{}, stepX{}, stepZ{};
        F baseResidual2 = F{} + std::numeric_limits<float>::infinity();
        F baseHeight{}, baseGx{}, baseGz{}, result{};
        I done{};
        for (int evaluation = 0;; ++evaluation) {
            F sx{}, sz{}, sjxx{}, sjxz{}, sjzz{}, sh{}, sgx{}, sgz{};
            for (int i = 0; i < w.waveCount_; ++i) {
                F s, c;
                sinCos<F, I>(theta0[i] + tryX * w.kx_[i] + tryZ * w.kz_[i], s, c);
                sx -= s * w.qax_[i];
                sz -= s * w.qaz_[i];
                sjxx -= c * w.jxx_[i];
                sjxz -= c * w.jxz_[i];
                sjzz -= c * w.jzz_[i];
                sh += c * w.amp_[i];
                sgx -= s * w.akx_[i];
                sgz -= s * w.akz_[i];
            }
            const F resX = tryX + sx;
            const F resZ = tryZ + sz;
            const F residual2 = resX * resX + resZ * resZ;

            const F jxx = sjxx + (1.0f + kRidge);
            const F jzz = sjzz + (1.0f + kRidge);
            const F det = jxx * jzz - sjxz * sjxz;
            const I invertible = det > 0.0f;
            F safeDet = F{} + 1.0f;
            select<F, I>(invertible, det, safeDet);
            F newtonX = -resX;
            F newtonZ = -resZ;
            select<F, I>(invertible, (sjxz * resZ - jzz * resX) / safeDet, newtonX);
            select<F, I>(invertible, (sjxz * resX - jxx * resZ) / safeDet, newtonZ);

            const I accept = residual2 < baseResidual2;
            select<F, I>(accept, tryX, baseX);
            select<F, I>(accept, tryZ, baseZ);
            select<F, I>(accept, residual2, baseResidual2);
            select<F, I>(accept, sh, baseHeight);
            select<F, I>(accept, sgx, baseGx);
            select<F, I>(accept, sgz, baseGz);
            stepX *= 0.5f;
            stepZ *= 0.5f;
            select<F, I>(accept, newtonX, stepX);
            select<F, I>(accept, newtonZ, stepZ);

            bool allDone = false;
            if (evaluation + 1 >= kFirstExit) {
                const I converged = accept & (stepX * stepX + stepZ * stepZ <= kTolerance2);
                const I newlyDone = converged & ~done;
                select<F, I>(newlyDone, baseHeight + baseGx * stepX + baseGz * stepZ, result);
                done |= newlyDone;
                allDone = true;
                for (int l = 0; l < kLanes; ++l)
                    allDone = allDone && done[l] != 0;
            }
            if (allDone)
                break;
            if (evaluation + 1 == kMaxEvaluations) {
                select<F, I>(~done, baseHeight, result);
                break;
            }

            tryX = baseX + stepX;
            tryZ = baseZ + stepZ;
            const F length2 = tryX * tryX + tryZ * tryZ;
            const I outside = length2 > radius2;
            bool anyOutside = false;
            for (int l = 0; l < kLanes; ++l)
                anyOutside = anyOutside || outside[l] != 0;
            if (anyOutside) { // rare: only far from converging
                for (int l = 0; l < kLanes; ++l) {
                    if (outside[l]) {
                        const float scale = std::sqrt(radius2 / length2[l]);
                        tryX[l] *= scale;
                        tryZ[l] *= scale;
                    }
                }
                stepX = tryX - baseX;
                stepZ = tryZ - baseZ;
            }
        }
        for (std::size_t l = 0; l < n; ++l)
            out[first + l] = static_cast<double>(result[l]);
    }
}

WaveSampler::WaveSampler(const WaveSet& set, double time_s, glm::dvec2 origin_m, Simd simd)
    : time_s_(time_s), origin_m_(origin_m), waveCount_(static_cast<int>(set.waves.size()))
{
    if (std::string why = validate(set); !why.empty())
        throw std::invalid_argument("swell::WaveSampler::WaveSampler(): " + why);
    simd_ = simd != Simd::Baseline && cpuHasAvx2Fma() ? Simd::Avx2 : Simd::Baseline;
    if (set.coast) {
        overCoast_ = std::make_shared<const WaveSet>(set);
        return;
    }
    maxOffset_m_ = static_cast<float>(waveReach(set).horizontal_m);
    for (int i = 0; i < waveCount_; ++i) {
        const Wave& w = set.waves[static_cast<std::size_t>(i)];
        const WaveTerms t = termsOf(w, set.depth_m);
        const double qa = w.steepness * w.amplitude_m;
        const double ka = t.k * w.amplitude_m;
        kxD_[i] = t.kd.x;
        kzD_[i] = t.kd.y;
        phase0_[i] = phaseAt(t, w.phase_rad, origin_m, time_s);
        kx_[i] = static_cast<float>(t.kd.x);
        kz_[i] = static_cast<float>(t.kd.y);
        qax_[i] = static_cast<float>(qa * t.d.x);
        qaz_[i] = static_cast<float>(qa * t.d.y);
        jxx_[i] = static_cast<float>(w.steepness * ka * t.d.x * t.d.x);
        jxz_[i] = static_cast<float>(w.steepness * ka * t.d.x * t.d.y);
        jzz_[i] = static_cast<float>(w.steepness * ka * t.d.y * t.d.y);
        amp_[i] = static_cast<float>(w.amplitude_m);
        akx_[i] = static_cast<float>(ka * t.d.x);
        akz_[i] = static_cast<float>(ka * t.d.y);
        for (float v : {kx_[i], kz_[i], qax_[i], qaz_[i], jxx_[i], jxz_[i], jzz_[i], amp_[i], akx_[i], akz_[i]}) {
            if (!std::isfinite(v))
                throw std::invalid_argument(fmt::format(
                    "swell::WaveSampler::WaveSampler(): wave {}: its terms overflow float "
                    "(wavelength {} m, amplitude {} m)", i, w.wavelength_m, w.amplitude_m));
        }
    }
}

double WaveSampler::heightAt(glm::dvec2 worldPoint_m) const
{
    if (overCoast_)
        return swell::heightAt(*overCoast_, worldPoint_m, time_s_);
#if SWELL_SAMPLER_AVX2
    if (simd_ == Simd::Avx2)
        return WaveSamplerKernel::avx2(*this, worldPoint_m);
#endif
    return WaveSamplerKernel::baseline(*this, worldPoint_m);
}

void WaveSampler::heightsAt(std::span<const glm::dvec2> worldPoints_m, std::span<double> heights_m) const
{
    if (worldPoints_m.size() != heights_m.size())
        throw std::invalid_argument(fmt::format("swell::WaveSampler::heightsAt(): {} points but {} heights",
                                                worldPoints_m.size(), heights_m.size()));
    if (overCoast_) {
        for (std::size_t i = 0; i < worldPoints_m.size(); ++i)
            heights_m[i] = swell::heightAt(*overCoast_, worldPoints_m[i], time_s_);
        return;
    }
    if (waveCount_ == 0) {
        std::fill(heights_m.begin(), heights_m.end(), 0.0);
        return;
    }
#if SWELL_SAMPLER_AVX2
    if (simd_ == Simd::Avx2) {
        WaveSamplerKernel::avx2Batch(*this, worldPoints_m.data(), heights_m.data(), worldPoints_m.size());
        return;
    }
#endif
    WaveSamplerKernel::baselineBatch(*this, worldPoints_m.data(), heights_m.data(), worldPoints_m.size());
}

} // namespace swell

