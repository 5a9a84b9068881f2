// The cloud layer on the GPU: the twin of src/core/clouds.cpp (the same
// steps in the same order; its shape in float on both sides), used only
// where the physical sky is baked (sky_bake.frag). Formulas and sources:
// swell/scene/clouds.h and clouds.cpp; tests/gl/test_clouds.cpp checks the two
// agree. Needs atmosphere.glsl (the air's transmittance).
#ifndef SWELL_CLOUDS_GLSL
#define SWELL_CLOUDS_GLSL
#include "swell/gpu/sky.h"
#include "gpu/constants.glsl"
#include "atmosphere.glsl"

// CloudSettings: cover 0..1 (0: no layer), altitude_m, opticalDepth, scale_m.
uniform float cloudCover;
uniform float cloudAltitude_m;
uniform float cloudOpticalDepth;
uniform float cloudScale_m;

// Jarzynski & Olano 2020, pcg2d.
uvec2 cloudPcg2d(uvec2 v)
{
    v = v * 1664525u + 1013904223u;
    v.x += v.y * 1664525u;
    v.y += v.x * 1664525u;
    v = v ^ (v >> 16u);
    v.x += v.y * 1664525u;
    v.y += v.x * 1664525u;
    v = v ^ (v >> 16u);
    return v;
}

vec2 cloudGradientAt(ivec2 cell, uint seed)
{
    uvec2 h = cloudPcg2d(uvec2(uint(cell.x), uint(cell.y) ^ (seed * 0x9E3779B9u)));
    uint k = h.x >> 29u;
    const float s = 0.70710678;
    if (k == 0u) return vec2(1.0, 0.0);
    if (k == 1u) return vec2(-1.0, 0.0);
    if (k == 2u) return vec2(0.0, 1.0);
    if (k == 3u) return vec2(0.0, -1.0);
    if (k == 4u) return vec2(s, s);
    if (k == 5u) return vec2(-s, s);
    if (k == 6u) return vec2(s, -s);
    return vec2(-s, -s);
}

float cloudNormalCdf(float x) { return 1.0 / (1.0 + exp(-1.702 * x)); }
float cloudNormalQuantile(float p) { return log(p / (1.0 - p)) / 1.702; }

float cloudGradientNoise(vec2 p, uint seed)
{
    vec2 i = floor(p);
    vec2 f = p - i;
    ivec2 c = ivec2(i);
    vec2 u = f * f * f * (f * (f * 6.0 - 15.0) + 10.0);
    float n00 = dot(cloudGradientAt(c, seed), f);
    float n10 = dot(cloudGradientAt(c + ivec2(1, 0), seed), f - vec2(1.0, 0.0));
    float n01 = dot(cloudGradientAt(c + ivec2(0, 1), seed), f - vec2(0.0, 1.0));
    float n11 = dot(cloudGradientAt(c + ivec2(1, 1), seed), f - vec2(1.0, 1.0));
    return mix(mix(n00, n10, u.x), mix(n01, n11, u.x), u.y);
}

float cloudFractalSum(vec2 p, float footprintCells, out float unresolvedSigma)
{
    const float warp = float(SWELL_CLOUD_WARP_CELLS);
    vec2 q = p + warp * vec2(cloudGradientNoise(p * 0.5 + vec2(17.3, 41.9), 100u),
                             cloudGradientNoise(p * 0.5 + vec2(-23.1, 7.7), 101u));
    float sum = 0.0, amplitude = 1.0, cells = footprintCells, variance = 0.0, lost = 0.0, slope = 0.0;
    for (int k = 0; k < SWELL_CLOUD_OCTAVES; ++k) {
        float keep = clamp(2.0 - 4.0 * cells, 0.0, 1.0);
        sum += keep * amplitude * cloudGradientNoise(q, uint(k));
        variance += amplitude * amplitude;
        lost += (1.0 - keep) * (1.0 - keep) * amplitude * amplitude;
        slope += keep * amplitude * cells;
        q = 2.0 * vec2(0.8 * q.x - 0.6 * q.y, 0.6 * q.x + 0.8 * q.y) + vec2(5.2, 1.3);
        amplitude *= 0.5;
        cells *= 2.0;
    }
    float faded = float(SWELL_CLOUD_FBM_SIGMA) * sqrt(lost / variance);
    unresolvedSigma = sqrt(faded * faded + 0.25 * slope * slope);
    return sum;
}

float cloudOpticalDepthAt(vec2 xz_m, float footprint_m)
{
    if (cloudCover <= 0.0)
        return 0.0;
    vec2 p = vec2(xz_m.x / (cloudScale_m * float(SWELL_CLOUD_STRETCH)), xz_m.y / cloudScale_m);
    float unresolved = 0.0;
    float n = cloudFractalSum(p, footprint_m / cloudScale_m, unresolved);
    const float sigma = float(SWELL_CLOUD_FBM_SIGMA);
    float threshold = sigma * cloudNormalQuantile(clamp(1.0 - cloudCover, 1.0e-6, 1.0 - 1.0e-6));
    float edge = float(SWELL_CLOUD_EDGE_SIGMA) * sigma;
    float mask = cloudNormalCdf((n - threshold) / sqrt(unresolved * unresolved + edge * edge));
    float thickness = 0.3 + 1.4 * cloudNormalCdf(n / sigma);
    return cloudOpticalDepth * mask * thickness;
}

