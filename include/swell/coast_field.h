// Waves over a varying bottom (docs/RENDERING.md "Waves that feel the
// bottom"): for each of a wave set's longest waves, the phase, height and
// direction it takes at each point of a sampled sea floor, solved once when
// the seabed or the waves change, and read by the Gerstner sum on the CPU
// (swell/scene/waves.h) and in GLSL (shaders/coast_field.glsl) from the same
// numbers.
//
// Linear wave theory over a slowly varying bottom (Dean & Dalrymple 1991,
// "Water Wave Mechanics for Engineers and Scientists", ch. 3 and 4):
// - each wave keeps its angular frequency omega from the open sea, and takes
//   the local wavenumber k(h) of the dispersion relation omega^2 = g k tanh(k h)
//   (eq. 4.20): shorter and slower in shallow water;
// - its phase S solves the eikonal |grad S| = k(h) (geometrical optics, the
//   wave rays being the curves along grad S), so crests turn towards the
//   depth contours as Snell's law for waves says (sin(theta) / c constant
//   on straight parallel contours, eq. 4.115);
// - its energy E ~ A^2 is carried along the rays at the group velocity C_g
//   with its flux conserved, div(E C_g grad S / |grad S|) = 0 (eq. 4.112):
//   shoaling H/H0 = sqrt(C_g0 / C_g) (eq. 4.104) and refraction's
//   sqrt(cos(theta0) / cos(theta)) in one;
// - where the sea's height reaches the breaker index times the depth,
//   H <= gamma h with gamma = 0.78 (McCowan 1894, the solitary wave's limit),
//   the waves are cut to it: the surf zone's height follows the depth down;
// - on dry land (depth <= 0) no wave;
// - behind obstacles (breakwaters, islands, headlands) the height is what
//   diffracts in: a parabolic march of the wave's complex amplitude along
//   its open-sea direction and 40 degrees to either side (Radder 1979, with
//   Kirby's 1986 wide-angle Pade operator), dry land a rigid side wall, read
//   where the straight rays from the open sea cross land and within a
//   wavelength of that shadow; elsewhere the ray solution's height times the
//   march's diffraction coefficient (the fringes beside a shadow's edge);
// - steep faces (breakwaters, walls, cliffs) send part of the wave back:
//   R = xi^2 / (5.5 + xi^2) of a smooth slope (Seelig & Ahrens 1981; the
//   surf similarity xi, Battjes 1974; a vertical wall 1, a gentle beach
//   under 0.1 and nothing), the reflected wave marched out from the faces
//   by the same eikonal and summed with the incident one as complex
//   amplitudes into the same texels (a clapotis before a wall: the phase
//   turns by half a wave across a node, where the height is small); in a
//   shadow its share of what diffracts round the edge is Penney & Price's
//   (1952) far-field ratio, so a rigid breakwater's lee holds their
//   solution with R = 1 within 25%.
// What it cannot do: a wave reflected twice, a reflected wave higher than
// the incident one, a face's material (R is a smooth impermeable slope's),
// refraction and shoaling inside a shadow (the march carries the diffracted
// wave at its height, cut only by breaking), more than one arrival where
// rays cross (the first arrival's phase wins, also in a lee, where the
// phase is the wave's from around the tip), and waves shorter than the
// coast waves feel the bottom only through the breaking cut and the dry
// land (they keep the open sea's phase): see RENDERING.md.
#pragma once

#include "swell/constants.h"
#include "swell/export.h"
#include "swell/surface_query.h"

#include <glm/vec2.hpp>
#include <glm/vec4.hpp>

#include <cstddef>
#include <limits>
#include <memory>
#include <span>
#include <vector>

namespace swell {

struct WaveSet;

// The sea floor's depth sampled on a square grid: what a coast field is
// solved on. Sample (i, j) lies at origin_m + cell_m * (i, j) in world x, z.
struct SWELL_API DepthGrid {
    glm::dvec2 origin_m{0.0};  // world x, z of sample (0, 0), m
    double cell_m = 1.0;       // spacing of the samples, m, > 0
    glm::ivec2 size{0};        // samples along x and z, each 2..kMaxCoastGridSide
    std::vector<float> depth_m; // depth below the sea's mean level, m, row by row along x; <= 0 is dry land
    // The depth beyond the grid, m (infinity: deep water): the open sea the
    // waves arrive from. The grid's own edges should lie in it.
    double outsideDepth_m = std::numeric_limits<double>::infinity();

