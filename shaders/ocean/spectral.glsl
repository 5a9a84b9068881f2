// The spectral ocean on the GPU: the GLSL twin of
// swell::spectral::CpuSurface::surfaceAt (src/ocean/spectral/spectral_cpu.cpp).
// The displacement is the sum over cascades of exact bilinear samples at
// level 0 (texelFetch with weights computed here: the hardware's filter
// weights have too few bits to match the CPU), each cascade weighed by
// whether the samples resolve its shortest wave; the normal comes from the
// slopes, filtered by the footprint through their mipmaps. Each cascade is
// looked up at its anti-tiling warp's point x + w_c(x)
// (src/ocean/spectral/spectral_warp.h), its slopes carried to the rest point
// through the warp's Jacobian.
#ifndef SWELL_OCEAN_SPECTRAL_GLSL
#define SWELL_OCEAN_SPECTRAL_GLSL
#include "swell/shader_constants.h"

// One sinusoid of a cascade's warp: w += amplitude_m * sin(wavevector_radpm . x + phase).
struct SpectralWarpWave {
    vec2 wavevector_radpm;
    vec2 amplitude_m;
    float phaseAtCentre_rad; // at the grid centre (reduced on the CPU in double)
};

struct SpectralCascade {
    vec2 originTexels;          // the grid centre modulo the patch, texels
    float texelsPerMetre;       // N / L
    float shortestWavelength_m; // the shortest wave the cascade holds, m
    SpectralWarpWave warp[SWELL_FFT_WARP_WAVES];
};

layout(std140, binding = SWELL_BINDING_OCEAN) uniform SpectralCascades {
    SpectralCascade cascades[SWELL_FFT_CASCADES];
    vec2 windDirection;     // unit, x,z: foam is drawn out into streaks along it
    float foamStreak;       // how far foam streaks are drawn out along the wind, 1 = not at all
    float unresolvedSlopeVariance; // mean square slope of the waves shorter than the last cascade's
    // Each foam level's window: x, y the grid centre in texels modulo the
    // window (as the texture repeats), z texels per metre.
    vec4 foamLevels[SWELL_FOAM_LEVELS];
};

layout(binding = SWELL_UNIT_OCEAN0) uniform sampler2DArray oceanDisplacement; // Dx, Dy, Dz, dDx/dz, m
// Layers 0 .. SWELL_FFT_CASCADES - 1: dDy/dx, dDy/dz, dDx/dx, dDz/dz; the
// next SWELL_FFT_CASCADES layers the slopes' second moments, mipmapped
// with them: (dDy/dx)^2, (dDy/dz)^2, their product.
layout(binding = SWELL_UNIT_OCEAN1) uniform sampler2DArray oceanDerivatives;
layout(binding = SWELL_UNIT_OCEAN2) uniform sampler2DArray oceanFoam;         // whitecap foam, 0..1, a layer a level

// Value noise on a lattice of 1 m cells: the bubbly texture inside foam.
// An integer hash (multiply-xorshift): uniform on 0..1 for any cell, where
// the usual fract(sin(x) * big) leans on sin's accuracy far from 0, which
// GLSL does not specify.
float foamHash(vec2 cell)
{
    uvec2 q = uvec2(ivec2(cell)) * uvec2(1597334673u, 3812015801u);
    uint n = (q.x ^ q.y) * 1597334673u;
    n ^= n >> 16;
    return float(n) * (1.0 / 4294967295.0);
}
float foamNoise(vec2 p)
{
    vec2 cell = floor(p), f = fract(p);
    vec2 u = f * f * (3.0 - 2.0 * f);
    return mix(mix(foamHash(cell), foamHash(cell + vec2(1.0, 0.0)), u.x),
               mix(foamHash(cell + vec2(0.0, 1.0)), foamHash(cell + vec2(1.0, 1.0)), u.x), u.y);
}

// How much of the water foam covers at a point of the world plane (relative
// to the grid centre; the phase of the noise does not matter), given the
// foam's amount there (1 where the wave breaks now, decaying as the foam
// ages). Where the pixel resolves the foam's texture, fresh foam is a nearly
// solid sheet and ageing foam thins into lace and streaks drawn out along
// the wind: the texture is covered where it exceeds 1 - amount, so the
// covered share of an area is about its amount. Where the pixel does not
// resolve the texture, that share itself: the same mean, without aliasing.
float foamCoverage(float amount, vec2 p_m, float footprint_m)
{
    vec2 along = windDirection, across = vec2(-windDirection.y, windDirection.x);
    // Streaks: the noise stretched along the wind.
    vec2 q = vec2(dot(p_m, along) / foamStreak, dot(p_m, across));
    // Octaves of 3 m down to 3 cm cells, of equal weight so that even a
    // small patch has gaps: the coarsest break up what the foam's coarser
    // level blurs, the finest are the bubbles' lace.
    float texture = 0.0, amplitude = 1.0, scale = 0.3, total = 0.0;
    float resolvedShare = 0.0;
    for (int octave = 0; octave < 6; ++octave, scale *= 2.5) {
        float resolved = 1.0 - smoothstep(0.25, 0.5, footprint_m * scale);
        texture += amplitude * resolved * (foamNoise(q * scale + float(octave) * 17.0) - 0.5);
        resolvedShare += amplitude * resolved;
        total += amplitude;
    }
    // 0..1 with mean 1/2 and a spread of about 0.3 (6 octaves' mean has
    // about 0.08), its contrast stretched
    // back as octaves fade, kept within the threshold's soft edge of 0 and 1
    // so that no foam covers nothing.
    const float edge = 0.08;
    texture = clamp(0.5 + 4.0 * texture / max(resolvedShare, 1e-3), edge, 1.0 - edge);
    // Even where a wave breaks now, the foam is froth with gaps, not paint.
    float share = 0.75 * amount;
    float lace = smoothstep(1.0 - edge - share, 1.0 + edge - share, texture);
    return mix(share, lace, resolvedShare / total);
}

