// The spectral ocean's CPU twin: the same spectra the GPU evolves, inverse
// transformed with kissfft, sampled with the same bilinear weights and the
// same per-cascade LOD weights as shaders/ocean/spectral.glsl, each cascade
// at its anti-tiling warp's point (spectral_warp.h).
//
// Only what a query reads is computed, and kept until another time is
// asked for. A 2D inverse transform is two passes of 1D transforms: every
// row of the spectrum along x, then each column along z; a column of the
// second pass gives one column of texels, all rows. So a query transforms
// the rows of the cascades it weighs (none of a cascade its filter leaves
// out) and then only the columns its bilinear samples touch: for floating
// bodies, whose water is a few metres across, a small part of a coarse
// cascade's 256. The derivative fields (for normals) likewise only when a
// query needs them. Every texel is made the same way whichever query asks
// first, so an answer never depends on the queries before it.
#pragma once

#include "ocean/spectral/spectral_field.h"
#include "swell/coast_field.h"
#include "swell/scene/waves.h"
#include "swell/wave_model.h"

#include <atomic>
#include <complex>
#include <cstdint>
#include <functional>
#include <memory>
#include <mutex>

namespace swell::detail {
class Worker;
}

namespace swell::spectral {

// The weight of cascade c where samples lie footprint_m apart: the GLSL
// twin is cascadeWeight() in shaders/ocean/spectral.glsl. A cascade is drawn
// in geometry only where its shortest wave is resolved (swell::waveLodWeight
// of that wavelength); 1 for a footprint of 0.
double cascadeWeight(const Cascade& cascade, double footprint_m);

// Where the first cascade's exact field fades (cascadeWeight below 1), its
// filtered field takes the rest: the same field averaged over texels as
// wide as the footprint (its mip chain, each level's texel the mean of the
// 2 x 2 below it, read at displacementLevel() through a cubic B-spline over
// the level's texels, whose lines a bilinear read creased), so the swell it holds stays
// in the geometry where its short waves would alias. Without it a far
// vertex lost the whole cascade, and with it every wave longer than its
// band's start: the storm's 300 m swell went flat 470 m off. The other
// cascades keep their exact fields alone: with theirs (drawn while the
// cells resolved their mean wavelength), the storm's foam seen from 20 m
// showed a lattice 0.23 m apart, about the grid's cells there
// (FoamTexture.NoCellsFrom20m: a peak 13.2 times its ring's median, 14.0
// through the B-spline, against 9.6): waves of a few cells each facet the
// drawn surface cell by cell. The GLSL twins are in
// shaders/ocean/spectral.glsl.
// 1 - cascadeWeight for the first SWELL_FFT_FILTERED_CASCADES, 0 for the others.
double filteredCascadeWeight(const SpectralField& field, int c, double footprint_m);
// The level of a cascade's mip chain whose texels are footprint_m wide,
// 0 .. log2(kSize), fractional: the two levels about it are blended.
double displacementLevel(const Cascade& cascade, double footprint_m);

// The field over a sea floor (spectral_coast.h): the trains solved over
// their coast field (trains.coast) and where they take over.
struct CoastTrains {
    WaveSet trains;
    CoastTrainDepths depths;
};

class CpuSurface {
public:
    // `coast` null: the open sea everywhere. Otherwise, at each point, every
    // cascade is weighed by the field's common gain (the breaking cut, no
    // water on dry land), cascade 0 also by sqrt(1 - b) and the trains added
    // at sqrt(b), b = coastTrainShare (the GLSL twin: spectral.glsl).
    explicit CpuSurface(std::shared_ptr<const SpectralField> field, std::shared_ptr<const CoastTrains> coast = nullptr);
    ~CpuSurface();

    // The displacement and normal at a rest point (world x,z) and time.
    // Thread-safe; transforms the fields when `time_s` differs from the last.
    SurfacePoint surfaceAt(glm::dvec2 restPoint_m, double time_s, const SurfaceFilter& filter) const;

    // The displacement alone, m: the same as surfaceAt().displacement_m, but
    // transforms only the displacement fields (2 of the 4 transforms a
    // cascade) when `time_s` is new. What height queries and
    // restPointUnder() need.
    glm::dvec3 displacementAt(glm::dvec2 restPoint_m, double time_s, const SurfaceFilter& filter) const;

    // The Jacobian of the horizontal displacement of cascades
    // 0..cascadeCount-1 at a rest point and time, each weighed for the
    // filter's footprint as the surface is: where the surface folds, and
    // foam is made. The GLSL twin is foldJacobian() in
    // shaders/ocean/spectral.glsl. Thread-safe.
    double foldJacobianAt(glm::dvec2 restPoint_m, double time_s, const SurfaceFilter& filter, int cascadeCount) const;

