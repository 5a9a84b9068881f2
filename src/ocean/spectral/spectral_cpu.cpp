#include "ocean/spectral/spectral_cpu.h"

#include "core/worker.h"
#include "ocean/gerstner/gerstner_terms.h"
#include "swell/scene/waves.h"

#include <kiss_fft.h>

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <limits>

namespace swell::spectral {

double cascadeWeight(const Cascade& cascade, double footprint_m)
{
    return waveLodWeight(cascade.shortestWavelength_m(), footprint_m);
}

double filteredCascadeWeight(const SpectralField& field, int c, double footprint_m)
{
    return c < SWELL_FFT_FILTERED_CASCADES ? 1.0 - cascadeWeight(field.cascades[size_t(c)], footprint_m) : 0.0;
}

double displacementLevel(const Cascade& cascade, double footprint_m)
{
    const double texels = footprint_m * kSize / cascade.patch_m;
    return std::clamp(std::log2(std::max(texels, 1.0)), 0.0, double(kLog2Size));
}

CpuSurface::CpuSurface(std::shared_ptr<const SpectralField> field, std::shared_ptr<const CoastTrains> coast)
    : field_(std::move(field)), coast_(std::move(coast))
{
    fft_ = kiss_fft_alloc(kSize, 1, nullptr, nullptr);
    workerFft_ = kiss_fft_alloc(kSize, 1, nullptr, nullptr);
    fields_.time_s = std::numeric_limits<double>::quiet_NaN();
}

CpuSurface::~CpuSurface()
{
    kiss_fft_free(fft_);
    kiss_fft_free(workerFft_);
}

const CpuSurface::Fields& CpuSurface::fieldsAt(double time_s) const { return fieldsFor(time_s, true); }

const CpuSurface::Fields& CpuSurface::fieldsAt(double time_s, detail::Worker& worker,
                                                const std::function<void(const Fields&, int)>& made) const
{
    if (!(fields_.time_s == time_s))
        startTime(time_s);
    // Each cascade's state, spectra and fields are its own, and each thread
    // has its own transform: the two threads share nothing they write but
    // the atomic counts. Each takes the next cascade not yet taken, so a
    // worker that wakes late (the cores busy with other work) takes fewer,
    // and the caller never waits for more than the one in the worker's hands.
    std::atomic<int> next = 0;
    auto take = [&](void* fft) {
        for (int c = next++; c < kCascades; c = next++) {
            makeCascade(c, 4, fft);
            made(fields_, c);
        }
    };
    worker.run([&] { take(workerFft_); }, [&] { take(fft_); });
    fields_.hasDerivatives = true;
    return fields_;
}

const CpuSurface::Fields& CpuSurface::displacementFieldsAt(double time_s) const { return fieldsFor(time_s, false); }

std::int64_t CpuSurface::columnsTransformed() const
{
    std::lock_guard lock(mutex_);
    return columnsTransformed_;
}

void CpuSurface::startTime(double time_s) const
{
    fields_.time_s = time_s;
    fields_.hasDerivatives = false;
    for (CascadeState& state : cascades_) {
        state.evolved = false;
        if (state.mipsUsed)
            for (std::vector<std::uint8_t>& done : state.mipDone)
                std::fill(done.begin(), done.end(), std::uint8_t(0));
        state.mipsUsed = false;
        state.rowsDone = {};
        for (std::vector<std::uint8_t>& done : state.columnDone)
            done.assign(size_t(kSize), 0);
    }
}

const CpuSurface::Fields& CpuSurface::fieldsFor(double time_s, bool derivatives) const
{
    if (!(fields_.time_s == time_s))
        startTime(time_s);
    // (Dx, Dy) and (Dz, dDx/dz): the displacement; (dDy/dx, dDy/dz) and
    // (dDx/dx, dDz/dz): the normal.
    makeAll(0, derivatives ? 4 : 2);
    fields_.hasDerivatives = fields_.hasDerivatives || derivatives;
    return fields_;
}

void CpuSurface::makeAll(int firstPacked, int lastPacked) const
{
    for (int c = 0; c < kCascades; ++c)
        for (int p = firstPacked; p < lastPacked; ++p)
            for (int column = 0; column < kSize; ++column)
                makeColumn(c, p, column);
}

void CpuSurface::makeCascade(int c, int lastPacked, void* fft) const
{
    for (int p = 0; p < lastPacked; ++p)
        for (int column = 0; column < kSize; ++column)
            makeColumn(c, p, column, fft);
}

void CpuSurface::makeColumn(int c, int p, int column, void* fft) const
{
    CascadeState& state = cascades_[size_t(c)];
    if (state.columnDone[size_t(p)][size_t(column)])
        return;
    static_assert(sizeof(kiss_fft_cpx) == sizeof(std::complex<float>));
    const auto cfg = static_cast<kiss_fft_cfg>(fft);
    if (!state.evolved) {
        evolve(*field_, c, fields_.time_s, state.spectra);
        state.evolved = true;
    }
    std::vector<std::complex<float>>& rows = state.rows[size_t(p)];
    if (!state.rowsDone[size_t(p)]) {
        // The first pass: each row of the spectrum (one kz) along x.
        const std::vector<std::complex<float>>& spectrum = state.spectra.packed[size_t(p)];
        rows.resize(spectrum.size());
        for (int kz = 0; kz < kSize; ++kz)
            kiss_fft(cfg, reinterpret_cast<const kiss_fft_cpx*>(spectrum.data() + size_t(kz) * kSize),
                     reinterpret_cast<kiss_fft_cpx*>(rows.data() + size_t(kz) * kSize));
        state.rowsDone[size_t(p)] = true;
    }
    // The second pass for this column alone: along z, every kSize-th value.
    std::array<std::complex<float>, kSize> texels;
    kiss_fft_stride(cfg, reinterpret_cast<const kiss_fft_cpx*>(rows.data() + column), reinterpret_cast<kiss_fft_cpx*>(texels.data()),
                    kSize);
    std::vector<float>& re = fields_.values[size_t(c)][size_t(2 * p)];
    std::vector<float>& im = fields_.values[size_t(c)][size_t(2 * p + 1)];
    re.resize(size_t(kSize) * kSize);
    im.resize(size_t(kSize) * kSize);
    for (int row = 0; row < kSize; ++row) {
        re[size_t(row) * kSize + size_t(column)] = texels[size_t(row)].real();
        im[size_t(row) * kSize + size_t(column)] = texels[size_t(row)].imag();
    }
    state.columnDone[size_t(p)][size_t(column)] = 1;
    ++columnsTransformed_;
}

namespace {

// Field v of one cascade at texel position (sx, sz), bilinear, the patch
// repeating every kSize texels.
struct Bilinear {
    size_t i00, i01, i10, i11; // (row, column) 00, 01, 10, 11
    int column0, column1;
    double fx, fz;
    Bilinear(double sx, double sz)
    {
        const double x0 = std::floor(sx), z0 = std::floor(sz);
        fx = sx - x0;
        fz = sz - z0;
        auto wrap = [](double v) { return int(v - kSize * std::floor(v / kSize)); };
        const int c0 = wrap(x0), c1 = (c0 + 1) % kSize, r0 = wrap(z0), r1 = (r0 + 1) % kSize;
        column0 = c0;
        column1 = c1;
        i00 = size_t(r0) * kSize + size_t(c0);
        i01 = size_t(r0) * kSize + size_t(c1);
        i10 = size_t(r1) * kSize + size_t(c0);
        i11 = size_t(r1) * kSize + size_t(c1);
    }
    double operator()(const std::vector<float>& a) const
    {
        const double top = a[i00] * (1.0 - fx) + a[i01] * fx;
        const double bottom = a[i10] * (1.0 - fx) + a[i11] * fx;
        return top * (1.0 - fz) + bottom * fz;
    }
};

} // namespace

float CpuSurface::mipTexel(int c, int level, int row, int column, int f) const
{
    if (level == 0) {
        makeColumn(c, f < 2 ? 0 : 1, column); // (Dx, Dy) and (Dz, dDx/dz)
        return fields_.values[size_t(c)][size_t(f)][size_t(row) * kSize + size_t(column)];
    }
    CascadeState& state = cascades_[size_t(c)];
    if (state.mips.empty()) {
        state.mips.resize(size_t(kLog2Size));
        state.mipDone.resize(size_t(kLog2Size));
        for (int l = 1; l <= kLog2Size; ++l) {
            const size_t texels = size_t(kSize >> l) * size_t(kSize >> l);
            for (std::vector<float>& v : state.mips[size_t(l - 1)])
                v.assign(texels, 0.0f);
            state.mipDone[size_t(l - 1)].assign(texels, 0);
        }
    }
    state.mipsUsed = true;
    const size_t at = size_t(row) * size_t(kSize >> level) + size_t(column);
    auto& values = state.mips[size_t(level - 1)];
    if (!state.mipDone[size_t(level - 1)][at]) {
        for (int field = 0; field < 3; ++field) {
            const float a = mipTexel(c, level - 1, 2 * row, 2 * column, field);
            const float b = mipTexel(c, level - 1, 2 * row, 2 * column + 1, field);
            const float d = mipTexel(c, level - 1, 2 * row + 1, 2 * column, field);
            const float e = mipTexel(c, level - 1, 2 * row + 1, 2 * column + 1, field);
            values[size_t(field)][at] = 0.25f * ((a + b) + (d + e));
        }
        state.mipDone[size_t(level - 1)][at] = 1;
    }
    return values[size_t(f)][at];
}

glm::dvec3 CpuSurface::filteredDisplacement(int c, glm::dvec2 s, double footprint_m) const
{
    const double level = displacementLevel(field_->cascades[size_t(c)], footprint_m);
    const int first = int(std::floor(level)), second = std::min(first + 1, kLog2Size);
    auto at = [&](int l) {
        // Level l's texel j is the mean of level 0's j * 2^l .. (j + 1) * 2^l - 1;
        // a cubic B-spline over its texels (spectral.glsl's bsplineDisplacementAt).
        const int n = kSize >> l;
        const double scale = std::ldexp(1.0, -l);
        const glm::dvec2 sl = (s + 0.5) * scale - 0.5;
        const glm::dvec2 cell = glm::floor(sl), f = sl - cell;
        glm::dvec2 w[4];
        w[0] = (1.0 - f) * (1.0 - f) * (1.0 - f) / 6.0;
        w[1] = (4.0 - 6.0 * f * f + 3.0 * f * f * f) / 6.0;
        w[3] = f * f * f / 6.0;
        w[2] = 1.0 - w[0] - w[1] - w[3];
        auto wrap = [n](double v) { return int(v - n * std::floor(v / n)); };
        const int x0 = wrap(cell.x - 1.0), z0 = wrap(cell.y - 1.0);
        glm::dvec3 v(0.0);
        for (int row = 0; row < 4; ++row) {
            glm::dvec3 line(0.0);
            for (int col = 0; col < 4; ++col)
                for (int field = 0; field < 3; ++field)
                    line[field] += w[col].x * mipTexel(c, l, (z0 + row) % n, (x0 + col) % n, field);
            v += w[row].y * line;
        }
        return v;
    };
    const glm::dvec3 a = at(first);
    return second == first ? a : glm::mix(a, at(second), level - first);
}

void CpuSurface::sample(double time_s, glm::dvec2 restPoint_m, const SurfaceFilter& filter, bool derivatives,
                        Sample& out, int cascadeCount, bool overCoast, bool filtered) const
{
    if (!(fields_.time_s == time_s))
        startTime(time_s);
    const Fields& f = fields_;
    out = Sample{};
    // Over a coast field: every cascade times the field's common gain, the
    // longest band shared with the trains (spectral_coast.h).
    double gain = 1.0, shareOfBand = 0.0;
    const CoastField* field = overCoast && coast_ ? coast_->trains.coast.get() : nullptr;
    if (field) {
        gain = field->commonAt(restPoint_m).gain;
        shareOfBand = coastTrainShare(*field, coast_->depths, restPoint_m);
    }
    for (int c = 0; c < std::min(cascadeCount, kCascades); ++c) {
        const Cascade& cascade = field_->cascades[size_t(c)];
        const double common = gain * (c == 0 ? std::sqrt(1.0 - shareOfBand) : 1.0);
        const double weight = cascadeWeight(cascade, filter.footprint_m) * common;
        const double filteredWeight = filtered ? filteredCascadeWeight(*field_, c, filter.footprint_m) * common : 0.0;
        if (weight <= 0.0 && filteredWeight <= 0.0)
            continue;
        // The anti-tiling warp: the cascade is looked up at x + w_c(x).
        const WarpSample warp = warpAt(field_->warps[size_t(c)], restPoint_m);
        // Sample (col, row) holds world (col, row) * L/N, repeating every L.
        const double scale = kSize / cascade.patch_m;
        const glm::dvec2 s = (restPoint_m + warp.offset_m) * scale;
        if (filteredWeight > 0.0)
            out.displacement_m += filteredWeight * filteredDisplacement(c, s, filter.footprint_m);
        if (weight <= 0.0)
            continue;
        const Bilinear at(s.x, s.y);
        // The two columns it reads, of the pairs it reads.
        for (int p = 0; p < (derivatives ? 4 : 2); ++p) {
            makeColumn(c, p, at.column0);
            makeColumn(c, p, at.column1);
        }
        const auto& v = f.values[size_t(c)];
        out.displacement_m += weight * glm::dvec3(at(v[0]), at(v[1]), at(v[2]));
        if (!derivatives)
            continue;
        // Gradients in the patch (d/ds_x, d/ds_z) to gradients at the rest
        // point through the warp's Jacobian (the chain rule): d/dx_j = grad_s . J[j].
        const double dxz = at(v[3]);
        const glm::dvec2 gradDx(at(v[6]), dxz), gradDy(at(v[4]), at(v[5])), gradDz(dxz, at(v[7]));
        for (int j = 0; j < 2; ++j) {
            out.gradDx[j] += weight * glm::dot(gradDx, warp.jacobian[j]);
            out.gradDy[j] += weight * glm::dot(gradDy, warp.jacobian[j]);
            out.gradDz[j] += weight * glm::dot(gradDz, warp.jacobian[j]);
        }
    }
    if (shareOfBand > 0.0)
        addCoast(restPoint_m, time_s, filter, shareOfBand, out);
    out.displacement_m *= filter.heightScale;
    out.gradDx *= filter.heightScale;
    out.gradDy *= filter.heightScale;
    out.gradDz *= filter.heightScale;
}

void CpuSurface::addCoast(glm::dvec2 restPoint_m, double time_s, const SurfaceFilter& filter, double shareOfBand,
                          Sample& out) const
{
    // The trains filtered as coast_field.glsl's coastTrainsSurface weighs
    // them (the height fade is applied to the whole sample by the caller).
    WaveSet trains = coast_->trains;
    const double scale = std::sqrt(shareOfBand);
    for (Wave& w : trains.waves)
        w.amplitude_m *= scale * waveLodWeight(w.wavelength_m, filter.footprint_m);
    gerstner::Evaluation e;
    gerstner::evaluateOverCoast(trains, *trains.coast, restPoint_m, time_s, e);
    out.displacement_m += e.displacement;
    // The partials less the rest point's own: the gradients of (Dx, Dy, Dz).
    out.gradDx += glm::dvec2(e.partials.alongX.x - 1.0, e.partials.alongZ.x);
    out.gradDy += glm::dvec2(e.partials.alongX.y, e.partials.alongZ.y);
    out.gradDz += glm::dvec2(e.partials.alongX.z, e.partials.alongZ.z - 1.0);
}

SurfacePoint CpuSurface::surfaceAt(glm::dvec2 restPoint_m, double time_s, const SurfaceFilter& filter) const
{
    std::lock_guard lock(mutex_);
    Sample sum;
    sample(time_s, restPoint_m, filter, true, sum);
    SurfacePoint p;
    p.displacement_m = sum.displacement_m;
    // The displaced surface's tangents along rest x and rest z.
    const glm::dvec3 alongX(1.0 + sum.gradDx.x, sum.gradDy.x, sum.gradDz.x);
    const glm::dvec3 alongZ(sum.gradDx.y, sum.gradDy.y, 1.0 + sum.gradDz.y);
    p.normal = glm::normalize(glm::cross(alongZ, alongX));
    return p;
}

glm::dvec3 CpuSurface::displacementAt(glm::dvec2 restPoint_m, double time_s, const SurfaceFilter& filter) const
{
    std::lock_guard lock(mutex_);
    Sample sum;
    sample(time_s, restPoint_m, filter, false, sum);
    return sum.displacement_m;
}

double CpuSurface::foldJacobianAt(glm::dvec2 restPoint_m, double time_s, const SurfaceFilter& filter,
                                  int cascadeCount) const
{
    std::lock_guard lock(mutex_);
    Sample sum;
    sample(time_s, restPoint_m, filter, true, sum, cascadeCount, false, false);
    return (1.0 + sum.gradDx.x) * (1.0 + sum.gradDz.y) - sum.gradDx.y * sum.gradDz.x;
}

} // namespace swell::spectral
