// How much of the spectral ocean is white: the whitecap climatology the foam
// is calibrated against, and the fold thresholds that make it so.
//
// Whitecap cover grows steeply with the wind, W = 3.84e-6 * U10^3.41
// (Monahan & O'Muircheartaigh 1980, eq. 3; 0.99% at 10 m/s, 10.5% at 20).
// The cascades' Jacobians do not: the spectrum's shape scales with its peak
// and so do the cascades, so each cascade's distribution of J is nearly the
// same at every wind. Foam is therefore made where J (of cascades 0 and 1
// together) is among the lowest `breakingFraction` of the sea - the most
// compressed, crest-folding parts of the surface - with that fraction set
// from W; the foam's lifetime then spreads each breaking over more area than
// it had while active, by foamPersistence() (measured on rendered frames,
// see tests/golden/test_whitecaps.cpp).
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

// How many times its active area a breaking whitens once its foam has
// spread and faded (3.85 s lifetime), as the mean covered share the shading
// draws. Measured on rendered frames with a fixed factor of 2.8: 6.51, 2.81,
// 1.85 and 1.23 times Monahan's cover at 8, 12, 16 and 20 m/s, so the
// factor was 18.2, 7.9, 5.2 and 3.4 there, about 3.44*(20/U10)^1.82; with
// that, 0.86, 0.88, 0.92 and 0.90 times Monahan, so 0.89 times it:
// 3.06*(20/U10)^1.82. Persistence falls as the wind grows since the breaking
// regions grow relative to how far their foam is carried in its lifetime.
double foamPersistence(double windSpeed10_mps);

// Monahan & O'Muircheartaigh (1980): the fraction of the sea white at U10, m/s.
double monahanWhitecapCover(double windSpeed10_mps);

// The fraction of each foam cascade's samples that make foam at a time.
double breakingFraction(double windSpeed10_mps);

// J of every sample of one cascade from its fields (dDx/dx, dDz/dz, dDx/dz).
std::vector<float> jacobians(const std::vector<float>& dxx, const std::vector<float>& dzz, const std::vector<float>& dxz);

// The value below which `fraction` of `values` lie (sorting a copy).
float quantile(std::vector<float> values, double fraction);

} // namespace swell::spectral
