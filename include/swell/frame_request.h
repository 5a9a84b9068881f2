// What a frame may be asked for, the same from the swell executable and from
// Python (docs/PERFORMANCE.md, "A still's history"): its size, its time, and
// the simulation its bodies need stepped before it can be drawn. Each check
// gives the message both print, so that a refusal reads the same wherever
// it comes from.
#pragma once

#include "swell/export.h"

#include "swell/scene/scene.h"

#include <optional>
#include <string>
#include <string_view>

namespace swell {

// The largest frame a side, pixels (`swell render --size`, Python's size).
inline constexpr int kMaxFrameSide = 16384;
// The latest frame time, s (`swell render --time`, Python's time_s).
inline constexpr double kMaxFrameTime_s = 1.0e9;

// "must be a number from 0 to 1e+09, got '-1'": what a number outside lo..hi
// is told, `shown` being the value as the user wrote it.
SWELL_API std::string outsideRangeMessage(std::string_view shown, double lo, double hi);
// "each side must be 1..16384 pixels, got '0x5'".
SWELL_API std::string frameSizeMessage(std::string_view shown);

// The most CPU time, s, a frame's history may be estimated to take on the
// reference machine of docs/PERFORMANCE.md before the first frame can be
// drawn: beyond it a still is refused up front, saying what it would cost.
inline constexpr double kMaxHistoryCpu_s = 30.0;

// What stepping a scene's floating rigid bodies (and their wake) from from_s
// to time_s costs: the seconds stepped, and the CPU time they are estimated
// to take there, from the costs measured per body and per wake step.
struct SWELL_API HistoryCost {
    double stepped_s = 0.0;
    int bodies = 0;         // floating rigid bodies (each stepped at 120 Hz)
    int wakeCells = 0;      // cells a side of the wake stepped with them; 0: none
    double perSecond_s = 0.0; // estimated CPU per second stepped, s
    double cpu_s = 0.0;       // each body's setup, plus stepped_s * perSecond_s
};
SWELL_API HistoryCost historyCost(const Scene& scene, double from_s, double time_s);

// Why a frame at time_s cannot be drawn within kMaxHistoryCpu_s; "" when it
// can. The bodies stand at `steppedTo_s` (a renderer's simulated time) when
// given and not after time_s; otherwise they are stepped from their start,
// bodiesStart_s(scene), as for a first frame. The message says the cost,
// the bound, and a history_start_s that would fit.
SWELL_API std::string historyProblem(const Scene& scene, double time_s, std::optional<double> steppedTo_s = {});

// A still estimated to spend longer than this on its history, CPU s, says
// so before it starts (historyNote): the user sees why it takes its time.
inline constexpr double kNotedHistoryCpu_s = 3.0;

// What a first frame at time_s will spend on the history of the scene's
// bodies, when the estimate passes kNotedHistoryCpu_s: "simulating 80 s of
// 2 floating bodies and their wake of 256 x 256 cells (from their start at
// -60 s) before the frame: about 21 s of CPU (...)"; "" when it is less.
SWELL_API std::string historyNote(const Scene& scene, double time_s);

} // namespace swell
