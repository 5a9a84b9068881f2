// Internal to the coast field (swell/coast_field.h): one wave's phase and
// energy over a depth grid, marched out from where it enters.
#pragma once

#include "swell/coast_field.h"

#include <cstdint>
#include <utility>
#include <vector>

namespace swell::coast {

// The local wavenumber k, rad/m, of a wave of angular frequency omega_radps
// in water depth_m deep: the root of omega^2 = g k tanh(k h) (Dean &
// Dalrymple 1991, eq. 4.20), from Fenton & McKee's (1990, Coastal Eng. 14,
// eq. 1) explicit approximation refined by two Newton steps (to the double's
// last digits). Deep water (infinite depth, or kh past 20): omega^2 / g.
double localWavenumber(double omega_radps, double depth_m);

// The group velocity C_g = d omega / dk, m/s, at wavenumber k and depth h:
// (c / 2) (1 + 2 k h / sinh(2 k h)) (Dean & Dalrymple 1991, eq. 4.33).
double localGroupVelocity(double omega_radps, double wavenumber_radpm, double depth_m);

// One wave over the grid: its phase S (rad, the first arrival from the edges
// it enters by, with |grad S| = k(h)) and its energy relative to the open
// sea's (E = (A / A0)^2, the flux E C_g along grad S conserved and cut at
// the breaking height). Dry cells and cells no ray reaches are not reached
// (reached[c] = 0).
struct WaveMarch {
    std::vector<double> phase_rad;
    std::vector<double> energy;
    std::vector<double> unbroken; // the energy as it would be were no wave cut: shoaling and refraction alone
    std::vector<glm::dvec2> wavenumber_radpm; // grad S
    std::vector<std::uint8_t> reached;
    std::vector<double> localWavenumber_radpm; // k(h) of the cell's depth; 0 on dry land
};

struct MarchedWave {
    glm::dvec2 direction{1.0, 0.0}; // unit, in the open sea
    double wavenumber_radpm = 0.0;  // in the open sea
    double omega_radps = 0.0;
    double amplitude_m = 0.0;       // in the open sea
};

// The most energy (relative to the open sea's) a wave of open-sea amplitude
// amplitude_m carries in water depth_m deep: its height 2 A0 sqrt(E) at most
// breakerIndex times the depth.
double breakingEnergyLimit(double depth_m, double amplitude_m, double breakerIndex);

// What one wave's marches use and drop, kept by the thread that solves
// the waves one after another: every buffer is the grid's size whatever the
// wave, and made afresh for each wave the kernel mapped and zeroed their
// pages again, wave after wave (a default-scene still under the sanitizers,
// whose allocator maps every large block: 159.6 thousand page faults
// before, 125.0 thousand after). Each user sets what it reads before it
// reads it.
struct MarchScratch {
    // marchWave
    std::vector<std::uint8_t> entry;
    std::vector<std::size_t> order;
    std::vector<glm::dvec2> velocity;
    std::vector<std::pair<double, std::size_t>> trial; // a heap, the least phase on top
    std::vector<double> seedEnergy;
    // marchWave's, for reflectWave: each reached sample's accepted
    // neighbour of least phase, where its ray comes from (size_t(-1): none).
    std::vector<std::size_t> parent;
    // diffractWave
    std::vector<double> energyLimit;
    std::vector<double> energy[3];
    std::vector<float> coefficientSquared, carriedEnergy;
    std::vector<std::uint8_t> wet;
    // diffractWave, for reflectWave: the wet samples the open sea's straight
    // rays reach only across dry land (empty: no dry land).
    std::vector<std::uint8_t> shadowed;
    // reflectWave
    WaveMarch reflected;
    std::vector<int> seedOf, faceAtEdge;
    std::vector<std::size_t> edgeOf;
};

WaveMarch marchWave(const DepthGrid& grid, const MarchedWave& wave, double breakerIndex, MarchScratch& scratch);

// k(h) of every sample for a wave of angular frequency omega_radps; 0 on dry land.
std::vector<double> localWavenumbers(const DepthGrid& grid, double omega_radps);

// Where a march starts: a wet sample, its phase and its energy.
struct MarchSeed {
    std::size_t cell = 0;
    double phase_rad = 0.0;
    double energy = 0.0;
    glm::dvec2 direction{0.0}; // unit, the way it leaves: marchWhileAbove's (marchFromSeeds takes the phase's gradient)
};

// marchWave's march from its seeds (the samples of the edges the open sea
// enters by), over the local wavenumbers k: the first arrival's phase from
// the seeds, and the energy carried from them along its gradient, cut at
// the breaking height (its `unbroken` holds no cut). Each reached sample's
// accepted neighbour of least phase is left in scratch.parent.
WaveMarch marchFromSeeds(const DepthGrid& grid, const MarchedWave& wave, std::vector<double> k,
                         const std::vector<MarchSeed>& seeds, double breakerIndex, MarchScratch& scratch);

// The march of a reflected wave from the faces it leaves (coast_reflection.h):
// marchFromSeeds's phase and carried energy (no breaking cut; no
// `unbroken`), the energy found as each sample is accepted (donor cells:
// in from its accepted neighbours, out to the others in the share of the
// phase's rise across each face), and no march on from a sample whose
// energy is under leastEnergy, so that a reflected wave is marched where it has some
// height, not over the whole grid. The samples it does not march on from
// are reached; those beyond them not. Into `march` (its phase, energy,
// wavenumber and reached).
void marchWhileAbove(const DepthGrid& grid, const MarchedWave& wave, const std::vector<double>& k,
                     const std::vector<MarchSeed>& seeds, double leastEnergy, MarchScratch& scratch,
                     WaveMarch& march);

} // namespace swell::coast
