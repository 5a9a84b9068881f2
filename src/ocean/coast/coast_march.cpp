// One wave's phase and energy over a depth grid (coast_march.h): the
// eikonal by fast marching (Sethian 1996, PNAS 93(4), "A fast marching level
// set method for monotonically advancing fronts", the first-order upwind
// update of his eq. 4), then the energy flux's conservation by upwind finite
// volumes in the order the march accepted the cells.
#include "ocean/coast/coast_march.h"

#include "swell/constants.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <utility>

namespace swell::coast {

namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();
// Shallower than this the depth is taken as this in the dispersion relation:
// the local wavenumber would grow without bound at the waterline, where the
// breaking cut has taken the wave to nothing anyway.
constexpr double kShallowest_m = 0.05;

} // namespace

double localWavenumber(double omega_radps, double depth_m)
{
    const double deep = omega_radps * omega_radps / kGravity;
    if (std::isinf(depth_m) || !(omega_radps > 0.0) || deep * depth_m > 20.0)
        return deep;
    // Fenton & McKee (1990): kh ~ k0h / tanh((k0h)^(3/4))^(2/3), within 1.5%.
    const double k0h = deep * depth_m;
    double k = k0h / std::pow(std::tanh(std::pow(k0h, 0.75)), 2.0 / 3.0) / depth_m;
    // Newton on f(k) = k tanh(kh) - k0, f' = tanh(kh) + kh sech^2(kh).
    for (int i = 0; i < 3; ++i) {
        const double t = std::tanh(k * depth_m);
        const double f = k * t - deep;
        const double df = t + k * depth_m * (1.0 - t * t);
        k -= f / df;
    }
    return k;
}

double localGroupVelocity(double omega_radps, double wavenumber_radpm, double depth_m)
{
    const double c = omega_radps / wavenumber_radpm;
    if (std::isinf(depth_m))
        return 0.5 * c;
    const double kh2 = 2.0 * wavenumber_radpm * depth_m;
    // 2kh / sinh(2kh) underflows to 0 in deep water, as it should.
    const double ratio = kh2 > 700.0 ? 0.0 : kh2 / std::sinh(kh2);
    return 0.5 * c * (1.0 + (kh2 > 0.0 ? ratio : 1.0));
}

double breakingEnergyLimit(double depth_m, double amplitude_m, double breakerIndex)
{
    if (!(amplitude_m > 0.0))
        return kInf;
    const double height = 0.5 * breakerIndex / amplitude_m * std::max(depth_m, 0.0);
    return height * height;
}

