// Gerstner waves on the GPU: the GLSL twin of swell::displacementAt and
// swell::normalAt (src/core/waves.cpp). tests/gl/test_wave_agreement.cpp
// proves they agree within 1 mm.
#ifndef SWELL_WAVES_GLSL
#define SWELL_WAVES_GLSL
#include "swell/shader_constants.h"

// Mirrored by swell::detail::WaveUniforms. Sorted longest wave first.
layout(std140, binding = SWELL_BINDING_WAVES) uniform Waves {
    vec4 waveShape[SWELL_MAX_WAVES]; // xy: direction of travel (unit), z: wavenumber k, rad/m, w: amplitude, m
    vec4 wavePhase[SWELL_MAX_WAVES]; // x: steepness Q, y: phase at the grid centre and this time, rad, z: wavelength, m
    ivec4 waveCount;                 // x: number of waves in use
};

struct SurfacePoint {
    vec3 displacement; // from the rest point, m
    vec3 normal;       // unit, pointing up
};

// Weight of a wave of wavelength_m on a grid whose cells are cellSize_m wide:
// waves shorter than SWELL_MIN_CELLS_PER_WAVELENGTH cells would alias, so they
// fade out before they get there.
float waveLodWeight(float wavelength_m, float cellSize_m)
{
    return smoothstep(SWELL_MIN_CELLS_PER_WAVELENGTH * cellSize_m,
                      SWELL_FULL_CELLS_PER_WAVELENGTH * cellSize_m, wavelength_m);
}

// The sum of all waves at a rest point given relative to the grid centre.
// heightScale (0..1) is the horizon fade; cellSize_m drives the wavelength filter.
SurfacePoint gerstnerSum(vec2 restOffset_m, float cellSize_m, float heightScale)
{
    vec3 displacement = vec3(0.0);
    // Partial derivatives of the displaced position along rest x and rest z.
    vec3 tangent = vec3(1.0, 0.0, 0.0);
    vec3 binormal = vec3(0.0, 0.0, 1.0);
    for (int i = 0; i < waveCount.x; ++i) {
        float weight = waveLodWeight(wavePhase[i].z, cellSize_m);
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
    return SurfacePoint(displacement, normalize(cross(binormal, tangent)));
}
#endif
