// The swash on a beach: how far up the waves run, from the offshore sea
// (Stockdon, Holman, Howd & Sallenger 2006, "Empirical parameterization of
// setup, swash, and runup", Coastal Engineering 53(7), 573-588), which the
// shading darkens the wet sand by (shaders/swash.glsl, its GLSL twin).
#pragma once

#include "swell/scene/scene.h"

namespace swell::coast {

// The 2% exceedance run-up R2 above the still water level, m, for a sea of
// deep-water significant height H0 (m) and deep-water wavelength L0 of its
// peak period (m), on a foreshore of slope beta (rise over run):
// R2 = 1.1 (setup + swash / 2), with the setup 0.35 beta sqrt(H0 L0) and
// the swash sqrt(H0 L0 (0.563 beta^2 + 0.004)) (Stockdon et al. 2006,
// eqs. 10 to 12 combined in their eq. 19).
double runUp2_m(double offshoreHeight_m, double offshoreWavelength_m, double slope);
// The wave-driven setup of the mean water level at the shore, m: 1.1 times
// 0.35 beta sqrt(H0 L0) (Stockdon et al. 2006, eq. 10, with eq. 19's 1.1).
double setup_m(double offshoreHeight_m, double offshoreWavelength_m, double slope);

// H0 L0 for the scene's sea, m^2: the wave model's significant height
// (4 times its height deviation, m) times the deep-water wavelength of the
// sea's peak period (a swell's when it has one, the wind sea's otherwise,
// the longest listed wave's for listed waves). 0 for a calm sea.
double offshoreHeightTimesWavelength_m2(const Scene& scene, double heightDeviation_m);

} // namespace swell::coast
