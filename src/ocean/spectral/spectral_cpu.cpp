#include "ocean/spectral/spectral_cpu.h"

#include "swell/waves.h"

#include <kiss_fftnd.h>

#include <glm/geometric.hpp>

#include <algorithm>
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

namespace {

// Field v of one cascade at texel position (sx, sz), bilinear, the patch
// repeating every kSize texels.
struct Bilinear {
    size_t i00, i01, i10, i11; // (row, column) 00, 01, 10, 11
    double fx, fz;
    Bilinear(double sx, double sz)
    {
        const double x0 = std::floor(sx), z0 = std::floor(sz);
        fx = sx - x0;
        fz = sz - z0;
        auto wrap = [](double v) { return int(v - kSize * std::floor(v / kSize)); };
        const int c0 = wrap(x0), c1 = (c0 + 1) % kSize, r0 = wrap(z0), r1 = (r0 + 1) % kSize;
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

void CpuSurface::sample(const Fields& f, glm::dvec2 restPoint_m, const SurfaceFilter& filter, bool derivatives,
                        Sample& out, int cascadeCount) const
{
    out = Sample{};
    for (int c = 0; c < std::min(cascadeCount, kCascades); ++c) {
        const Cascade& cascade = field_->cascades[size_t(c)];
        const double weight = cascadeWeight(cascade, filter.footprint_m);
        if (weight <= 0.0)
            continue;
        // The anti-tiling warp: the cascade is looked up at x + w_c(x).
        const WarpSample warp = warpAt(field_->warps[size_t(c)], restPoint_m);
        // Sample (col, row) holds world (col, row) * L/N, repeating every L.
        const double scale = kSize / cascade.patch_m;
        const glm::dvec2 s = (restPoint_m + warp.offset_m) * scale;
        const Bilinear at(s.x, s.y);
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
    out.displacement_m *= filter.heightScale;
    out.gradDx *= filter.heightScale;
    out.gradDy *= filter.heightScale;
    out.gradDz *= filter.heightScale;
}

SurfacePoint CpuSurface::surfaceAt(glm::dvec2 restPoint_m, double time_s, const SurfaceFilter& filter) const
{
    std::lock_guard lock(mutex_);
    Sample sum;
    sample(fieldsFor(time_s, true), restPoint_m, filter, true, sum);
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
    sample(fieldsFor(time_s, false), restPoint_m, filter, false, sum);
    return sum.displacement_m;
}

double CpuSurface::foldJacobianAt(glm::dvec2 restPoint_m, double time_s, const SurfaceFilter& filter,
                                  int cascadeCount) const
{
    std::lock_guard lock(mutex_);
    Sample sum;
    sample(fieldsFor(time_s, true), restPoint_m, filter, true, sum, cascadeCount);
    return (1.0 + sum.gradDx.x) * (1.0 + sum.gradDz.y) - sum.gradDx.y * sum.gradDz.x;
}

} // namespace swell::spectral