namespace {

struct Grid {
    int nx, nz;
    double cell;
    std::size_t index(int i, int j) const { return std::size_t(j) * std::size_t(nx) + std::size_t(i); }
    bool inside(int i, int j) const { return i >= 0 && j >= 0 && i < nx && j < nz; }
};

constexpr int kNeighbours[4][2] = {{-1, 0}, {1, 0}, {0, -1}, {0, 1}};

// A march's fields before any cell is reached: no phase, no energy, the
// open sea's wavenumber everywhere.
void startMarch(WaveMarch& m, std::size_t n, const MarchedWave& wave)
{
    m.phase_rad.assign(n, kInf);
    m.energy.assign(n, 0.0);
    m.wavenumber_radpm.assign(n, wave.wavenumber_radpm * wave.direction);
    m.reached.assign(n, 0);
}

// The trial cells: a heap of (phase, cell), the least on top, as
// std::priority_queue keeps one (the same push_heap and pop_heap), in the
// scratch's storage.
class TrialCells {
public:
    using Entry = std::pair<double, std::size_t>;
    explicit TrialCells(std::vector<Entry>& storage) : cells_(storage) { cells_.clear(); }
    void push(Entry e)
    {
        cells_.push_back(e);
        std::push_heap(cells_.begin(), cells_.end(), std::greater<>{});
    }
    static constexpr std::size_t kNone = std::size_t(-1);
    // The next cell the march accepts, marked reached and added to `order`:
    // the least phase on the heap that is current (not reached already, nor
    // pushed before a lower phase was found for it); kNone when none is left.
    std::size_t acceptNext(WaveMarch& m, std::vector<std::size_t>& order)
    {
        while (!cells_.empty()) {
            std::pop_heap(cells_.begin(), cells_.end(), std::greater<>{});
            const auto [phase, c] = cells_.back();
            cells_.pop_back();
            if (m.reached[c] || phase > m.phase_rad[c])
                continue;
            m.reached[c] = 1;
            order.push_back(c);
            return c;
        }
        return kNone;
    }

private:
    std::vector<Entry>& cells_;
};

// Sethian's update: the S that makes the upwind differences' gradient k
// long, from the accepted neighbours along x and along z.
double upwindPhase(double alongX, double alongZ, double step)
{
    const double a = std::min(alongX, alongZ), b = std::max(alongX, alongZ);
    if (std::isinf(b) || b - a >= step)
        return a + step;
    const double disc = 2.0 * step * step - (b - a) * (b - a);
    return 0.5 * (a + b + std::sqrt(disc));
}

// The gradient of S at a reached cell, from central differences where both
// neighbours are reached, else the one-sided difference that is.
glm::dvec2 phaseGradient(const Grid& g, const WaveMarch& m, int i, int j, glm::dvec2 fallback)
{
    glm::dvec2 grad;
    for (int axis = 0; axis < 2; ++axis) {
        const int di = axis == 0 ? 1 : 0, dj = axis == 0 ? 0 : 1;
        const bool lo = g.inside(i - di, j - dj) && m.reached[g.index(i - di, j - dj)];
        const bool hi = g.inside(i + di, j + dj) && m.reached[g.index(i + di, j + dj)];
        const double s = m.phase_rad[g.index(i, j)];
        if (lo && hi)
            grad[axis] = (m.phase_rad[g.index(i + di, j + dj)] - m.phase_rad[g.index(i - di, j - dj)]) / (2.0 * g.cell);
        else if (hi)
            grad[axis] = (m.phase_rad[g.index(i + di, j + dj)] - s) / g.cell;
        else if (lo)
            grad[axis] = (s - m.phase_rad[g.index(i - di, j - dj)]) / g.cell;
        else
            grad[axis] = fallback[axis];
    }
    return grad;
}

} // namespace

std::vector<double> localWavenumbers(const DepthGrid& depth, double omega_radps)
{
    std::vector<double> k(depth.depth_m.size(), 0.0);
    for (std::size_t c = 0; c < k.size(); ++c)
        k[c] = depth.depth_m[c] > 0.0f ? localWavenumber(omega_radps, std::max(double(depth.depth_m[c]), kShallowest_m))
                                       : 0.0;
    return k;
}

WaveMarch marchWave(const DepthGrid& depth, const MarchedWave& wave, double breakerIndex, MarchScratch& scratch)
{
    const Grid g{depth.size.x, depth.size.y, depth.cell_m};
    std::vector<double> k = localWavenumbers(depth, wave.omega_radps);

    // The wave enters by the edges it runs into the grid across, as the open
    // sea's plane wave: where the edge lies in the open sea (as deep as the
    // sea beyond the grid, or deep enough for this wave not to feel the
    // bottom, kh >= pi), or, when no cell of those edges does, all along
    // them. Cells of an entry edge in shallower water are reached from
    // inside, as rays from the open sea reach them. An entry cell shallower
    // than the open sea has shoaled on the way (the normal-incidence
    // shoaling of eq. 4.104, C_g0 / C_g).
    const double openGroupVelocity = localGroupVelocity(wave.omega_radps, wave.wavenumber_radpm, depth.outsideDepth_m);
    std::vector<MarchSeed> seeds;
    const double deepEnough_m = std::min(depth.outsideDepth_m, kPi / wave.wavenumber_radpm);
    for (int pass = 0; pass < 2 && seeds.empty(); ++pass)
        for (int j = 0; j < g.nz; ++j)
            for (int i = 0; i < g.nx; ++i) {
                const bool edge = (i == 0 && wave.direction.x > 0.0) || (i == g.nx - 1 && wave.direction.x < 0.0)
                                  || (j == 0 && wave.direction.y > 0.0) || (j == g.nz - 1 && wave.direction.y < 0.0);
                const std::size_t c = g.index(i, j);
                if (!edge || !(k[c] > 0.0) || (pass == 0 && double(depth.depth_m[c]) < deepEnough_m))
                    continue;
                const glm::dvec2 p = depth.origin_m + depth.cell_m * glm::dvec2(i, j);
                const double h = std::max(double(depth.depth_m[c]), kShallowest_m);
                seeds.push_back({c, wave.wavenumber_radpm * glm::dot(wave.direction, p),
                                 openGroupVelocity / localGroupVelocity(wave.omega_radps, k[c], h)});
            }
    return marchFromSeeds(depth, wave, std::move(k), seeds, breakerIndex, scratch);
}

