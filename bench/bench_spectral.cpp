// The spectral ocean's CPU twin: what one frame costs it. fieldsAt() for a
// new time evolves every cascade's spectra and inverse-transforms all 8
// fields (4 packed complex transforms of 256^2 per cascade);
// displacementFieldsAt() only the displacement (2 of them); evolve() alone
// is the spectra without the transforms; surfaceAt() is one query once the
// frame's fields exist.
#include "ocean/spectral/spectral_cpu.h"
#include "ocean/spectral/spectral_field.h"
#include "swell/scene/spectrum.h"

#include <benchmark/benchmark.h>

#include <memory>

namespace {

std::shared_ptr<const swell::spectral::SpectralField> benchField()
{
    swell::WindSettings wind;
    wind.windSpeed_mps = 12.0;
    wind.seed = 7;
    return std::make_shared<const swell::spectral::SpectralField>(
        swell::spectral::makeSpectralField(swell::SeaSpectrum(wind), 1.0, 7));
}

// One frame: a new time each iteration, so nothing is cached.
void BM_spectralFieldsAt(benchmark::State& state)
{
    swell::spectral::CpuSurface surface(benchField());
    double time_s = 0.0;
    for (auto _ : state) {
        time_s += 1.0 / 60.0;
        benchmark::DoNotOptimize(surface.fieldsAt(time_s).values[0][1].data());
    }
    state.SetItemsProcessed(state.iterations());
}
BENCHMARK(BM_spectralFieldsAt)->Unit(benchmark::kMillisecond);

// A frame whose queries are all heights: the displacement fields only.
void BM_spectralDisplacementFieldsAt(benchmark::State& state)
{
    swell::spectral::CpuSurface surface(benchField());
    double time_s = 0.0;
    for (auto _ : state) {
        time_s += 1.0 / 60.0;
        benchmark::DoNotOptimize(surface.displacementFieldsAt(time_s).values[0][1].data());
    }
    state.SetItemsProcessed(state.iterations());
}
BENCHMARK(BM_spectralDisplacementFieldsAt)->Unit(benchmark::kMillisecond);

// The spectra of every cascade for a new time, without the transforms.
void BM_spectralEvolve(benchmark::State& state)
{
    const auto field = benchField();
    swell::spectral::Spectra spectra;
    double time_s = 0.0;
    for (auto _ : state) {
        time_s += 1.0 / 60.0;
        for (int c = 0; c < swell::spectral::kCascades; ++c) {
            swell::spectral::evolve(*field, c, time_s, spectra);
            benchmark::DoNotOptimize(spectra.packed[0].data());
        }
    }
    state.SetItemsProcessed(state.iterations());
}
BENCHMARK(BM_spectralEvolve)->Unit(benchmark::kMillisecond);

// One query of the surface once the frame's fields are there.
void BM_spectralSurfaceAt(benchmark::State& state)
{
    swell::spectral::CpuSurface surface(benchField());
    const swell::SurfaceFilter filter{};
    double x = 0.0;
    for (auto _ : state) {
        x += 0.37;
        benchmark::DoNotOptimize(surface.surfaceAt({x, 0.5 * x}, 1.0, filter));
    }
    state.SetItemsProcessed(state.iterations());
}
BENCHMARK(BM_spectralSurfaceAt);

} // namespace
