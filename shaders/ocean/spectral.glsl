// The spectral ocean on the GPU: the GLSL twin of
// swell::spectral::CpuSurface::surfaceAt (src/ocean/spectral/spectral_cpu.cpp).
// The displacement is the sum over cascades of exact bilinear samples at
// level 0 (texelFetch with weights computed here: the hardware's filter
// weights have too few bits to match the CPU), each cascade weighed by
// whether the samples resolve its shortest wave, and where they do not, of
// the same field averaged over the footprint (its mip chain); the normal comes from the
// slopes, filtered by the footprint through their mipmaps. Each cascade is
// looked up at its anti-tiling warp's point x + w_c(x)
// (src/ocean/spectral/spectral_warp.h), its slopes carried to the rest point
// through the warp's Jacobian.
#ifndef SWELL_OCEAN_SPECTRAL_GLSL
#define SWELL_OCEAN_SPECTRAL_GLSL
#include "swell/gpu/bindings.h"
#include "swell/gpu/ocean.h"

// The SpectralCascades block (swell::spectral::SpectralUniforms,
// src/ocean/spectral/gpu/spectral_uniforms.h): each cascade's place and warp
// (SpectralWarpWave: w += amplitude_m * sin(wavevector_radpm . x + phase)),
// the wind, each foam level's window and the lattices of the foam's
// texture anchored at the grid centre.
#include "gpu/spectral_block.glsl"
// The whitecaps' look, which the callers give the block's lattices.
#include "whitecap_foam.glsl"
// Over a sea floor: the trains that carry the longest band near the coast
// (src/ocean/spectral/spectral_coast.h).
#include "coast_field.glsl"

layout(binding = SWELL_UNIT_OCEAN0) uniform sampler2DArray oceanDisplacement; // Dx, Dy, Dz, dDx/dz, m
// For shading, layers 0 .. SWELL_FFT_CASCADES - 1: dDy/dx, dDy/dz, dDx/dx,
// dDz/dz; the next SWELL_FFT_CASCADES layers the slopes' second moments,
// mipmapped with them: (dDy/dx)^2, (dDy/dz)^2, their product, and the cross
// derivative dDx/dz; all in half floats.
layout(binding = SWELL_UNIT_OCEAN1) uniform sampler2DArray oceanDerivatives;
layout(binding = SWELL_UNIT_OCEAN2) uniform sampler2DArray oceanFoam;         // whitecap foam, 0..1, a layer a level
// The same derivatives in the full floats the FFT made, its base level
// alone: what the foam's folding reads, as the CPU twin's foam does.
layout(binding = SWELL_UNIT_OCEAN3) uniform sampler2DArray oceanFoldDerivatives;

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

// swell::spectral::displacementLevel: the level of a cascade's mip chain
// whose texels are footprint_m wide.
float displacementLevel(int c, float footprint_m)
{
    return clamp(log2(max(footprint_m * cascades[c].texelsPerMetre, 1.0)), 0.0, float(SWELL_FFT_LOG2_SIZE));
}

// swell::spectral::filteredCascadeWeight: where the exact field of the
// first SWELL_FFT_FILTERED_CASCADES fades, the filtered one takes the rest.
float filteredCascadeWeight(int c, float footprint_m)
{
    return c < SWELL_FFT_FILTERED_CASCADES ? 1.0 - cascadeWeight(cascades[c].shortestWavelength_m, footprint_m) : 0.0;
}

// The uniform cubic B-spline's weights of the texels at cell - 1 .. cell + 2
// for a point f (0..1) past texel `cell`, along each axis.
void cubicBSplineWeights(vec2 f, out vec2 w[4])
{
    w[0] = (1.0 - f) * (1.0 - f) * (1.0 - f) / 6.0;
    w[1] = (4.0 - 6.0 * f * f + 3.0 * f * f * f) / 6.0;
    w[3] = f * f * f / 6.0;
    w[2] = 1.0 - w[0] - w[1] - w[3];
}

