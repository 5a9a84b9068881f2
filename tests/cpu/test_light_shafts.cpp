// The closed form of the shafts of light under a level surface
// (src/render/light_shafts.h, the twin of shaders/light_shafts.glsl): the
// phase function is a probability density over the sphere with mean cosine
// g, and the closed form is the path integral it claims to be, checked by
// summing the integrand along the ray in small steps.
#include "render/light_shafts.h"
#include "swell/constants.h"

#include <gtest/gtest.h>

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <numbers>

namespace {

const glm::dvec3 kSun = glm::normalize(glm::dvec3(-0.3, 0.8, -0.5));
const glm::dvec3 kAbsorption_per_m(0.40, 0.07, 0.09);
const glm::dvec3 kSunIrradiance(1.0, 0.96, 0.9);
constexpr double kTransmittance = 0.97;

TEST(LightShaftsModel, ThePhaseFunctionIsADensityWithMeanCosineG)
{
    // Over the sphere, dOmega = 2 pi sin(theta) dtheta, midpoint rule.
    constexpr int kSteps = 200000;
    double total = 0.0, meanCosine = 0.0;
    for (int i = 0; i < kSteps; ++i) {
        const double theta = (i + 0.5) * std::numbers::pi / kSteps;
        const double w = 2.0 * std::numbers::pi * std::sin(theta) * std::numbers::pi / kSteps;
        total += swell::detail::henyeyGreenstein(std::cos(theta)) * w;
        meanCosine += swell::detail::henyeyGreenstein(std::cos(theta)) * std::cos(theta) * w;
    }
    EXPECT_NEAR(total, 1.0, 1e-4);
    EXPECT_NEAR(meanCosine, swell::kWaterPhaseG, 1e-4);
    // Seawater scatters forwards: more than 100 times as much at 5 degrees as at 90.
    EXPECT_GT(swell::detail::henyeyGreenstein(std::cos(5.0 * std::numbers::pi / 180.0)),
              100.0 * swell::detail::henyeyGreenstein(0.0));
}

TEST(LightShaftsModel, TheClosedFormIsThePathIntegral)
{
    const glm::dvec3 ray = swell::detail::levelRefractedRay(kSun);
    // Snell: sin T = sin I / n.
    EXPECT_NEAR(std::sqrt(1.0 - ray.y * ray.y), std::sqrt(1.0 - kSun.y * kSun.y) / swell::kWaterIor, 1e-12);
    const double cosT = -ray.y;
    for (const glm::dvec3 d : {-ray, glm::normalize(glm::dvec3(1.0, 0.0, 0.2)), glm::normalize(glm::dvec3(0.3, 0.9, -0.1)),
                               glm::normalize(glm::dvec3(-0.2, -0.7, 0.5))})
        for (const double depth_m : {0.5, 3.0, 12.0})
            for (const double path_m : {2.0, 40.0}) {
                const glm::dvec3 start(1.0, -depth_m, -2.0);
                // The integrand summed in 1 cm steps to the path's end or the surface.
                double end_m = path_m;
                if (d.y > 0.0)
                    end_m = std::min(end_m, depth_m / d.y);
                const int steps = std::max(1, int(end_m / 0.01));
                const double dt = end_m / steps;
                glm::dvec3 sum(0.0);
                for (int i = 0; i < steps; ++i) {
                    const double t = (i + 0.5) * dt;
                    const double z = depth_m - t * d.y;
                    const glm::dvec3 beam =
                        kSunIrradiance * kSun.y * kTransmittance / cosT * glm::exp(-kAbsorption_per_m * z / cosT);
                    sum += beam * swell::kWaterScattering_per_m * swell::detail::henyeyGreenstein(glm::dot(ray, -d)) *
                           glm::exp(-kAbsorption_per_m * t) * dt;
                }
                const glm::dvec3 closed = swell::detail::levelShaftsRadiance(kSun, kSunIrradiance, kAbsorption_per_m,
                                                                             kTransmittance, start, d, path_m);
                for (int c = 0; c < 3; ++c)
                    EXPECT_NEAR(closed[c], sum[c], 1e-5 * sum[c]) << "depth " << depth_m << ", path " << path_m
                                                                  << ", d " << d.x << " " << d.y << " " << d.z;
            }
    // No sun, no light.
    EXPECT_EQ(swell::detail::levelShaftsRadiance(glm::dvec3(0.0, -0.2, 0.98), kSunIrradiance, kAbsorption_per_m,
                                                 kTransmittance, glm::dvec3(0.0, -3.0, 0.0), glm::dvec3(1.0, 0.0, 0.0),
                                                 10.0),
              glm::dvec3(0.0));
}

} // namespace
