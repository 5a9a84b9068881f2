// Gerstner waves on the GPU: the GLSL twin of swell::surfaceAt
// (src/ocean/gerstner/gerstner_waves.cpp), the Gerstner model's
// oceanSurface(). tests/gl/test_wave_agreement.cpp proves they agree within 1 mm.
#ifndef SWELL_OCEAN_GERSTNER_GLSL
#define SWELL_OCEAN_GERSTNER_GLSL
#include "swell/gpu/ocean.h"

// The GerstnerWaves block (swell::detail::GerstnerUniforms,
// src/ocean/gerstner/gpu/gerstner_uniforms.h): gerstnerWaves[], sorted longest
// first, and gerstnerWaveCount.
#include "gpu/gerstner_block.glsl"
#include "coast_field.glsl"

// Weight of a wave of wavelength_m where samples lie footprint_m apart:
// waves shorter than SWELL_MIN_CELLS_PER_WAVELENGTH samples would alias, so
// they fade out before they get there (swell::waveLodWeight).
float waveLodWeight(float wavelength_m, float footprint_m)
{
    return smoothstep(SWELL_MIN_CELLS_PER_WAVELENGTH * footprint_m,
                      SWELL_FULL_CELLS_PER_WAVELENGTH * footprint_m, wavelength_m);
}

// Wave i at the rest point: its phase (the open sea's plus what the bottom
// added) and the direction, length, height and steepness the bottom gave it
// there (coast_field.glsl; the open sea's beyond the field).
CoastWave gerstnerWaveAt(int i, vec2 restOffset_m, CoastCell cell, vec4 everyWave, out float theta)
{
    vec2 openDirection = gerstnerWaves[i].direction;
    float openK = gerstnerWaves[i].wavenumber_rad_per_m;
    CoastWave w = coastWave(cell, everyWave, gerstnerWaves[i].coastLayer, openDirection, openK,
                            gerstnerWaves[i].amplitude_m, gerstnerWaves[i].steepness);
    theta = openK * dot(openDirection, restOffset_m) + gerstnerWaves[i].phase_rad + w.phase_rad;
    return w;
}

// The sum of all waves at a rest point given relative to the grid centre.
// heightScale (0..1) is the horizon fade; footprint_m drives the wavelength filter.
SurfacePoint oceanSurface(vec2 restOffset_m, float footprint_m, float heightScale)
{
    vec3 displacement = vec3(0.0);
    // Partial derivatives of the displaced position along rest x and rest z.
    vec3 tangent = vec3(1.0, 0.0, 0.0);
    vec3 binormal = vec3(0.0, 0.0, 1.0);
    CoastCell cell = coastCellAt(restOffset_m);
    vec4 everyWave = coastEveryWaveAt(cell);
    for (int i = 0; i < gerstnerWaveCount; ++i) {
        float weight = waveLodWeight(gerstnerWaves[i].wavelength_m, footprint_m);
        // The waves come longest first: none after this one is resolved either.
        if (weight <= 0.0)
            break;
        float theta;
        CoastWave w = gerstnerWaveAt(i, restOffset_m, cell, everyWave, theta);
        accumulateGerstnerWave(w, w.amplitude_m * heightScale * weight, theta, displacement, tangent, binormal);
    }
    return SurfacePoint(displacement, normalize(cross(binormal, tangent)), 0.0, tangent, binormal, 0.0, 0.0, vec2(0.0));
}

// The index of the first wave shorter than length_m, gerstnerWaveCount if none
// is: the waves come longest first, so a binary search finds it in at most
// log2(SWELL_MAX_WAVES) + 1 look-ups.
int firstWaveShorterThan(float length_m)
{
    int lo = 0, hi = gerstnerWaveCount;
    while (lo < hi) {
        int mid = (lo + hi) / 2;
        bool longer = gerstnerWaves[mid].wavelength_m >= length_m;
        lo = longer ? mid + 1 : lo;
        hi = longer ? hi : mid;
    }
    return lo;
}

