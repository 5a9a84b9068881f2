// What the renderer counts of its own frame work (FrameCounters, issue 24):
// the spectral model's GPU work of one step, found by hand from its cascades
// and their formats, so that a dispatch, barrier or mipmap chain added or
// taken away, or an image's format changed, shows here; and the
// simulation's CPU time, which is the calling thread's, with a pass
// observer's time left out. Counted, never timed: the CPU time is checked
// only against the same thread's clock read around the frame.
#include "support/gl_test.h"

#include "support/open_sea.h"
#include "swell/debug.h"
#include "swell/gl/context.h"
#include "swell/gpu/bindings.h"
#include "swell/gpu/ocean.h"
#include "swell/gpu/spray.h"
#include "swell/gpu/underwater.h"
#include "swell/renderer.h"

#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <time.h>
#include <vector>

namespace {

using namespace swell;

class FrameWork : public test::GlTest {};

constexpr glm::ivec2 kFrameWorkSize{32, 18};
constexpr double kFrame_s = 1.0 / 60.0;

// What a view in the air over the storm's sea (20 m/s: past the spray's
// onset) counts of the crests' spray (render/spray_buffers.h): three
// dispatches (every slot's clump, the list of the living, their streaks)
// and a barrier after each; a record of three vec4 and a list entry (a
// uint) for each of the lattice's slots, and the commands (eight uints).
// The streaks, as many as the GPU found living, are the GPU's to count.
constexpr long long kSpraySlots = SWELL_SPRAY_CELLS * SWELL_SPRAY_CELLS * SWELL_SPRAY_SLOTS;
constexpr long long kSprayBytes = kSpraySlots * (3 * 16 + 4) + 8 * 4;
static_assert(kSprayBytes == 2555936, "today's 64^2 cells of 12 slots");

// What each view's water counts when it is drawn in two passes
// (render/water_visibility.h): the dispatch listing the tiles that show
// water and a barrier before and after it; the triangles' R32UI clear over
// the frame and the reset of the tiles' draw command (four uints). The
// tiles listed are the GPU's to count.
constexpr int kWaterDispatches = 1, kWaterBarriers = 2;
constexpr long long kWaterBytes = 4LL * kFrameWorkSize.x * kFrameWorkSize.y + 16;
static_assert(kWaterBytes == 2320, "32 x 18 pixels of 4 bytes, and 16");

// Texels of levels 1 .. log2(size) of a square mip chain, `layers` layers.
long long mipLevelsAboveBase(long long size, long long layers)
{
    long long texels = 0;
    for (size /= 2; size >= 1; size /= 2)
        texels += size * size * layers;
    return texels;
}

// A frame 1/60 s after the last: one step of the spectral model.
TEST_F(FrameWork, OneSpectralStepIsItsDispatchesBarriersMipmapsAndBytes)
{
    const Scene scene = test::openSpectralStorm();
    Renderer renderer(scene);
    const Camera camera = cameraAt(scene.camera, 0.0);
    renderer.renderImage(camera, 0.0, kFrameWorkSize); // the first frame replays the foam's history
    renderer.renderImage(camera, kFrame_s, kFrameWorkSize);
    const FrameCounters& c = renderer.counters();
    ASSERT_EQ(c.oceanTransforms, 1);
    ASSERT_EQ(c.foamSteps, 1);

    // The step: transform the rows (evolving the spectra as they are read),
    // then the columns (in place, writing the shading's half-float copy of
    // the derivatives with the slopes' second moments), step the foam; a
    // barrier after each; then mipmaps of that copy, of the foam and of the
    // displacement (what far vertices read), by compute dispatches and a
    // barrier after each (gl/mip_downsample.h): on a GPU from shared
    // memory, each chain by dispatches of up to SWELL_DOWNSAMPLE_LEVELS
    // levels (a 256^2 chain's 8 levels: 2); on a software rasteriser by
    // blocks, the copy's and the foam's chains in the same dispatches of up
    // to SWELL_DOWNSAMPLE_BLOCK_LEVELS levels (2), the displacement's in
    // two more; then the frame's water queries (render/surface_probe.h),
    // one dispatch and its barrier.
    const long long n = 1 << SWELL_FFT_LOG2_SIZE, cascades = SWELL_FFT_CASCADES;
    const long long foamSize = 1 << SWELL_FOAM_LOG2_SIZE, foamLevels = SWELL_FOAM_LEVELS;
    constexpr long long kRgba32f = 16, kRgba16f = 8, kR16f = 2; // bytes a texel
    const auto dispatchesOfChain = [](long long log2Size, int levelsADispatch) {
        return int((log2Size + levelsADispatch - 1) / levelsADispatch);
    };
    ASSERT_LE(std::abs(camera.position_m.y - scene.sea.level_m), renderer.waveModel().reach().vertical_m)
        << "the eye within the waves' reach, so its side of the water is asked on the GPU";
    static_assert(SWELL_FFT_LOG2_SIZE == SWELL_FOAM_LOG2_SIZE, "the chains share dispatches when of one size");
    const int chains = gl::isSoftwareRasterizer()
        ? 2 * dispatchesOfChain(SWELL_FFT_LOG2_SIZE, SWELL_DOWNSAMPLE_BLOCK_LEVELS)
        : 2 * dispatchesOfChain(SWELL_FFT_LOG2_SIZE, SWELL_DOWNSAMPLE_LEVELS) +
              dispatchesOfChain(SWELL_FOAM_LOG2_SIZE, SWELL_DOWNSAMPLE_LEVELS);
    EXPECT_EQ(c.simulationGpu.dispatches, 4 + chains);
    EXPECT_EQ(c.simulationGpu.barriers, 4 + chains);
    EXPECT_EQ(c.simulationGpu.dispatches, gl::isSoftwareRasterizer() ? 8 : 10) << "today's 256^2 fields and foam";
    EXPECT_EQ(c.simulationGpu.mipmaps, 0) << "no glGenerateTextureMipmap";
    const long long spectra = 2 * n * n * cascades * kRgba32f; // the displacement's and the derivatives' images
    const long long transforms = 2 * spectra;                  // written by each FFT pass
    // Written by the column pass: the derivatives' copy and the moments.
    const long long slopes = 2 * n * n * cascades * kRgba16f;
    const long long slopeMips = mipLevelsAboveBase(n, 2 * cascades) * kRgba16f; // the moments' layers too
    const long long displacementMips = mipLevelsAboveBase(n, SWELL_FFT_FILTERED_CASCADES) * kRgba32f; // their layers alone
    const long long foam = foamSize * foamSize * foamLevels * kR16f + mipLevelsAboveBase(foamSize, foamLevels) * kR16f;
    // Each query's answer: 3 vec4s and the 8 x 8 block's vertices; this
    // open sea floats nothing, so the viewpoint's alone.
    const long long queries = (3 + SWELL_PROBE_BLOCK * SWELL_PROBE_BLOCK) * 16;
    EXPECT_EQ(c.simulationGpu.bytesWritten, transforms + slopes + slopeMips + displacementMips + foam + queries);
    // The same by hand for today's 4 cascades of 256^2 and 2 foam levels of
    // 256^2: 16 MiB of spectra, 4 MiB of the shading's copy (2 MiB of
    // derivatives, 2 MiB of moments), 1398080 bytes of its mipmaps, 349520
    // of the first cascade's displacement's, 256 KiB of foam and 87380
    // bytes of its mipmaps, 1072 bytes of the answer.
    EXPECT_EQ(c.simulationGpu.bytesWritten, 23069716);

    // A view simulates nothing: the spectral model's views write no image;
    // the spray's passes and the water's tile list are its only dispatches.
    EXPECT_EQ(c.viewsGpu.dispatches, 3 + kWaterDispatches);
    EXPECT_EQ(c.viewsGpu.barriers, 3 + kWaterBarriers);
    EXPECT_EQ(c.viewsGpu.mipmaps, 0);
    EXPECT_EQ(c.viewsGpu.bytesWritten, kSprayBytes + kWaterBytes);
    EXPECT_GT(c.drawCalls, 0);

    // The same frame again is no step and no work.
    renderer.advanceTo(kFrame_s, camera.position_m);
    EXPECT_EQ(renderer.counters().simulationGpu.dispatches, 0);
    EXPECT_EQ(renderer.counters().simulationGpu.bytesWritten, 0);
}

// A view that draws the caustics map (the eye under the water) counts what
// the map's pass does beside its draws: its two dispatches (the refracted
// source grid, the slices' triangles) and their barriers, the buffers they
// write, the clear of its slices' base level and its mip chain, one
// glGenerateTextureMipmap (the surface hides the spray from it); a view in
// the air over an open sea draws no map and counts the spray's passes alone.
TEST_F(FrameWork, AViewUnderTheWaterCountsTheCausticsMapsClearAndMipChain)
{
    const Scene scene = test::openSpectralStorm();
    Renderer renderer(scene);
    Camera camera = cameraAt(scene.camera, 0.0);
    camera.position_m.y = -6.0;
    renderer.renderImage(camera, 0.0, kFrameWorkSize);
    const FrameCounters& c = renderer.counters();
    ASSERT_GT(c.causticsTriangles, 0) << "the view under the water drew the caustics map";
    long long texels = 0;
    for (long long size = SWELL_CAUSTICS_SIZE; size >= 1; size /= 2)
        texels += size * size * SWELL_CAUSTICS_SLICES;
    const long long points = (SWELL_CAUSTICS_CELLS + 1) * (SWELL_CAUSTICS_CELLS + 1);
    const long long corners = 3 * 2 * SWELL_CAUSTICS_CELLS * SWELL_CAUSTICS_CELLS * SWELL_CAUSTICS_SLICES;
    EXPECT_EQ(c.viewsGpu.mipmaps, 1);
    EXPECT_EQ(c.viewsGpu.dispatches, 2 + kWaterDispatches);
    EXPECT_EQ(c.viewsGpu.barriers, 2 + kWaterBarriers);
    EXPECT_EQ(c.viewsGpu.bytesWritten, texels * 4 + points * 32 + corners * 16 + kWaterBytes)
        << "R32F texels, base level and mip chain; two vec4 a source point; a vec4 a corner; the water's";
    EXPECT_EQ(c.causticsTriangles, 2 * SWELL_CAUSTICS_CELLS * SWELL_CAUSTICS_CELLS);
    // Today's map: 3 slices of 512^2 (4,194,300 bytes), from 257^2 points
    // (2,113,568) and 3 x 131,072 triangles (18,874,368).
    EXPECT_EQ(c.viewsGpu.bytesWritten, 25182236 + kWaterBytes);

    camera.position_m.y = 40.0;
    renderer.renderImage(camera, 1.0, kFrameWorkSize);
    EXPECT_EQ(renderer.counters().causticsTriangles, 0);
    EXPECT_EQ(renderer.counters().viewsGpu.mipmaps, 0);
    EXPECT_EQ(renderer.counters().viewsGpu.bytesWritten, kSprayBytes + kWaterBytes);
}

double threadCpu_ms()
{
    timespec t{};
    ::clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
    return double(t.tv_sec) * 1e3 + double(t.tv_nsec) * 1e-6;
}

// An observer that spends CPU time on the calling thread at every pass's
// begin and end, and counts it.
class BusyObserver : public PassObserver {
public:
    void beginPass(const char*) override { burn(); }
    void endPass(const char*) override { burn(); }
    double spent_ms = 0.0;
    int calls = 0;

private:
    void burn()
    {
        const double start = threadCpu_ms();
        volatile double sink = 0.0;
        while (threadCpu_ms() - start < kBurn_ms)
            sink = sink + 1.0;
        spent_ms += threadCpu_ms() - start;
        ++calls;
    }
    static constexpr double kBurn_ms = 5.0;
};

// The parts are the calling thread's CPU time within the frame, apart from
// each other and from the observer's: together they fit in the thread's
// time around the frame less the observer's. Charging the observer's time
// to a part would not fit (it is most of the frame's thread time here), nor
// would the process's clock, which counts the software rasteriser's threads
// computing the spectra.
TEST_F(FrameWork, SimulationCpuTimeIsTheCallingThreadsWithoutTheObserver)
{
    const Scene scene = test::openSpectralStorm();
    Renderer renderer(scene);
    const Camera camera = cameraAt(scene.camera, 0.0);
    renderer.renderImage(camera, 0.0, kFrameWorkSize); // shaders compiled, the history replayed
    BusyObserver observer;
    renderer.setPassObserver(&observer);
    const double before_ms = threadCpu_ms();
    renderer.renderImage(camera, kFrame_s, kFrameWorkSize);
    const double around_ms = threadCpu_ms() - before_ms;
    renderer.setPassObserver(nullptr);

    const SimulationCpuTime& cpu = renderer.counters().simulationCpu;
    EXPECT_GT(cpu.model_ms, 0.0) << "the spectral model's step";
    EXPECT_GT(cpu.queries_ms, 0.0) << "the frame's drawn surface";
    EXPECT_GT(cpu.views_ms, 0.0) << "culling and uniforms";
    EXPECT_GE(observer.calls, 10);
    EXPECT_GE(observer.spent_ms, 5.0 * observer.calls);
    EXPECT_LE(cpu.total_ms() + observer.spent_ms, around_ms + 1e-6)
        << "parts " << cpu.total_ms() << " ms, observer " << observer.spent_ms << " ms, thread " << around_ms << " ms";
}

// An observer that writes down every begin and end, indented by nesting.
class PassLog : public PassObserver {
public:
    void beginPass(const char* name) override { log.push_back(std::string(size_t(depth++) * 2, ' ') + "+" + name); }
    void endPass(const char* name) override { log.push_back(std::string(size_t(--depth) * 2, ' ') + "-" + name); }
    std::vector<std::string> log;
    int depth = 0;
};

// The spectral model tells the observer the stages of its GPU work, inside
// the "ocean" pass and in the order it runs them (the benchmark times each:
// issue 24, item 2), and nothing of them outside it.
TEST_F(FrameWork, TheSpectralStepsStagesArePassesInsideTheOceanPass)
{
    const Scene scene = test::openSpectralStorm();
    Renderer renderer(scene);
    const Camera camera = cameraAt(scene.camera, 0.0);
    renderer.renderImage(camera, 0.0, kFrameWorkSize);
    PassLog observer;
    renderer.setPassObserver(&observer);
    renderer.renderImage(camera, kFrame_s, kFrameWorkSize);
    renderer.setPassObserver(nullptr);
    EXPECT_EQ(observer.depth, 0);
    const std::vector<std::string> expected{
        "+ocean", "  +fft rows", "  -fft rows", "  +fft columns", "  -fft columns",
        "  +foam", "  -foam",    "  +mipmaps", "  -mipmaps",     "-ocean"};
    ASSERT_GE(observer.log.size(), expected.size());
    EXPECT_EQ(std::vector<std::string>(observer.log.begin(), observer.log.begin() + std::ptrdiff_t(expected.size())),
              expected);
    // The views' passes after it: none of them a stage.
    for (size_t i = expected.size(); i < observer.log.size(); ++i)
        for (const char* stage : {"fft", "mipmaps", "foam", "moments"})
            EXPECT_EQ(observer.log[i].find(stage), std::string::npos) << observer.log[i];
}

} // namespace
