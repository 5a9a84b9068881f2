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
    // diffractWave
    std::vector<double> energyLimit;
    std::vector<double> energy[3];
    std::vector<float> coefficientSquared, carriedEnergy;
    std::vector<std::uint8_t> wet;
};

WaveMarch marchWave(const DepthGrid& grid, const MarchedWave& wave, double breakerIndex, MarchScratch& scratch);

} // namespace swell::coast
