// The coast field's solve (swell/coast_field.h): each coast wave's ray
// march and diffraction marches over a depth grid, then the sea's breaking
// per sample. The default scene's island is the case every renderer of that
// scene pays once per process (the field is kept for the same waves over
// the same floor): its 16 longest waves over 320 x 320 samples.
#include "ocean/coast/coast_grid.h"

#include "swell/coast_field.h"
#include "swell/scene/waves.h"
#include "swell/scene/scene.h"
#include "swell/scene/seabed.h"

#include <benchmark/benchmark.h>

#include <algorithm>

namespace {

void BM_coastFieldOfTheDefaultIsland(benchmark::State& state)
{
    const swell::Scene scene = swell::defaultScene();
    swell::WaveSet waves = swell::resolveWaves(scene);
    swell::limitSteepness(waves);
    const swell::DepthGrid grid = *swell::coast::depthGridOf(swell::Seabed(scene), waves);
    for (auto _ : state) {
        // Not coastFieldOf: its cache would hand the first field out again.
        const swell::CoastField field(waves, grid);
        benchmark::DoNotOptimize(field.commonAt({0.0, 0.0}).depth_m);
    }
    state.counters["waves"] = double(std::min(swell::kMaxCoastWaves, waves.waves.size()));
    state.counters["samples"] = double(grid.depth_m.size());
}
// CPU: the process's, both threads of the solve.
BENCHMARK(BM_coastFieldOfTheDefaultIsland)->Unit(benchmark::kMillisecond)->MeasureProcessCPUTime();

} // namespace
