#include "ocean/spectral/spectral_cpu.h"

#include "swell/waves.h"

#include <kiss_fftnd.h>

#include <glm/geometric.hpp>

#include <cmath>

namespace swell::spectral {

double cascadeWeight(const Cascade& cascade, double footprint_m)
{
    return waveLodWeight(cascade.shortestWavelength_m(), footprint_m);
}

CpuSurface::CpuSurface(std::shared_ptr<const SpectralField> field) : field_(std::move(field))
{
    const int dims[2] = {kSize, kSize};
    fft_ = kiss_fftnd_alloc(dims, 2, 1, nullptr, nullptr);
}

CpuSurface::~CpuSurface() { kiss_fft_free(fft_); }

const CpuSurface::Fields& CpuSurface::fieldsAt(double time_s) const { return fieldsFor(time_s, true); }

const CpuSurface::Fields& CpuSurface::displacementFieldsAt(double time_s) const { return fieldsFor(time_s, false); }

const CpuSurface::Fields& CpuSurface::fieldsFor(double time_s, bool derivatives) const
{
    if (!fields_ || fields_->time_s != time_s) {
        fields_ = std::make_unique<Fields>();
        fields_->time_s = time_s;
        for (int c = 0; c < kCascades; ++c)
            evolve(*field_, c, time_s, spectra_[size_t(c)]);
        // (Dx, Dy) and (Dz, dDx/dz): the displacement.
        transform(0, 2);
    }
    if (derivatives && !fields_->hasDerivatives) {
        // (dDy/dx, dDy/dz) and (dDx/dx, dDz/dz): the normal.
        transform(2, 4);
        fields_->hasDerivatives = true;
    }
    return *fields_;
}

void CpuSurface::transform(int firstPacked, int lastPacked) const
{
    std::vector<std::complex<float>> spatial(size_t(kSize) * kSize);
    static_assert(sizeof(kiss_fft_cpx) == sizeof(std::complex<float>));
    for (int c = 0; c < kCascades; ++c)
        for (int p = firstPacked; p < lastPacked; ++p) {
            kiss_fftnd(static_cast<kiss_fftnd_cfg>(fft_),
                       reinterpret_cast<const kiss_fft_cpx*>(spectra_[size_t(c)].packed[size_t(p)].data()),
                       reinterpret_cast<kiss_fft_cpx*>(spatial.data()));
            std::vector<float>& re = fields_->values[size_t(c)][size_t(2 * p)];
            std::vector<float>& im = fields_->values[size_t(c)][size_t(2 * p + 1)];
            re.resize(spatial.size());
            im.resize(spatial.size());
            for (size_t i = 0; i < spatial.size(); ++i) {
                re[i] = spatial[i].real();
                im[i] = spatial[i].imag();
            }
        }
}

void CpuSurface::sample(const Fields& f, glm::dvec2 restPoint_m, const SurfaceFilter& filter, int fieldCount,
                        double* sum) const
{
    for (int v = 0; v < fieldCount; ++v)
        sum[v] = 0.0;
    for (int c = 0; c < kCascades; ++c) {
        const Cascade& cascade = field_->cascades[size_t(c)];
        const double weight = cascadeWeight(cascade, filter.footprint_m);
        if (weight <= 0.0)
            continue;
        // Sample (col, row) holds world (col, row) * L/N, repeating every L.
        const double scale = kSize / cascade.patch_m;
        const double sx = restPoint_m.x * scale, sz = restPoint_m.y * scale;
        const double x0 = std::floor(sx), z0 = std::floor(sz);
        const double fx = sx - x0, fz = sz - z0;
        auto wrap = [](double v) { return int(v - kSize * std::floor(v / kSize)); };
        const int c0 = wrap(x0), c1 = (c0 + 1) % kSize, r0 = wrap(z0), r1 = (r0 + 1) % kSize;
        for (int v = 0; v < fieldCount; ++v) {
            const std::vector<float>& a = f.values[size_t(c)][size_t(v)];
            const double top = a[size_t(r0) * kSize + size_t(c0)] * (1.0 - fx) + a[size_t(r0) * kSize + size_t(c1)] * fx;
            const double bottom = a[size_t(r1) * kSize + size_t(c0)] * (1.0 - fx) + a[size_t(r1) * kSize + size_t(c1)] * fx;
            sum[v] += weight * (top * (1.0 - fz) + bottom * fz);
        }
    }
    for (int v = 0; v < fieldCount; ++v)
        sum[v] *= filter.heightScale;
}

SurfacePoint CpuSurface::surfaceAt(glm::dvec2 restPoint_m, double time_s, const SurfaceFilter& filter) const
{
    std::lock_guard lock(mutex_);
    // Packed order -> field: 0 Dx, 1 Dy, 2 Dz, 3 Dxz, 4 Dyx, 5 Dyz, 6 Dxx, 7 Dzz.
    double sum[8];
    sample(fieldsFor(time_s, true), restPoint_m, filter, 8, sum);
    SurfacePoint p;
    p.displacement_m = {sum[0], sum[1], sum[2]};
    // The displaced surface's tangents along rest x and rest z.
    const glm::dvec3 alongX(1.0 + sum[6], sum[4], sum[3]);
    const glm::dvec3 alongZ(sum[3], sum[5], 1.0 + sum[7]);
    p.normal = glm::normalize(glm::cross(alongZ, alongX));
    return p;
}

glm::dvec3 CpuSurface::displacementAt(glm::dvec2 restPoint_m, double time_s, const SurfaceFilter& filter) const
{
    std::lock_guard lock(mutex_);
    double sum[3];
    sample(fieldsFor(time_s, false), restPoint_m, filter, 3, sum);
    return {sum[0], sum[1], sum[2]};
}

} // namespace swell::spectral
