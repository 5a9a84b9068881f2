// The coast field on the GPU (swell/coast_field.h): the GLSL twin of
// CoastField::waveAt and commonAt (src/ocean/coast/coast_field.cpp), the
// same four texels mixed by the same weights, and of the trains a wave
// model hands the field (coastTrainShare, coastTrainsSurface). Every wave
// model's GPU half binds its block and units (ocean/coast/gpu/coast_gpu.h).
#ifndef SWELL_COAST_FIELD_GLSL
#define SWELL_COAST_FIELD_GLSL
#include "swell/gpu/bindings.h"
#include "swell/gpu/ocean.h"

// The Coast block (swell::detail::CoastUniforms,
// src/ocean/coast/gpu/coast_uniforms.h): coastLayers (0: no field),
// coastOrigin_m (sample (0, 0) relative to the grid centre), coastSize,
// coastCell_m, the trains and where they take over.
#include "gpu/coast_block.glsl"

// (phase_rad, gain, wavenumber x, wavenumber z) per coast wave, a layer each.
layout(binding = SWELL_UNIT_COAST_WAVES) uniform sampler2DArray coastWaves;
// (depth_m, gain, steepness scale, breaking): what every wave shares
// (swell::CoastCommonSample; breaking: the share of the shoaled height the
// breaking took, what shaders/surf.glsl draws the surf from).
layout(binding = SWELL_UNIT_COAST_COMMON) uniform sampler2D coastCommon;

// Where a rest point falls among the field's samples: the lower corner of
// its cell and its place in it; inside false beyond the grid.
struct CoastCell {
    ivec2 corner;
    vec2 f;
    bool inside;
};

CoastCell coastCellAt(vec2 restOffset_m)
{
    CoastCell cell;
    vec2 u = (restOffset_m - coastOrigin_m) / coastCell_m;
    vec2 last = vec2(coastSize - 1);
    cell.inside = coastLayers > 0 && all(greaterThanEqual(u, vec2(0.0))) && all(lessThanEqual(u, last));
    cell.corner = min(ivec2(u), coastSize - 2);
    cell.f = u - vec2(cell.corner);
    return cell;
}

vec4 coastWaveAt(CoastCell cell, int layer)
{
    vec4 t00 = texelFetch(coastWaves, ivec3(cell.corner, layer), 0);
    vec4 t10 = texelFetch(coastWaves, ivec3(cell.corner + ivec2(1, 0), layer), 0);
    vec4 t01 = texelFetch(coastWaves, ivec3(cell.corner + ivec2(0, 1), layer), 0);
    vec4 t11 = texelFetch(coastWaves, ivec3(cell.corner + ivec2(1, 1), layer), 0);
    return mix(mix(t00, t10, cell.f.x), mix(t01, t11, cell.f.x), cell.f.y);
}

vec4 coastCommonAt(CoastCell cell)
{
    vec4 t00 = texelFetch(coastCommon, cell.corner, 0);
    vec4 t10 = texelFetch(coastCommon, cell.corner + ivec2(1, 0), 0);
    vec4 t01 = texelFetch(coastCommon, cell.corner + ivec2(0, 1), 0);
    vec4 t11 = texelFetch(coastCommon, cell.corner + ivec2(1, 1), 0);
    return mix(mix(t00, t10, cell.f.x), mix(t01, t11, cell.f.x), cell.f.y);
}

// What every wave shares at the cell's point: the field's texels, or the
// open sea's (depth unused, gain 1, steepness scale 1, no breaking) beyond the grid.
vec4 coastEveryWaveAt(CoastCell cell)
{
    return cell.inside ? coastCommonAt(cell) : vec4(0.0, 1.0, 1.0, 0.0);
}

// One wave as the bottom has made it at the rest point: its direction,
// wavenumber, amplitude and steepness, and the phase it adds to the open
// sea's (swell::gerstner::evaluateOverCoast).
struct CoastWave {
    vec2 direction;
    float wavenumber_rad_per_m;
    float amplitude_m;
    float steepness;
    float phase_rad;
};

