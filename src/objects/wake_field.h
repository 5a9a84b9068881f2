// The wake field: linear water waves on a square grid of cells that follows
// the moving bodies, stirred by their footprints. Each Fourier mode of the
// height and the surface potential is evolved exactly over a fixed step
// with its own frequency (deep water: omega^2 = g k; any depth: g k tanh(k d)),
// so the waves disperse as real ones do and a body moving at constant speed
// leaves Kelvin's wedge of half-angle asin(1/3) = 19.47 deg (Lamb 1932,
// Hydrodynamics, sec. 256). A plain wave equation (every wave at one speed)
// would leave a Mach cone instead.
//
// The equations are Tessendorf's (2004, "Interactive Water Surfaces", Game
// Programming Gems 4, eq. 1-3; and "Simulating Ocean Water", 2001, eq. 14):
//   d(eta)/dt = K phi,  d(phi)/dt = -g (eta + D),   K = |k| tanh(|k| d)
// with D the bodies' drafts (the pressure they put on the water, over rho g).
// The field holds E = eta + D: flat under a body at rest, so what is drawn
// and what other bodies float on is the waves alone, never the hollow a hull
// already makes. Over a step with D held, (E, phi) turns as a free
// oscillator; between steps a body's move changes D, and E by as much.
//
// Deterministic: the same sources at the same steps give the same field bit
// for bit. Waves are absorbed by a sponge along the border; the grid moves by
// whole cells only (no resampling), so it never blurs the waves it carries.
#pragma once

#include <glm/vec2.hpp>

#include <complex>
#include <cstdint>
#include <limits>
#include <memory>
#include <vector>

namespace swell::detail {

// The wake's fixed step: 30 a second, the rate the floating bodies sample
// the water at (kBodyStepsPerWaterSample steps of 1/120 s), so each of
// their water samples finds a wake state at its very time. The exact modal
// evolution is stable at any step; the step only limits how finely a
// body's motion is followed (a boat at 5 m/s moves 0.17 m, a sixth of a
// 1 m cell, per step).
inline constexpr int kWakeStepsPerSecond = 30;
inline constexpr double kWakeStep_s = 1.0 / kWakeStepsPerSecond;

struct WakeFieldSettings {
    int cells = 256;          // per side; a power of two, 32..1024
    double cellSize_m = 1.0;  // 0.1..10; waves shorter than 2 cells are not carried
    double depth_m = std::numeric_limits<double>::infinity(); // water depth for the dispersion, m
    // Sponge along the border, cells: waves entering it die out before they
    // reach the edge and come back from the other side (the FFT's domain is periodic).
    int spongeCells = 32;
    // When false, every wave travels at dispersionFreeSpeed_m_per_s (a plain
    // wave equation); for tests only.
    bool dispersive = true;
    double dispersionFreeSpeed_m_per_s = 3.0;
};

// The wake's Fourier modes on an n x n grid (row-major, FFT order: index
// p + q n, wavenumber index p - n for p >= n/2) and their exact turn over
// one step of kWakeStep_s (wake_modes.cpp).
struct WakeModes {
    explicit WakeModes(const WakeFieldSettings& settings);

    // From C = F(E + i phi) (n * n modes) to norm * F(E' + i phi') a step
    // later, into `turned` (not overlapping `spectrum`).
    void turn(const std::complex<float>* spectrum, float norm, std::complex<float>* turned) const;

    int cells = 0;
    // Per mode: cos and sin of omega dt, K / omega and g / omega. A mode
    // and its mirror -k have the same (omega depends on |k| only).
    std::vector<float> cosStep, sinStep, kOverOmega, gOverOmega;
};

// The wake's grid for `cells` asked: the next size up whose prime factors
// are 2, 3 and 5 (kissfft's fast radices), so that its FFTs cost about
// n^2 log n: 1021, a prime, would cost about 100 times 1024's, and is drawn
// as 1024; every power of two, 300, 1000... as they are.
int fastWakeCells(int cells);

// A body's footprint on the water: a smooth hollow of volume volume_m3,
// D = D0 (1 - u^2)^2 (1 - v^2)^2 for |u|, |v| < 1, u along the heading over
// halfLength_m and v across it over halfBeam_m (a Wigley-like hull whose
// edges meet the water tangentially, so it sheds no waves shorter than the hull).
struct WakeSource {
    glm::dvec2 centre_m{0.0};  // world x, z
    glm::dvec2 heading{1.0, 0.0}; // unit, the length's direction in x, z
    double halfLength_m = 1.0;
    double halfBeam_m = 1.0;
    double volume_m3 = 0.0;    // displaced water
};

class WakeField {
public:
    explicit WakeField(const WakeFieldSettings& settings);
    ~WakeField();
    WakeField(WakeField&&) noexcept;
    WakeField& operator=(WakeField&&) noexcept;

    // Flat water, step 0, centred on focus_m (snapped to whole cells).
    void reset(glm::dvec2 focus_m);
    // Moves the grid so that its centre is the cell nearest focus_m: the
    // waves stay where they are in the world, cells coming in are flat.
    void recentre(glm::dvec2 focus_m);
    // One step of kWakeStep_s: the water under `sources` as they stand now.
    void step(const std::vector<WakeSource>& sources);
    // The water's depth for the dispersion from the next step on, m (> 0;
    // infinity: deep water): the waves on the grid keep their heights and
    // potentials and travel at the new depth's speeds.
    void setDepth(double depth_m);

    std::int64_t steps() const { return steps_; }
    const WakeFieldSettings& settings() const { return settings_; }
    int cells() const { return settings_.cells; }
    double cellSize_m() const { return settings_.cellSize_m; }
    // World x, z of cell (0, 0)'s centre; cell (i, j) lies at corner + (i, j) * cellSize.
    glm::dvec2 corner_m() const;
    // The cell index of the corner cell in whole cells from the world origin.
    glm::ivec2 cornerCell() const { return cornerCell_; }
    // The wave height E per cell, m, row-major (index i + j * cells, i along x).
    std::vector<float> heights() const;
    // The same into `out`, reusing its storage.
    void heightsInto(std::vector<float>& out) const;
    // The wave height E of cell m (= i + j * cells), m.
    float heightOfCell(std::size_t m) const { return field_[m].real(); }
    // Height at a world point, m, bilinear between cell centres (0 outside).
    double heightAt(glm::dvec2 world_m) const;
    // The foam per cell, 0..1, laid out as heights(): made where the wake's
    // slope passes the breaking steepness, fading as whitecaps do.
    const std::vector<float>& foam() const { return foam_; }

private:
    void addFootprints(const std::vector<WakeSource>& sources, double sign);
    void absorbAtBorder();
    void updateFoam();

    WakeFieldSettings settings_;
    glm::ivec2 cornerCell_{0};
    std::int64_t steps_ = 0;
    // Per cell, E + i phi (m, m^2/s): one complex transform carries both.
    std::vector<std::complex<float>> field_, spectrum_, turned_;
    WakeModes modes_;
    std::vector<float> spongeOfIndex_; // per row or column index, the factor a step keeps
    int spongeWidth_ = 1; // cells along each border where spongeOfIndex_ is below 1
    std::vector<float> foam_;
    std::vector<float> draftChange_; // per cell, how much the footprints' draft changed this step, m
    std::vector<WakeSource> lastSources_; // the footprints in E, taken out again next step
    struct Transforms;
    std::unique_ptr<Transforms> fft_;
};

// Cell index (floor) of world coordinate x for cells of size cellSize_m centred on multiples of it.
int wakeCellOf(double x_m, double cellSize_m);

} // namespace swell::detail