// swell::cloudHit: distance, point (x, z), cosine with the vertical and
// footprint where a ray from the observer meets the layer.
struct CloudHit {
    float distance_m;
    vec2 xz_m;
    float cosZenith;
    float footprint_m;
};

vec3 cloudHorizonClamped(vec3 direction)
{
    vec3 d = normalize(direction);
    if (d.y < 0.0) {
        float horizontal = length(d.xz);
        d = horizontal > 1.0e-6 ? vec3(d.x / horizontal, 0.0, d.z / horizontal) : vec3(1.0, 0.0, 0.0);
    }
    return d;
}

CloudHit cloudHit(vec3 direction)
{
    vec3 d = cloudHorizonClamped(direction);
    const float bottom = SWELL_ATMOSPHERE_BOTTOM_RADIUS_M;
    const float h0 = SWELL_ATMOSPHERE_OBSERVER_ALTITUDE_M;
    float hc = max(cloudAltitude_m, h0 + 1.0);
    float r0 = bottom + h0, rc = bottom + hc;
    float c = (hc - h0) * (2.0 * bottom + hc + h0);
    float b = r0 * d.y;
    float t = c / (b + sqrt(b * b + c));
    CloudHit hit;
    hit.distance_m = t;
    hit.xz_m = t * d.xz;
    hit.cosZenith = max((b + t) / rc, 1.0e-3);
    hit.footprint_m = t * float(SWELL_CLOUD_TEXEL_RAD) / hit.cosZenith;
    return hit;
}

// swell::cloudTransmittance: the layer's direct transmittance along a direction.
float cloudTransmittance(vec3 direction)
{
    if (cloudCover <= 0.0)
        return 1.0;
    CloudHit hit = cloudHit(direction);
    return exp(-cloudOpticalDepthAt(hit.xz_m, hit.footprint_m) / hit.cosZenith);
}

// swell::cloudShadowTransmittance: the layer's direct transmittance along
// the sun's ray from a world point (x, z world metres; y over the mean level).
float cloudShadowTransmittance(vec3 point_m, vec3 sun, float footprint_m)
{
    if (cloudCover <= 0.0 || point_m.y >= cloudAltitude_m)
        return 1.0;
    float up = max(sun.y, float(SWELL_CLOUD_SHADOW_MIN_SUN_Y));
    vec2 crossing = point_m.xz + sun.xz * ((cloudAltitude_m - point_m.y) / up);
    return exp(-cloudOpticalDepthAt(crossing, footprint_m) / up);
}

float cloudHenyeyGreenstein(float cosAngle, float g)
{
    return (1.0 - g * g) / (4.0 * SWELL_PI * pow(1.0 + g * g - 2.0 * g * cosAngle, 1.5));
}

// swell::cloudySkyRadiance: the sky with the layer, from the clear sky's
// radiance in that direction, per unit solar irradiance.
vec3 cloudySkyRadiance(vec3 direction, vec3 sun, vec3 clear)
{
    if (cloudCover <= 0.0)
        return clear;
    vec3 d = cloudHorizonClamped(direction);
    CloudHit hit = cloudHit(d);
    float tau = cloudOpticalDepthAt(hit.xz_m, hit.footprint_m);
    const float bottom = SWELL_ATMOSPHERE_BOTTOM_RADIUS_M;
    const float h0 = SWELL_ATMOSPHERE_OBSERVER_ALTITUDE_M;
    float hc = max(cloudAltitude_m, h0 + 1.0);
    float r0 = bottom + h0, rc = bottom + hc;
    float t = hit.distance_m;
    float muView = hit.cosZenith;
    vec3 toCloud = atmosphereTransmittanceTo(r0, h0, d.y);
    vec3 beyond = atmosphereTransmittanceTo(rc, hc, muView);
    vec3 air = min(toCloud / max(beyond, vec3(1.0e-30)), vec3(1.0));
    float cosAngle = dot(d, sun);
    float muSun = (r0 * sun.y + t * cosAngle) / rc;
    vec3 sunlight = muSun > 0.0 ? atmosphereTransmittanceTo(rc, hc, muSun) : vec3(0.0);
    const float g = SWELL_CLOUD_ASYMMETRY;
    float direct = exp(-tau / muView);
    float total = 1.0 / (1.0 + 0.5 * (1.0 - g) * tau);
    float light = 0.0;
    if (muSun > 0.0) {
        float sunDirect = exp(-tau / muSun);
        float diffuse = max(total - sunDirect, 0.0) * muSun / SWELL_PI;
        float p = cloudHenyeyGreenstein(cosAngle, g);
        float once = abs(muView - muSun) < 1.0e-4 ? p * tau / muSun * sunDirect
                                                    : p * muSun / (muView - muSun) * (direct - sunDirect);
        light = diffuse + once;
    }
    vec3 cloud = sunlight * light + clear * max(total - direct, 0.0);
    float shade = 1.0 - cloudCover * (1.0 - exp(-cloudOpticalDepth / max(sun.y, 0.05)));
    vec3 veil = vec3(1.0) - air;
    return clear * (shade * veil + air * direct) + cloud * (air + (1.0 - shade) * veil);
}
#endif
