// The coast field (swell/coast_field.h): each coast wave marched over the
// depth grid (coast_march.cpp), the sea's breaking cut and fold limit per
// point, the field blended into the open sea at the grid's edges, and its
// bilinear reading, which shaders/coast_field.glsl repeats.
#include "swell/coast_field.h"

#include "core/worker.h"
#include "ocean/coast/coast_diffraction.h"
#include "ocean/coast/coast_march.h"
#include "ocean/coast/coast_reflection.h"

#include "swell/constants.h"
#include "swell/error.h"
#include "swell/scene/waves.h"

#include <fmt/format.h>
#include <glm/geometric.hpp>

#include <algorithm>
#include <atomic>
#include <cmath>

namespace swell {

namespace {

// The band along the grid's edges, in samples, over which the field is
// blended into the open sea's values, so that the surface is continuous
// where the grid ends: the waves in a lee that reaches the edge take the open
// sea's phase again there.
int blendBand(const DepthGrid& g) { return std::max(2, std::min(g.size.x, g.size.y) / 12); }

// A random sea's breaker index: its significant height 4 sqrt(variance) is
// at most this times the depth. Thornton & Guza (1983, "Transformation of
// wave height distribution", J. Geophys. Res. 88(C10), 5925) find the rms
// height of a saturated surf zone 0.42 h; with Rayleigh heights H_s =
// sqrt(2) H_rms, 0.59 h.
constexpr double kSeaBreakerIndex = 0.42 * 1.4142135623730951;

// The depth at which a sea whose waves' heights sum to `heights` and whose
// surface has variance `variance` breaks, m: the shallower of where its
// highest possible wave (all crests at once) reaches the breaker index
// times the depth and where its significant height reaches the random
// sea's index. A single wave's own height is the first (its significant
// height, 1.41 times it, would break it far too soon); a sea of many waves
// reaches the second first (cutting the sum alone would break it when its
// significant height is a third of the depth).
double breakingDepth(double heights, double variance, double breakerIndex)
{
    return std::min(heights / breakerIndex, 4.0 * std::sqrt(variance) / kSeaBreakerIndex);
}

double smoothstep01(double t)
{
    t = std::clamp(t, 0.0, 1.0);
    return t * t * (3.0 - 2.0 * t);
}

void check(const DepthGrid& g)
{
    if (g.size.x < 2 || g.size.y < 2 || g.size.x > kMaxCoastGridSide || g.size.y > kMaxCoastGridSide)
        throw Error(fmt::format("swell::CoastField: a depth grid of {} x {} samples; each side must be 2..{}",
                                g.size.x, g.size.y, kMaxCoastGridSide));
    if (g.depth_m.size() != std::size_t(g.size.x) * std::size_t(g.size.y))
        throw Error(fmt::format("swell::CoastField: {} depths for a grid of {} x {} samples", g.depth_m.size(),
                                g.size.x, g.size.y));
    if (!(g.cell_m > 0.0) || !std::isfinite(g.cell_m) || !std::isfinite(g.origin_m.x) || !std::isfinite(g.origin_m.y))
        throw Error(fmt::format("swell::CoastField: cell_m {} and origin ({}, {}) must be finite, cell_m > 0",
                                g.cell_m, g.origin_m.x, g.origin_m.y));
    for (std::size_t c = 0; c < g.depth_m.size(); ++c)
        if (!std::isfinite(g.depth_m[c]))
            throw Error(fmt::format("swell::CoastField: the depth at sample ({}, {}) is {}", c % std::size_t(g.size.x),
                                    c / std::size_t(g.size.x), g.depth_m[c]));
    if (!(g.outsideDepth_m > 0.0))
        throw Error(fmt::format("swell::CoastField: outsideDepth_m must be > 0 or infinity (got {})", g.outsideDepth_m));
}

// Cells no ray reached (land, a lagoon) take their reached neighbours' mean
// phase and wavenumber, a few cells deep, so that the bilinear reading at
// the shore mixes no foreign phase into the last wet cells.
// Cells left unknown after that (far inland) take the open sea's.
void extendPhase(const DepthGrid& g, coast::WaveMarch& m, glm::dvec2 openWavenumber_radpm)
{
    std::vector<std::uint8_t> known = m.reached;
    for (int pass = 0; pass < 4; ++pass) {
        std::vector<std::uint8_t> next = known;
        for (int j = 0; j < g.size.y; ++j)
            for (int i = 0; i < g.size.x; ++i) {
                const std::size_t c = std::size_t(j) * std::size_t(g.size.x) + std::size_t(i);
                if (known[c])
                    continue;
                double phase = 0.0;
                glm::dvec2 wavenumber(0.0);
                int count = 0;
                const int nbs[4][2] = {{-1, 0}, {1, 0}, {0, -1}, {0, 1}};
                for (const auto& nb : nbs) {
                    const int a = i + nb[0], b = j + nb[1];
                    if (a < 0 || b < 0 || a >= g.size.x || b >= g.size.y)
                        continue;
                    const std::size_t d = std::size_t(b) * std::size_t(g.size.x) + std::size_t(a);
                    if (!known[d])
                        continue;
                    phase += m.phase_rad[d];
                    wavenumber += m.wavenumber_radpm[d];
                    ++count;
                }
                if (count > 0) {
                    m.phase_rad[c] = phase / count;
                    m.wavenumber_radpm[c] = wavenumber / double(count);
                    next[c] = 1;
                }
            }
        known = std::move(next);
    }
    for (std::size_t c = 0; c < known.size(); ++c)
        if (!known[c]) {
            const glm::dvec2 p = g.origin_m + g.cell_m * glm::dvec2(double(c % std::size_t(g.size.x)),
                                                                   double(c / std::size_t(g.size.x)));
            m.phase_rad[c] = glm::dot(openWavenumber_radpm, p);
            m.wavenumber_radpm[c] = openWavenumber_radpm;
        }
}

} // namespace

CoastField::CoastField(const WaveSet& waves, DepthGrid depth, double breakerIndex) : depth_(std::move(depth))
{
    check(depth_);
    if (!(breakerIndex > 0.0) || !std::isfinite(breakerIndex))
        throw Error(fmt::format("swell::CoastField: the breaker index must be finite and > 0 (got {})", breakerIndex));
    const DepthGrid& g = depth_;
    const std::size_t n = g.depth_m.size();
    const std::size_t coastWaves = std::min(kMaxCoastWaves, waves.waves.size());
    const int band = blendBand(g);

    // The open sea's wavenumber vector of every wave.
    std::vector<glm::dvec2> openK(waves.waves.size());
    for (std::size_t w = 0; w < waves.waves.size(); ++w)
        openK[w] = wavenumberVector(waves.waves[w]);
    // The longest waves get the layers, longest first.
    std::vector<std::size_t> longest(waves.waves.size());
    for (std::size_t w = 0; w < longest.size(); ++w)
        longest[w] = w;
    std::stable_sort(longest.begin(), longest.end(), [&](std::size_t a, std::size_t b) {
        return waves.waves[a].wavelength_m > waves.waves[b].wavelength_m;
    });
    longest.resize(coastWaves);
    layerOfWave_.assign(waves.waves.size(), -1);
    for (std::size_t l = 0; l < coastWaves; ++l)
        layerOfWave_[longest[l]] = int(l);

    // Each wave's marches depend on that wave and the grid alone, so two
    // threads share them, each taking the next wave not taken, into a
    // march of its own: the same bits in whichever order they run (the
    // built-in island's 16 waves were about 0.6 s on one thread).
    // The open sea's significant height 4 sqrt(variance): the height a
    // face's reflection is reckoned with (coast_reflection.h).
    double openVariance = 0.0;
    for (const Wave& wave : waves.waves)
        openVariance += 0.5 * wave.amplitude_m * wave.amplitude_m;
    const double seaHeight_m = 4.0 * std::sqrt(openVariance);
    std::vector<coast::WaveMarch> marches(coastWaves);
    std::atomic<std::size_t> next{0};
    auto march = [&] {
        coast::MarchScratch scratch;
        for (std::size_t l; (l = next.fetch_add(1)) < coastWaves;) {
            const std::size_t w = longest[l];
            const Wave& wave = waves.waves[w];
            coast::MarchedWave marched;
            marched.wavenumber_radpm = std::sqrt(glm::dot(openK[w], openK[w]));
            marched.direction = openK[w] / marched.wavenumber_radpm;
            marched.omega_radps = angularFrequency(marched.wavenumber_radpm, waves.depth_m);
            marched.amplitude_m = wave.amplitude_m;
            marches[l] = coast::marchWave(g, marched, breakerIndex, scratch);
            coast::diffractWave(g, marched, breakerIndex, marches[l], scratch);
            coast::reflectWave(g, marched, seaHeight_m, breakerIndex, marches[l], scratch);
            extendPhase(g, marches[l], openK[w]);
        }
    };
    if (coastWaves > 1) {
        detail::Worker worker;
        worker.run(march, march);
    } else {
        march();
    }

    // Per point: the sea cut where it breaks (breakingDepth: all waves
    // together), the fold limit, and the blend into the open sea.
    layers_.assign(coastWaves, std::vector<glm::vec4>(n));
    common_.assign(n, glm::vec4(0.0f));
    reach_ = waveReach(WaveSet{waves.waves, waves.depth_m, nullptr});
    std::vector<double> gain(waves.waves.size());
    for (int j = 0; j < g.size.y; ++j)
        for (int i = 0; i < g.size.x; ++i) {
            const std::size_t c = std::size_t(j) * std::size_t(g.size.x) + std::size_t(i);
            const double h = g.depth_m[c];
            const int edge = std::min({i, j, g.size.x - 1 - i, g.size.y - 1 - j});
            const double inner = smoothstep01(double(edge) / double(band));
            const glm::dvec2 p = g.origin_m + g.cell_m * glm::dvec2(i, j);
            std::fill(gain.begin(), gain.end(), 1.0);
            // The sea's height, and what it would be had no wave broken (the
            // surf's measure below).
            double heights = 0.0, variance = 0.0, unbrokenHeight = 0.0;
            for (std::size_t w = 0; w < waves.waves.size(); ++w) {
                double unbroken = 1.0;
                if (const int l = layerOfWave_[w]; l >= 0) {
                    const coast::WaveMarch& m = marches[std::size_t(l)];
                    gain[w] = m.reached[c] ? std::sqrt(m.energy[c]) : 0.0;
                    unbroken = m.reached[c] ? std::sqrt(m.unbroken[c]) : 0.0;
                }
                gain[w] = h > 0.0 ? (1.0 - inner) + inner * gain[w] : 0.0;
                const double a = waves.waves[w].amplitude_m * gain[w];
                heights += 2.0 * a;
                variance += 0.5 * a * a;
                unbrokenHeight += 2.0 * waves.waves[w].amplitude_m * (h > 0.0 ? (1.0 - inner) + inner * unbroken : 0.0);
            }
            const double breaksAt_m = breakingDepth(heights, variance, breakerIndex);
            const double cut = h <= 0.0 ? 0.0 : (breaksAt_m > h ? h / breaksAt_m : 1.0);
            double fold = 0.0;
            for (std::size_t w = 0; w < waves.waves.size(); ++w) {
                const Wave& wave = waves.waves[w];
                gain[w] *= cut;
                glm::dvec2 kv = openK[w];
                if (const int l = layerOfWave_[w]; l >= 0) {
                    const coast::WaveMarch& m = marches[std::size_t(l)];
                    kv = (1.0 - inner) * openK[w] + inner * m.wavenumber_radpm[c];
                    const double phase = inner * (m.phase_rad[c] - glm::dot(openK[w], p));
                    layers_[std::size_t(l)][c] = glm::vec4(float(phase), float(gain[w]), float(kv.x), float(kv.y));
                }
                fold += wave.steepness * std::sqrt(glm::dot(kv, kv)) * wave.amplitude_m * gain[w];
            }
            double vertical = 0.0, horizontal = 0.0;
            for (std::size_t w = 0; w < waves.waves.size(); ++w) {
                vertical += waves.waves[w].amplitude_m * gain[w];
                horizontal += waves.waves[w].steepness * waves.waves[w].amplitude_m * gain[w];
            }
            // Bilinear readings lie between the texels' values: their largest bounds them.
            reach_.vertical_m = std::max(reach_.vertical_m, vertical);
            reach_.horizontal_m = std::max(reach_.horizontal_m, horizontal);
            // At most 1 at the texels would let the bilinear reading between
            // them pass 1 where the waves shorten fast: 0.9 inside, 1 at the
            // edges, where the open sea's own limit (limitSteepness) holds.
            const double foldLimit = 1.0 - 0.1 * inner;
            const double steepnessScale = fold > foldLimit ? foldLimit / fold : 1.0;
            // The surf's measure (shaders/surf.glsl): the share of the
            // shoaled height the breaking took (each wave's own cut in its
            // march, then the sea's), 0 where no wave breaks (offshore, and
            // on dry land, where no wave is).
            const double breaking = unbrokenHeight > 0.0 ? std::max(0.0, 1.0 - cut * heights / unbrokenHeight) : 0.0;
            common_[c] = glm::vec4(float(h), float(cut), float(steepnessScale), float(breaking));
        }
}

namespace {

struct Bilinear {
    std::size_t c00, c10, c01, c11;
    double fx, fz;
};

// The four texels around world point p and its weights, as coast_field.glsl
// finds them; false beyond the grid.
bool bilinearAt(const DepthGrid& g, glm::dvec2 p, Bilinear& b)
{
    const glm::dvec2 u = (p - g.origin_m) / g.cell_m;
    if (!(u.x >= 0.0 && u.y >= 0.0 && u.x <= g.size.x - 1.0 && u.y <= g.size.y - 1.0))
        return false;
    const int i = std::min(int(u.x), g.size.x - 2), j = std::min(int(u.y), g.size.y - 2);
    b.fx = u.x - i;
    b.fz = u.y - j;
    b.c00 = std::size_t(j) * std::size_t(g.size.x) + std::size_t(i);
    b.c10 = b.c00 + 1;
    b.c01 = b.c00 + std::size_t(g.size.x);
    b.c11 = b.c01 + 1;
    return true;
}

glm::dvec4 read(std::span<const glm::vec4> texels, const Bilinear& b)
{
    const glm::dvec4 lo = glm::mix(glm::dvec4(texels[b.c00]), glm::dvec4(texels[b.c10]), b.fx);
    const glm::dvec4 hi = glm::mix(glm::dvec4(texels[b.c01]), glm::dvec4(texels[b.c11]), b.fx);
    return glm::mix(lo, hi, b.fz);
}

} // namespace

CoastWaveSample CoastField::waveAt(int layer, glm::dvec2 world_m, glm::dvec2 openWavenumber_radpm) const
{
    Bilinear b;
    if (layer < 0 || std::size_t(layer) >= layers_.size() || !bilinearAt(depth_, world_m, b))
        return {0.0, 1.0, openWavenumber_radpm};
    const glm::dvec4 t = read(layers_[std::size_t(layer)], b);
    return {t.x, t.y, {t.z, t.w}};
}

CoastCommonSample CoastField::commonAt(glm::dvec2 world_m) const
{
    Bilinear b;
    if (!bilinearAt(depth_, world_m, b))
        return {depth_.outsideDepth_m, 1.0, 1.0, 0.0};
    const glm::dvec4 t = read(common_, b);
    return {t.x, t.y, t.z, t.w};
}

int CoastField::edgeBand() const { return blendBand(depth_); }

double CoastField::inside(glm::dvec2 world_m) const
{
    const glm::dvec2 u = (world_m - depth_.origin_m) / depth_.cell_m;
    const double edge = std::min({u.x, u.y, depth_.size.x - 1.0 - u.x, depth_.size.y - 1.0 - u.y});
    return smoothstep01(edge / double(edgeBand()));
}

double coastTrainShare(const CoastField& field, const CoastTrainDepths& depths, glm::dvec2 world_m)
{
    const double inside = field.inside(world_m);
    if (inside <= 0.0)
        return 0.0;
    const double t = (field.commonAt(world_m).depth_m - depths.fullDepth_m) / (depths.noneDepth_m - depths.fullDepth_m);
    return (1.0 - smoothstep01(t)) * inside;
}

} // namespace swell