CoastWave coastWave(CoastCell cell, vec4 everyWave, int layer, vec2 direction, float k, float amplitude_m, float q)
{
    CoastWave w = CoastWave(direction, k, amplitude_m, q, 0.0);
    if (!cell.inside)
        return w;
    w.steepness *= everyWave.z;
    if (layer < 0) {
        w.amplitude_m *= everyWave.y;
        return w;
    }
    vec4 t = coastWaveAt(cell, layer);
    w.phase_rad = t.x;
    w.amplitude_m *= t.y;
    float local = length(t.zw);
    if (local > 0.0) {
        w.wavenumber_rad_per_m = local;
        w.direction = t.zw / local;
    }
    return w;
}

// swell::coastTrainShare: the trains' share b of a model's longest band at
// the rest point, from the field's bilinear depth and how far inside its
// edge blend the point lies (CoastField::inside).
float coastTrainShare(CoastCell cell, vec4 everyWave, vec2 restOffset_m)
{
    if (!cell.inside || coastTrainCount == 0)
        return 0.0;
    vec2 u = (restOffset_m - coastOrigin_m) / coastCell_m;
    vec2 last = vec2(coastSize - 1);
    float edge = min(min(u.x, u.y), min(last.x - u.x, last.y - u.y));
    float inside = smoothstep(0.0, 1.0, edge / coastEdgeBand_cells);
    return (1.0 - smoothstep(coastTrainsFullDepth_m, coastTrainsNoneDepth_m, everyWave.x)) * inside;
}

// One Gerstner wave's share of the sum at its phase theta, with the
// amplitude its caller weighed: the displacement and the partials along
// rest x and z (swell::gerstner::accumulate, the CPU's). Shared by the
// Gerstner model's sum (ocean/gerstner.glsl) and the trains below.
void accumulateGerstnerWave(CoastWave w, float amplitude, float theta, inout vec3 displacement, inout vec3 alongX,
                            inout vec3 alongZ)
{
    vec2 d = w.direction;
    float q = w.steepness;
    float s = sin(theta);
    float c = cos(theta);
    displacement += vec3(-q * amplitude * d.x * s, amplitude * c, -q * amplitude * d.y * s);
    float ka = w.wavenumber_rad_per_m * amplitude;
    alongX -= vec3(q * ka * d.x * d.x * c, ka * d.x * s, q * ka * d.x * d.y * c);
    alongZ -= vec3(q * ka * d.x * d.y * c, ka * d.y * s, q * ka * d.y * d.y * c);
}

// The trains' sum at the rest point, each weighed by waveLodWeight at the
// footprint and by `scale` (the caller's sqrt(b) times its height fade):
// the displacement and the partial derivatives along rest x and z, less
// the rest point's own (1, 0, 0) and (0, 0, 1). The CPU twin is the
// Gerstner sum over the field (swell::gerstner::evaluateOverCoast) of the
// trains' WaveSet, filtered alike.
void coastTrainsSurface(vec2 restOffset_m, CoastCell cell, vec4 everyWave, float footprint_m, float scale,
                        inout vec3 displacement, inout vec3 alongX, inout vec3 alongZ)
{
    for (int i = 0; i < coastTrainCount; ++i) {
        float weight = smoothstep(SWELL_MIN_CELLS_PER_WAVELENGTH * footprint_m,
                                  SWELL_FULL_CELLS_PER_WAVELENGTH * footprint_m, coastTrains[i].wavelength_m);
        // Longest first: none after this one is resolved either.
        if (weight <= 0.0)
            break;
        vec2 openDirection = coastTrains[i].direction;
        float openK = coastTrains[i].wavenumber_rad_per_m;
        CoastWave w = coastWave(cell, everyWave, coastTrains[i].layer, openDirection, openK,
                                coastTrains[i].amplitude_m, coastTrains[i].steepness);
        float theta = openK * dot(openDirection, restOffset_m) + coastTrains[i].phase_rad + w.phase_rad;
        accumulateGerstnerWave(w, w.amplitude_m * weight * scale, theta, displacement, alongX, alongZ);
    }
}
#endif
