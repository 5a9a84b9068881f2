// Physical and mathematical constants used across Swell, each defined once.
// Those the shaders read too are written into GLSL at build time, under the
// names kGlslConstants (src/gpu/glsl_constants.h) gives them, so C++ and
// GLSL read the one value.
#pragma once

#include <numbers>

namespace swell {

// pi and 2*pi, rad.
inline constexpr double kPi = std::numbers::pi;
inline constexpr double kTwoPi = 2.0 * std::numbers::pi;

// Standard gravity, m/s^2 (CGPM 1901; ISO 80000-3).
inline constexpr double kGravity = 9.80665;

// Refractive index of sea water for visible light (air: 1). 1.333 is pure
// water's at 589 nm and 20 C; sea water's is about 1.34 (Quan and Fry 1995).
// Snell's window's half-angle is asin(1 / n): 48.6 degrees.
inline constexpr double kWaterIor = 1.333;

// The sun's angular diameter, rad (0.53 deg, Allen's Astrophysical
// Quantities): no caustic's focus is sharper than the sun's disc seen from
// the floor.
inline constexpr double kSunAngularDiameter_rad = 0.00925;

// The air (the physical sky: swell/scene/atmosphere.h, src/core/atmosphere.cpp
// and shaders/atmosphere.glsl; docs/RENDERING.md). Coefficients for the
// three wavelengths drawn as red, green and blue: 680, 550 and 440 nm
// (Bruneton 2017's RGB wavelengths).
// The Earth and the top of its atmosphere (Bruneton 2017's Earth).
inline constexpr double kAtmosphereBottomRadius_m = 6360000.0;
inline constexpr double kAtmosphereTopRadius_m = 6420000.0;
// Rayleigh scattering at sea level, 1.24062e-6 / lambda^4 (lambda in um)
// (Bruneton 2017; the same figures in Hillaire 2020, sec. 4), and its
// scale height (Bruneton & Neyret 2008, sec. 2.1).
inline constexpr double kRayleighScatteringRed_per_m = 5.802e-6;
inline constexpr double kRayleighScatteringGreen_per_m = 13.558e-6;
inline constexpr double kRayleighScatteringBlue_per_m = 33.1e-6;
inline constexpr double kRayleighScaleHeight_m = 8000.0;
// Aerosols (Mie): Bruneton 2017's Angstrom beta 5.328e-3 over the scale
// height (alpha 0: grey), single-scattering albedo 0.9, so extinction
// 4.44e-6 and scattering 3.996e-6; Cornette-Shanks asymmetry g = 0.8.
inline constexpr double kMieExtinction_per_m = 4.44e-6;
inline constexpr double kMieScattering_per_m = 3.996e-6;
inline constexpr double kMieScaleHeight_m = 1200.0;
inline constexpr double kMieAsymmetry = 0.8;
// Ozone absorbs (it does not scatter): its peak coefficient (Hillaire 2020,
// sec. 4), in a tent profile 1 at 25 km falling to 0 at 10 and 40 km
// (Bruneton 2017's two linear layers).
inline constexpr double kOzoneAbsorptionRed_per_m = 0.650e-6;
inline constexpr double kOzoneAbsorptionGreen_per_m = 1.881e-6;
inline constexpr double kOzoneAbsorptionBlue_per_m = 0.085e-6;
inline constexpr double kOzonePeakAltitude_m = 25000.0;
inline constexpr double kOzoneHalfWidth_m = 15000.0;
// Henyey-Greenstein asymmetry of cloud droplets in visible light: about
// 0.85 (Bohren 1987; Liou 2002, sec. 5.3): strongly forward.
inline constexpr double kCloudDropletAsymmetry = 0.85;

// Sea water's particles (the shafts of light: shaders/light_shafts.glsl,
// src/render/light_shafts.h).
// Their scattering coefficient: Petzold 1972's clear ocean water (the
// Bahamas' Tongue of the Ocean, 530 nm), b = 0.037 (Mobley 1994, "Light and
// Water", table 3.10), the clear water Swell's scenes show.
inline constexpr double kWaterScattering_per_m = 0.037;
// The Henyey-Greenstein 1941 phase function's asymmetry g (the mean cosine
// of the scattering angle) matching Petzold's average particle phase
// function: g = 0.924 (Mobley, Sundman and Boss 2002, "Phase function
// effects on oceanic light fields", Applied Optics 41(6)). So forward a
// lobe that the shafts show mainly looking towards the sun.
inline constexpr double kWaterPhaseG = 0.924;

// Sea water's density (a typical surface value; UNESCO 1981 gives
// 1020..1030 at 35 PSU and 0..25 degC): what floats the bodies, and what
// the spray's sheets and drops weigh.
inline constexpr double kSeaWaterDensity_kg_per_m3 = 1025.0;

// The breaker index gamma: the highest wave a depth h carries is gamma h
// (McCowan 1894; Dean & Dalrymple 1991, sec. 4.6). The coast field cuts the
// waves with it; the surf's shader places a point in its wave by it.
inline constexpr double kBreakerIndex = 0.78;
// Sea water's surface tension, as a sheet of it tears (Taylor-Culick: the
// bow spray's bowSheetRetraction_mps, shaders/spray.glsl).
inline constexpr double kSeaWaterSurfaceTension_N_per_m = 0.073;

} // namespace swell
