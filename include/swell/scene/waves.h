// Gerstner waves on the CPU: the one C++ definition of the wave function,
// the first wave model (src/ocean/gerstner/; the classes that put it behind
// swell::SurfaceQuery and swell::WaveModel are in swell/gerstner_model.h).
// Its GLSL twin is shaders/ocean/gerstner.glsl;
// tests/gl/test_wave_agreement.cpp proves the two agree within 1 mm.
//
// A wave i displaces the rest point x0 (world xz, metres) at time t (s) by
//   theta_i = k_i * dot(d_i, x0) - omega_i * t + phase_i
//   dx, dz  = -Q_i * A_i * d_i * sin(theta_i)
//   dy      =         A_i       * cos(theta_i)
// with wavenumber k = 2*pi/wavelength and omega from the dispersion relation.
#pragma once

#include "swell/export.h"

#include "swell/constants.h"
#include "swell/gpu/limits.h"
#include "swell/gpu/ocean.h"
#include "swell/surface_query.h"

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include <limits>
#include <memory>
#include <span>
#include <string>
#include <vector>

namespace swell {

// One wave as a user writes it.
struct SWELL_API Wave {
    glm::dvec2 direction{1.0, 0.0}; // direction of travel in the xz plane; normalised on use
    double wavelength_m = 10.0;     // crest to crest, m, > 0
    double amplitude_m = 0.1;       // crest height above rest, m, >= 0
    double steepness = 0.5;         // Q, dimensionless, 0..1: 0 is a sine wave, 1 the sharpest crest
    double phase_rad = 0.0;         // phase offset, rad