// Level `level` of a cascade's displacement at level 0's texel position s,
// through a cubic B-spline over its texels (level l's texel j is the mean
// of level 0's j * 2^l .. (j + 1) * 2^l - 1), with exact weights: a
// bilinear surface creases along the texels' lines, and the chain's coarse
// texels are cells wide.
vec3 bsplineDisplacementAt(vec2 s, int cascade, int level)
{
    float scale = exp2(-float(level));
    vec2 sl = (s + 0.5) * scale - 0.5;
    vec2 cell = floor(sl);
    vec2 w[4];
    cubicBSplineWeights(sl - cell, w);
    int mask = (SWELL_FFT_SIZE >> level) - 1;
    ivec2 first = ivec2(cell) - 1;
    vec3 sum = vec3(0.0);
    for (int row = 0; row < 4; ++row) {
        vec3 line = vec3(0.0);
        for (int col = 0; col < 4; ++col)
            line += w[col].x *
                    texelFetch(oceanDisplacement, ivec3((first.x + col) & mask, (first.y + row) & mask, cascade), level).xyz;
        sum += w[row].y * line;
    }
    return sum;
}

// swell::spectral::CpuSurface::filteredDisplacement: cascade c's
// displacement averaged over texels as wide as the footprint, the two
// levels about it blended.
vec3 filteredDisplacement(int c, vec2 s, float footprint_m)
{
    float level = displacementLevel(c, footprint_m);
    int first = int(floor(level));
    int second = min(first + 1, SWELL_FFT_LOG2_SIZE);
    vec3 a = bsplineDisplacementAt(s, c, first);
    return second == first ? a : mix(a, bsplineDisplacementAt(s, c, second), level - float(first));
}

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
        vec4 d = bilinearFetch(oceanFoldDerivatives, s, c);
        vec2 alongDx = vec2(d.z, dxz), alongDz = vec2(dxz, d.w);
        for (int j = 0; j < 2; ++j) {
            gradDx[j] += dot(alongDx, jacobian[j]);
            gradDz[j] += dot(alongDz, jacobian[j]);
        }
    }
    return (1.0 + gradDx.x) * (1.0 + gradDz.y) - gradDx.y * gradDz.x;
}

// A foam level at texel position s (texel centres at integers), through a
// cubic B-spline: four bilinear taps weighed as Sigg & Hadwiger (2005,
// GPU Gems 2 ch. 20). Its contours are smooth curves where the bilinear
// filter's, thresholded into foam edges, step along the texel grid.
float foamBSpline(vec2 s, int level)
{
    vec2 cell = floor(s);
    vec2 w[4];
    cubicBSplineWeights(s - cell, w);
    vec2 g0 = w[0] + w[1], g1 = w[2] + w[3];
    // The taps' texel coordinates, plus half a texel for the hardware's filter.
    vec2 h0 = (cell - 1.0 + w[1] / g0 + 0.5) / float(SWELL_FOAM_SIZE);
    vec2 h1 = (cell + 1.0 + w[3] / g1 + 0.5) / float(SWELL_FOAM_SIZE);
    float l = float(level);
    return g0.y * (g0.x * textureLod(oceanFoam, vec3(h0.x, h0.y, l), 0.0).r +
                   g1.x * textureLod(oceanFoam, vec3(h1.x, h0.y, l), 0.0).r) +
           g1.y * (g0.x * textureLod(oceanFoam, vec3(h0.x, h1.y, l), 0.0).r +
                   g1.x * textureLod(oceanFoam, vec3(h1.x, h1.y, l), 0.0).r);
}