// swell::spectral::cascadeWeight.
float cascadeWeight(float shortestWavelength_m, float footprint_m)
{
    return smoothstep(SWELL_MIN_CELLS_PER_WAVELENGTH * footprint_m,
                      SWELL_FULL_CELLS_PER_WAVELENGTH * footprint_m, shortestWavelength_m);
}

// swell::spectral::warpAt: where cascade c is looked up for a rest point
// (texels), and the Jacobian of the lookup point (column j: d(x + w)/dx_j).
vec2 warpedTexels(int c, vec2 restOffset_m, out mat2 jacobian)
{
    vec2 offset = vec2(0.0);
    jacobian = mat2(1.0);
    for (int i = 0; i < SWELL_FFT_WARP_WAVES; ++i) {
        SpectralWarpWave w = cascades[c].warp[i];
        float phase = w.phaseAtCentre_rad + dot(w.wavevector_radpm, restOffset_m);
        offset += w.amplitude_m * sin(phase);
        jacobian += outerProduct(w.amplitude_m, w.wavevector_radpm) * cos(phase);
    }
    return cascades[c].originTexels + (restOffset_m + offset) * cascades[c].texelsPerMetre;
}

// A cascade's level-0 field at texel position s, bilinear with exact weights.
vec4 bilinearFetch(sampler2DArray field, vec2 s, int cascade)
{
    vec2 cell = floor(s);
    vec2 f = s - cell;
    ivec2 i0 = ivec2(cell) & (SWELL_FFT_SIZE - 1);
    ivec2 i1 = (i0 + 1) & (SWELL_FFT_SIZE - 1);
    vec4 top = mix(texelFetch(field, ivec3(i0.x, i0.y, cascade), 0),
                   texelFetch(field, ivec3(i1.x, i0.y, cascade), 0), f.x);
    vec4 bottom = mix(texelFetch(field, ivec3(i0.x, i1.y, cascade), 0),
                      texelFetch(field, ivec3(i1.x, i1.y, cascade), 0), f.x);
    return mix(top, bottom, f.y);
}

vec4 bilinearDisplacement(vec2 s, int cascade) { return bilinearFetch(oceanDisplacement, s, cascade); }

// The Jacobian of the horizontal displacement of cascades
// 0..cascadeCount-1 (unfiltered) at a rest point: where it falls low, the
// surface folds and breaks. The CPU twin is
// swell::spectral::CpuSurface::foldJacobianAt.
float foldJacobian(vec2 restOffset_m, int cascadeCount)
{
    vec2 gradDx = vec2(0.0), gradDz = vec2(0.0); // (d/dx, d/dz) at the rest point
    for (int c = 0; c < cascadeCount; ++c) {
        mat2 jacobian;
        vec2 s = warpedTexels(c, restOffset_m, jacobian);
        float dxz = bilinearDisplacement(s, c).w;
        vec4 d = bilinearFetch(oceanDerivatives, s, c);
        vec2 alongDx = vec2(d.z, dxz), alongDz = vec2(dxz, d.w);
        for (int j = 0; j < 2; ++j) {
            gradDx[j] += dot(alongDx, jacobian[j]);
            gradDz[j] += dot(alongDz, jacobian[j]);
        }
    }
    return (1.0 + gradDx.x) * (1.0 + gradDz.y) - gradDx.y * gradDz.x;
}

// The whitecap foam at a rest point, filtered over the footprint: from the
// finest foam level whose window holds the point, cross-faded to the next
// toward the window's edge (where texels are newest), and beyond the last,
// that level's mean (its last mip), which is what distant foam averages to.
float worldFoam(vec2 restOffset_m, float footprint_m)
{
    float foam = textureLod(oceanFoam, vec3(0.5, 0.5, float(SWELL_FOAM_LEVELS - 1)), float(SWELL_FOAM_LOG2_SIZE)).r;
    for (int level = SWELL_FOAM_LEVELS - 1; level >= 0; --level) {
        vec4 window = foamLevels[level];
        vec2 texels = restOffset_m * window.z;
        float fromCentre = max(abs(texels.x), abs(texels.y)) / float(SWELL_FOAM_SIZE / 2);
        float inside = 1.0 - smoothstep(0.6, 0.9, fromCentre);
        if (inside > 0.0) {
            vec3 uvw = vec3((window.xy + texels) / float(SWELL_FOAM_SIZE), float(level));
            float lod = log2(max(footprint_m * window.z, 1.0));
            foam = mix(foam, textureLod(oceanFoam, uvw, lod).r, inside);
        }
    }
    return foam;
}

