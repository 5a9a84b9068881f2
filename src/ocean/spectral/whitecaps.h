// How much of the spectral ocean is white: the whitecap climatology the foam
// is calibrated against, and the share of the sea that makes foam.
//
// Whitecap cover grows steeply with the wind, W = 3.84e-6 * U10^3.41
// (Monahan & O'Muircheartaigh 1980, eq. 3; 0.99% at 10 m/s, 10.5% at 20).
// Foam is made where the breaking score (breaking.h: J of cascades 0 and 1
// against its own 5 x 5 texel neighbourhood) is low, so that every stretch
// of sea a few metres across has its share of breaking crests, whatever
// phase of the longest waves lies under it; how low is found for each sea
// on the CPU twin, so that a still's foam covers Monahan's share of it
// (calibratedBreakingRamps, breaking.h).
#pragma once

#include "ocean/spectral/spectral_field.h"

#include "swell/gpu/ocean.h"

namespace swell::spectral {

// Cascades 0 and 1 fold into foam: they hold the waves of metres and more
// that break white. The finer ones ripple: their folds come and go many
// times within a foam lifetime, so foam made by them whitens a speckled
// haze over every breaking region instead of patches (tried: calibrated to
// Monahan's cover it reads as noise).
inline constexpr int kFoamCascades = 2;

// Monahan & O'Muircheartaigh (1980): the fraction of the sea white at U10, m/s.
double monahanWhitecapCover(double windSpeed10_mps);

// The lifetime Monahan's cover is measured at: salt-water foam's e-folding
// time, s (Monahan & O'Muircheartaigh 1986). The breaking is calibrated at
// it; a scene's longer lifetime keeps its foam longer on the same breaking.
inline constexpr double kSaltWaterFoamLifetime_s = SWELL_SOURCE_FOAM_LIFETIME_S;

} // namespace swell::spectral
