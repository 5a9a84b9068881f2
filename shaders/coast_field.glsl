// The coast field on the GPU (swell/coast_field.h): the GLSL twin of
// CoastField::waveAt and commonAt (src/ocean/coast/coast_field.cpp), the
// same four texels mixed by the same weights. Included by gerstner.glsl
// after its block (coastLayers, coastOrigin_m, coastSize, coastCell_m).
#ifndef SWELL_COAST_FIELD_GLSL
#define SWELL_COAST_FIELD_GLSL
#include "swell/gpu/bindings.h"

// (phase_rad, gain, wavenumber x, wavenumber z) per coast wave, a layer each.
layout(binding = SWELL_UNIT_OCEAN0) uniform sampler2DArray coastWaves;
// (depth_m, gain, steepness scale, breaking): what every wave shares
// (swell::CoastCommonSample; breaking: the share of the shoaled height the
// breaking cut took, what shaders/surf.glsl draws the surf from).
layout(binding = SWELL_UNIT_OCEAN1) uniform sampler2D coastCommon;

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
#endif
