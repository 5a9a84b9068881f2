// The spray's kinematics (src/render/spray_kinematics.h, the twin of
// shaders/spray.glsl): a drop's closed-form flight against Stokes drag
// integrated in small steps, and a slot's lives following one another.
#include "render/spray_kinematics.h"
#include "swell/gpu/spray.h"

#include <gtest/gtest.h>

#include <glm/geometric.hpp>

namespace {

using namespace swell::detail;

// dv/dt = (v_air - v) / tau - g, integrated by the midpoint rule in 10 us
// steps: the closed form within a millimetre, for mist and large drops.
TEST(SprayKinematics, DropFlightIsStokesDragIntegrated)
{
    const glm::vec3 launch(4.0f, 3.0f, -1.0f), air(16.0f, 0.5f, 0.0f);
    for (const float tau_s : {0.006f, 0.04f, 0.2f, 0.38f}) {
        glm::dvec3 x(0.0), v(launch);
        const double dt = 1e-5;
        for (int step = 1; step <= 120000; ++step) {
            const glm::dvec3 a = (glm::dvec3(air) - v) / double(tau_s) - glm::dvec3(0.0, 9.81, 0.0);
            const glm::dvec3 vMid = v + 0.5 * dt * a;
            const glm::dvec3 aMid = (glm::dvec3(air) - vMid) / double(tau_s) - glm::dvec3(0.0, 9.81, 0.0);
            x += dt * vMid;
            v += dt * aMid;
            if (step % 30000 == 0) {
                const glm::dvec3 closed(sprayDropOffset(launch, air, tau_s, float(step * dt)));
                EXPECT_LT(glm::length(closed - x), 1e-3) << "tau " << tau_s << " s at " << step * dt << " s";
            }
        }
    }
}

// The mist is taken up by the wind: after a quarter of a second it flies
// with the air to within 1%, while the largest drop is still far from it.
TEST(SprayKinematics, MistFollowsTheWindDropsLag)
{
    for (std::uint32_t key : {1u, 77u, 123456u}) {
        for (std::uint32_t drop = 0; drop < SWELL_SPRAY_DROPS; ++drop) {
            const float tau_s = sprayTau_s(key, drop);
            if (drop < SWELL_SPRAY_MIST_DROPS)
                EXPECT_LT(tau_s, 0.25f / 4.6f) << "mist drop " << drop; // e^-4.6 = 1%
            else
                EXPECT_GT(tau_s, 0.05f) << "large drop " << drop;
        }
    }
}

// A slot's age grows with the time and wraps at the lifetime, where a new
// life (a new key, a new place) begins; the period's split carries on.
TEST(SprayKinematics, LivesFollowOneAnother)
{
    const glm::ivec2 cell(-7, 12);
    const float lifetime_s = float(SWELL_SPRAY_LIFETIME_S);
    const SprayLife a = sprayLife(cell, 3, sprayPeriodTime(100.0));
    const SprayLife b = sprayLife(cell, 3, sprayPeriodTime(100.0 + 0.5 * (lifetime_s - a.age_s)));
    EXPECT_EQ(a.key, b.key);
    EXPECT_NEAR(b.age_s - a.age_s, 0.5 * (lifetime_s - a.age_s), 1e-4);
    const SprayLife c = sprayLife(cell, 3, sprayPeriodTime(100.0 + (lifetime_s - a.age_s) + 0.01));
    EXPECT_NE(a.key, c.key);
    EXPECT_NEAR(c.age_s, 0.01, 1e-4);
    EXPECT_NE(a.inCell, c.inCell);
    const glm::vec2 late = sprayPeriodTime(SWELL_SPRAY_LIFETIME_S * 4096.0 * 3.0 + 5.0);
    EXPECT_FLOAT_EQ(late.y, 3.0f);
    EXPECT_NEAR(late.x, 5.0f, 1e-4f);
}

} // namespace