// The grid's vertices summed each wave at weight waveLodWeight(wavelength,
// gridFootprint_m) and the pixel resolves it at waveLodWeight(wavelength,
// pixelFootprint_m): only the difference is summed here, its partial
// derivatives added to the grid's (Bruneton et al. 2010, "Real-time realistic ocean
// lighting using seamless transitions from geometry to BRDF", sec. 4: the
// geometry carries the waves the grid resolves, the normals those a pixel
// resolves). Waves the grid holds at full weight that the pixel resolves
// fully too cost nothing here, so a pixel sums only the short ones.
SurfacePoint oceanShading(vec2 restOffset_m, float pixelFootprint_m, float gridFootprint_m, vec3 gridAlongX,
                          vec3 gridAlongZ, float heightScale)
{
    // The sums are linear in the partial derivatives: the band's add to the grid's.
    vec3 tangent = gridAlongX;
    vec3 binormal = gridAlongZ;
    // Waves at least this long have full weight in both sums, and waves at
    // most this long zero weight in both: neither adds anything here.
    float bothFull_m = SWELL_FULL_CELLS_PER_WAVELENGTH * max(gridFootprint_m, pixelFootprint_m);
    float neither_m = SWELL_MIN_CELLS_PER_WAVELENGTH * min(gridFootprint_m, pixelFootprint_m);
    // The slopes of the waves the pixel resolves only in part, or not at all,
    // go to the highlight's spread (Bruneton et al. 2010, sec. 4.2: the
    // filtered-out part of the slope variance becomes BRDF roughness).
    float slopeVariance = 0.0;
    float fade2 = heightScale * heightScale;
    // Start at the band's longest wave rather than skipping the longer ones
    // in the loop: a software rasteriser (llvmpipe) runs the loop's whole
    // body, masked, for every wave any pixel of a block still iterates over.
    int i = firstWaveShorterThan(bothFull_m);
    CoastCell cell = coastCellAt(restOffset_m);
    vec4 everyWave = coastEveryWaveAt(cell);
    for (; i < gerstnerWaveCount; ++i) {
        float wavelength = gerstnerWaves[i].wavelength_m;
        // The waves come longest first: none after this one adds anything either.
        if (wavelength <= neither_m)
            break;
        // Negative where the pixel is wider than the grid's cells (far away):
        // the pixel then takes out what it cannot resolve.
        float weight = waveLodWeight(wavelength, pixelFootprint_m) - waveLodWeight(wavelength, gridFootprint_m);
        float theta;
        CoastWave w = gerstnerWaveAt(i, restOffset_m, cell, everyWave, theta);
        vec2 d = w.direction;
        float k = w.wavenumber_rad_per_m;
        float q = w.steepness;
        float s = sin(theta);
        float c = cos(theta);
        float ka = k * w.amplitude_m * heightScale * weight;
        tangent -= vec3(q * ka * d.x * d.x * c, ka * d.x * s, q * ka * d.x * d.y * c);
        binormal -= vec3(q * ka * d.x * d.y * c, ka * d.y * s, q * ka * d.y * d.y * c);
        float resolved = waveLodWeight(wavelength, pixelFootprint_m);
        float kaFull = k * w.amplitude_m;
        slopeVariance += 0.5 * kaFull * kaFull * fade2 * (1.0 - resolved * resolved);
    }
    // Every shorter wave is wholly unresolved.
    if (i < gerstnerWaveCount)
        slopeVariance += gerstnerWaves[i].tailSlopeVariance * fade2;
    return SurfacePoint(vec3(0.0), normalize(cross(binormal, tangent)), 0.0, tangent, binormal, slopeVariance, 0.0, vec2(0.0));
}

// The footprint's shape left out: each wave is weighed by its length
// against the footprint's size alone.
SurfacePoint oceanShading(vec2 restOffset_m, float pixelFootprint_m, mat2 pixelSteps_m, float gridFootprint_m,
                          vec3 gridAlongX, vec3 gridAlongZ, float heightScale)
{
    return oceanShading(restOffset_m, pixelFootprint_m, gridFootprint_m, gridAlongX, gridAlongZ, heightScale);
}

// No foam, so no bubbles under it.
float oceanFoamBelow(vec2 restOffset_m, float footprint_m) { return 0.0; }
float oceanFoamAtPoint(vec2 restOffset_m, float heightScale) { return 0.0; }
#endif