WaveMarch marchFromSeeds(const DepthGrid& depth, const MarchedWave& wave, std::vector<double> k,
                         const std::vector<MarchSeed>& seeds, double breakerIndex, MarchScratch& scratch)
{
    const Grid g{depth.size.x, depth.size.y, depth.cell_m};
    const std::size_t n = std::size_t(g.nx) * std::size_t(g.nz);
    WaveMarch m;
    startMarch(m, n, wave);
    std::vector<std::size_t>& parent = scratch.parent;
    parent.assign(n, std::size_t(-1));
    TrialCells trial(scratch.trial);
    std::vector<std::uint8_t>& entry = scratch.entry;
    entry.assign(n, 0);
    std::vector<double>& seedEnergy = scratch.seedEnergy;
    seedEnergy.assign(n, 0.0);
    for (const MarchSeed& seed : seeds) {
        m.phase_rad[seed.cell] = seed.phase_rad;
        entry[seed.cell] = 1;
        seedEnergy[seed.cell] = seed.energy;
        trial.push({seed.phase_rad, seed.cell});
    }

    std::vector<std::size_t>& order = scratch.order;
    order.clear();
    order.reserve(n);
    for (std::size_t c; (c = trial.acceptNext(m, order)) != TrialCells::kNone;) {
        const int ci = int(c % std::size_t(g.nx)), cj = int(c / std::size_t(g.nx));
        for (const auto& nb : kNeighbours) {
            const int i = ci + nb[0], j = cj + nb[1];
            if (!g.inside(i, j))
                continue;
            const std::size_t d = g.index(i, j);
            if (m.reached[d] || k[d] <= 0.0)
                continue;
            auto accepted = [&](int ai, int aj) {
                return g.inside(ai, aj) && m.reached[g.index(ai, aj)] ? m.phase_rad[g.index(ai, aj)] : kInf;
            };
            const double alongX = std::min(accepted(i - 1, j), accepted(i + 1, j));
            const double alongZ = std::min(accepted(i, j - 1), accepted(i, j + 1));
            const double candidate = upwindPhase(alongX, alongZ, k[d] * g.cell);
            if (candidate < m.phase_rad[d]) {
                m.phase_rad[d] = candidate;
                trial.push({candidate, d});
                // The accepted neighbour of least phase: where the ray
                // through d comes from.
                double least = kInf;
                for (const auto& back : kNeighbours) {
                    const int a = i + back[0], b = j + back[1];
                    if (accepted(a, b) < least) {
                        least = accepted(a, b);
                        parent[d] = g.index(a, b);
                    }
                }
            }
        }
    }

    for (std::size_t c : order) {
        const int i = int(c % std::size_t(g.nx)), j = int(c / std::size_t(g.nx));
        m.wavenumber_radpm[c] = phaseGradient(g, m, i, j, wave.wavenumber_radpm * wave.direction);
    }

    // The energy, cell by cell in the order of arrival: what flows in across
    // the faces the group velocity crosses inwards leaves across the others
    // (upwind finite volumes of div(E C_g d) = 0). A seed takes its own.
    std::vector<glm::dvec2>& velocity = scratch.velocity;
    velocity.assign(n, glm::dvec2(0.0));
    for (std::size_t c : order) {
        const double h = std::max(double(depth.depth_m[c]), kShallowest_m);
        const glm::dvec2 kv = m.wavenumber_radpm[c];
        const double length = std::sqrt(glm::dot(kv, kv));
        velocity[c] = length > 0.0 ? localGroupVelocity(wave.omega_radps, k[c], h) * kv / length : glm::dvec2(0.0);
    }
    // The energy arriving at cell c of a field marched in the order of
    // arrival.
    auto arriving = [&](const std::vector<double>& field, std::size_t c) {
        const int ci = int(c % std::size_t(g.nx)), cj = int(c / std::size_t(g.nx));
        if (entry[c])
            return seedEnergy[c];
        double in = 0.0, out = 0.0, inflowing = 0.0;
        for (const auto& nb : kNeighbours) {
            const int i = ci + nb[0], j = cj + nb[1];
            const glm::dvec2 normal(nb[0], nb[1]);
            const bool wet = g.inside(i, j) && m.reached[g.index(i, j)];
            const glm::dvec2 v = wet ? 0.5 * (velocity[c] + velocity[g.index(i, j)]) : velocity[c];
            const double across = glm::dot(v, normal);
            if (across > 0.0)
                out += across; // into a neighbour, or onto the shore, where it is spent
            else if (wet) {
                in += -across * field[g.index(i, j)];
                inflowing += -across;
            }
        }
        // Nothing leaves (the rays stand still): the inflow's mean.
        return out > 1e-12 ? in / out : (inflowing > 0.0 ? in / inflowing : 0.0);
    };
    m.unbroken.assign(n, 0.0);
    for (std::size_t c : order) {
        // Depth-limited breaking: the wave's height 2 A0 sqrt(E) at most gamma h.
        m.energy[c] = std::min(arriving(m.energy, c),
                               breakingEnergyLimit(double(depth.depth_m[c]), wave.amplitude_m, breakerIndex));
        m.unbroken[c] = arriving(m.unbroken, c);
    }
    m.localWavenumber_radpm = std::move(k);
    return m;
}

} // namespace swell::coast

