// The waves steep faces send back (coast_reflection.h): seeds on the faces
// the incident wave runs into, a march out from them, and the sum of the
// two waves as complex amplitudes; in a shadow, the reflected wave's share
// of what diffracts round an edge. Penney & Price 1952, "The diffraction
// theory of sea waves and the shelter afforded by breakwaters", Phil.
// Trans. R. Soc. A 244, 236; Keller 1962, "Geometrical theory of
// diffraction", J. Opt. Soc. Am. 52(2), 116.
#include "ocean/coast/coast_reflection.h"

#include "swell/constants.h"

#include <glm/common.hpp>
#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <complex>
#include <limits>

namespace swell::coast {

double surfSimilarity(double slope, double waveHeight_m, double deepWavelength_m)
{
    if (!(waveHeight_m > 0.0))
        return std::numeric_limits<double>::infinity();
    return slope / std::sqrt(waveHeight_m / deepWavelength_m);
}

double reflectionCoefficient(double slope, double waveHeight_m, double deepWavelength_m)
{
    constexpr double a = 1.0, b = 5.5;
    const double xi = surfSimilarity(slope, waveHeight_m, deepWavelength_m);
    if (std::isinf(xi))
        return a;
    return a * xi * xi / (b + xi * xi);
}

namespace {

using Complex = std::complex<double>;

constexpr std::size_t kNone = std::size_t(-1);

// The grazing angles between which a face's reflection fades in (see the seeds).
const double kSinGrazingNone = std::sin(10.0 * kPi / 180.0), kSinGrazingAll = std::sin(30.0 * kPi / 180.0);

double smoothstep01(double t)
{
    t = std::clamp(t, 0.0, 1.0);
    return t * t * (3.0 - 2.0 * t);
}

// What a seed's face did to the wave: its R and the reflected wave's direction.
struct Face {
    double reflection = 0.0;
    glm::dvec2 reflected{0.0};
};

double depthAt(const DepthGrid& g, int i, int j)
{
    return double(g.at(std::clamp(i, 0, g.size.x - 1), std::clamp(j, 0, g.size.y - 1)));
}

// The bilinear depth at fractional sample (u, v), clamped to the grid.
double depthAt(const DepthGrid& g, glm::dvec2 u)
{
    u = glm::clamp(u, glm::dvec2(0.0), glm::dvec2(g.size - 1));
    const int i = std::min(int(u.x), g.size.x - 2), j = std::min(int(u.y), g.size.y - 2);
    const double fx = u.x - i, fz = u.y - j;
    const double lo = (1.0 - fx) * g.at(i, j) + fx * g.at(i + 1, j);
    const double hi = (1.0 - fx) * g.at(i, j + 1) + fx * g.at(i + 1, j + 1);
    return (1.0 - fz) * lo + fz * hi;
}

// The unsigned angle between two directions, rad.
double angleBetween(glm::dvec2 a, glm::dvec2 b)
{
    return std::abs(std::atan2(a.x * b.y - a.y * b.x, glm::dot(a, b)));
}

} // namespace

void reflectWave(const DepthGrid& depth, const MarchedWave& wave, double seaHeight_m, double breakerIndex,
                 WaveMarch& march, MarchScratch& scratch)
{
    if (scratch.shadowed.empty())
        return; // no dry land, no face
    const std::vector<std::uint8_t>& shadowed = scratch.shadowed;
    const DepthGrid& g = depth;
    const std::size_t n = g.depth_m.size();
    const double deepWavelength_m = kTwoPi * kGravity / (wave.omega_radps * wave.omega_radps);

    // The seeds: wet samples beside dry land, lit by the open sea, that the
    // wave runs into. The face's normal is the depth's gradient (central
    // differences, dry land's heights included, so a staircase of samples
    // along a wall at an angle gives the wall's normal); its slope the fall
    // from the sample to the depth one sample further along that normal, as
    // steep as the land is beyond a wall, a plane slope's own; the waterline
    // where that line crosses zero depth.
    std::vector<MarchSeed> seeds;
    std::vector<Face> faces;
    std::vector<int>& seedOf = scratch.seedOf;
    seedOf.assign(n, -1);
    for (int j = 0; j < g.size.y; ++j)
        for (int i = 0; i < g.size.x; ++i) {
            const std::size_t c = std::size_t(j) * std::size_t(g.size.x) + std::size_t(i);
            const double h = double(g.depth_m[c]);
            if (!(h > 0.0) || !march.reached[c] || shadowed[c] || !(march.energy[c] > 0.0))
                continue;
            if (depthAt(g, i - 1, j) > 0.0 && depthAt(g, i + 1, j) > 0.0 && depthAt(g, i, j - 1) > 0.0
                && depthAt(g, i, j + 1) > 0.0)
                continue;
            const glm::dvec2 fall(depthAt(g, i + 1, j) - depthAt(g, i - 1, j), depthAt(g, i, j + 1) - depthAt(g, i, j - 1));
            const double length = std::sqrt(glm::dot(fall, fall));
            if (!(length > 0.0))
                continue;
            const glm::dvec2 normal = -fall / length; // into the land
            const double slope = (h - depthAt(g, glm::dvec2(i, j) + normal)) / g.cell_m;
            if (!(slope > 0.0))
                continue;
            const glm::dvec2 k = march.wavenumber_radpm[c];
            const double towards = glm::dot(k, normal);
            if (!(towards > 0.0))
                continue;
            // Near grazing the reflected wave runs with the incident one and
            // is the same wave (at grazing their sum is the one wave running
            // along the face): a face sends back nothing within 10 degrees
            // of grazing, all of R from 30 degrees, smoothly between. A
            // round head or a cliff's flank seen from the side would
            // otherwise add a second wave along the shadow's edge, where
            // the diffraction march's rigid side walls already carry the
            // wave past the face.
            const double grazing = smoothstep01((towards / std::sqrt(glm::dot(k, k)) - kSinGrazingNone)
                                                / (kSinGrazingAll - kSinGrazingNone));
            const double reflection = grazing * reflectionCoefficient(slope, seaHeight_m, deepWavelength_m);
            if (reflection < kNegligibleReflection)
                continue;
            // The crest mirrored in the face at the waterline, toWaterline
            // away: the reflected wave's phase there the incident one's (an
            // antinode), here twice the normal's share of the way more.
            const double toWaterline_m = std::min(h / slope, g.cell_m);
            // R is the ratio of the heights at the face's toe (Seelig &
            // Ahrens's incident height is the one there): down the face
            // along the normal while it stays at least half as steep, a
            // wavelength at most. The toe's energy, shoaled up to the seed
            // as the unbroken wave shoals there, makes the reflected wave
            // (marched without a breaking cut, which the sum takes) leave
            // the toe R^2 times the incident one's energy: a wave that surges
            // up a steep face without breaking, as it does for a steep face
            // (Battjes 1974, xi > 3.3), and that the march's cut on the
            // face itself would otherwise have taken before it reflected.
            std::size_t toe = c;
            double toeDepth = h;
            const int steps = int(std::ceil(kTwoPi / march.localWavenumber_radpm[c] / g.cell_m));
            for (int step = 1; step <= steps; ++step) {
                const glm::ivec2 at(glm::round(glm::dvec2(i, j) - double(step) * normal));
                if (at.x < 0 || at.y < 0 || at.x >= g.size.x || at.y >= g.size.y)
                    break;
                const std::size_t d = std::size_t(at.y) * std::size_t(g.size.x) + std::size_t(at.x);
                if (!march.reached[d] || double(g.depth_m[d]) < toeDepth + 0.5 * slope * g.cell_m)
                    break;
                toe = d;
                toeDepth = double(g.depth_m[d]);
            }
            const double shoaled = march.unbroken[toe] > 0.0 ? march.unbroken[c] / march.unbroken[toe] : 1.0;
            const glm::dvec2 incident = k / std::sqrt(glm::dot(k, k));
            const glm::dvec2 mirrored = incident - 2.0 * glm::dot(incident, normal) * normal;
            seedOf[c] = int(seeds.size());
            seeds.push_back({c, march.phase_rad[c] + 2.0 * towards * toWaterline_m,
                             reflection * reflection * march.energy[toe] * shoaled, mirrored});
            faces.push_back({reflection, mirrored});
        }
    if (seeds.empty())
        return;

    WaveMarch& reflected = scratch.reflected;
    marchWhileAbove(depth, wave, march.localWavenumber_radpm, seeds, kLeastReflectedEnergy, scratch, reflected);

    // Where a sample in the shadow comes round into it: the first lit
    // sample back along its incident ray (the incident march's parents).
    std::vector<std::size_t>& edgeOf = scratch.edgeOf;
    edgeOf.assign(n, kNone);
    std::vector<std::size_t> path;
    auto edgeOfSample = [&](std::size_t c) {
        path.clear();
        std::size_t at = c;
        while (at < n && shadowed[at] && edgeOf[at] == kNone) {
            path.push_back(at);
            at = scratch.parent[at];
        }
        const std::size_t edge = at >= n ? kNone : (shadowed[at] ? edgeOf[at] : at);
        for (std::size_t p : path)
            edgeOf[p] = edge;
        return edge;
    };
    // A face as an edge sees it: R and the reflected direction averaged over
    // the seeds within half a wavelength of the edge, so that the sample at
    // a staircase's corner, whose normal is the grid's more than the face's,
    // does not stand for the face (R 0: no seed there). Made when a shadow
    // first asks.
    const int around = std::max(1, int(std::ceil(0.5 * kTwoPi / wave.wavenumber_radpm / g.cell_m)));
    std::vector<int>& faceAtEdge = scratch.faceAtEdge;
    faceAtEdge.assign(n, -1);
    std::vector<Face> edgeFaces;
    auto faceAround = [&](std::size_t e) {
        if (faceAtEdge[e] >= 0)
            return edgeFaces[std::size_t(faceAtEdge[e])];
        const int ci = int(e % std::size_t(g.size.x)), cj = int(e / std::size_t(g.size.x));
        Face sum;
        int count = 0;
        for (int j = std::max(0, cj - around); j <= std::min(g.size.y - 1, cj + around); ++j)
            for (int i = std::max(0, ci - around); i <= std::min(g.size.x - 1, ci + around); ++i) {
                const int other = seedOf[std::size_t(j) * std::size_t(g.size.x) + std::size_t(i)];
                if (other < 0 || (i - ci) * (i - ci) + (j - cj) * (j - cj) > around * around)
                    continue;
                sum.reflection += faces[std::size_t(other)].reflection;
                sum.reflected += faces[std::size_t(other)].reflected;
                ++count;
            }
        const double length = std::sqrt(glm::dot(sum.reflected, sum.reflected));
        faceAtEdge[e] = int(edgeFaces.size());
        edgeFaces.push_back(count > 0 && length > 0.0 ? Face{sum.reflection / count, sum.reflected / length} : Face{});
        return edgeFaces.back();
    };

    for (std::size_t c = 0; c < n; ++c) {
        const double incidentEnergy = march.energy[c];
        if (!march.reached[c] || !(g.depth_m[c] > 0.0f) || !(incidentEnergy > 0.0))
            continue;
        const glm::dvec2 ki = march.wavenumber_radpm[c];
        double energy = incidentEnergy;
        // In the shadow, round an edge: both waves cylindrical from it, in
        // phase, the reflected one's share Penney & Price's. The incident
        // wave's direction at the edge is the open sea's, whose straight
        // rays make the shadow; a point nearer the reflected wave's
        // direction than that (no half-plane's lee: a face that sends its
        // wave on into the shadow) takes the reflected wave as marched.
        double share = -1.0; // none: the reflected wave as marched
        if (const std::size_t edge = shadowed[c] ? edgeOfSample(c) : kNone; edge < n) {
            const Face face = faceAround(edge);
            const double kLength = std::sqrt(glm::dot(ki, ki));
            const glm::dvec2 u = kLength > 0.0 ? ki / kLength : wave.direction;
            const double fromIncident = std::sin(0.5 * angleBetween(u, wave.direction));
            const double fromReflected = std::sin(0.5 * angleBetween(u, face.reflected));
            if (face.reflection > 0.0 && fromReflected > fromIncident)
                share = face.reflection * fromIncident / fromReflected;
        }
        if (share >= 0.0) {
            energy = incidentEnergy * (1.0 + share) * (1.0 + share);
        } else {
            if (!reflected.reached[c] || !(reflected.energy[c] > 0.0))
                continue;
            // The two as complex amplitudes relative to the incident one's
            // phase; the reflected one held at most the incident one's
            // height, so that the sum's phase stays within a quarter turn of
            // the incident one's and its texels interpolate without a
            // wrap (where it would be higher, a lee the incident wave
            // hardly reaches, it is cut).
            // Where the march stops (kLeastReflectedEnergy) the reflected
            // wave fades in over twice the least height, not at once. In
            // the surf, where the incident wave breaks, it does not stand:
            // it is held to the share of its height the breaking left the
            // incident one (R, the heights' ratio seaward of the face, has
            // counted what the breaking takes).
            const double least = std::sqrt(kLeastReflectedEnergy), height = std::sqrt(reflected.energy[c]);
            const double ai = std::sqrt(incidentEnergy);
            const double unbroken = march.unbroken[c] > incidentEnergy ? std::sqrt(incidentEnergy / march.unbroken[c]) : 1.0;
            const double ar = std::min(height * smoothstep01((height - least) / least) * unbroken, ai);
            const Complex rotation = std::polar(1.0, reflected.phase_rad[c] - march.phase_rad[c]);
            const Complex sum = ai + ar * rotation;
            energy = std::norm(sum);
            march.phase_rad[c] += std::arg(sum);
            // The sum's local wavenumber, the gradient of its phase:
            // Im(grad Z / Z), grad Z = i (ai ki + ar kr e^(i delta)) e^(i Si)
            // (the heights' own gradients left out, as the ray solution
            // leaves them). At a node of a standing wave it grows without
            // bound where the height goes to nothing; twice the local
            // wavenumber (a clapotis's slope 2 k A at its node over a
            // texel) bounds it, so that the bilinear reading between a
            // node's texels does not multiply a large wavenumber by a large
            // height.
            if (energy > 1e-12) {
                const glm::dvec2 kr = reflected.wavenumber_radpm[c];
                const double weightI = (std::conj(sum) * ai).real();
                const double weightR = (std::conj(sum) * ar * rotation).real();
                glm::dvec2 k = (weightI * ki + weightR * kr) / energy;
                const double most = 2.0 * march.localWavenumber_radpm[c], length = std::sqrt(glm::dot(k, k));
                if (length > most)
                    k *= most / length;
                march.wavenumber_radpm[c] = k;
            }
        }
        march.unbroken[c] *= energy / incidentEnergy;
        march.energy[c] = std::min(energy, breakingEnergyLimit(double(g.depth_m[c]), wave.amplitude_m, breakerIndex));
    }
}

} // namespace swell::coast