// The whitecap foam at a rest point, filtered over the footprint: from the
// finest foam level whose window holds the point, cross-faded to the next
// toward the window's edge (where texels are newest), and beyond the last,
// that level's mean (its last mip), which is what distant foam averages to.
// The finest level first, so that where its window holds the point fully
// no coarser level is fetched. With bSpline, where the pixel is finer than
// a texel, the B-spline, cross-faded into the mipmaps as the footprint
// grows to two texels.
float worldFoam(vec2 restOffset_m, float footprint_m, bool bSpline)
{
    float foam = 0.0, left = 1.0; // the weight the coarser levels still have
    for (int level = 0; level < SWELL_FOAM_LEVELS && left > 0.0; ++level) {
        SpectralFoamLevel window = foamLevels[level];
        vec2 texels = restOffset_m * window.texelsPerMetre;
        float fromCentre = max(abs(texels.x), abs(texels.y)) / float(SWELL_FOAM_SIZE / 2);
        float inside = 1.0 - smoothstep(0.6, 0.9, fromCentre);
        if (inside > 0.0) {
            vec2 s = window.centreTexels + texels - 0.5;
            float lod = log2(max(footprint_m * window.texelsPerMetre, 1.0));
            float here = textureLod(oceanFoam, vec3((s + 0.5) / float(SWELL_FOAM_SIZE), float(level)), lod).r;
            if (bSpline && lod < 1.0)
                here = mix(foamBSpline(s, level), here, lod);
            foam += left * inside * here;
            left *= 1.0 - inside;
        }
    }
    if (left > 0.0)
        foam += left * textureLod(oceanFoam, vec3(0.5, 0.5, float(SWELL_FOAM_LEVELS - 1)), float(SWELL_FOAM_LOG2_SIZE)).r;
    return foam;
}

// What the coast does to the cascades at a rest point (CpuSurface::sample):
// every cascade times the field's common gain (the breaking cut, no water on
// dry land), cascade 0 also times sqrt(1 - b), and the trains added at
// sqrt(b), b the trains' share of the longest band (coastTrainShare).
struct SpectralCoast {
    CoastCell cell;
    vec4 everyWave;
    float share;       // b
    float firstWeight; // cascade 0's factor
    float otherWeight; // the other cascades'
};

SpectralCoast spectralCoastAt(vec2 restOffset_m)
{
    SpectralCoast coast;
    coast.cell = coastCellAt(restOffset_m);
    coast.everyWave = coastEveryWaveAt(coast.cell);
    coast.share = coastTrainShare(coast.cell, coast.everyWave, restOffset_m);
    coast.otherWeight = coast.everyWave.y;
    coast.firstWeight = coast.otherWeight * sqrt(1.0 - coast.share);
    return coast;
}

float coastCascadeWeight(SpectralCoast coast, int c) { return c == 0 ? coast.firstWeight : coast.otherWeight; }

// Where each cascade is looked up at a rest point and the Jacobian of the
// lookup (warpedTexels).
struct CascadeLookups {
    vec2 texels[SWELL_FFT_CASCADES];
    mat2 jacobian[SWELL_FFT_CASCADES];
};

CascadeLookups warpedLookups(vec2 restOffset_m)
{
    CascadeLookups l;
    for (int c = 0; c < SWELL_FFT_CASCADES; ++c)
        l.texels[c] = warpedTexels(c, restOffset_m, l.jacobian[c]);
    return l;
}

// The water's vertices hand their pixels each cascade's lookup
// (ocean.glsl's optional SWELL_OCEAN_VERTEX_DATA): per cascade c, data[c]
// holds its texel position and its Jacobian's first column, and the second
// column sits in data[SWELL_FFT_CASCADES + c / 2] (xy for even c, zw for
// odd). The warp's sinusoids are each 4.5 patches or more long, so over
// a small cell the lookup is nearly linear: interpolated across it, it is
// what the pixel would evaluate (SWELL_FFT_WARP_CELLS_PER_WAVELENGTH), for
// 6 vector additions instead of 12 sines and cosines a cascade.
#define SWELL_OCEAN_VERTEX_DATA (SWELL_FFT_CASCADES + SWELL_FFT_CASCADES / 2)