// The normal and the foam at a footprint (the displacement left zero): the
// slopes and the foam through their mipmaps. The slope variance the mipmaps
// average away comes back from the second moments (LEAN mapping, Olano &
// Baker 2010: E[s^2] - E[s]^2 over the footprint), with that of the waves no
// cascade holds (Elfouhaily et al. 1997), as the highlight's spread.
SurfacePoint spectralSlopes(vec2 restOffset_m, float footprint_m, float heightScale)
{
    // Gradients along rest x and z, each (d/dx, d/dz).
    vec2 gradDx = vec2(0.0), gradDy = vec2(0.0), gradDz = vec2(0.0);
    float slopeVariance = 0.0;
    for (int c = 0; c < SWELL_FFT_CASCADES; ++c) {
        SpectralCascade cascade = cascades[c];
        mat2 jacobian;
        vec2 s = warpedTexels(c, restOffset_m, jacobian);
        float weight = cascadeWeight(cascade.shortestWavelength_m, footprint_m);
        // Sample centres sit at integer texels: shift by half a texel for the
        // hardware's filter, and pick the mip the footprint covers.
        vec3 uvw = vec3((s + 0.5) / float(SWELL_FFT_SIZE), float(c));
        float lod = log2(max(footprint_m * cascade.texelsPerMetre, 1.0));
        vec4 d = textureLod(oceanDerivatives, uvw, lod); // dDy/dx, dDy/dz, dDx/dx, dDz/dz in the patch
        vec3 moments = textureLod(oceanDerivatives, uvw + vec3(0.0, 0.0, float(SWELL_FFT_CASCADES)), lod).xyz;
        float crossSlope = textureLod(oceanDisplacement, uvw, 0.0).w * weight; // dDx/dz = dDz/dx
        // The chain rule through the warp: d/dx_j = (d/ds) . jacobian[j].
        vec2 slope = d.xy, alongDx = vec2(d.z, crossSlope), alongDz = vec2(crossSlope, d.w);
        for (int j = 0; j < 2; ++j) {
            gradDx[j] += dot(alongDx, jacobian[j]);
            gradDy[j] += dot(slope, jacobian[j]);
            gradDz[j] += dot(alongDz, jacobian[j]);
        }
        // The slopes' covariance over the footprint, carried the same way:
        // the trace of J^T C J.
        mat2 covariance = mat2(max(moments.x - d.x * d.x, 0.0), moments.z - d.x * d.y,
                               moments.z - d.x * d.y, max(moments.y - d.y * d.y, 0.0));
        slopeVariance += max(dot(jacobian[0], covariance * jacobian[0]) + dot(jacobian[1], covariance * jacobian[1]), 0.0);
    }
    gradDx *= heightScale;
    gradDy *= heightScale;
    gradDz *= heightScale;
    slopeVariance = (slopeVariance + unresolvedSlopeVariance) * heightScale * heightScale;
    vec3 alongX = vec3(1.0 + gradDx.x, gradDy.x, gradDz.x);
    vec3 alongZ = vec3(gradDx.y, gradDy.y, 1.0 + gradDz.y);
    float foam = foamCoverage(heightScale * worldFoam(restOffset_m, footprint_m), restOffset_m, footprint_m);
    return SurfacePoint(vec3(0.0), normalize(cross(alongZ, alongX)), foam, alongX, alongZ, slopeVariance);
}

SurfacePoint oceanSurface(vec2 restOffset_m, float footprint_m, float heightScale)
{
    vec4 displacement = vec4(0.0); // Dx, Dy, Dz, dDx/dz
    for (int c = 0; c < SWELL_FFT_CASCADES; ++c) {
        float weight = cascadeWeight(cascades[c].shortestWavelength_m, footprint_m);
        if (weight > 0.0) {
            mat2 jacobian;
            displacement += weight * bilinearDisplacement(warpedTexels(c, restOffset_m, jacobian), c);
        }
    }
    SurfacePoint p = spectralSlopes(restOffset_m, footprint_m, heightScale);
    p.displacement = displacement.xyz * heightScale;
    return p;
}

// The slope textures hold every wave the pixel resolves, at the cost of one
// filtered fetch per cascade: the grid's normal adds nothing.
SurfacePoint oceanShading(vec2 restOffset_m, float pixelFootprint_m, float gridFootprint_m, vec3 gridAlongX,
                          vec3 gridAlongZ, float heightScale)
{
    return spectralSlopes(restOffset_m, pixelFootprint_m, heightScale);
}
#endif
