// The plane-parallel Rayleigh layer's radiance by forward Monte Carlo
// (rayleigh_layer_transfer.h).
#include "rayleigh_layer_transfer.h"

#include "swell/constants.h"

#include <glm/geometric.hpp>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include <cmath>
#include <numbers>
#include <random>

namespace swell::test {
namespace {

using swell::kPi;
constexpr double kRayleighNorm = 3.0 / (16.0 * kPi); // Rayleigh's phase function is this times 1 + cos^2

// Uniform in [0, 1) from the top 53 bits: the same on every standard library.
double uniform(std::mt19937_64& rng) { return double(rng() >> 11) * 0x1.0p-53; }

// A unit vector perpendicular to unit d.
glm::dvec3 perpendicular(glm::dvec3 d)
{
    return glm::normalize(glm::cross(d, std::abs(d.z) < 0.9 ? glm::dvec3(0.0, 0.0, 1.0) : glm::dvec3(1.0, 0.0, 0.0)));
}

// A photon's polarisation: the Stokes vector (I, Q, U, V) with I = 1 (the
// photon's weight carries its intensity), Q = I_par - I_perp with respect
// to `reference`, a unit vector perpendicular to the direction of travel.
struct Polarisation {
    glm::dvec4 stokes{1.0, 0.0, 0.0, 0.0};
    glm::dvec3 reference{1.0, 0.0, 0.0};
};

// The Stokes vector re-expressed with respect to the scattering plane of a
// photon travelling along `from` and scattered into `to`: the plane's
// parallel axis n x from, n = from x to. Returns that axis too. A rotation
// of the reference by psi turns (Q, U) by 2 psi (Hovenier et al. 2004, eq.
// 1.44); the sense of U does not change the intensity, only its
// consistency does.
glm::dvec4 inScatteringPlane(const Polarisation& p, glm::dvec3 from, glm::dvec3 to, glm::dvec3& parallelOut)
{
    glm::dvec3 n = glm::cross(from, to);
    const double length = glm::length(n);
    n = length > 1.0e-12 ? n / length : perpendicular(from);
    const glm::dvec3 parallelIn = glm::cross(n, from);
    parallelOut = glm::cross(n, to);
    const double c = glm::dot(p.reference, parallelIn), s = glm::dot(glm::cross(p.reference, parallelIn), from);
    const double c2 = c * c - s * s, s2 = 2.0 * s * c;
    const glm::dvec4 v = p.stokes;
    return {v.x, v.y * c2 + v.z * s2, -v.y * s2 + v.z * c2, v.w};
}

// Rayleigh's scattering matrix in the scattering plane's frame, without its
// norm (Chandrasekhar 1950, sec. 17; Hovenier et al. 2004, eq. 2.62 with no
// depolarisation): scattered light at 90 degrees is polarised
// perpendicularly to the plane (Q = -I).
glm::dvec4 rayleighMatrix(double cosAngle, glm::dvec4 s)
{
    const double a = 1.0 + cosAngle * cosAngle, b = cosAngle * cosAngle - 1.0;
    return {a * s.x + b * s.y, b * s.x + a * s.y, 2.0 * cosAngle * s.z, 2.0 * cosAngle * s.w};
}

// A direction scattered from unit d, its angle's cosine drawn from 1 +
// cos^2 (by rejection) and its azimuth uniform.
glm::dvec3 scatter(glm::dvec3 d, std::mt19937_64& rng, double& cosAngle)
{
    do
        cosAngle = 2.0 * uniform(rng) - 1.0;
    while (2.0 * uniform(rng) > 1.0 + cosAngle * cosAngle);
    const double phi = 2.0 * kPi * uniform(rng);
    const glm::dvec3 e1 = perpendicular(d), e2 = glm::cross(d, e1);
    const double sinAngle = std::sqrt(std::max(1.0 - cosAngle * cosAngle, 0.0));
    return glm::normalize(cosAngle * d + sinAngle * (std::cos(phi) * e1 + std::sin(phi) * e2));
}

} // namespace

std::vector<double> rayleighLayerRadiance(double opticalDepth, double sunZenith_deg, const std::vector<LayerView>& views,
                                          bool polarised, long photons, std::uint64_t seed)
{
    // z up; the sun in the x-z plane; each view's light travels down
    // towards the eye, along -view.
    const double sunZenith = sunZenith_deg * kPi / 180.0, mu0 = std::cos(sunZenith);
    std::vector<glm::dvec3> arriving;
    for (const LayerView& v : views) {
        const double z = v.viewZenith_deg * kPi / 180.0, a = v.azimuthFromSun_deg * kPi / 180.0;
        arriving.push_back(-glm::dvec3(std::sin(z) * std::cos(a), std::sin(z) * std::sin(a), std::cos(z)));
    }
    std::vector<double> sum(views.size(), 0.0);
    std::mt19937_64 rng(seed);
    for (long photon = 0; photon < photons; ++photon) {
        glm::dvec3 d(-std::sin(sunZenith), 0.0, -mu0);
        Polarisation p{{1.0, 0.0, 0.0, 0.0}, perpendicular(d)};
        double weight = 1.0, depth = 0.0; // optical depth from the top
        while (true) {
            depth -= std::log(1.0 - uniform(rng)) * -d.z;
            if (depth < 0.0 || depth > opticalDepth)
                break; // out at the top, or into the black ground
            // The local estimate: this collision's light scattered straight
            // to the eye, through the rest of the layer below.
            for (size_t k = 0; k < views.size(); ++k) {
                const glm::dvec3 to = arriving[k];
                const double cosAngle = glm::dot(d, to);
                double intensity = 1.0 + cosAngle * cosAngle;
                if (polarised) {
                    glm::dvec3 unused;
                    intensity = rayleighMatrix(cosAngle, inScatteringPlane(p, d, to, unused)).x;
                }
                sum[k] += weight * kRayleighNorm * intensity * std::exp(-(opticalDepth - depth) / -to.z) / -to.z;
            }
            // On along a direction drawn from the scalar phase function; the
            // weight takes the polarised intensity over it.
            double cosAngle = 0.0;
            const glm::dvec3 next = scatter(d, rng, cosAngle);
            if (polarised) {
                glm::dvec3 parallel;
                const glm::dvec4 scattered = rayleighMatrix(cosAngle, inScatteringPlane(p, d, next, parallel));
                weight *= scattered.x / (1.0 + cosAngle * cosAngle);
                p = {scattered / scattered.x, parallel};
            }
            d = next;
        }
    }
    // Each photon carries the sun's flux through a unit of horizontal area,
    // mu0 per unit irradiance normal to the rays.
    for (double& s : sum)
        s *= mu0 / double(photons);
    return sum;
}

} // namespace swell::test
