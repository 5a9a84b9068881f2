// The look of foam on the water: how much of a pixel foam covers, given
// the foam made there, for the spectral ocean's whitecaps (worldFoam() in
// spectral.glsl) and the surface sources' foam (the bodies' wake: its
// stern wash and breaking crests; surface_sources.glsl) alike. Its texture
// is gradient noise on lattices turned from one another and warped
// (src/ocean/foam/foam_texture.h: no cells, seams or repetition at any
// distance), anchored to the world at the rest point, so it rides the
// water's own horizontal motion with the waves; each octave fades into its
// mean where the pixel no longer resolves it. Each caller passes its own
// lattices (its uniform block's, anchored to its own origin) and the foam
// amount that marks a breaking's own foam.
#ifndef SWELL_WHITECAP_FOAM_GLSL
#define SWELL_WHITECAP_FOAM_GLSL
#include "swell/gpu/ocean.h"

// One lattice of the foam's texture (swell::spectral::FoamNoiseMap):
// FoamNoise, cells q = map * x + offset_cells for x from the lattices'
// origin, m (swell::detail::FoamNoiseUniform, src/ocean/foam/gpu/foam_noise_block.h).
#include "gpu/foam_noise.glsl"

// A random gradient at a lattice vertex: an integer hash of the vertex
// modulo the period (multiply-xorshift; GLSL does not specify sin's
// accuracy far from 0, which the usual fract(sin(x) * big) leans on), its
// two halves uniform on -1..1. Uniform in the square rather than on the
// circle, so a little longer along its diagonals: each octave's lattice is
// turned from the others', so the sum keeps no direction. (Unit gradients
// from the hash's angle cost a sine and a cosine each, 28 a pixel: the
// storm's water pass took 249 and 258 ms of CPU a frame with them against
// 206 ms without, llvmpipe at 640x360.)
vec2 foamGradient(ivec2 vertex)
{
    uvec2 q = uvec2(vertex & ivec2(SWELL_FOAM_NOISE_PERIOD - 1));
    uint n = (q.x * 1597334673u) ^ (q.y * 3812015801u);
    n = (n ^ (n >> 16u)) * 0x7feb352du;
    n = (n ^ (n >> 15u)) * 0x846ca68bu;
    n ^= n >> 16u;
    return vec2(uvec2(n & 0xffffu, n >> 16u)) * (2.0 / 65535.0) - 1.0;
}

// Gradient noise (Perlin 2002, with its quintic fade) at q cells and its
// gradient per cell: (value, d/dq.x, d/dq.y). Its standard deviation is
// kFoamNoiseDeviation (measured over 4 million points; 0.216 with unit gradients).
const float kFoamNoiseDeviation = 0.176;
vec3 foamGradientNoise(vec2 q)
{
    vec2 cell = floor(q), f = q - cell;
    ivec2 i = ivec2(cell);
    vec2 g00 = foamGradient(i), g10 = foamGradient(i + ivec2(1, 0));
    vec2 g01 = foamGradient(i + ivec2(0, 1)), g11 = foamGradient(i + ivec2(1, 1));
    float v00 = dot(g00, f), v10 = dot(g10, f - vec2(1.0, 0.0));
    float v01 = dot(g01, f - vec2(0.0, 1.0)), v11 = dot(g11, f - vec2(1.0, 1.0));
    vec2 u = f * f * f * (f * (f * 6.0 - 15.0) + 10.0);
    vec2 du = 30.0 * f * f * (f * (f - 2.0) + 1.0);
    float k = v00 - v10 - v01 + v11;
    float value = v00 + u.x * (v10 - v00) + u.y * (v01 - v00) + u.x * u.y * k;
    vec2 gradient = g00 + u.x * (g10 - g00) + u.y * (g01 - g00) + u.x * u.y * (g00 - g10 - g01 + g11) +
                    du * (vec2(v10 - v00, v01 - v00) + u.yx * k);
    return vec3(value, gradient);
}

