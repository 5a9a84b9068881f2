#include "ocean/spectral/breaking.h"

#include "core/derived_cache.h"

#include "ocean/foam/foam_texture.h"
#include "ocean/spectral/foam_replay.h"
#include "ocean/spectral/whitecaps.h"
#include "ocean/spectral/world_foam.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <map>
#include <mutex>
#include <span>
#include <vector>

namespace swell::spectral {

namespace {

// What the breaking depends on: the folding cascades' seeded amplitudes,
// their patches, warps and the choppiness, and the wind that sets the cover
// asked for.
detail::CacheBytes breakingInputsOf(const SpectralField& field, double windSpeed10_mps)
{
    detail::CacheBytes inputs;
    for (int c = 0; c < kFoamCascades; ++c) {
        inputs.addSpan(std::span(field.h0[size_t(c)]));
        inputs.add(field.cascades[size_t(c)].patch_m);
        inputs.add(field.warps[size_t(c)]);
    }
    inputs.add(field.choppiness);
    inputs.add(windSpeed10_mps);
    return inputs;
}

// Each texel's lowest score over all the steps (NaN scores, which make no
// foam, left out).
std::vector<float> lowestOverSteps(const std::vector<std::vector<float>>& steps)
{
    std::vector<float> lowest(steps.front().size(), std::numeric_limits<float>::infinity());
    for (const std::vector<float>& step : steps)
        for (size_t p = 0; p < lowest.size(); ++p)
            lowest[p] = std::min(lowest[p], step[p]);
    return lowest;
}

// The mean share foam covers at the last of the steps whose lowest scores
// are `steps` (one level's, every stored texel), with full foam at score
// `full`: the foam kept from step to step as the replay keeps it.
// `lowestEver` (lowestOverSteps) skips the texels no step makes foam on:
// their foam is 0 and its share exactly 0, so the sum is the same bits.
double coverAt(const std::vector<std::vector<float>>& steps, const std::vector<float>& lowestEver, float full,
               double decay, double breakingAmount)
{
    const size_t texels = steps.front().size();
    const float start = full + kBreakingSpan;
    double sum = 0.0;
    for (size_t p = 0; p < texels; ++p) {
        if (!(lowestEver[p] < start))
            continue;
        float foam = 0.0f;
        for (const std::vector<float>& lowest : steps)
            foam = std::max(foam * float(decay), foamMadeAt(lowest[p], start, kBreakingSpan));
        sum += foam::foamShare(foam, breakingAmount);
    }
    return sum / double(texels);
}

BreakingRamps findRamps(std::shared_ptr<const SpectralField> field, double windSpeed10_mps)
{
    // A still's replay at the salt-water lifetime, over both windows around
    // a place away from the origin (any place: the score's statistics are
    // the same everywhere, which is its point).
    const glm::dvec2 centre_m{1234.5, -678.9};
    std::array<FoamWindow, kFoamLevels> windows{};
    for (int level = 0; level < kFoamLevels; ++level)
        windows[size_t(level)] = foamWindowAt(centre_m, foamTexel_m(*field, level));
    std::vector<double> times_s;
    for (const double offset_s : foamReplayOffsets_s(kSaltWaterFoamLifetime_s))
        times_s.push_back(-offset_s);
    FoamReplay replay(field, BreakingRamps{});
    const auto scores = replay.lowestScores(centre_m, windows, times_s);

    const double target = monahanWhitecapCover(windSpeed10_mps);
    const double decay = std::exp(-kFoamReplayStep_s / kSaltWaterFoamLifetime_s);
    const double breakingAmount = std::exp(-foam::kBreakingFoamAge_s / kSaltWaterFoamLifetime_s);
    BreakingRamps ramps;
    for (int level = 0; level < kFoamLevels; ++level) {
        const std::vector<std::vector<float>>& steps = scores[size_t(level)];
        const std::vector<float> lowestEver = lowestOverSteps(steps);
        // The cover grows with the score of full foam: bisect it. A box's
        // score lies within +-sqrt(24) (one texel against 24 others).
        float low = -6.0f, high = 6.0f;
        for (int i = 0; i < 32; ++i) {
            const float mid = 0.5f * (low + high);
            (coverAt(steps, lowestEver, mid, decay, breakingAmount) < target ? low : high) = mid;
        }
        ramps[size_t(level)] = {0.5f * (low + high) + kBreakingSpan, kBreakingSpan};
    }
    return ramps;
}

} // namespace

BreakingRamps calibratedBreakingRamps(std::shared_ptr<const SpectralField> field, double windSpeed10_mps)
{
    // A scene is often built again with the same sea (the viewer's edits of
    // other keys, tests, a sweep's frames): the ramps found once serve it,
    // in this process and, through the cache on disk, in the next.
    static std::mutex mutex;
    static std::map<std::uint64_t, BreakingRamps> found;
    const detail::CacheBytes inputs = breakingInputsOf(*field, windSpeed10_mps);
    // The inputs are megabytes of spectra: the disk's key is their 128-bit
    // hash, the process's its first half.
    const std::array<std::uint64_t, 2> diskKey = detail::hash128(inputs.bytes());
    const std::uint64_t key = diskKey[0];
    const auto diskKeyBytes = std::as_bytes(std::span(diskKey));
    {
        const std::lock_guard<std::mutex> lock(mutex);
        if (const auto it = found.find(key); it != found.end())
            return it->second;
    }
    BreakingRamps ramps;
    if (const auto entry = detail::loadDerived("ramps", diskKeyBytes); entry && entry->payload().size() == sizeof ramps) {
        std::memcpy(&ramps, entry->payload().data(), sizeof ramps);
    } else {
        ramps = findRamps(std::move(field), windSpeed10_mps);
        detail::storeDerived("ramps", diskKeyBytes, std::as_bytes(std::span(&ramps, 1)));
    }
    const std::lock_guard<std::mutex> lock(mutex);
    if (found.size() >= 64)
        found.clear();
    found.emplace(key, ramps);
    return ramps;
}

BreakingRamps breakingRampsStartingAt(const std::array<float, kFoamLevels>& starts)
{
    BreakingRamps ramps;
    for (int level = 0; level < kFoamLevels; ++level)
        ramps[size_t(level)] = {starts[size_t(level)], kBreakingSpan};
    return ramps;
}

} // namespace swell::spectral
