// Internal to the coast field (swell/coast_field.h): the waves that steep
// faces (breakwaters, walls, cliffs) send back, summed with the waves that
// came in.
#pragma once

#include "ocean/coast/coast_march.h"

namespace swell::coast {

// Below this reflection coefficient a face sends nothing back: 1% of the
// energy, a height change of at most 10% in front of it (a gentle beach's
// R is some 0.05), and no march for a coast without steep faces.
inline constexpr double kNegligibleReflection = 0.1;
// The reflected wave is marched on from a sample while its energy there is
// at least this share of the open sea's (a tenth of its height), and fades
// in from there to twice that height: where it ends it moves the sum by
// at most 20%, smoothly; and a coast whose faces reflect a little, as the
// built-in island's steeper shores do (R 0.1 to 0.5 for its longer waves),
// is marched near its shore, not over the whole grid (a fifth of the
// island's samples for its longest wave; half at 1e-3).
inline constexpr double kLeastReflectedEnergy = 1e-2;

// The surf similarity parameter xi = tan(alpha) / sqrt(H / L0) of a slope
// tan(alpha) under waves of height H whose deep-water length is L0
// (Battjes 1974, "Surf similarity", Proc. 14th Coastal Eng. Conf., eq. 1).
double surfSimilarity(double slope, double waveHeight_m, double deepWavelength_m);

// The share of a wave's height a smooth impermeable slope reflects:
// R = a xi^2 / (b + xi^2), a = 1.0 and b = 5.5 (Seelig & Ahrens 1981,
// "Estimation of wave reflection and energy dissipation coefficients for
// beaches, revetments, and breakwaters", CERC Technical Paper 81-1): 1 for a vertical wall (slope infinite), some 0.05 for a beach of 1:20
// under a swell of steepness 0.01.
double reflectionCoefficient(double slope, double waveHeight_m, double deepWavelength_m);

// Adds to `march` (its energy, phase and wavenumber) the wave reflected
// from the grid's steep faces. It reads what marchWave and diffractWave
// left in the scratch for this wave (the incident rays' parents, the
// geometric shadow). Each wet sample beside dry land that the wave runs
// into in the lit sea reflects it with the R of its face's slope under
// waves of height seaHeight_m (the open sea's significant height), its
// crest mirrored in the face (an antinode where the bilinear depth crosses
// zero); the reflected wave is marched out from there as the incident one
// is (marchWhileAbove) and summed with it as complex amplitudes. In the
// geometric shadow, where both reach a point round the same edge, as
// cylindrical waves from it in phase, the reflected one is the incident
// one's diffracted height times the ratio of the two terms of Sommerfeld's
// solution there (Penney & Price 1952, eq. 3.6, far from the shadow lines;
// the two terms of Keller's 1962 edge-diffraction coefficient),
// R sin(beta / 2) / sin(alpha / 2), beta and alpha the angles between the
// wave's direction at the point and the open sea's and the reflected
// wave's directions at the edge it comes round.
void reflectWave(const DepthGrid& depth, const MarchedWave& wave, double seaHeight_m, double breakerIndex,
                 WaveMarch& march, MarchScratch& scratch);

} // namespace swell::coast