// The texture of the lattices foamNoise (the octaves, coarsest first, then
// the warp) at a rest point p_m (from their origin): x a standard normal
// variate (the octaves' sum over its deviation), yz its gradient per metre,
// w how much of it the pixel resolves (0: none, only the mean; 1: two
// octaves or more).
vec4 foamTexture(FoamNoise foamNoise[SWELL_FOAM_NOISE_MAPS], vec2 p_m, float footprint_m)
{
    // The warp: a coarser lattice's gradient (about one a cell) moves the
    // first octave's point by up to half a cell, each octave's gradient the
    // next's: no octave's lattice stays straight over a patch of foam.
    FoamNoise w = foamNoise[SWELL_FOAM_OCTAVES];
    vec2 warp = foamGradientNoise(mat2(w.map.xy, w.map.zw) * p_m + w.offset_cells).yz;
    float sum = 0.0, variance = 0.0, resolvedShare = 0.0;
    vec2 gradient_perm = vec2(0.0);
    for (int i = 0; i < SWELL_FOAM_OCTAVES; ++i) {
        FoamNoise o = foamNoise[i];
        float resolved = 1.0 - smoothstep(0.25, 0.5, footprint_m * o.cyclesPerMetre);
        if (resolved <= 0.0)
            break; // the finer octaves are finer still
        mat2 map = mat2(o.map.xy, o.map.zw);
        vec3 n = foamGradientNoise(map * p_m + o.offset_cells + 0.5 * warp);
        sum += resolved * n.x;
        gradient_perm += resolved * (transpose(map) * n.yz);
        variance += resolved * resolved;
        resolvedShare += resolved;
        warp = n.yz;
    }
    float scale = variance > 0.0 ? 1.0 / (kFoamNoiseDeviation * sqrt(variance)) : 0.0;
    return vec4(sum * scale, gradient_perm * scale, clamp(0.5 * resolvedShare, 0.0, 1.0));
}

// What a pixel of foam looks like.
struct FoamLook {
    float cover;    // the share of the pixel foam covers, 0..1
    float breaking; // the share of that foam a crest breaking now made, 0..1
    vec2 slope;     // the bubbles' relief: d/dx, d/dz of their height
};

// The bubbles' relief, m of height per unit of the texture's standard
// normal variate: thinning lace lies nearly flat on the water, a breaking
// crest's foam heaps up into a froth of mounds (chosen by eye: slopes of
// about 0.2 on lace, 0.5 on fresh foam where the finest octaves resolve).
const float kLaceRelief_m = 0.004;
const float kBreakingRelief_m = 0.010;

// The foam at a point of the world plane (p_m from the lattices' origin)
// given its amount there (1 where the wave breaks now, decaying as
// exp(-age / lifetime); breakingFoamAmount: the amount of foam a second
// old): two layers.
// - Where a crest breaks now (amount above breakingFoamAmount, less than a
//   second old), a dense sheet: 0.9 of the water, its gaps the texture's
//   lowest values (holes among the bubbles).
// - Older foam covers 0.75 of its amount and thins into lace: where the
//   texture is near its median, a network of filaments around dark holes
//   that narrows as the foam decays (and, from Beaufort 6, streaks drawn
//   out along the wind); the last of it (amount below 0.1, 9 s old at the
//   default lifetime) breaks up into scattered flecks, where the texture is
//   highest, rather than a fine net over the whole sea.
// Where the pixel resolves the texture the share is a threshold of it;
// where it does not, the share itself. The texture is made uniform on 0..1
// (a standard normal's distribution, in Bowling et al. 2009's logistic
// approximation), and so is its skew-tent fold that makes the lace, so
// the covered share of an area is the share at any distance: the cover the
// whitecap calibration counts does not change as octaves fade. The
// threshold's soft band is as wide as the texture changes over the pixel,
// so a foam edge is antialiased rather than stepped.
// The foam of an amount at a point: the share it covers, how much of it a
// breaking's own, and the texture there made uniform on 0..1 (u: the foam
// covers the point where u > 1 - share), with how fast u changes along the
// surface, per metre, and the texture itself (foamTexture()).
struct FoamField {
    float share, breaking, u, rate;
    vec4 texture;
};

// How much of the foam of this amount a crest breaking now made, 0..1
// (breakingFoamAmount: the amount of foam a second old).
float foamBreaking(float amount, float breakingFoamAmount)
{
    return clamp((amount - breakingFoamAmount) / max(1.0 - breakingFoamAmount, 1e-3), 0.0, 1.0);
}

