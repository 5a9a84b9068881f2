// Gerstner waves on the GPU: the GLSL twin of swell::surfaceAt
// (src/ocean/gerstner/gerstner_waves.cpp), the Gerstner model's
// oceanSurface(). tests/gl/test_wave_agreement.cpp proves they agree within 1 mm.
#ifndef SWELL_OCEAN_GERSTNER_GLSL
#define SWELL_OCEAN_GERSTNER_GLSL
#include "swell/shader_constants.h"

// Mirrored by swell::detail::GerstnerUniforms. Sorted longest wave first.
layout(std140, binding = SWELL_BINDING_OCEAN) uniform GerstnerWaves {
    vec4 waveShape[SWELL_MAX_WAVES]; // xy: direction of travel (unit), z: wavenumber k, rad/m, w: amplitude, m
    vec4 wavePhase[SWELL_MAX_WAVES]; // x: steepness Q, y: phase at the grid centre and this time, rad, z: wavelength, m
    ivec4 waveCount;                 // x: number of waves in use
};

// Weight of a wave of wavelength_m where samples lie footprint_m apart:
// waves shorter than SWELL_MIN_CELLS_PER_WAVELENGTH samples would alias, so
// they fade out before they get there (swell::waveLodWeight).
float waveLodWeight(float wavelength_m, float footprint_m)
{
    return smoothstep(SWELL_MIN_CELLS_PER_WAVELENGTH * footprint_m,
                      SWELL_FULL_CELLS_PER_WAVELENGTH * footprint_m, wavelength_m);
}

// The sum of all waves at a rest point given relative to the grid centre.
// heightScale (0..1) is the horizon fade; footprint_m drives the wavelength filter.
SurfacePoint oceanSurface(vec2 restOffset_m, float footprint_m, float heightScale)
{
    vec3 displacement = vec3(0.0);
    // Partial derivatives of the displaced position along rest x and rest z.
    vec3 tangent = vec3(1.0, 0.0, 0.0);
    vec3 binormal = vec3(0.0, 0.0, 1.0);
    for (int i = 0; i < waveCount.x; ++i) {
        float weight = waveLodWeight(wavePhase[i].z, footprint_m);
        // The waves come longest first: none after this one is resolved either.
        if (weight <= 0.0)
            break;
        vec2 d = waveShape[i].xy;
        float k = waveShape[i].z;
        float amplitude = waveShape[i].w * heightScale * weight;
        float q = wavePhase[i].x;
        float theta = k * dot(d, restOffset_m) + wavePhase[i].y;
        float s = sin(theta);
        float c = cos(theta);
        displacement += vec3(-q * amplitude * d.x * s, amplitude * c, -q * amplitude * d.y * s);
        float ka = k * amplitude;
        tangent -= vec3(q * ka * d.x * d.x * c, ka * d.x * s, q * ka * d.x * d.y * c);
        binormal -= vec3(q * ka * d.x * d.y * c, ka * d.y * s, q * ka * d.y * d.y * c);
    }
    return SurfacePoint(displacement, normalize(cross(binormal, tangent)), 0.0);
}
#endif
