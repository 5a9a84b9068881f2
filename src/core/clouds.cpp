// The cloud layer's shape and light (swell/scene/clouds.h). The shape functions
// are float, written step for step as shaders/clouds.glsl writes them; the
// GPU bakes the layer with those and the C++ twin is what tests compare.
#include "swell/scene/clouds.h"

#include "swell/constants.h"
#include "swell/gpu/sky.h"
#include "swell/scene/atmosphere.h"

#include <glm/common.hpp>
#include <glm/exponential.hpp>
#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <numbers>

namespace swell {

namespace {

// Jarzynski & Olano 2020 ("Hash Functions for GPU Rendering"), pcg2d: two
// 32-bit words in, two well-mixed words out, in unsigned arithmetic that C++
// and GLSL share bit for bit.
glm::uvec2 pcg2d(glm::uvec2 v)
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

// One of eight unit gradients (Perlin 2002 picks from a fixed set too): exact
// in float on both sides, unlike a cosine of a hashed angle.
glm::vec2 gradientAt(glm::ivec2 cell, std::uint32_t seed)
{
    const glm::uvec2 h = pcg2d(glm::uvec2(std::uint32_t(cell.x), std::uint32_t(cell.y) ^ (seed * 0x9E3779B9u)));
    const std::uint32_t k = h.x >> 29u;
    constexpr float s = 0.70710678f;
    switch (k) {
    case 0: return {1.0f, 0.0f};
    case 1: return {-1.0f, 0.0f};
    case 2: return {0.0f, 1.0f};
    case 3: return {0.0f, -1.0f};
    case 4: return {s, s};
    case 5: return {-s, s};
    case 6: return {s, -s};
    default: return {-s, -s};
    }
}

// The normal distribution's CDF by the logistic curve (Bowling et al. 2009:
// within 0.0095 everywhere), and its inverse.
float normalCdf(float x) { return 1.0f / (1.0f + std::exp(-1.702f * x)); }
float normalQuantile(float p) { return std::log(p / (1.0f - p)) / 1.702f; }

double henyeyGreenstein(double cosAngle, double g)
{
    return (1.0 - g * g) / (4.0 * std::numbers::pi * std::pow(1.0 + g * g - 2.0 * g * cosAngle, 1.5));
}

} // namespace

float cloudGradientNoise(glm::vec2 p, std::uint32_t seed)
{
    const glm::vec2 i = glm::floor(p);
    const glm::vec2 f = p - i;
    const glm::ivec2 c(i);
    // Quintic fade (Perlin 2002): continuous second derivative, no creases.
    const glm::vec2 u = f * f * f * (f * (f * 6.0f - 15.0f) + 10.0f);
    const float n00 = glm::dot(gradientAt(c, seed), f);
    const float n10 = glm::dot(gradientAt(c + glm::ivec2(1, 0), seed), f - glm::vec2(1.0f, 0.0f));
    const float n01 = glm::dot(gradientAt(c + glm::ivec2(0, 1), seed), f - glm::vec2(0.0f, 1.0f));
    const float n11 = glm::dot(gradientAt(c + glm::ivec2(1, 1), seed), f - glm::vec2(1.0f, 1.0f));
    return glm::mix(glm::mix(n00, n10, u.x), glm::mix(n01, n11, u.x), u.y);
}

float cloudFractalSum(glm::vec2 p, float footprintCells, float& unresolvedSigma)
{
    // The warp: two coarse noises move the point by up to about
    // SWELL_CLOUD_WARP_CELLS, so no octave's lattice runs straight.
    const float warp = float(SWELL_CLOUD_WARP_CELLS);
    glm::vec2 q = p + warp * glm::vec2(cloudGradientNoise(p * 0.5f + glm::vec2(17.3f, 41.9f), 100u),
                                       cloudGradientNoise(p * 0.5f + glm::vec2(-23.1f, 7.7f), 101u));
    float sum = 0.0f, amplitude = 1.0f, cells = footprintCells, variance = 0.0f, lost = 0.0f, slope = 0.0f;
    for (int k = 0; k < SWELL_CLOUD_OCTAVES; ++k) {
        // An octave whose cells are under two footprints wide is faded to
        // its mean (0): the bake's texels cannot hold it, and it would alias.
        const float keep = glm::clamp(2.0f - 4.0f * cells, 0.0f, 1.0f);
        sum += keep * amplitude * cloudGradientNoise(q, std::uint32_t(k));
        variance += amplitude * amplitude;
        lost += (1.0f - keep) * (1.0f - keep) * amplitude * amplitude;
        // How much the kept octave changes across one footprint: its
        // gradient (about 1 a cell, times its amplitude) times the
        // footprint in its cells.
        slope += keep * amplitude * cells;
        // The next octave: half the cell, on a lattice turned by 36.87
        // degrees (cos 0.8, sin 0.6: exact in float) and shifted.
        q = 2.0f * glm::vec2(0.8f * q.x - 0.6f * q.y, 0.6f * q.x + 0.8f * q.y) + glm::vec2(5.2f, 1.3f);
        amplitude *= 0.5f;
        cells *= 2.0f;
    }
    // What the footprint averages away: the faded octaves' deviation, and
    // half the kept ones' change across it (so a cloud's edge, which the
    // threshold makes sharper than any octave, is never sharper than a
    // footprint: the bake's texels hold it without aliasing).
    const float faded = float(SWELL_CLOUD_FBM_SIGMA) * std::sqrt(lost / variance);
    unresolvedSigma = std::sqrt(faded * faded + 0.25f * slope * slope);
    return sum;
}

float cloudOpticalDepth(const CloudSettings& settings, glm::vec2 xz_m, float footprint_m)
{
    return cloudSample(settings, xz_m, footprint_m).opticalDepth;
}

CloudSample cloudSample(const CloudSettings& settings, glm::vec2 xz_m, float footprint_m)
{
    const float cover = float(settings.cover);
    if (cover <= 0.0f)
        return {};
    const float scale_m = float(settings.scale_m);
    const glm::vec2 p(xz_m.x / (scale_m * float(SWELL_CLOUD_STRETCH)), xz_m.y / scale_m);
    float unresolved = 0.0f;
    const float n = cloudFractalSum(p, footprint_m / scale_m, unresolved);
    const float sigma = float(SWELL_CLOUD_FBM_SIGMA);
    // Cloud where the sum exceeds its (1 - cover) quantile; what the
    // footprint averaged away blurs the edge as the expectation of the mask
    // over it would.
    const float threshold = sigma * normalQuantile(glm::clamp(1.0f - cover, 1.0e-6f, 1.0f - 1.0e-6f));
    const float edge = float(SWELL_CLOUD_EDGE_SIGMA) * sigma;
    const float mask = normalCdf((n - threshold) / std::sqrt(unresolved * unresolved + edge * edge));
    // Thicker where the sum is high: cores, and the dark bands of a deck;
    // 0.3..1.7 of the mean, 1 where the detail is averaged away.
    const float thickness = 0.3f + 1.4f * normalCdf(n / sigma);
    return {mask, float(settings.opticalDepth) * mask * thickness};
}

CloudHit cloudHit(const CloudSettings& settings, glm::vec3 direction)
{
    glm::vec3 d = glm::normalize(direction);
    if (d.y < 0.0f) {
        const float horizontal = std::sqrt(d.x * d.x + d.z * d.z);
        d = horizontal > 1.0e-6f ? glm::vec3(d.x / horizontal, 0.0f, d.z / horizontal) : glm::vec3(1.0f, 0.0f, 0.0f);
    }
    const float bottom = float(kAtmosphereBottomRadius_m);
    const float h0 = float(SWELL_ATMOSPHERE_OBSERVER_ALTITUDE_M);
    const float hc = std::max(float(settings.altitude_m), h0 + 1.0f);
    const float r0 = bottom + h0, rc = bottom + hc;
    // Distance to the sphere of radius rc: t^2 + 2 r0 mu t - (rc^2 - r0^2) = 0,
    // in the form without the cancellation of -r0 mu + sqrt(...) in float.
    const float c = (hc - h0) * (2.0f * bottom + hc + h0);
    const float b = r0 * d.y;
    const float t = c / (b + std::sqrt(b * b + c));
    CloudHit hit;
    hit.distance_m = t;
    hit.xz_m = t * glm::vec2(d.x, d.z);
    hit.cosZenith = std::max((b + t) / rc, 1.0e-3f);
    // A texel's angle at distance t, drawn out by the slant of the layer.
    hit.footprint_m = t * float(SWELL_CLOUD_TEXEL_RAD) / hit.cosZenith;
    return hit;
}

float cloudTransmittance(const CloudSettings& settings, glm::vec3 direction)
{
    if (settings.cover <= 0.0)
        return 1.0f;
    const CloudHit hit = cloudHit(settings, direction);
    return std::exp(-cloudOpticalDepth(settings, hit.xz_m, hit.footprint_m) / hit.cosZenith);
}

float cloudShadowTransmittance(const CloudSettings& settings, glm::vec3 point_m, glm::vec3 sun, float footprint_m)
{
    const float altitude_m = float(settings.altitude_m);
    if (settings.cover <= 0.0 || point_m.y >= altitude_m)
        return 1.0f;
    const float up = std::max(sun.y, float(SWELL_CLOUD_SHADOW_MIN_SUN_Y));
    const glm::vec2 crossing = glm::vec2(point_m.x, point_m.z) + glm::vec2(sun.x, sun.z) * ((altitude_m - point_m.y) / up);
    return std::exp(-cloudOpticalDepth(settings, crossing, footprint_m) / up);
}

glm::dvec3 cloudySkyRadiance(const Atmosphere& atmosphere, const CloudSettings& settings, glm::dvec3 direction,
                             glm::dvec3 sunDirection, glm::dvec3 clear)
{
    if (settings.cover <= 0.0)
        return clear;
    const glm::dvec3 d = glm::normalize(direction), sun = glm::normalize(sunDirection);
    const CloudHit hit = cloudHit(settings, glm::vec3(d));
    const double tau = cloudOpticalDepth(settings, hit.xz_m, hit.footprint_m);
    const double bottom = kAtmosphereBottomRadius_m;
    const double r0 = bottom + SWELL_ATMOSPHERE_OBSERVER_ALTITUDE_M;
    const double rc = bottom + std::max(settings.altitude_m, SWELL_ATMOSPHERE_OBSERVER_ALTITUDE_M + 1.0);
    const double t = hit.distance_m;
    const double muView = hit.cosZenith;
    // Below the horizon, the horizon in the same azimuth (as cloudHit takes it).
    const double horizontal = glm::length(glm::dvec2(d.x, d.z));
    const glm::dvec3 dh = d.y >= 0.0 ? d : horizontal > 1.0e-6 ? glm::dvec3(d.x, 0.0, d.z) / horizontal : glm::dvec3(1.0, 0.0, 0.0);
    // The air between the eye and the cloud: the ratio of the transmittances
    // to the top from both ends (Bruneton & Neyret 2008, sec. 2.1).
    const glm::dvec3 toCloud = atmosphere.transmittance(r0, dh.y);
    const glm::dvec3 beyond = atmosphere.transmittance(rc, muView);
    const glm::dvec3 air = glm::min(toCloud / glm::max(beyond, glm::dvec3(1.0e-30)), glm::dvec3(1.0));
    // The sun's light at the cloud, and its cosine with the vertical there.
    const double cosAngle = glm::dot(dh, sun);
    const double muSun = (r0 * sun.y + t * cosAngle) / rc;
    const glm::dvec3 sunlight = muSun > 0.0 ? atmosphere.transmittance(rc, muSun) : glm::dvec3(0.0);
    const double g = kCloudDropletAsymmetry;
    const double direct = std::exp(-tau / muView);
    // Two-stream theory's transmittance of a non-absorbing slab (Bohren 1987):
    // 1 / (1 + (1 - g) tau / 2); what is not the direct beam leaves its base
    // diffuse.
    const double total = 1.0 / (1.0 + 0.5 * (1.0 - g) * tau);
    double light = 0.0;
    if (muSun > 0.0) {
        const double sunDirect = std::exp(-tau / muSun);
        const double diffuse = std::max(total - sunDirect, 0.0) * muSun / std::numbers::pi;
        // Sunlight scattered once towards the eye in the slab (Liou 2002,
        // sec. 6.2): p mu0 / (mu - mu0) (e^(-tau/mu) - e^(-tau/mu0)), whose
        // limit for mu = mu0 is p tau / mu0 e^(-tau/mu0): the silver edge of
        // a thin cloud near the sun, which the isotropic diffuse lacks.
        const double p = henyeyGreenstein(cosAngle, g);
        const double once = std::abs(muView - muSun) < 1.0e-4
            ? p * tau / muSun * sunDirect
            : p * muSun / (muView - muSun) * (direct - sunDirect);
        light = diffuse + once;
    }
    // The sky's own light through the slab, diffused (the clear sky's
    // radiance in this direction stands for it).
    const glm::dvec3 cloud = sunlight * light + clear * std::max(total - direct, 0.0);
    // The air in front of the cloud scatters the sun's light (the clear
    // sky's radiance holds it) where the layer lets the sun through, on
    // average 1 - cover (1 - e^(-tau/mu_sun)) of it; in the layer's shadow
    // it scatters the cloud's light instead: under a deck the haze is grey.
    const double shade = 1.0 - settings.cover * (1.0 - std::exp(-settings.opticalDepth / std::max(sun.y, 0.05)));
    const glm::dvec3 veil = glm::dvec3(1.0) - air;
    return clear * (shade * veil + air * direct) + cloud * (air + (1.0 - shade) * veil);
}

} // namespace swell