namespace swell::coast {

void marchWhileAbove(const DepthGrid& depth, const MarchedWave& wave, const std::vector<double>& k,
                     const std::vector<MarchSeed>& seeds, double leastEnergy, MarchScratch& scratch, WaveMarch& m)
{
    const Grid g{depth.size.x, depth.size.y, depth.cell_m};
    const std::size_t n = std::size_t(g.nx) * std::size_t(g.nz);
    startMarch(m, n, wave);
    TrialCells trial(scratch.trial);
    std::vector<std::uint8_t>& entry = scratch.entry;
    entry.assign(n, 0);
    // A seed's velocity is the way it leaves, set before the march.
    std::vector<glm::dvec2>& velocity = scratch.velocity;
    velocity.assign(n, glm::dvec2(0.0));
    for (const MarchSeed& seed : seeds) {
        const double h = std::max(double(depth.depth_m[seed.cell]), kShallowest_m);
        velocity[seed.cell] = localGroupVelocity(wave.omega_radps, k[seed.cell], h) * seed.direction;
        m.phase_rad[seed.cell] = seed.phase_rad;
        m.energy[seed.cell] = seed.energy;
        entry[seed.cell] = 1;
        trial.push({seed.phase_rad, seed.cell});
    }
    std::vector<std::size_t>& order = scratch.order;
    order.clear();
    auto accepted = [&](int ai, int aj) {
        return g.inside(ai, aj) && m.reached[g.index(ai, aj)] ? m.phase_rad[g.index(ai, aj)] : kInf;
    };
    for (std::size_t c; (c = trial.acceptNext(m, order)) != TrialCells::kNone;) {
        const double s = m.phase_rad[c]; // the phase it was accepted at
        const int ci = int(c % std::size_t(g.nx)), cj = int(c / std::size_t(g.nx));
        // The gradient from the upwind neighbours, the only ones final now.
        glm::dvec2 grad(0.0);
        for (int axis = 0; axis < 2; ++axis) {
            const int di = axis == 0 ? 1 : 0, dj = axis == 0 ? 0 : 1;
            const double lo = accepted(ci - di, cj - dj), hi = accepted(ci + di, cj + dj);
            if (lo <= hi && lo < kInf)
                grad[axis] = (s - lo) / g.cell;
            else if (hi < kInf)
                grad[axis] = (hi - s) / g.cell;
        }
        const double length = std::sqrt(glm::dot(grad, grad));
        const double h = std::max(double(depth.depth_m[c]), kShallowest_m);
        if (!entry[c] && length > 0.0)
            velocity[c] = localGroupVelocity(wave.omega_radps, k[c], h) * grad / length;
        // The phase each wet neighbour not yet accepted would take from
        // here, as the march's update gives it.
        double candidate[4];
        for (int b = 0; b < 4; ++b) {
            const int i = ci + kNeighbours[b][0], j = cj + kNeighbours[b][1];
            candidate[b] = kInf;
            if (!g.inside(i, j) || m.reached[g.index(i, j)] || k[g.index(i, j)] <= 0.0)
                continue;
            const double alongX = std::min(accepted(i - 1, j), accepted(i + 1, j));
            const double alongZ = std::min(accepted(i, j - 1), accepted(i, j + 1));
            candidate[b] = std::min(m.phase_rad[g.index(i, j)], upwindPhase(alongX, alongZ, k[g.index(i, j)] * g.cell));
        }
        // The energy flux's balance by donor cells, each face's share of
        // the flux the phase's rise across it over the rise a full step
        // along the rays makes there (the cosine of the rays' angle to the
        // face's normal): in, the accepted neighbours' energy at their own
        // group velocity; out, this sample's at its own, also sideways where
        // the rays spread (a corner's cylindrical wave thins as it goes),
        // and onto dry land along its upwind gradient, spent there. Over a
        // slope at normal incidence E C_g is held, as eq. 4.104 says.
        if (!entry[c]) {
            const double speed = std::sqrt(glm::dot(velocity[c], velocity[c]));
            double in = 0.0, out = 0.0, inflowing = 0.0;
            for (int b = 0; b < 4; ++b) {
                const int i = ci + kNeighbours[b][0], j = cj + kNeighbours[b][1];
                const glm::dvec2 normal(kNeighbours[b][0], kNeighbours[b][1]);
                if (!g.inside(i, j) || k[g.index(i, j)] <= 0.0) {
                    out += std::max(0.0, glm::dot(velocity[c], normal));
                    continue;
                }
                const std::size_t d = g.index(i, j);
                if (m.reached[d]) {
                    const double share = std::min(1.0, (s - m.phase_rad[d]) / (k[c] * g.cell));
                    if (share > 0.0) {
                        const double flux = share * std::sqrt(glm::dot(velocity[d], velocity[d]));
                        in += flux * m.energy[d];
                        inflowing += flux;
                    }
                } else if (candidate[b] < kInf) {
                    out += speed * std::clamp((candidate[b] - s) / (k[d] * g.cell), 0.0, 1.0);
                }
            }
            m.energy[c] = out > 1e-12 ? in / out : (inflowing > 0.0 ? in / inflowing : 0.0);
            if (m.energy[c] < leastEnergy)
                continue; // too low to march on from
        }
        for (int b = 0; b < 4; ++b) {
            const int i = ci + kNeighbours[b][0], j = cj + kNeighbours[b][1];
            if (candidate[b] < kInf && candidate[b] < m.phase_rad[g.index(i, j)]) {
                m.phase_rad[g.index(i, j)] = candidate[b];
                trial.push({candidate[b], g.index(i, j)});
            }
        }
    }
    for (std::size_t c : order) {
        const int i = int(c % std::size_t(g.nx)), j = int(c / std::size_t(g.nx));
        m.wavenumber_radpm[c] = phaseGradient(g, m, i, j, wave.wavenumber_radpm * wave.direction);
    }
}

} // namespace swell::coast
