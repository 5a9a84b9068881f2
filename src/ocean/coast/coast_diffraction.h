// Internal to the coast field (swell/coast_field.h): the energy that
// diffracts into the lee of obstacles (breakwaters, islands, headlands),
// which the ray solution of coast_march.h leaves to its numerical spreading.
#pragma once

#include "ocean/coast/coast_march.h"

namespace swell::coast {

// Replaces march.energy with the ray solution diffracted by the grid's dry
// cells: a parabolic approximation of the wave's complex amplitude (Radder
// 1979, J. Fluid Mech. 95(1), "On the parabolic equation method for
// water-wave propagation", with the wide-angle [1/1] Pade operator of Kirby
// 1986, J. Geophys. Res. 91(C1), eq. 12) over the local wavenumber, dry
// cells a rigid side wall, marched along the wave's open-sea direction and
// 40 degrees to either side. In the geometric shadow (the straight line
// back to the open sea crosses dry land) and within a wavelength of it the
// energy is what the march carries in from the lit water (or the ray
// solution's, where that is more: a wave healed behind a small obstacle);
// elsewhere the ray solution's times the diffraction coefficient's square
// (the fringes beside a shadow's edge); the breaking cut applied to both.
// Refraction stays the ray solution's: the march turns no crest.
void diffractWave(const DepthGrid& depth, const MarchedWave& wave, double breakerIndex, WaveMarch& march,
                  MarchScratch& scratch);

} // namespace swell::coast