    bool operator==(const Wave&) const = default;
};

class CoastField;

// The set of waves summed over the ocean, with the water depth they travel in.
struct SWELL_API WaveSet {
    std::vector<Wave> waves;
    // Water depth, m, > 0; infinity means deep water (omega^2 = g*k). Over a
    // coast field, the open sea's: where the waves come from.
    double depth_m = std::numeric_limits<double>::infinity();
    // The waves over a varying bottom (swell/coast_field.h), solved for these
    // waves: each point's phase, height and direction; null: the open sea
    // everywhere. Every function below reads it.
    std::shared_ptr<const CoastField> coast;
};

// The wavenumber vector k*d, rad/m: the normalised direction times
// 2*pi/wavelength. Every function here uses exactly this value, so a caller
// that evaluates theta itself (the GPU upload, tests) should too.
SWELL_API glm::dvec2 wavenumberVector(const Wave& wave);

// Angular frequency, rad/s, of a wave of wavenumber k (rad/m) in water of
// depth depth_m: omega^2 = g*k*tanh(k*depth), or g*k in deep water.
SWELL_API double angularFrequency(double wavenumber_radpm, double depth_m);

// The fold-free measure sum(Q_i * k_i * A_i). Above 1 the surface loops over itself.
SWELL_API double foldMeasure(const WaveSet& set);

// How far a wave set can move the surface from its rest plane, m: up or down
// (the sum of amplitudes) and sideways (the sum of Q * amplitude).
SWELL_API WaveReach waveReach(const WaveSet& set);

// Why a wave set is not usable, or an empty string. Checks finiteness,
// wavelength > 0, amplitude >= 0, steepness in 0..1, depth > 0, a non-zero
// direction, and at most SWELL_MAX_WAVES waves.
SWELL_API std::string validate(const WaveSet& set);

// Scales every steepness so that foldMeasure(set) <= 1. Returns a warning that
// names the waves that contributed most when it had to scale, else "".
SWELL_API std::string limitSteepness(WaveSet& set);

// Displacement (dx, dy, dz), m, of the rest point x0 = (x, z) at time t, s.
SWELL_API glm::dvec3 displacementAt(const WaveSet& set, glm::dvec2 restPoint_m, double time_s);

// Partial derivatives of the displaced position P(x0) = (x0.x, 0, x0.z) + D(x0)
// with respect to the rest coordinates, dimensionless.
struct SWELL_API SurfacePartials {
    glm::dvec3 alongX{1.0, 0.0, 0.0}; // dP/dx0, the tangent
    glm::dvec3 alongZ{0.0, 0.0, 1.0}; // dP/dz0, the binormal
};

// Analytic partial derivatives of the sum at rest point x0 and time t, s.
SWELL_API SurfacePartials partialsAt(const WaveSet& set, glm::dvec2 restPoint_m, double time_s);

// Unit surface normal at the displaced image of rest point x0, from the
// analytic partial derivatives of the sum.
SWELL_API glm::dvec3 normalAt(const WaveSet& set, glm::dvec2 restPoint_m, double time_s);

// The weight of a wave of wavelength_m where the surface is carried by
// samples footprint_m apart (the grid's cells, a pixel's footprint): 0 below
// SWELL_MIN_CELLS_PER_WAVELENGTH samples per wavelength, where it would
// alias, 1 from SWELL_FULL_CELLS_PER_WAVELENGTH on, smooth between. 1 for a
// footprint of 0. The GPU's twin is waveLodWeight() in shaders/ocean/gerstner.glsl.
SWELL_API double waveLodWeight(double wavelength_m, double footprint_m);

// The set as a filter sees it: every amplitude times the horizon fade and
// its wave's waveLodWeight().
SWELL_API WaveSet filteredWaves(const WaveSet& set, const SurfaceFilter& filter);

// Displacement and unit normal at rest point x0 and time t, of the filtered
// set: what the GPU's oceanSurface() computes for the same filter.
SWELL_API SurfacePoint surfaceAt(const WaveSet& set, glm::dvec2 restPoint_m, double time_s, const SurfaceFilter& filter);

// Surface height, m, at world (x, z) = worldPoint_m: solves for the rest
// point whose horizontal image is worldPoint_m, then returns its dy. Accurate
// to well under 1 mm for fold-free sets.
SWELL_API double heightAt(const WaveSet& set, glm::dvec2 worldPoint_m, double time_s);

// The rest point x0 whose displaced horizontal position is worldPoint_m.
// Newton's method on x0 + Dxz(x0) = worldPoint_m with the analytic 2x2
// Jacobian, started at worldPoint_m; a step that does not shrink the residual
// is halved, and a singular Jacobian (a cusp at the fold limit) falls back to
// the fixed-point step. It stops once the residual is below 1e-10 m (or 1e-15
// of the summed amplitudes, for sets too big for that), when no step helps any
// more, or after 100 steps. Fold-free sets typically need 2 to 5 steps.
SWELL_API glm::dvec2 restPointUnder(const WaveSet& set, glm::dvec2 worldPoint_m, double time_s);

// Phase of wave i at rest point origin_m and time t, wrapped to [-pi, pi) in
// double precision. The GPU evaluates theta = k*dot(d, x0 - origin) + this,
// so that float precision is spent only near the camera.
SWELL_API double wrappedPhase(const Wave& wave, double depth_m, glm::dvec2 origin_m, double time_s);

// Many height queries at one time, for buoyancy and picking. The constructor
// does the per-wave work once (wavenumber vectors, amplitude terms, the phase
// at origin_m and time_s); a query then reduces each phase in double relative
// to the origin and solves for the rest point in float, with a polynomial
// sincos over several waves (heightAt) or several points (heightsAt) at a
// time. Build one per frame (about 1 us for 16 waves) and query it freely;
// it is immutable, so threads may share it.
//
// Agrees with swell::heightAt within 1 mm (typically 0.01 mm) for points
// within 10 km of the origin, and degrades slowly beyond; it assumes
// wavelengths of a centimetre or more. The solve is Newton on the rest point
// (a step that does not shrink the residual is halved), at most 12
// evaluations of the waves, stopping once a step is under kStepTolerance_m;
// that last step is then applied to the height to first order. Typical
// queries take 2 or 3 evaluations.
class SWELL_API WaveSampler {
public:
    // Which instructions the queries use. Auto picks AVX2 with FMA where the
    // CPU has them (x86-64 built with GCC or Clang), else Baseline: SSE2 on
    // x86-64, NEON on ARM64. Asking for Avx2 on a CPU without it gives Baseline.
    enum class Simd { Auto, Baseline, Avx2 };