void oceanVertexData(vec2 restOffset_m, out vec4 data[SWELL_OCEAN_VERTEX_DATA])
{
    // Whole vec4s into a local array (NVIDIA's compiler refuses a swizzled
    // write through a computed index of an out array: "lvalue in
    // assignment too complex"), handed out at once.
    vec4 d[SWELL_OCEAN_VERTEX_DATA];
    vec2 second[SWELL_FFT_CASCADES];
    for (int c = 0; c < SWELL_FFT_CASCADES; ++c) {
        mat2 jacobian;
        vec2 s = warpedTexels(c, restOffset_m, jacobian);
        d[c] = vec4(s, jacobian[0]);
        second[c] = jacobian[1];
    }
    for (int i = 0; i < SWELL_FFT_CASCADES / 2; ++i)
        d[SWELL_FFT_CASCADES + i] = vec4(second[2 * i], second[2 * i + 1]);
    data = d;
}

// The lookups a pixel takes: the vertices' interpolated (data) for the
// cascades whose warp the pixel's cell (cellSize_m) samples finely enough,
// its own for the rest.
CascadeLookups interpolatedLookups(vec2 restOffset_m, vec4 data[SWELL_OCEAN_VERTEX_DATA], float cellSize_m)
{
    CascadeLookups l;
    for (int c = 0; c < SWELL_FFT_CASCADES; ++c) {
        if (cellSize_m <= cascades[c].vertexWarpCell_m) {
            vec4 second = data[SWELL_FFT_CASCADES + c / 2];
            l.texels[c] = data[c].xy;
            l.jacobian[c] = mat2(data[c].zw, (c & 1) == 0 ? second.xy : second.zw);
        } else {
            l.texels[c] = warpedTexels(c, restOffset_m, l.jacobian[c]);
        }
    }
    return l;
}

// Where the slopes are filtered: a square size_m wide (the vertices', or a
// pixel's without a shape), or a pixel's footprint on the water: size_m
// long along the unit vector axis, width_m wide across it (m). Seen at a
// slant the footprint is several times longer along the view than across
// it; filtered over a square its length wide, the slopes lose the waves it
// resolves across the view, and the smooth mean that is left reflects the
// sky as a mirror would: where the reflection holds the edges of clouds it
// breaks into flat, straight-edged plates (the cloud-shadows preset's
// mosaic, docs/RENDERING.md).
struct SlopeFootprint {
    float size_m;  // the footprint's length, m
    vec2 axis;     // unit, along its length; zero for a square
    float width_m; // its width, m (size_m for a square)
};

SlopeFootprint squareFootprint(float size_m) { return SlopeFootprint(size_m, vec2(0.0), size_m); }

// A pixel's footprint from its two sides on the water (steps_m's columns
// M): the ellipse they span, its long axis along M's first singular vector
// (the eigenvector of M*M^T of the larger eigenvalue, which turns smoothly
// with the steps, where the longer of the two sides would jump from one to
// the other as their lengths cross) and its width the parallelogram's area
// over the long axis's length, both scaled so that the length is size_m
// (the square a pixel is filtered over without its shape: a square
// footprint keeps that filter).
SlopeFootprint pixelFootprint(float size_m, mat2 steps_m)
{
    vec2 a = steps_m[0], b = steps_m[1];
    float p = a.x * a.x + b.x * b.x, r = a.y * a.y + b.y * b.y, q = a.x * a.y + b.x * b.y;
    float halfDifference = 0.5 * (p - r);
    float longest2 = 0.5 * (p + r) + sqrt(halfDifference * halfDifference + q * q);
    if (!(longest2 > 0.0))
        return squareFootprint(size_m);
    // atan(0, 0) is undefined: a round footprint's axis is any (its lookups coincide).
    float angle = q == 0.0 && p == r ? 0.0 : 0.5 * atan(2.0 * q, p - r);
    float width_m = abs(a.x * b.y - a.y * b.x) / sqrt(longest2);
    return SlopeFootprint(size_m, vec2(cos(angle), sin(angle)), clamp(width_m / sqrt(longest2), 0.0, 1.0) * size_m);
}