// The share of the water foam of this amount covers: a breaking's own
// SWELL_FOAM_BREAKING_SHARE, older foam SWELL_FOAM_LACE_SHARE of its
// amount, none below SWELL_FOAM_LEAST_AMOUNT. Its C++ twin,
// swell::foam::foamShare, finds the whitecaps' breaking with it
// (FoamShare.TheLooksShareIsItsCppTwins holds the two together).
float foamShare(float amount, float breakingFoamAmount)
{
    if (amount < SWELL_FOAM_LEAST_AMOUNT)
        return 0.0;
    return mix(SWELL_FOAM_LACE_SHARE * amount, SWELL_FOAM_BREAKING_SHARE, foamBreaking(amount, breakingFoamAmount));
}

FoamField foamField(FoamNoise foamNoise[SWELL_FOAM_NOISE_MAPS], float breakingFoamAmount, float amount, vec2 p_m,
                    float footprint_m)
{
    FoamField f;
    f.breaking = foamBreaking(amount, breakingFoamAmount);
    f.share = foamShare(amount, breakingFoamAmount);
    f.texture = foamTexture(foamNoise, p_m, footprint_m);
    float uniform01 = 1.0 / (1.0 + exp(-1.702 * f.texture.x));
    // The lace: the texture folded about its quantile `peak` (a skew tent,
    // uniform01 / peak below it, (1 - uniform01) / (1 - peak) above), so
    // foam follows the texture's contour at that quantile, a network of
    // filaments around dark holes, rather than its highest values (blobs).
    // The fold keeps u uniform on 0..1 (each u has two preimages, whose
    // densities peak and 1 - peak add to 1), so foam covers the share it
    // is given at every point sampled (the labels' rule) as over an area.
    // A mix of the texture and its tent fold, as before, was not uniform,
    // so a point was under foam less often than the share said.
    float laced = smoothstep(0.1, 0.4, amount) * (1.0 - f.breaking);
    float peak = 1.0 - 0.4 * laced; // 1: no fold; 0.6 at the most lace
    bool below = uniform01 < peak;
    f.u = below ? uniform01 / peak : (1.0 - uniform01) / max(1.0 - peak, 1e-6);
    // The fold's slope times the texture's.
    f.rate = uniform01 * (1.0 - uniform01) * 1.702 * length(f.texture.yz) / (below ? peak : max(1.0 - peak, 1e-6));
    return f;
}

FoamLook foamLook(FoamNoise foamNoise[SWELL_FOAM_NOISE_MAPS], float breakingFoamAmount, float amount, vec2 p_m,
                  float footprint_m)
{
    FoamLook look;
    // Where no foam is (most of a calm sea), the texture is not worth its
    // cost: a share of 0.0004 is a tenth of the darkest 8-bit level's step.
    // (A share of 0.002 left out lowered the cover at 8 m/s by 4%: its
    // faint rims and old foam count.)
    if (amount < SWELL_FOAM_LEAST_AMOUNT) {
        look.cover = 0.0;
        look.breaking = 0.0;
        look.slope = vec2(0.0);
        return look;
    }
    FoamField f = foamField(foamNoise, breakingFoamAmount, amount, p_m, footprint_m);
    float band = 0.04 + f.rate * footprint_m;
    // No foam covers nothing: below the band's width, the soft edge shrinks with the share.
    float lace = smoothstep(1.0 - f.share - band, 1.0 - f.share + band, f.u) * min(1.0, f.share / band);
    look.cover = mix(f.share, lace, f.texture.w);
    look.breaking = f.breaking;
    look.slope = mix(kLaceRelief_m, kBreakingRelief_m, f.breaking) * f.texture.w * f.texture.yz;
    return look;
}

// Whether foam of this amount covers the point p itself (1) or not (0):
// the texture at full detail (a millimetre's footprint) against the share,
// with no soft edge, so over an area the share of points under foam is the
// share, however small (the look's soft edge, 0.04 of u wide, covers no
// point wholly where the share is under 0.02: the faint foam of distant or
// light seas). What the labels take (docs/LABELS.md).
float foamAtPoint(FoamNoise foamNoise[SWELL_FOAM_NOISE_MAPS], float breakingFoamAmount, float amount, vec2 p_m)
{
    if (amount < SWELL_FOAM_LEAST_AMOUNT)
        return 0.0;
    FoamField f = foamField(foamNoise, breakingFoamAmount, amount, p_m, 1e-3);
    return f.u > 1.0 - f.share ? 1.0 : 0.0;
}
#endif
