// The physical sky's model in double precision (swell/scene/atmosphere.h). The
// GPU's twin, used for the baked sky, is shaders/atmosphere.glsl: the same
// steps in the same order, reading the two tables built here.
//
// Geometry: the Earth is a sphere of kAtmosphereBottomRadius_m, the
// air ends at kAtmosphereTopRadius_m; a point is given by its radius r
// and a direction by the cosine mu of its angle to the point's zenith
// (Bruneton & Neyret 2008, sec. 4).
#include "swell/scene/atmosphere.h"

#include "swell/constants.h"
#include "swell/gpu/sky.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <numbers>

namespace swell {
namespace {

constexpr double kBottom_m = kAtmosphereBottomRadius_m;
constexpr double kTop_m = kAtmosphereTopRadius_m;
constexpr int kMuSize = SWELL_TRANSMITTANCE_MU_SIZE;
constexpr int kRSize = SWELL_TRANSMITTANCE_R_SIZE;
constexpr int kMsSize = SWELL_MULTISCATTER_SIZE;
constexpr int kMsLayers = SWELL_MULTISCATTER_LAYERS;
constexpr size_t kMsLayerFloats = size_t(3 * kMsSize * kMsSize);
// Hillaire 2020, sec. 5.5: 64 directions around each point of the
// multiple-scattering table, 20 steps along each.
constexpr int kMsDirectionsPerAxis = 8;
constexpr int kMsSteps = 20;
// The transmittance table's trapezoids per ray (Bruneton 2017 uses 500;
// 128 agree with 4096 within 1e-3 of the value along every ray tried).
constexpr int kTableSteps = 128;

// Distance along (r, mu) to the top of the atmosphere, and to the ground
// (ray-sphere intersection; Bruneton 2017, DistanceToTopAtmosphereBoundary).
double distanceToTop(double r, double mu)
{
    const double discriminant = r * r * (mu * mu - 1.0) + kTop_m * kTop_m;
    return std::max(0.0, -r * mu + std::sqrt(std::max(discriminant, 0.0)));
}
bool meetsGround(double r, double mu)
{
    return mu < 0.0 && r * r * (mu * mu - 1.0) + kBottom_m * kBottom_m >= 0.0;
}
double distanceToGround(double r, double mu)
{
    const double discriminant = r * r * (mu * mu - 1.0) + kBottom_m * kBottom_m;
    return std::max(0.0, -r * mu - std::sqrt(std::max(discriminant, 0.0)));
}

// Bruneton 2017's transmittance-table coordinates of (r, mu), each 0..1:
// x_r = rho / H and x_mu = (d - d_min) / (d_max - d_min), where H is the
// distance to the top's horizon from the ground, rho that from r, d the
// distance to the top along mu. Dense where transmittance changes fastest,
// towards the horizon.
glm::dvec2 transmittanceCoordinates(double r, double mu)
{
    const double H = std::sqrt(kTop_m * kTop_m - kBottom_m * kBottom_m);
    const double rho = std::sqrt(std::max(r * r - kBottom_m * kBottom_m, 0.0));
    const double d = distanceToTop(r, mu);
    const double dMin = kTop_m - r, dMax = rho + H;
    return {dMax > dMin ? (d - dMin) / (dMax - dMin) : 0.0, rho / H};
}

// ...and back.
void radiusAndMuOf(glm::dvec2 x, double& r, double& mu)
{
    const double H = std::sqrt(kTop_m * kTop_m - kBottom_m * kBottom_m);
    const double rho = H * x.y;
    r = std::sqrt(rho * rho + kBottom_m * kBottom_m);
    const double dMin = kTop_m - r, dMax = rho + H;
    const double d = dMin + x.x * (dMax - dMin);
    mu = d == 0.0 ? 1.0 : std::clamp((H * H - rho * rho - d * d) / (2.0 * r * d), -1.0, 1.0);
}

// Bilinear lookup of a row-major RGB float table of w x h texels at
// coordinates x in 0..1 that map linearly onto texel centres 0..w-1 (what
// GL's linear filter does at u = 0.5/w + x (1 - 1/w)), clamped at the edges.
glm::dvec3 lookup(const float* table, int w, int h, glm::dvec2 x)
{
    const double fx = std::clamp(x.x, 0.0, 1.0) * (w - 1), fy = std::clamp(x.y, 0.0, 1.0) * (h - 1);
    const int x0 = std::min(int(fx), w - 2), y0 = std::min(int(fy), h - 2);
    const double ax = fx - x0, ay = fy - y0;
    auto at = [&](int i, int j) {
        const float* p = table + 3 * (size_t(j) * size_t(w) + size_t(i));
        return glm::dvec3(p[0], p[1], p[2]);
    };
    return (at(x0, y0) * (1.0 - ax) + at(x0 + 1, y0) * ax) * (1.0 - ay)
        + (at(x0, y0 + 1) * (1.0 - ax) + at(x0 + 1, y0 + 1) * ax) * ay;
}

void put(std::vector<float>& table, size_t texel, glm::dvec3 v)
{
    table[3 * texel + 0] = float(v.x);
    table[3 * texel + 1] = float(v.y);
    table[3 * texel + 2] = float(v.z);
}

// The multiple-scattering table's coordinates (Hillaire 2020, sec. 5.5):
// the sun zenith cosine and the altitude, linearly.
glm::dvec2 multiScatteringCoordinates(double r, double muSun)
{
    return {muSun * 0.5 + 0.5, std::clamp((r - kBottom_m) / (kTop_m - kBottom_m), 0.0, 1.0)};
}

// The three real spherical harmonics of order 2 that light scattered
// around a point can have, at a unit direction (x, y, z) in the frame whose
// y is the point's zenith and whose x points at the sun's azimuth: the
// light is mirror-symmetric about the sun's vertical plane (z to -z), so
// Y_2-1 and Y_21, odd in z, are 0. Ramamoorthi & Hanrahan's (2001, sec. 2)
// Y_2-2, Y_20 and Y_22 in this frame; z enters squared, as 1 - x^2 - y^2.
std::array<double, 3> sunFrameHarmonics(double x, double y)
{
    const double zz = std::max(1.0 - x * x - y * y, 0.0);
    return {1.092548 * x * y, 0.315392 * (3.0 * y * y - 1.0), 0.546274 * (x * x - zz)};
}

// The scattering a sample adds towards the eye, per unit solar irradiance
// and unit length: sunlight scattered once (Hillaire 2020, sec. 4, the
// in-scattering term with the phase functions), plus the light scattered
// twice or more: the scattering coefficients times Psi_ms (Hillaire 2020,
// sec. 5.5), the air's with its order-2 part `rayleighOrder2` (see
// buildMultipleScattering).
glm::dvec3 inScattering(const AtmosphereCoefficients& c, glm::dvec3 sunTransmittance, glm::dvec3 multiple,
                        glm::dvec3 rayleighOrder2, double phaseRayleigh, double phaseMie)
{
    return sunTransmittance * (c.rayleighScattering * phaseRayleigh + glm::dvec3(c.mieScattering * phaseMie))
        + c.rayleighScattering * (multiple + rayleighOrder2) + glm::dvec3(c.mieScattering) * multiple;
}

} // namespace

AtmosphereCoefficients atmosphereAt(double altitude_m, const AtmosphereSettings& settings)
{
    const double h = std::max(altitude_m, 0.0);
    // Exponential profiles of air and aerosols (Bruneton & Neyret 2008,
    // sec. 2.1); ozone's tent (Bruneton 2017's two linear layers).
    const double rayleigh = settings.rayleighScale * std::exp(-h / kRayleighScaleHeight_m);
    const double mie = settings.mieScale * std::exp(-h / kMieScaleHeight_m);
    const double ozone =
        std::max(0.0, 1.0 - std::abs(h - kOzonePeakAltitude_m) / kOzoneHalfWidth_m);
    AtmosphereCoefficients c;
    c.rayleighScattering =
        rayleigh * glm::dvec3(kRayleighScatteringRed_per_m, kRayleighScatteringGreen_per_m, kRayleighScatteringBlue_per_m);
    c.mieScattering = mie * kMieScattering_per_m;
    c.extinction = c.rayleighScattering + glm::dvec3(mie * kMieExtinction_per_m)
        + ozone * glm::dvec3(kOzoneAbsorptionRed_per_m, kOzoneAbsorptionGreen_per_m, kOzoneAbsorptionBlue_per_m);
    return c;
}

glm::dvec3 transmittanceToTop(double r_m, double mu, const AtmosphereSettings& settings, int steps)
{
    if (meetsGround(r_m, mu))
        return glm::dvec3(0.0);
    const double length = distanceToTop(r_m, mu);
    const double dt = length / steps;
    glm::dvec3 depth(0.0);
    for (int i = 0; i <= steps; ++i) {
        const double t = i * dt;
        const double r = std::sqrt(r_m * r_m + 2.0 * r_m * mu * t + t * t);
        const double weight = (i == 0 || i == steps) ? 0.5 : 1.0;
        depth += weight * dt * atmosphereAt(r - kBottom_m, settings).extinction;
    }
    return glm::exp(-depth);
}

double rayleighPhase(double cosAngle) { return 3.0 / (16.0 * kPi) * (1.0 + cosAngle * cosAngle); }

double miePhase(double cosAngle, double g)
{
    const double k = 3.0 / (8.0 * kPi) * (1.0 - g * g) / (2.0 + g * g);
    return k * (1.0 + cosAngle * cosAngle) / std::pow(1.0 + g * g - 2.0 * g * cosAngle, 1.5);
}

Atmosphere::Atmosphere(const AtmosphereSettings& settings)
    : settings_(settings), transmittanceTable_(size_t(3 * kMuSize * kRSize)),
      multiScatteringTable_(kMsLayers * kMsLayerFloats)
{
    for (int j = 0; j < kRSize; ++j)
        for (int i = 0; i < kMuSize; ++i) {
            double r = 0.0, mu = 0.0;
            radiusAndMuOf({double(i) / (kMuSize - 1), double(j) / (kRSize - 1)}, r, mu);
            put(transmittanceTable_, size_t(j) * kMuSize + size_t(i), transmittanceToTop(r, mu, settings_, kTableSteps));
        }
    buildMultipleScattering();
}

glm::dvec3 Atmosphere::transmittance(double r_m, double mu) const
{
    if (meetsGround(r_m, mu))
        return glm::dvec3(0.0);
    return lookup(transmittanceTable_.data(), kMuSize, kRSize, transmittanceCoordinates(r_m, mu));
}

glm::dvec3 Atmosphere::multipleScattering(double r_m, double muSun) const
{
    return lookup(multiScatteringTable_.data(), kMsSize, kMsSize, multiScatteringCoordinates(r_m, muSun));
}

glm::dvec3 Atmosphere::rayleighMultipleScatteringOrder2(double r_m, double muSun, double muView, double cosAngle) const
{
    // The view's cosine to the sun's azimuth: its projection on the
    // horizontal towards the sun. With the sun at the zenith (no azimuth)
    // the harmonics that need one are 0 in the table.
    const double horizontal = std::sqrt(std::max(1.0 - muSun * muSun, 0.0));
    const double x = horizontal > 1.0e-6 ? std::clamp((cosAngle - muSun * muView) / horizontal, -1.0, 1.0) : 0.0;
    const std::array<double, 3> harmonics = sunFrameHarmonics(x, muView);
    const glm::dvec2 at = multiScatteringCoordinates(r_m, muSun);
    glm::dvec3 sum(0.0);
    for (size_t m = 0; m < 3; ++m)
        sum += harmonics[m] * lookup(multiScatteringTable_.data() + (m + 1) * kMsLayerFloats, kMsSize, kMsSize, at);
    return sum;
}

// Hillaire 2020, sec. 5.5: around a point, the light scattered towards it
// once from every direction (L_2ndorder's integrand: the sun's light
// scattered along each ray, plus the ground's reflection where the ray
// meets it), and the fraction f_ms of isotropic light scattered back to it;
// light scattered any number of times more is the geometric series
// L_2ndorder (1 + f_ms + f_ms^2 ...) = L_2ndorder / (1 - f_ms), Psi_ms.
//
// Two departures from the paper, both for a low sun, where most of the
// sky's light has been scattered more than once and arrives near the
// horizon:
// - The sunlight scattered along each ray takes the air's and the aerosols'
//   phase functions, not an isotropic one.
// - The air scatters that light on with Rayleigh's phase function, not an
//   isotropic one. Rayleigh's is (1 + P_2(cos) / 2) / (4 pi), so the light
//   it scatters into a direction w from a field L is the mean of L plus
//   (1/10) sum_m c_2m Y_2m(w), where c_2m are L's order-2 harmonics (by the
//   addition theorem, P_2(w.w') = 4 pi / 5 sum_m Y_2m(w) Y_2m(w')): orders
//   0 and 2 carry all of it. Layers 1 to 3 of the table keep those
//   harmonics (sunFrameHarmonics) over 1 - f_ms, as if every further order
//   had the second's shape. The aerosols keep the isotropic estimate: their
//   forward peak needs far more than order 2.
void Atmosphere::buildMultipleScattering()
{
    const double isotropic = 1.0 / (4.0 * kPi);
    const int directions = kMsDirectionsPerAxis * kMsDirectionsPerAxis;
    const double solidAngle = 4.0 * kPi / directions;
    for (int j = 0; j < kMsSize; ++j)
        for (int i = 0; i < kMsSize; ++i) {
            const double muSun = 2.0 * i / (kMsSize - 1) - 1.0;
            const double r0 = kBottom_m + std::max(double(j) / (kMsSize - 1) * (kTop_m - kBottom_m), 1.0);
            const glm::dvec3 origin(0.0, r0, 0.0);
            const glm::dvec3 sun(std::sqrt(std::max(1.0 - muSun * muSun, 0.0)), muSun, 0.0);
            glm::dvec3 secondOrder(0.0), transfer(0.0);
            std::array<glm::dvec3, 3> order2{};
            // Equal-area strata of the sphere: cos(theta) and phi uniform.
            for (int a = 0; a < kMsDirectionsPerAxis; ++a)
                for (int b = 0; b < kMsDirectionsPerAxis; ++b) {
                    const double cosTheta = 1.0 - 2.0 * (a + 0.5) / kMsDirectionsPerAxis;
                    const double sinTheta = std::sqrt(std::max(1.0 - cosTheta * cosTheta, 0.0));
                    const double phi = 2.0 * kPi * (b + 0.5) / kMsDirectionsPerAxis;
                    const glm::dvec3 d(sinTheta * std::cos(phi), cosTheta, sinTheta * std::sin(phi));
                    const double cosAngle = glm::dot(d, sun);
                    const double phaseRayleigh = rayleighPhase(cosAngle);
                    const double phaseMie = miePhase(cosAngle, kMieAsymmetry);
                    const bool ground = meetsGround(r0, cosTheta);
                    const double length = ground ? distanceToGround(r0, cosTheta) : distanceToTop(r0, cosTheta);
                    const double dt = length / kMsSteps;
                    glm::dvec3 depth(0.0), light(0.0), fraction(0.0);
                    for (int s = 0; s < kMsSteps; ++s) {
                        const glm::dvec3 p = origin + (s + 0.5) * dt * d;
                        const double r = glm::length(p);
                        const AtmosphereCoefficients c = atmosphereAt(r - kBottom_m, settings_);
                        const glm::dvec3 toEye = glm::exp(-(depth + 0.5 * dt * c.extinction));
                        const glm::dvec3 scattering = c.rayleighScattering + glm::dvec3(c.mieScattering);
                        light += toEye * (c.rayleighScattering * phaseRayleigh + glm::dvec3(c.mieScattering * phaseMie))
                            * transmittance(r, glm::dot(p, sun) / r) * dt;
                        fraction += toEye * scattering * isotropic * dt;
                        depth += dt * c.extinction;
                    }
                    if (ground) {
                        // The ground's Lambertian reflection of the sun (Hillaire 2020, sec. 5.5).
                        const glm::dvec3 p = origin + length * d;
                        const double muGround = glm::dot(glm::normalize(p), sun);
                        light += glm::exp(-depth) * transmittance(kBottom_m, muGround) * std::max(muGround, 0.0)
                            * settings_.groundAlbedo / kPi;
                    }
                    // Integrals over the sphere: sums over equal-area cells.
                    secondOrder += light * isotropic * solidAngle;
                    transfer += fraction * solidAngle;
                    const std::array<double, 3> y = sunFrameHarmonics(d.x, d.y);
                    for (size_t m = 0; m < 3; ++m)
                        order2[m] += light * y[m] * solidAngle;
                }
            const glm::dvec3 series = glm::dvec3(1.0) / (glm::dvec3(1.0) - transfer);
            const size_t texel = size_t(j) * kMsSize + size_t(i);
            put(multiScatteringTable_, texel, secondOrder * series);
            for (size_t m = 0; m < 3; ++m)
                put(multiScatteringTable_, (m + 1) * size_t(kMsSize * kMsSize) + texel, 0.1 * order2[m] * series);
        }
}

glm::dvec3 Atmosphere::skyRadiance(glm::dvec3 direction, glm::dvec3 sunDirection, int steps) const
{
    glm::dvec3 d = glm::normalize(direction);
    if (d.y < 0.0) {
        const double horizontal = std::sqrt(d.x * d.x + d.z * d.z);
        d = horizontal > 1.0e-6 ? glm::dvec3(d.x / horizontal, 0.0, d.z / horizontal) : glm::dvec3(1.0, 0.0, 0.0);
    }
    const glm::dvec3 sun = glm::normalize(sunDirection);
    const double r0 = kBottom_m + SWELL_ATMOSPHERE_OBSERVER_ALTITUDE_M;
    const glm::dvec3 origin(0.0, r0, 0.0);
    const double length = distanceToTop(r0, d.y);
    const double cosAngle = glm::dot(d, sun);
    const double phaseRayleigh = rayleighPhase(cosAngle), phaseMie = miePhase(cosAngle, kMieAsymmetry);
    // Single scattering along the ray (Hillaire 2020, sec. 4; Bruneton &
    // Neyret 2008, sec. 2), by the midpoint rule on segments whose ends
    // grow as the square of their index.
    glm::dvec3 depth(0.0), radiance(0.0);
    const int n = steps;
    for (int k = 0; k < n; ++k) {
        const double t0 = length * (double(k) / n) * (double(k) / n);
        const double t1 = length * (double(k + 1) / n) * (double(k + 1) / n);
        const double dt = t1 - t0;
        const glm::dvec3 p = origin + 0.5 * (t0 + t1) * d;
        const double r = glm::length(p);
        const AtmosphereCoefficients c = atmosphereAt(r - kBottom_m, settings_);
        const double muSun = glm::dot(p, sun) / r;
        const glm::dvec3 toEye = glm::exp(-(depth + 0.5 * dt * c.extinction));
        radiance += toEye
            * inScattering(c, transmittance(r, muSun), multipleScattering(r, muSun),
                           rayleighMultipleScatteringOrder2(r, muSun, glm::dot(p, d) / r, cosAngle), phaseRayleigh,
                           phaseMie)
            * dt;
        depth += dt * c.extinction;
    }
    return radiance;
}

glm::dvec3 Atmosphere::sunTransmittance(glm::dvec3 sunDirection) const
{
    const glm::dvec3 sun = glm::normalize(sunDirection);
    return transmittanceToTop(kBottom_m + SWELL_ATMOSPHERE_OBSERVER_ALTITUDE_M, sun.y, settings_, 4096);
}

std::array<double, 9> shHarmonics(glm::dvec3 n)
{
    // Real spherical harmonics, orthonormal over the sphere (Ramamoorthi &
    // Hanrahan 2001, sec. 2), y up.
    return {0.282095,
            0.488603 * n.z,
            0.488603 * n.y,
            0.488603 * n.x,
            1.092548 * n.x * n.z,
            1.092548 * n.z * n.y,
            0.315392 * (3.0 * n.y * n.y - 1.0),
            1.092548 * n.x * n.y,
            0.546274 * (n.x * n.x - n.z * n.z)};
}

glm::dvec3 evaluateSh(const std::array<glm::dvec3, 9>& coefficients, glm::dvec3 n)
{
    const std::array<double, 9> y = shHarmonics(n);
    glm::dvec3 e(0.0);
    for (size_t i = 0; i < 9; ++i)
        e += coefficients[i] * y[i];
    return e;
}

std::array<glm::dvec3, 9> Atmosphere::irradianceSh(glm::dvec3 sunDirection) const
{
    return irradianceSh(sunDirection, [](glm::dvec3, glm::dvec3 clear) { return clear; }, 1.0);
}

std::array<glm::dvec3, 9> Atmosphere::irradianceSh(glm::dvec3 sunDirection,
                                                   const std::function<glm::dvec3(glm::dvec3, glm::dvec3)>& radianceOf,
                                                   double sunScale) const
{
    const glm::dvec3 sun = glm::normalize(sunDirection);
    // Radiance projected on the harmonics (Ramamoorthi & Hanrahan 2001,
    // sec. 3) over equal-area cells of each hemisphere: the sky above, and
    // below the ground's Lambertian radiance, albedo / pi times the sun's
    // and the sky's irradiance on it.
    constexpr int kRings = 24, kSectors = 48;
    const double cell = 2.0 * kPi / (kRings * kSectors);
    std::array<glm::dvec3, 9> radiance{};
    glm::dvec3 skyOnGround(0.0);
    auto direction = [](int ring, int sector, double sign) {
        const double cosTheta = (ring + 0.5) / kRings;
        const double sinTheta = std::sqrt(1.0 - cosTheta * cosTheta);
        const double phi = 2.0 * kPi * (sector + 0.5) / kSectors;
        return glm::dvec3(sinTheta * std::cos(phi), sign * cosTheta, sinTheta * std::sin(phi));
    };
    for (int ring = 0; ring < kRings; ++ring)
        for (int sector = 0; sector < kSectors; ++sector) {
            const glm::dvec3 d = direction(ring, sector, 1.0);
            const glm::dvec3 l = radianceOf(d, skyRadiance(d, sun));
            skyOnGround += l * d.y * cell;
            const std::array<double, 9> y = shHarmonics(d);
            for (size_t i = 0; i < 9; ++i)
                radiance[i] += l * y[i] * cell;
        }
    const glm::dvec3 ground =
        settings_.groundAlbedo / kPi * (sunScale * sunTransmittance(sun) * std::max(sun.y, 0.0) + skyOnGround);
    for (int ring = 0; ring < kRings; ++ring)
        for (int sector = 0; sector < kSectors; ++sector) {
            const std::array<double, 9> y = shHarmonics(direction(ring, sector, -1.0));
            for (size_t i = 0; i < 9; ++i)
                radiance[i] += ground * y[i] * cell;
        }
    // Irradiance is radiance convolved with the clamped cosine: band l
    // scaled by A_0 = pi, A_1 = 2 pi / 3, A_2 = pi / 4 (Ramamoorthi &
    // Hanrahan 2001, sec. 3).
    const double a[9] = {kPi, 2.0 * kPi / 3.0, 2.0 * kPi / 3.0, 2.0 * kPi / 3.0, kPi / 4.0, kPi / 4.0, kPi / 4.0, kPi / 4.0, kPi / 4.0};
    for (size_t i = 0; i < 9; ++i)
        radiance[i] *= a[i];
    return radiance;
}

} // namespace swell