    float at(int i, int j) const { return depth_m[std::size_t(j) * std::size_t(size.x) + std::size_t(i)]; }
};

// The largest grid side a coast field accepts: 1024 x 1024 samples a wave.
inline constexpr int kMaxCoastGridSide = 1024;
// The breaker index gamma, kBreakerIndex: swell/constants.h (the shaders' too).
// How many of a set's waves, longest first, get a field of their own.
inline constexpr std::size_t kMaxCoastWaves = 16;

// One coast wave at one point: what replaces the open sea's values in the
// Gerstner sum (swell/scene/waves.h).
struct CoastWaveSample {
    double phase_rad = 0.0;      // added to the open sea's phase k0 d0 . x - omega t + phi
    double gain = 1.0;           // times the wave's amplitude: shoaling, refraction, breaking; 0 on land
    glm::dvec2 wavenumber_radpm; // the local wavenumber vector: grad of the phase, rad/m
};

// What every wave shares at one point.
struct CoastCommonSample {
    double depth_m = std::numeric_limits<double>::infinity(); // the grid's, bilinear
    double gain = 1.0;            // the breaking cut and dry land, for the waves without a field
    double steepnessScale = 1.0;  // times every Q, so the local sum of Q k A stays <= 1 (no loops)
    // How hard the waves break here, 0..1: the share of the shoaled height
    // (all waves' 2A summed) the breaking cut took, 1 - (gamma h / that
    // height) where it exceeds gamma h; 0 offshore, where none breaks, and
    // on dry land. What the surf's whitewater is drawn from (shaders/surf.glsl).
    double breaking = 0.0;
};

// Where a wave model hands its longest band to coast trains (WaveSet
// waves solved over a field: the spectral model's; docs/RENDERING.md "Waves
// that feel the bottom"): the trains carry all of it where the depth is at
// most fullDepth_m, none where it is noneDepth_m or more, and none at the
// field's edges and beyond.
struct CoastTrainDepths {
    double fullDepth_m = 0.0; // m, > 0
    double noneDepth_m = 0.0; // m, > fullDepth_m
};

class CoastField;
namespace detail {
struct CoastFieldBytes;
}

// The trains' share b of the band at world point (x, z): 1 - smoothstep
// between the two depths of the field's bilinear depth there, times how far
// inside its edge blend the point lies. The band's own waves are weighed by
// sqrt(1 - b) and the trains by sqrt(b), so that their height variance adds
// up to the band's wherever the two are independent. The GLSL twin is
// coast_field.glsl's coastTrainShare.
SWELL_API double coastTrainShare(const CoastField& field, const CoastTrainDepths& depths, glm::dvec2 world_m);

class SWELL_API CoastField {
public:
    // Solves the field of each of the min(kMaxCoastWaves, n) longest waves
    // of `waves` (their amplitudes the open sea's, at depth waves.depth_m;
    // of equal lengths, the first listed). Throws swell::Error when the grid
    // is not usable (its size, a NaN depth).
    CoastField(const WaveSet& waves, DepthGrid depth, double breakerIndex = kBreakerIndex);

    const DepthGrid& depth() const { return depth_; }
    // The coast waves: how many, and which layer holds wave i of the set
    // (-1: none, a shorter wave, read with the common gain alone).
    std::size_t waveCount() const { return layers_.size(); }
    int layerOf(std::size_t wave) const { return wave < layerOfWave_.size() ? layerOfWave_[wave] : -1; }
    // Texels of one layer, as the GPU's texture array holds them, row by row
    // along x: (phase_rad, gain, wavenumber x, wavenumber z).
    std::span<const glm::vec4> layer(std::size_t layer) const { return layers_[layer]; }
    // Texels every wave shares: (depth_m, gain, steepnessScale, breaking).
    std::span<const glm::vec4> common() const { return common_; }
    // How far the waves may move the surface anywhere, m: the open sea's
    // reach or, where shoaling raises them before they break, the largest
    // sum over the field's texels of each wave's amplitude (and Q times it,
    // sideways) times its gain there.
    WaveReach reach() const { return reach_; }

    // Bilinear between the four texels around world point (x, z), as the
    // GLSL twin reads them; beyond the grid, the open sea's values.
    // `layer` is layerOf(the wave); beyond the grid, or for no layer, the open sea's.
    CoastWaveSample waveAt(int layer, glm::dvec2 world_m, glm::dvec2 openWavenumber_radpm) const;
    CoastCommonSample commonAt(glm::dvec2 world_m) const;

    // The band along the grid's edges over which the field is blended into
    // the open sea's values, in samples.
    int edgeBand() const;
    // How far inside that blend world point (x, z) lies: 0 at the grid's
    // edge and beyond, 1 a band or more inside; smooth between. Read at the
    // point itself, not from texels, as coast_field.glsl does.
    double inside(glm::dvec2 world_m) const;

private:
    // The cache on disk of derived data keeps the solved texels and gives
    // a field back from them (src/ocean/coast/coast_cache.cpp).
    friend struct detail::CoastFieldBytes;
    CoastField() = default;

    DepthGrid depth_;
    std::vector<std::vector<glm::vec4>> layers_;
    std::vector<int> layerOfWave_;
    std::vector<glm::vec4> common_;
    WaveReach reach_;
};

} // namespace swell
