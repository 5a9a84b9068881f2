// The physical sky on the GPU: the twin of src/core/atmosphere.cpp (the
// same steps in the same order, in float), used only when the sky cubemap is
// baked (sky_bake.frag with SWELL_SKY_PHYSICAL 1). It reads the two tables
// the C++ model builds: transmittance to the top of the atmosphere
// (Bruneton 2017's parametrisation) and Hillaire's (2020, sec. 5.5)
// multiple scattering with the air's order-2 part. Formulas and their
// sources: swell/scene/atmosphere.h and atmosphere.cpp. tests/golden/test_sky_physical.cpp
// checks that the baked sky agrees, tests/gl/test_atmosphere_gpu.cpp the
// multiple-scattering look-ups point by point.
#ifndef SWELL_ATMOSPHERE_GLSL
#define SWELL_ATMOSPHERE_GLSL
#include "swell/gpu/bindings.h"
#include "swell/gpu/sky.h"
#include "gpu/constants.glsl"

layout(binding = SWELL_UNIT_SKY_TRANSMITTANCE) uniform sampler2D atmosphereTransmittance;
// Layer 0: Psi_ms; layers 1 to 3: the air's order-2 harmonics.
layout(binding = SWELL_UNIT_SKY_MULTISCATTER) uniform sampler2DArray atmosphereMultipleScattering;
// AtmosphereSettings::mieScale: aerosols over Bruneton 2017's clear air;
// rayleighScale: air over Bruneton 2017's Earth.
uniform float atmosphereMieScale;
uniform float atmosphereRayleighScale;

const float kAtmosphereBottom = SWELL_ATMOSPHERE_BOTTOM_RADIUS_M;
const float kAtmosphereTop = SWELL_ATMOSPHERE_TOP_RADIUS_M;

// Extinction, Rayleigh scattering (rgb) and Mie scattering (a) at an altitude.
void atmosphereAt(float altitude_m, out vec3 extinction, out vec4 scattering)
{
    float h = max(altitude_m, 0.0);
    float rayleigh = atmosphereRayleighScale * exp(-h / SWELL_RAYLEIGH_SCALE_HEIGHT_M);
    float mie = atmosphereMieScale * exp(-h / SWELL_MIE_SCALE_HEIGHT_M);
    float ozone = max(0.0, 1.0 - abs(h - SWELL_OZONE_PEAK_ALTITUDE_M) / SWELL_OZONE_HALF_WIDTH_M);
    vec3 rayleighScattering =
        rayleigh * vec3(SWELL_RAYLEIGH_SCATTERING_R, SWELL_RAYLEIGH_SCATTERING_G, SWELL_RAYLEIGH_SCATTERING_B);
    scattering = vec4(rayleighScattering, mie * SWELL_MIE_SCATTERING);
    extinction = rayleighScattering + vec3(mie * SWELL_MIE_EXTINCTION)
        + ozone * vec3(SWELL_OZONE_ABSORPTION_R, SWELL_OZONE_ABSORPTION_G, SWELL_OZONE_ABSORPTION_B);
}

// Radii are about 6.4e6 m, where a float's step is half a metre, so
// differences of squared radii are formed from the altitude h instead:
// r^2 - bottom^2 = h (2 bottom + h), top^2 - r^2 = (top - r)(top + r).
float atmosphereDistanceToTop(float r, float altitude, float mu)
{
    float discriminant = r * r * mu * mu + (kAtmosphereTop - kAtmosphereBottom - altitude) * (kAtmosphereTop + r);
    return max(0.0, -r * mu + sqrt(max(discriminant, 0.0)));
}

bool atmosphereMeetsGround(float r, float altitude, float mu)
{
    return mu < 0.0 && r * r * mu * mu - altitude * (2.0 * kAtmosphereBottom + altitude) >= 0.0;
}

// A table coordinate x in 0..1 onto texel centres 0..n-1.
vec2 atmosphereTexel(vec2 x, vec2 n)
{
    return (0.5 + clamp(x, 0.0, 1.0) * (n - 1.0)) / n;
}

vec3 atmosphereTransmittanceTo(float r, float altitude, float mu)
{
    if (atmosphereMeetsGround(r, altitude, mu))
        return vec3(0.0);
    float H = sqrt((kAtmosphereTop - kAtmosphereBottom) * (kAtmosphereTop + kAtmosphereBottom));
    float rho = sqrt(max(altitude * (2.0 * kAtmosphereBottom + altitude), 0.0));
    float d = atmosphereDistanceToTop(r, altitude, mu);
    float dMin = kAtmosphereTop - kAtmosphereBottom - altitude, dMax = rho + H;
    vec2 x = vec2(dMax > dMin ? (d - dMin) / (dMax - dMin) : 0.0, rho / H);
    return texture(atmosphereTransmittance,
                   atmosphereTexel(x, vec2(SWELL_TRANSMITTANCE_MU_SIZE, SWELL_TRANSMITTANCE_R_SIZE))).rgb;
}

