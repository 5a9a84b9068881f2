// How much of the spectral ocean is white: the whitecap climatology the foam
// is calibrated against, and the share of the sea that makes foam.
//
// Whitecap cover grows steeply with the wind, W = 3.84e-6 * U10^3.41
// (Monahan & O'Muircheartaigh 1980, eq. 3; 0.99% at 10 m/s, 10.5% at 20).
// Foam is made where the breaking score (breaking.h: J of cascades 0 and 1
// against its own 5 x 5 texel neighbourhood) is among the lowest
// `breakingFraction` of the sea, so that every stretch of sea a few metres
// across has its share of breaking crests, whatever phase of the longest
// waves lies under it; the foam's lifetime then spreads each breaking over
// more area than it had while active, by foamPersistence().
#pragma once

#include "ocean/spectral/spectral_field.h"

#include <array>
#include <vector>

namespace swell::spectral {

// Cascades 0 and 1 fold into foam: they hold the waves of metres and more
// that break white. The finer ones ripple: their folds come and go many
// times within a foam lifetime, so foam made by them whitens a speckled
// haze over every breaking region instead of patches (tried: calibrated to
// Monahan's cover it reads as noise).
inline constexpr int kFoamCascades = 2;

// Monahan & O'Muircheartaigh (1980): the fraction of the sea white at U10, m/s.
double monahanWhitecapCover(double windSpeed10_mps);

// How many times its active area a breaking whitens once its foam has
// spread and faded (3.85 s lifetime), as the mean covered share the shading
// draws. Measured on rendered frames (tests/golden/test_whitecaps.cpp) with
// the breaking score: with 3.06*(20/U10)^1.82, the sea-wide J threshold's
// fit, the cover was 1.54, 2.10, 2.65 and 2.57 times Monahan's at 8, 12,
// 16 and 20 m/s (the score's breakings are scattered, so their foam
// spreads over more sea); with 6.8*(20/U10)^1.26, 1.33, 1.47, 1.83 and
// 1.68 (the cover grows more slowly than the share that breaks); with
// 19.2*(20/U10)^0.75, 0.80, 0.92, 1.10 and 1.00. Persistence falls as the
// wind grows since the breaking regions grow relative to how far their
// foam is carried in its lifetime.
double foamPersistence(double windSpeed10_mps);

// The fraction of the sea that makes foam in full at a time.
double breakingFraction(double windSpeed10_mps);

// J of every sample of one cascade from its fields (dDx/dx, dDz/dz, dDx/dz).
std::vector<float> jacobians(const std::vector<float>& dxx, const std::vector<float>& dzz, const std::vector<float>& dxz);

// The value below which `fraction` of `values` lie (sorting a copy).
float quantile(std::vector<float> values, double fraction);

} // namespace swell::spectral