    // The 8 spatial fields of every cascade at time_s (Dx, Dy, Dz, dDx/dz,
    // dDy/dx, dDy/dz, dDx/dx, dDz/dz), N*N each, row = z: for tests and the
    // model's constructor. Not thread-safe, unlike the queries: the
    // reference holds until the next call for another time.
    struct Fields {
        double time_s = 0.0;
        bool hasDerivatives = false; // fields 4..7 (and their spectra transformed)
        std::array<std::array<std::vector<float>, 8>, kCascades> values;
    };
    const Fields& fieldsAt(double time_s) const;
    // The same fields, the cascades shared between `worker` and the calling
    // thread (each takes the next cascade not yet taken): each cascade is
    // made on one thread exactly as fieldsAt() makes it, so every float is
    // fieldsAt()'s, bit for bit, whichever thread made it. `made(fields, c)`
    // runs on the thread that made cascade c as soon as its fields are there
    // (so what the caller does with a cascade's fields shares the split).
    // Not thread-safe, as fieldsAt(); what an interactive view uploads on a
    // software rasteriser (spectral/gpu/spectral_gpu.cpp), whose other core is idle
    // while one thread transforms.
    const Fields& fieldsAt(double time_s, detail::Worker& worker,
                           const std::function<void(const Fields& fields, int cascade)>& made) const;
    // Only fields 0..3 (Dx, Dy, Dz, dDx/dz) are sure to be there.
    const Fields& displacementFieldsAt(double time_s) const;

    // Texel columns transformed since the twin was made (every packed pair
    // of every cascade, one column of kSize texels each): what the queries
    // cost, for tests.
    std::int64_t columnsTransformed() const;

private:
    std::shared_ptr<const SpectralField> field_;
    mutable std::mutex mutex_;
    // The fields at fields_.time_s (NaN before the first time asked), each
    // vector kSize * kSize once any of its columns is made.
    mutable Fields fields_;
    // What of each cascade is made for fields_.time_s.
    struct CascadeState {
        bool evolved = false;
        Spectra spectra;
        // Per packed pair: its rows transformed along x (kSize * kSize, row = kz),
        // and which of its texel columns are made.
        std::array<bool, 4> rowsDone{};
        std::array<std::vector<std::complex<float>>, 4> rows;
        std::array<std::vector<std::uint8_t>, 4> columnDone;
        // The displacement's mip chain (Dx, Dy, Dz), levels 1 .. log2(kSize),
        // each texel made when a query first reads it (from the level-0
        // columns under it): a floating body's query makes a few.
        bool mipsUsed = false; // since the time started
        std::vector<std::array<std::vector<float>, 3>> mips; // [level - 1][field]
        std::vector<std::vector<std::uint8_t>> mipDone;      // [level - 1][texel]
    };
    mutable std::array<CascadeState, kCascades> cascades_;
    // Atomic: the split fieldsAt() counts from two threads.
    mutable std::atomic<std::int64_t> columnsTransformed_ = 0;
    // Starts a new time: nothing of it is made yet (the buffers are kept).
    void startTime(double time_s) const;
    // Makes packed pair p's texel column `column` of cascade c at
    // fields_.time_s, with the 1D transform `fft` (kiss_fft_cfg: fft_, or
    // workerFft_ on the split's worker; both the same inverse of kSize).
    void makeColumn(int c, int p, int column, void* fft) const;
    void makeColumn(int c, int p, int column) const { makeColumn(c, p, column, fft_); }
    // Makes every column of packed pairs [0, lastPacked) of cascade c.
    void makeCascade(int c, int lastPacked, void* fft) const;
    // Makes every column of packed pairs [firstPacked, lastPacked) of every cascade.
    void makeAll(int firstPacked, int lastPacked) const;
    // Field f (0..2: Dx, Dy, Dz) of cascade c's texel (row, column) at
    // `level` of its mip chain, made with the texels under it if not yet,
    // in the order of shaders/mip_blocks.comp and mip_downsample.comp:
    // (a + b) + (c + d), the two pairs along x, then times 1/4, in floats.
    // Every field of the texel is made at once.
    float mipTexel(int c, int level, int row, int column, int f) const;
    // Cascade c's filtered displacement at texel position s (level 0's
    // texels, centres at integers) for a footprint (displacementLevel).
    glm::dvec3 filteredDisplacement(int c, glm::dvec2 s, double footprint_m) const;
    const Fields& fieldsFor(double time_s, bool derivatives) const;
    // The displacement at a rest point and, with derivatives, its gradients
    // along rest x and z: every cascade's bilinear sample at its warped
    // point, LOD weights applied, gradients through the warp's Jacobian.
    // Makes the columns it reads.
    struct Sample {
        glm::dvec3 displacement_m{0.0};                       // Dx, Dy, Dz, m
        glm::dvec2 gradDx{0.0}, gradDy{0.0}, gradDz{0.0}; // (d/dx, d/dz), dimensionless
    };
    // overCoast: with the coast's weights and trains (the surface's
    // queries); without, the patches' own sum (the foam's fold, which the GPU
    // makes in the patches).
    // Without `filtered`, the exact fields alone (the foam's fold, whose
    // displacement is not read).
    void sample(double time_s, glm::dvec2 restPoint_m, const SurfaceFilter& filter, bool derivatives, Sample& out,
                int cascadeCount = kCascades, bool overCoast = true, bool filtered = true) const;
    // The coast's share of the sample (trains, weights): what sample() adds.
    void addCoast(glm::dvec2 restPoint_m, double time_s, const SurfaceFilter& filter, double shareOfBand,
                  Sample& out) const;
    std::shared_ptr<const CoastTrains> coast_;
    void* fft_ = nullptr;       // kiss_fft_cfg: 1D inverse, kSize
    void* workerFft_ = nullptr; // the same, the split's worker's own
};

} // namespace swell::spectral
