// The swash's wet sand: how far up a beach the waves run (Stockdon et al.
// 2006, "Empirical parameterization of setup, swash, and runup", Coastal
// Eng. 53(7); the C++ twin, src/ocean/coast/swash.h, is held to it), and
// how much the sand there is darkened. Called by mesh.frag for the island
// and the seabed, the only world geometry the sea runs up.
#ifndef SWELL_SWASH_GLSL
#define SWELL_SWASH_GLSL
#include "frame.glsl"

// The wave-driven setup of the mean water level at the shore, m
// (Stockdon et al. 2006, eq. 10, times eq. 19's 1.1).
float swashSetup_m(float heightTimesWavelength_m2, float slope)
{
    return 1.1 * 0.35 * slope * sqrt(heightTimesWavelength_m2);
}

// The 2% exceedance run-up above the still water level, m: 1.1 (setup +
// swash / 2), the swash sqrt(H0 L0 (0.563 beta^2 + 0.004)) (eq. 19).
float swashRunUp2_m(float heightTimesWavelength_m2, float slope)
{
    float swash_m = sqrt(heightTimesWavelength_m2 * (0.563 * slope * slope + 0.004));
    return swashSetup_m(heightTimesWavelength_m2, slope) + 0.55 * swash_m;
}

// Wet sand's albedo over dry's: water filling the pores and a film over the
// grains trap light by total internal reflection (Lekner & Dorf 1988,
// "Why some things are darker when wet", Appl. Opt. 27(7)); beach sand
// reads about 0.6 of its dry brightness (chosen by eye within that).
const float kWetSandAlbedo = 0.6;

// How wet the ground at height_m above the mean level is, 0..1, on a face
// of unit normal n: soaked up to the setup, drying up the beach to the
// run-up line, which the swash reaches only now and then; 0 without a sea
// (frame.glsl's swashH0L0_m2 is 0) and on faces steeper than 1:1 (walls,
// where the beach's formula does not hold).
float swashWetness(float height_m, vec3 n)
{
    if (swashH0L0_m2 <= 0.0 || height_m < 0.0 || n.y < 0.7)
        return 0.0;
    float slope = sqrt(max(1.0 - n.y * n.y, 0.0)) / n.y;
    float setup = swashSetup_m(swashH0L0_m2, slope);
    float runUp = max(swashRunUp2_m(swashH0L0_m2, slope), setup + 1e-3);
    return 1.0 - smoothstep(setup, runUp, height_m);
}
#endif
