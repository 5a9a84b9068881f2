// The spray's kinematics: the C++ twin of shaders/spray.glsl, line for
// line and in float as the shader computes: which slot of the lattice
// lives when and where in its cell, whether the crest signal (the
// whitecaps' foam there) lets it live, its launch, the air its drops meet
// and each drop's flight; and the bow spray's (the hull's sample at a
// life's birth, its launch, its drops). tests/gl/test_spray_kinematics.cpp runs the
// shader's functions and these over a set of seeds and times.
#pragma once

#include "swell/constants.h"
#include "swell/gpu/spray.h"

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>

namespace swell::detail {

// spray.glsl's sprayHash (Wellons 2018, "lowbias32").
inline std::uint32_t sprayHash(std::uint32_t x)
{
    x ^= x >> 16u;
    x *= 0x7feb352du;
    x ^= x >> 15u;
    x *= 0x846ca68bu;
    x ^= x >> 16u;
    return x;
}

inline float sprayUnit(std::uint32_t key, std::uint32_t n)
{
    return float(sprayHash(key + n * 0x9e3779b9u) >> 8u) * (1.0f / 16777216.0f);
}

struct SprayLife {
    std::uint32_t key = 0;
    float age_s = 0.0f;
    glm::vec2 inCell{0.0f};
};

// The shader's time uniform: the time within a period of 4096 lifetimes
// (x, s) and the period's index (y).
inline glm::vec2 sprayPeriodTime(double time_s)
{
    const double period_s = SWELL_SPRAY_LIFETIME_S * 4096.0;
    const double period = std::floor(time_s / period_s);
    return {float(time_s - period * period_s), float(period)};
}

inline SprayLife sprayLife(glm::ivec2 worldCell, int slot, glm::vec2 time_s)
{
    const std::uint32_t slotKey = sprayHash(std::uint32_t(worldCell.x) * 0x9e3779b1u ^
                                            sprayHash(std::uint32_t(worldCell.y) ^ sprayHash(std::uint32_t(slot))));
    const float lifetime_s = float(SWELL_SPRAY_LIFETIME_S);
    const float local_s = time_s.x + sprayUnit(slotKey, 0u) * lifetime_s;
    const float life = std::floor(local_s / lifetime_s);
    SprayLife l;
    l.age_s = local_s - life * lifetime_s;
    const std::uint32_t lifeIndex = std::uint32_t(int(time_s.y)) * 4096u + std::uint32_t(int(life));
    l.key = sprayHash(slotKey ^ sprayHash(lifeIndex));
    l.inCell = {sprayUnit(l.key, 2u), sprayUnit(l.key, 3u)};
    return l;
}

inline bool sprayLives(std::uint32_t key, float foam, float youngFoam, float amount)
{
    const float young = youngFoam * youngFoam, old = young * young * youngFoam;
    const float breaking = std::clamp((foam - old) / std::max(young - old, 1e-3f), 0.0f, 1.0f);
    return sprayUnit(key, 1u) < amount && sprayUnit(key, 4u) < breaking;
}

inline glm::vec3 sprayLaunch(std::uint32_t key, std::uint32_t drop, glm::vec2 windDirection, float windSpeed_mps)
{
    const glm::vec2 across(-windDirection.y, windDirection.x);
    const float side = (sprayUnit(key, 8u) - 0.5f) * 2.0f + (sprayUnit(key, 20u + drop) - 0.5f);
    const glm::vec2 level = windDirection * windSpeed_mps * (0.3f + 0.3f * sprayUnit(key, 7u)) + across * side;
    return {level.x, 1.0f + 3.0f * sprayUnit(key, 6u) + (sprayUnit(key, 30u + drop) - 0.5f), level.y};
}

inline glm::vec3 sprayAir(std::uint32_t key, std::uint32_t drop, glm::vec2 windDirection, float windSpeed_mps)
{
    const glm::vec2 across(-windDirection.y, windDirection.x);
    const glm::vec2 level = windDirection * (0.8f * windSpeed_mps * (0.9f + 0.2f * sprayUnit(key, 40u + drop))) +
                            across * (sprayUnit(key, 50u + drop) - 0.5f) * 3.0f;
    return {level.x, 0.2f + 0.8f * sprayUnit(key, 60u + drop), level.y};
}

inline float sprayTau_s(std::uint32_t key, std::uint32_t drop)
{
    const float u = sprayUnit(key, 10u + drop);
    const float d_m = drop < std::uint32_t(SWELL_SPRAY_MIST_DROPS) ? (40.0f + 80.0f * u) * 1e-6f
                                                                    : (150.0f + 200.0f * u) * 1e-6f;
    return float(kSeaWaterDensity_kg_per_m3) * d_m * d_m / (18.0f * 1.8e-5f);
}

inline glm::vec3 sprayDropOffset(glm::vec3 launch_mps, glm::vec3 air_mps, float tau_s, float age_s)
{
    const glm::vec3 terminal = air_mps + glm::vec3(0.0f, -9.81f * tau_s, 0.0f);
    return terminal * age_s + (launch_mps - terminal) * tau_s * (1.0f - std::exp(-age_s / tau_s));
}

// The bow's spray (spray.glsl, after sprayDropOffset).
inline int bowSpraySample(float age_s, float lag_s)
{
    return std::max(int(std::ceil((age_s - lag_s) * float(SWELL_BOW_SPRAY_SAMPLES_PER_S))), 0);
}

inline bool bowSprayLives(std::uint32_t key, float share) { return sprayUnit(key, 1u) < share; }

inline float bowSprayFallSpeed_mps(float diameter_m) { return 4030.0f * diameter_m; }

inline float bowSprayTau_s(std::uint32_t key, std::uint32_t drop)
{
    if (drop < std::uint32_t(SWELL_SPRAY_MIST_DROPS))
        return sprayTau_s(key, drop);
    const float d_m = (400.0f + 600.0f * sprayUnit(key, 10u + drop)) * 1e-6f;
    return bowSprayFallSpeed_mps(d_m) / 9.81f;
}

inline float bowSlamJet_mps(float plunge_mps, float flareCot)
{
    return 3.14159265f * plunge_mps * std::clamp(flareCot, 0.0f, float(SWELL_BOW_SPRAY_MAX_FLARE_COT));
}

inline glm::vec3 bowSheetLaunch(std::uint32_t key, glm::vec2 forward, glm::vec2 outward, float speed_mps,
                                float plunge_mps, float flareCot)
{
    const float sheet_mps = speed_mps * (0.5f + 0.5f * sprayUnit(key, 70u)) +
                            bowSlamJet_mps(plunge_mps, flareCot) * (0.5f + 0.5f * sprayUnit(key, 71u));
    const float rise = 0.45f + 0.45f * sprayUnit(key, 72u);
    const glm::vec2 level = outward * (sheet_mps * std::sqrt(1.0f - rise * rise)) +
                            forward * (speed_mps * (0.3f + 0.3f * sprayUnit(key, 73u)));
    return {level.x, sheet_mps * rise, level.y};
}

inline glm::vec3 bowSprayLaunch(std::uint32_t key, std::uint32_t drop, glm::vec2 forward, glm::vec2 outward,
                                float speed_mps, float plunge_mps, float flareCot)
{
    const glm::vec3 scatter =
        glm::vec3(sprayUnit(key, 80u + drop), sprayUnit(key, 90u + drop), sprayUnit(key, 100u + drop)) - 0.5f;
    return bowSheetLaunch(key, forward, outward, speed_mps, plunge_mps, flareCot) + 0.5f * scatter;
}

inline float bowSheetTau_s() { return bowSprayFallSpeed_mps(1.0e-3f) / 9.81f; }

inline float bowSheetRetraction_mps(float thickness_m)
{
    return std::sqrt(2.0f * float(kSeaWaterSurfaceTension_N_per_m)
                     / (float(kSeaWaterDensity_kg_per_m3) * thickness_m));
}

inline float bowSheetTorn(std::uint32_t key, float age_s)
{
    const float u = sprayUnit(key, 110u);
    const float thickness_m =
        (float(SWELL_BOW_SPRAY_SHEET_MIN_MM) * (1.0f - u) + float(SWELL_BOW_SPRAY_SHEET_MAX_MM) * u) * 1e-3f;
    const float r_m = bowSheetRetraction_mps(thickness_m) * age_s;
    const float spacing_m = float(SWELL_BOW_SPRAY_HOLE_SPACING_M);
    return std::min(3.14159265f * r_m * r_m / (spacing_m * spacing_m), 1.0f);
}

} // namespace swell::detail
