// Light through the crests: sunlight that enters the back of a wave, is
// scattered forward by the water and leaves through the face the eye sees.
// Single scattering along the path d through the crest, not a transport
// solution:
//   glow = E_sun * p_HG(theta) * (1 - exp(-b d)) * exp(-a d) * crest
// - p_HG: the Henyey & Greenstein (1941, Astrophys. J. 93, 70, eq. 1) phase
//   function with g = 0.8: ocean water scatters strongly forward (Petzold
//   1972's particle phase functions have g of about 0.9).
// - a: the scene's per-channel absorption (water.absorption_per_m): red is
//   lost first, so the glow is blue-green.
// - b: the scattering coefficient the scene's own deep colour R implies:
//   R = 0.33 b_b / a (Gordon, Brown & Jacobs 1975, Appl. Opt. 14, eq. 2
//   to first order), and particles backscatter b_b = 0.019 b of what they
//   scatter (Petzold 1972, as summarised by Mobley 1994, "Light and Water",
//   sec. 3.8), so b = R a / (0.33 * 0.019).
// - d: the path through the crest, from the sea's height scale sigma:
//   4 sigma at mean level, thinning to sigma at the top of a 2-sigma crest.
// - crest: 0 at or below mean level, 1 for crests 2 sigma up; the sun's
//   light does not reach through the troughs.
#ifndef SWELL_SUBSURFACE_GLSL
#define SWELL_SUBSURFACE_GLSL
#include "gpu/constants.glsl"
#include "frame.glsl"

float henyeyGreenstein(float cosTheta, float g)
{
    float d = 1.0 + g * g - 2.0 * g * cosTheta;
    return (1.0 - g * g) / (4.0 * SWELL_PI * d * sqrt(d));
}

// Radiance the crest at height height_m (above the mean level) sends to the
// eye along v (surface to eye, unit), before Fresnel transmission out.
vec3 crestGlow(float height_m, vec3 v)
{
    float sigma = waveHeightDeviation_m;
    if (sigma <= 0.0 || sunDirection.y <= 0.0)
        return vec3(0.0);
    float crest = smoothstep(0.0, 2.0 * sigma, height_m);
    float path_m = mix(4.0, 1.0, crest) * sigma;
    vec3 scattering = waterDeep * waterAbsorption / (0.33 * 0.019);
    vec3 scattered = (1.0 - exp(-scattering * path_m)) * exp(-waterAbsorption * path_m);
    // Light travels along -sunDirection; forward scattering sends it on to
    // an eye that looks towards the sun.
    float phase = henyeyGreenstein(dot(-sunDirection, v), 0.8);
    return sunColor * sunIntensity * (phase * crest) * scattered;
}
#endif
