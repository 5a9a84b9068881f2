// The spectral ocean over a sea floor (docs/RENDERING.md "Waves that feel
// the bottom"): its longest cascade's band handed, near the coast, to a few
// long-crested trains that the coast field (swell/coast_field.h) carries
// over the floor, as it does the Gerstner model's waves: shorter and
// slower in shallow water, turning to the contours, shoaling and breaking.
// Offshore the band stays the cascade's own, untouched.
#pragma once

#include "ocean/spectral/spectral_field.h"
#include "swell/coast_field.h"
#include "swell/scene/waves.h"

namespace swell::spectral {

// The trains: the kMaxCoastWaves samples of cascade 0 with the most
// energy, each the travelling wave its sample holds (amplitude 2|h0(k)|,
// phase arg h0(k), direction k/|k|: a sample of frequency k contributes
// 2 Re[h0(k) exp(i(k.x - omega t))] to the height, Tessendorf 2001, eq. 26
// with its partner's term), their amplitudes scaled together so that they
// carry the whole band's height variance, 2 sum |h0|^2 over the band; their
// steepness the field's choppiness (a Gerstner wave's Q A is the
// horizontal displacement's amplitude, the spectrum's lambda A), limited so
// that they do not fold (limitSteepness). In water of depth depth_m (the
// sea's, as the field's dispersion).
WaveSet coastTrainsOf(const SpectralField& field, double depth_m);

// Where the trains take over (swell::coastTrainShare): wholly where the
// depth is at most a quarter of their variance-weighted mean wavelength
// (k h <= pi/2 for it, where it is 10% slower than in deep water), not at
// all from half of it (k h >= pi, where deep water's dispersion holds within
// 0.2%), so that the band stays the cascade's wherever the bottom does not
// change it.
CoastTrainDepths coastTrainDepthsOf(const WaveSet& trains);

} // namespace swell::spectral