// How much longer than wide a footprint is followed: beyond it each lookup
// widens to the footprint's length over this. Not more: the sharper the
// slopes, the more the water drawn in one pass and in two differs
// (WaterTwoPasses; docs/RENDERING.md, "Slopes the pixel cannot draw").
#define SWELL_SLOPE_FOOTPRINT_ANISOTROPY 1.75

// The size of the square each lookup filters, m: the footprint's width,
// at least its length over SWELL_SLOPE_FOOTPRINT_ANISOTROPY.
float footprintTapSize(SlopeFootprint f) { return max(f.width_m, f.size_m / SWELL_SLOPE_FOOTPRINT_ANISOTROPY); }

// The lookups a footprint takes along its length: its length over the
// lookups' size, rounded up (a square takes one). The lookups sit at the
// midpoints of equal parts of the stretch their centres cover, so that a
// footprint whose lookups number one more takes nearly the same mean (each
// lookup is at least as wide as a part).
int footprintTaps(SlopeFootprint f)
{
    return int(clamp(ceil(f.size_m / footprintTapSize(f) - 1e-3), 1.0, ceil(SWELL_SLOPE_FOOTPRINT_ANISOTROPY)));
}

// The normal at a footprint (the displacement left zero, the foam left to
// oceanShading): the slopes through their mipmaps. The slope variance the mipmaps
// average away comes back from the second moments (LEAN mapping, Olano &
// Baker 2010: E[s^2] - E[s]^2 over the footprint), with that of the waves no
// cascade holds (Elfouhaily et al. 1997), as the highlight's spread.
// Over a coast, each cascade's slopes are weighed as its displacement is
// (the weights' own gradients left out, as the CPU twin leaves them: they
// change over tens of metres) and the trains' added at the footprint.
SurfacePoint spectralSlopes(CascadeLookups lookups, vec2 restOffset_m, SpectralCoast coast, SlopeFootprint footprint,
                            float heightScale)
{
    // Gradients along rest x and z, each (d/dx, d/dz).
    vec2 gradDx = vec2(0.0), gradDy = vec2(0.0), gradDz = vec2(0.0);
    float slopeVariance = 0.0;
    int taps = footprintTaps(footprint);
    float tap_m = footprintTapSize(footprint);
    for (int c = 0; c < SWELL_FFT_CASCADES; ++c) {
        float coastWeight = coastCascadeWeight(coast, c);
        SpectralCascade cascade = cascades[c];
        mat2 jacobian = lookups.jacobian[c];
        vec2 s = lookups.texels[c];
        // Sample centres sit at integer texels: shift by half a texel for the
        // hardware's filter. The footprint's length is covered by lookups
        // spaced along it, each at the mip of a square its width wide; for
        // a square footprint they coincide, one lookup at its size's mip.
        vec3 uvw = vec3((s + 0.5) / float(SWELL_FFT_SIZE), float(c));
        float lod = log2(max(tap_m * cascade.texelsPerMetre, 1.0));
        // The stretch of the footprint's length the lookups' centres cover,
        // in the patch's uv (footprintTaps).
        vec2 span = jacobian * footprint.axis * ((footprint.size_m - tap_m) * cascade.texelsPerMetre / float(SWELL_FFT_SIZE));
        vec4 d = vec4(0.0), moments = vec4(0.0); // dDy/dx, dDy/dz, dDx/dx, dDz/dz in the patch; the moments
        for (int t = 0; t < taps; ++t) {
            vec3 at = uvw + vec3(span * ((float(t) + 0.5) / float(taps) - 0.5), 0.0);
            d += textureLod(oceanDerivatives, at, lod);
            moments += textureLod(oceanDerivatives, at + vec3(0.0, 0.0, float(SWELL_FFT_CASCADES)), lod);
        }
        d /= float(taps);
        moments /= float(taps);
        // dDx/dz = dDz/dx, filtered by the footprint as its siblings are (the
        // displacement's own copy is sampled nearest: a texel's value over
        // the whole texel, at level 0 whatever the footprint).
        float crossSlope = moments.w;
        // The chain rule through the warp: d/dx_j = (d/ds) . jacobian[j].
        vec2 slope = d.xy, alongDx = vec2(d.z, crossSlope), alongDz = vec2(crossSlope, d.w);
        for (int j = 0; j < 2; ++j) {
            gradDx[j] += coastWeight * dot(alongDx, jacobian[j]);
            gradDy[j] += coastWeight * dot(slope, jacobian[j]);
            gradDz[j] += coastWeight * dot(alongDz, jacobian[j]);
        }
        // The slopes' covariance over the footprint, carried the same way:
        // the trace of J^T C J.
        mat2 covariance = mat2(max(moments.x - d.x * d.x, 0.0), moments.z - d.x * d.y,
                               moments.z - d.x * d.y, max(moments.y - d.y * d.y, 0.0));
        slopeVariance += coastWeight * coastWeight
                       * max(dot(jacobian[0], covariance * jacobian[0]) + dot(jacobian[1], covariance * jacobian[1]), 0.0);
    }
    if (coast.share > 0.0) {
        vec3 trains = vec3(0.0), alongX = vec3(0.0), alongZ = vec3(0.0);
        coastTrainsSurface(restOffset_m, coast.cell, coast.everyWave, footprint.size_m, sqrt(coast.share), trains,
                           alongX, alongZ);
        gradDx += vec2(alongX.x, alongZ.x);
        gradDy += vec2(alongX.y, alongZ.y);
        gradDz += vec2(alongX.z, alongZ.z);
    }
    gradDx *= heightScale;
    gradDy *= heightScale;
    gradDz *= heightScale;
    slopeVariance = (slopeVariance + unresolvedSlopeVariance) * heightScale * heightScale;
    vec3 alongX = vec3(1.0 + gradDx.x, gradDy.x, gradDz.x);
    vec3 alongZ = vec3(gradDx.y, gradDy.y, 1.0 + gradDz.y);
    return SurfacePoint(vec3(0.0), normalize(cross(alongZ, alongX)), 0.0, alongX, alongZ, slopeVariance, 0.0, vec2(0.0));
}