    // The solve stops once a Newton step is shorter than this, m. Newton's
    // convergence is quadratic and the step is applied to first order, so
    // the height error left is of order step^2 * sum(A*k^2): 5 mm gives
    // ~0.01 mm on generated seas, and saves an evaluation on most queries.
    static constexpr float kStepTolerance_m = 5e-3f;

    // An empty sampler: height 0 everywhere.
    WaveSampler() = default;

    // Throws std::invalid_argument when validate(set) fails or a wave's terms
    // do not fit in float. A set over a coast field (WaveSet::coast) is
    // answered by swell::heightAt itself: the field's waves change from
    // point to point, which the per-wave arrays cannot hold.
    WaveSampler(const WaveSet& set, double time_s, glm::dvec2 origin_m, Simd simd = Simd::Auto);

    // Surface height, m, at world (x, z) = worldPoint_m.
    double heightAt(glm::dvec2 worldPoint_m) const;

    // heights_m[i] = height at worldPoints_m[i], computed several points side
    // by side: about 2.5 times the throughput of heightAt for 16 waves. The
    // same solve, so within 1 mm of heightAt, but not bit for bit. The spans
    // must be the same size (else std::invalid_argument).
    void heightsAt(std::span<const glm::dvec2> worldPoints_m, std::span<double> heights_m) const;

    double time_s() const { return time_s_; }
    glm::dvec2 origin_m() const { return origin_m_; }
    int waveCount() const { return waveCount_; }
    // Baseline or Avx2: what the queries actually use.
    Simd simd() const { return simd_; }

    // The per-wave arrays are padded with zero-amplitude waves to a multiple
    // of this many, the widest vector any path uses.
    static constexpr int kLanes = 8;

private:
    friend struct WaveSamplerKernel;

    double time_s_ = 0.0;
    glm::dvec2 origin_m_{0.0, 0.0};
    int waveCount_ = 0;
    float maxOffset_m_ = 0.0f; // sum(Q*A), m: how far a rest point can lie from its image
    Simd simd_ = Simd::Baseline;
    std::shared_ptr<const WaveSet> overCoast_; // the set, when it has a coast field

    // Per wave, struct of arrays. Double for the phase at the query point,
    // float for the solve, which only moves a few metres from it.
    alignas(32) double kxD_[SWELL_MAX_WAVES] = {};    // k*d.x, rad/m
    alignas(32) double kzD_[SWELL_MAX_WAVES] = {};    // k*d.z, rad/m
    alignas(32) double phase0_[SWELL_MAX_WAVES] = {}; // phase at origin and time, rad
    alignas(32) float kx_[SWELL_MAX_WAVES] = {};      // k*d.x, rad/m
    alignas(32) float kz_[SWELL_MAX_WAVES] = {};      // k*d.z, rad/m
    alignas(32) float qax_[SWELL_MAX_WAVES] = {};     // Q*A*d.x, m
    alignas(32) float qaz_[SWELL_MAX_WAVES] = {};     // Q*A*d.z, m
    alignas(32) float jxx_[SWELL_MAX_WAVES] = {};     // Q*A*k*d.x*d.x, dimensionless
    alignas(32) float jxz_[SWELL_MAX_WAVES] = {};     // Q*A*k*d.x*d.z, dimensionless
    alignas(32) float jzz_[SWELL_MAX_WAVES] = {};     // Q*A*k*d.z*d.z, dimensionless
    alignas(32) float amp_[SWELL_MAX_WAVES] = {};     // A, m
    alignas(32) float akx_[SWELL_MAX_WAVES] = {};     // A*k*d.x, dimensionless
    alignas(32) float akz_[SWELL_MAX_WAVES] = {};     // A*k*d.z, dimensionless
};

} // namespace swell
