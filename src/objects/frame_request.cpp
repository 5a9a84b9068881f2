// What a frame may be asked for (swell/frame_request.h): the shared
// messages, and the cost model of a still's history.
#include "swell/frame_request.h"

#include "objects/wake_field.h"
#include "swell/error.h"
#include "swell/scene/waves.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

namespace swell {

std::string outsideRangeMessage(std::string_view shown, double lo, double hi)
{
    return fmt::format("must be a number from {:g} to {:g}, got '{}'", lo, hi, shown);
}

std::string frameSizeMessage(std::string_view shown)
{
    return fmt::format("each side must be 1..{} pixels, got '{}'", kMaxFrameSide, shown);
}

namespace {

// The CPU a second of history costs, s, measured on the reference machine
// of docs/PERFORMANCE.md ("A still's history": 64x36 stills at t = 1 s of
// boats under way, user CPU time, rounded up). Each is an upper bound for
// its part: a body's hull is simplified for its hydrostatics to at most
// kMaxHydrostaticTriangles, and is costed at that many.
//
// A floating rigid body under Gerstner waves: its hydrostatics at 120 Hz
// over a hull at the triangle bound (1.6 us a triangle-step), and its
// 36-point water patch at 30 Hz, which costs with every wave summed.
constexpr double kBodyBase_s = 0.0060;    // 1.3 ms measured with the 1140-triangle boat, + 4.7 ms to 4096 triangles
constexpr double kBodyPerWave_s = 0.00027;
// Under the spectral model: a body's patch looked up in the CPU's fields...
constexpr double kSpectralBody_s = 0.041;
// ...which are synthesised once for each of the bodies' 30 water samples a second.
constexpr double kSpectralSea_s = 0.115;
// The wake: 30 steps a second, each two FFTs of n x n cells (kissfft, n a
// product of 2, 3 and 5): 0.48, 2.0, 10.5 and 58.8 ms measured at 128, 256,
// 512 and 1024 cells, 4.2, 3.8, 4.5 and 5.6 ns times n^2 log2 n (the
// largest no longer in the cache).
constexpr double kWakeStepsPerSecond = 30.0;

double wakeStep_s(int cells)
{
    const double n = cells;
    return (cells > 512 ? 6.0e-9 : 4.5e-9) * n * n * std::log2(n);
}

// Building each body before the first step (its rest height and
// stiffnesses found by bisection over its hull) and drawing it: 11 s for
// 256 boats.
constexpr double kBodySetup_s = 0.045;

int gerstnerWaves(const Scene& scene)
{
    try {
        return int(resolveWaves(scene).waves.size());
    } catch (const std::exception&) {
        return 64; // a scene that fails its checks is refused there; cost it at the most
    }
}

} // namespace

HistoryCost historyCost(const Scene& scene, double from_s, double time_s)
{
    HistoryCost cost;
    bool underWay = false;
    for (const SceneObject& o : scene.objects)
        if (o.isRigidBody()) {
            ++cost.bodies;
            underWay = underWay || o.velocity_m_per_s.x != 0.0 || o.velocity_m_per_s.z != 0.0;
        }
    if (cost.bodies == 0)
        return cost;
    cost.stepped_s = std::max(0.0, time_s - from_s);
    const bool spectral = scene.waves.model == WaveModelKind::Spectral;
    const double body_s = spectral ? kSpectralBody_s : kBodyBase_s + kBodyPerWave_s * gerstnerWaves(scene);
    cost.perSecond_s = cost.bodies * body_s + (spectral ? kSpectralSea_s : 0.0);
    if (scene.wake.enabled && underWay) {
        cost.wakeCells = detail::fastWakeCells(scene.wake.cells);
        cost.perSecond_s += kWakeStepsPerSecond * wakeStep_s(cost.wakeCells);
    }
    cost.cpu_s = cost.bodies * kBodySetup_s + cost.stepped_s * cost.perSecond_s;
    return cost;
}

std::string historyProblem(const Scene& scene, double time_s, std::optional<double> steppedTo_s)
{
    const double start_s = bodiesStart_s(scene);
    const double from_s = steppedTo_s && *steppedTo_s <= time_s ? std::max(*steppedTo_s, start_s) : start_s;
    const HistoryCost cost = historyCost(scene, from_s, time_s);
    if (cost.cpu_s <= kMaxHistoryCpu_s)
        return {};
    const bool one = cost.bodies == 1;
    const std::string what =
        fmt::format("{} floating bod{}{}", cost.bodies, one ? "y" : "ies",
                    cost.wakeCells ? fmt::format(" and {} wake of {} x {} cells", one ? "its" : "their", cost.wakeCells,
                                                 cost.wakeCells)
                                   : "");
    const std::string from = from_s == start_s ? fmt::format("from {} start at {:g} s", one ? "its" : "their", start_s)
                                               : fmt::format("from {:g} s, where {} stand{}", from_s, one ? "it" : "they",
                                                             one ? "s" : "");
    // What would fit: the seconds the bound buys, as a later start.
    const double affordable_s = std::max(0.0, kMaxHistoryCpu_s - cost.bodies * kBodySetup_s) / cost.perSecond_s;
    const std::string remedy =
        from_s == start_s
            ? fmt::format("start {} later (history_start_s = {:g} fits), or give fewer bodies{}", one ? "it" : "them",
                          std::ceil(time_s - affordable_s) + 0.0, cost.wakeCells ? " or a smaller wake" : "") // + 0.0: never "-0"
            : fmt::format("go there in steps of at most {:g} s, or give fewer bodies", std::floor(affordable_s));
    return fmt::format("{:g} s: the scene's {} {} stepped {}: {:g} s of history, estimated at {:.0f} s of CPU "
                       "({:.3g} s per second stepped; docs/PERFORMANCE.md, \"A still's history\"), over the {:g} s "
                       "a frame may take; {}",
                       time_s, what, one ? "is" : "are", from, cost.stepped_s, cost.cpu_s, cost.perSecond_s,
                       kMaxHistoryCpu_s, remedy);
}

} // namespace swell