SurfacePoint oceanSurface(vec2 restOffset_m, float footprint_m, float heightScale)
{
    SpectralCoast coast = spectralCoastAt(restOffset_m);
    vec3 displacement = vec3(0.0); // Dx, Dy, Dz
    for (int c = 0; c < SWELL_FFT_CASCADES; ++c) {
        float coastWeight = coastCascadeWeight(coast, c);
        float weight = cascadeWeight(cascades[c].shortestWavelength_m, footprint_m) * coastWeight;
        float filteredWeight = filteredCascadeWeight(c, footprint_m) * coastWeight;
        if (weight > 0.0 || filteredWeight > 0.0) {
            mat2 jacobian;
            vec2 s = warpedTexels(c, restOffset_m, jacobian);
            if (filteredWeight > 0.0)
                displacement += filteredWeight * filteredDisplacement(c, s, footprint_m);
            if (weight > 0.0)
                displacement += weight * bilinearDisplacement(s, c).xyz;
        }
    }
    if (coast.share > 0.0) {
        vec3 alongX = vec3(0.0), alongZ = vec3(0.0);
        coastTrainsSurface(restOffset_m, coast.cell, coast.everyWave, footprint_m, sqrt(coast.share), displacement,
                           alongX, alongZ);
    }
    SurfacePoint p =
        spectralSlopes(warpedLookups(restOffset_m), restOffset_m, coast, squareFootprint(footprint_m), heightScale);
    p.displacement = displacement * heightScale;
    return p;
}