vec2 atmosphereMultipleScatteringTexel(float altitude, float muSun)
{
    vec2 x = vec2(muSun * 0.5 + 0.5, altitude / (kAtmosphereTop - kAtmosphereBottom));
    return atmosphereTexel(x, vec2(SWELL_MULTISCATTER_SIZE));
}

vec3 atmosphereMultipleScatteringAt(float altitude, float muSun)
{
    return texture(atmosphereMultipleScattering, vec3(atmosphereMultipleScatteringTexel(altitude, muSun), 0.0)).rgb;
}

// Atmosphere::rayleighMultipleScatteringOrder2: the order-2 harmonics
// (sunFrameHarmonics) at the view, whose zenith cosine is muView and whose
// angle to the sun has cosine cosAngle.
vec3 atmosphereRayleighOrder2At(float altitude, float muSun, float muView, float cosAngle)
{
    float horizontal = sqrt(max(1.0 - muSun * muSun, 0.0));
    float x = horizontal > 1.0e-6 ? clamp((cosAngle - muSun * muView) / horizontal, -1.0, 1.0) : 0.0;
    float y = muView;
    float zz = max(1.0 - x * x - y * y, 0.0);
    vec2 uv = atmosphereMultipleScatteringTexel(altitude, muSun);
    return 1.092548 * x * y * texture(atmosphereMultipleScattering, vec3(uv, 1.0)).rgb
        + 0.315392 * (3.0 * y * y - 1.0) * texture(atmosphereMultipleScattering, vec3(uv, 2.0)).rgb
        + 0.546274 * (x * x - zz) * texture(atmosphereMultipleScattering, vec3(uv, 3.0)).rgb;
}

float atmosphereRayleighPhase(float c)
{
    return 3.0 / (16.0 * SWELL_PI) * (1.0 + c * c);
}

float atmosphereMiePhase(float c, float g)
{
    float k = 3.0 / (8.0 * SWELL_PI) * (1.0 - g * g) / (2.0 + g * g);
    return k * (1.0 + c * c) / pow(1.0 + g * g - 2.0 * g * c, 1.5);
}

// Atmosphere::skyRadiance: the sky's radiance along a unit direction seen
// from the observer's altitude, per unit solar irradiance, 1/sr.
vec3 atmosphereSkyRadiance(vec3 direction, vec3 sun)
{
    vec3 d = normalize(direction);
    if (d.y < 0.0) {
        float horizontal = length(d.xz);
        d = horizontal > 1.0e-6 ? vec3(d.x / horizontal, 0.0, d.z / horizontal) : vec3(1.0, 0.0, 0.0);
    }
    const float h0 = SWELL_ATMOSPHERE_OBSERVER_ALTITUDE_M;
    float r0 = kAtmosphereBottom + h0;
    float len = atmosphereDistanceToTop(r0, h0, d.y);
    float cosAngle = dot(d, sun);
    float phaseRayleigh = atmosphereRayleighPhase(cosAngle);
    float phaseMie = atmosphereMiePhase(cosAngle, SWELL_MIE_ASYMMETRY);
    vec3 depth = vec3(0.0), radiance = vec3(0.0);
    const int n = SWELL_SKY_MARCH_STEPS;
    for (int k = 0; k < n; ++k) {
        float t0 = len * (float(k) / n) * (float(k) / n);
        float t1 = len * (float(k + 1) / n) * (float(k + 1) / n);
        float dt = t1 - t0;
        // The sample relative to the Earth's centre; its radius from the
        // observer's frame without the cancellation of |(0, r0, 0) + t d|
        // in float: r^2 = r0^2 + 2 r0 t mu + t^2.
        float t = 0.5 * (t0 + t1);
        float r = sqrt(r0 * r0 + t * (2.0 * r0 * d.y + t));
        float altitude = (t * (2.0 * r0 * d.y + t) + h0 * (2.0 * kAtmosphereBottom + h0)) / (r + kAtmosphereBottom);
        float muSun = (r0 * sun.y + t * cosAngle) / r;
        float muView = (r0 * d.y + t) / r;
        vec3 extinction;
        vec4 scattering;
        atmosphereAt(altitude, extinction, scattering);
        vec3 toEye = exp(-(depth + 0.5 * dt * extinction));
        vec3 sunLight = atmosphereTransmittanceTo(r, altitude, muSun);
        vec3 multiple = atmosphereMultipleScatteringAt(altitude, muSun);
        vec3 rayleighOrder2 = atmosphereRayleighOrder2At(altitude, muSun, muView, cosAngle);
        vec3 single = sunLight * (scattering.rgb * phaseRayleigh + vec3(scattering.a * phaseMie));
        radiance += toEye * (single + scattering.rgb * (multiple + rayleighOrder2) + vec3(scattering.a) * multiple) * dt;
        depth += dt * extinction;
    }
    return radiance;
}
#endif
