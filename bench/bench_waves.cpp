// Throughput of the CPU wave function: the exact double evaluations
// (displacement, normal, height under a world point), WaveSampler's fast
// height queries (one at a time and in batches), and wave generation. Each runs for 16, 32 and 64 waves of a
// generated set; queries cycle through points scattered over 1 km^2.
#include "swell/scene/spectrum.h"
#include "swell/scene/waves.h"

#include <benchmark/benchmark.h>

#include <cstddef>
#include <cstdint>
#include <random>
#include <vector>

namespace {

swell::WaveSet benchSet(int waveCount)
{
    swell::WindSettings wind;
    wind.windSpeed_mps = 12.0;
    wind.waveCount = waveCount;
    wind.seed = 7;
    return swell::generateWaves(wind);
}

// A power of two, so the index wraps with a mask.
constexpr std::size_t kPoints = 4096;

std::vector<glm::dvec2> benchPoints()
{
    std::mt19937 rng(3);
    std::vector<glm::dvec2> points(kPoints);
    for (glm::dvec2& p : points)
        p = {rng() * (1000.0 / 4294967296.0) - 500.0, rng() * (1000.0 / 4294967296.0) - 500.0};
    return points;
}

constexpr double kTime_s = 1234.5;

void BM_displacementAt(benchmark::State& state)
{
    const swell::WaveSet set = benchSet(static_cast<int>(state.range(0)));
    const std::vector<glm::dvec2> points = benchPoints();
    std::size_t i = 0;
    for (auto _ : state) {
        benchmark::DoNotOptimize(swell::displacementAt(set, points[i], kTime_s));
        i = (i + 1) & (kPoints - 1);
    }
    state.SetItemsProcessed(state.iterations());
}
BENCHMARK(BM_displacementAt)->Arg(16)->Arg(32)->Arg(64);

void BM_normalAt(benchmark::State& state)
{
    const swell::WaveSet set = benchSet(static_cast<int>(state.range(0)));
    const std::vector<glm::dvec2> points = benchPoints();
    std::size_t i = 0;
    for (auto _ : state) {
        benchmark::DoNotOptimize(swell::normalAt(set, points[i], kTime_s));
        i = (i + 1) & (kPoints - 1);
    }
    state.SetItemsProcessed(state.iterations());
}
BENCHMARK(BM_normalAt)->Arg(16)->Arg(32)->Arg(64);

void BM_heightAt(benchmark::State& state)
{
    const swell::WaveSet set = benchSet(static_cast<int>(state.range(0)));
    const std::vector<glm::dvec2> points = benchPoints();
    std::size_t i = 0;
    for (auto _ : state) {
        benchmark::DoNotOptimize(swell::heightAt(set, points[i], kTime_s));
        i = (i + 1) & (kPoints - 1);
    }
    state.SetItemsProcessed(state.iterations());
}
BENCHMARK(BM_heightAt)->Arg(16)->Arg(32)->Arg(64);

// Auto picks AVX2 with FMA where the CPU has it; the Baseline variants show
// what a CPU without it gets (SSE2 on x86-64).
void samplerHeightAt(benchmark::State& state, swell::WaveSampler::Simd simd)
{
    const swell::WaveSet set = benchSet(static_cast<int>(state.range(0)));
    const swell::WaveSampler sampler(set, kTime_s, {0.0, 0.0}, simd);
    const std::vector<glm::dvec2> points = benchPoints();
    std::size_t i = 0;
    for (auto _ : state) {
        benchmark::DoNotOptimize(sampler.heightAt(points[i]));
        i = (i + 1) & (kPoints - 1);
    }
    state.SetItemsProcessed(state.iterations());
}

void BM_samplerHeightAt(benchmark::State& state)
{
    samplerHeightAt(state, swell::WaveSampler::Simd::Auto);
}
BENCHMARK(BM_samplerHeightAt)->Arg(16)->Arg(32)->Arg(64);

void BM_samplerHeightAtBaseline(benchmark::State& state)
{
    samplerHeightAt(state, swell::WaveSampler::Simd::Baseline);
}
BENCHMARK(BM_samplerHeightAtBaseline)->Arg(16)->Arg(64);

// The batch query: the same solve with several queries across the vector
// lanes instead of several waves.
void samplerHeightsAt(benchmark::State& state, swell::WaveSampler::Simd simd)
{
    const swell::WaveSet set = benchSet(static_cast<int>(state.range(0)));
    const swell::WaveSampler sampler(set, kTime_s, {0.0, 0.0}, simd);
    const std::vector<glm::dvec2> points = benchPoints();
    std::vector<double> heights(points.size());
    for (auto _ : state) {
        sampler.heightsAt(points, heights);
        benchmark::DoNotOptimize(heights.data());
        benchmark::ClobberMemory();
    }
    state.SetItemsProcessed(state.iterations() * static_cast<std::int64_t>(points.size()));
}

void BM_samplerHeightsAt(benchmark::State& state)
{
    samplerHeightsAt(state, swell::WaveSampler::Simd::Auto);
}
BENCHMARK(BM_samplerHeightsAt)->Arg(16)->Arg(32)->Arg(64);

void BM_samplerHeightsAtBaseline(benchmark::State& state)
{
    samplerHeightsAt(state, swell::WaveSampler::Simd::Baseline);
}
BENCHMARK(BM_samplerHeightsAtBaseline)->Arg(16)->Arg(64);

// The sampler's constructor: paid once per frame by a user of the sampler.
void BM_samplerSetup(benchmark::State& state)
{
    const swell::WaveSet set = benchSet(static_cast<int>(state.range(0)));
    double t = kTime_s;
    for (auto _ : state) {
        swell::WaveSampler sampler(set, t, {0.0, 0.0});
        benchmark::DoNotOptimize(sampler);
        t += 0.016;
    }
    state.SetItemsProcessed(state.iterations());
}
BENCHMARK(BM_samplerSetup)->Arg(16)->Arg(64);

void BM_generateWaves(benchmark::State& state)
{
    swell::WindSettings wind;
    wind.waveCount = static_cast<int>(state.range(0));
    for (auto _ : state) {
        benchmark::DoNotOptimize(swell::generateWaves(wind));
        ++wind.seed;
    }
    state.SetItemsProcessed(state.iterations());
}
BENCHMARK(BM_generateWaves)->Arg(16)->Arg(64);

} // namespace