// The slope textures hold every wave the pixel resolves, at the cost of one
// filtered fetch per cascade: the grid's normal adds nothing. The foam is
// the pixel's alone (the vertices have no use for it).
SurfacePoint spectralShading(CascadeLookups lookups, vec2 restOffset_m, float pixelFootprint_m, mat2 pixelSteps_m,
                             float heightScale)
{
    SurfacePoint p = spectralSlopes(lookups, restOffset_m, spectralCoastAt(restOffset_m),
                                    pixelFootprint(pixelFootprint_m, pixelSteps_m), heightScale);
    FoamLook foam = foamLook(foamNoise, breakingFoamAmount, heightScale * worldFoam(restOffset_m, pixelFootprint_m, true),
                             restOffset_m, pixelFootprint_m);
    p.foam = foam.cover;
    p.breakingFoam = foam.breaking;
    p.foamSlope = foam.slope;
    return p;
}

SurfacePoint oceanShading(vec2 restOffset_m, float pixelFootprint_m, mat2 pixelSteps_m, float gridFootprint_m,
                          vec3 gridAlongX, vec3 gridAlongZ, float heightScale)
{
    return spectralShading(warpedLookups(restOffset_m), restOffset_m, pixelFootprint_m, pixelSteps_m, heightScale);
}

// A square footprint.
SurfacePoint oceanShading(vec2 restOffset_m, float pixelFootprint_m, float gridFootprint_m, vec3 gridAlongX,
                          vec3 gridAlongZ, float heightScale)
{
    return oceanShading(restOffset_m, pixelFootprint_m, mat2(0.0), gridFootprint_m, gridAlongX, gridAlongZ, heightScale);
}

// oceanShading with what the pixel's vertices handed it (oceanVertexData,
// interpolated) and the grid's cell there, m.
SurfacePoint oceanShadingFromVertices(vec2 restOffset_m, float pixelFootprint_m, mat2 pixelSteps_m,
                                      float gridFootprint_m, vec3 gridAlongX, vec3 gridAlongZ, float heightScale,
                                      vec4 vertexData[SWELL_OCEAN_VERTEX_DATA], float cellSize_m)
{
    return spectralShading(interpolatedLookups(restOffset_m, vertexData, cellSize_m), restOffset_m,
                           pixelFootprint_m, pixelSteps_m, heightScale);
}

// A square footprint.
SurfacePoint oceanShadingFromVertices(vec2 restOffset_m, float pixelFootprint_m, float gridFootprint_m,
                                      vec3 gridAlongX, vec3 gridAlongZ, float heightScale,
                                      vec4 vertexData[SWELL_OCEAN_VERTEX_DATA], float cellSize_m)
{
    return oceanShadingFromVertices(restOffset_m, pixelFootprint_m, mat2(0.0), gridFootprint_m, gridAlongX, gridAlongZ,
                                    heightScale, vertexData, cellSize_m);
}

// The bubbles under the whitecaps: a breaking crest drives a plume of them
// down, which thins faster than the surface foam fades (its bubbles rise
// into the foam and dissolve): the foam's amount squared, filtered over
// the footprint (which the caller widens: the plume is diffuse, none of
// the surface's lace shows through the water), without the B-spline.
float oceanFoamBelow(vec2 restOffset_m, float footprint_m)
{
    float amount = worldFoam(restOffset_m, footprint_m, false);
    return amount * amount;
}

// The foam's cover of the point itself (foamAtPoint(): 1 or 0), its amount
// read through the B-spline at the finest level: over an area the share of
// points under foam is the foam's covered share at any distance, which is
// what the whitecap calibration and Monahan's cover count.
float oceanFoamAtPoint(vec2 restOffset_m, float heightScale)
{
    const float kPointFootprint_m = 1e-3;
    float amount = heightScale * worldFoam(restOffset_m, kPointFootprint_m, true);
    return foamAtPoint(foamNoise, breakingFoamAmount, amount, restOffset_m);
}
#endif
