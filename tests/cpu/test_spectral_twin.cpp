// The CPU twin transforms the derivative fields only when a query needs
// them, and only the columns of texels a query reads: the displacement it
// gives without them, and the fields it ends up with, are exactly those of a
// twin that transforms everything at once.
#include "core/worker.h"
#include "ocean/spectral/spectral_cpu.h"
#include "ocean/spectral/spectral_field.h"
#include "swell/scene/spectrum.h"

#include <gtest/gtest.h>

#include <array>
#include <atomic>
#include <chrono>
#include <cmath>
#include <condition_variable>
#include <cstdio>
#include <memory>
#include <mutex>
#include <stdexcept>
#include <thread>

namespace {

using namespace swell::spectral;

std::shared_ptr<const SpectralField> testField()
{
    swell::WindSettings wind;
    wind.windSpeed_mps = 11.0;
    return std::make_shared<const SpectralField>(makeSpectralField(swell::SeaSpectrum(wind), 0.8, 3));
}

TEST(SpectralTwin, DisplacementWithoutDerivativesEqualsTheFullQuery)
{
    const auto field = testField();
    CpuSurface lazy(field), eager(field);
    const swell::SurfaceFilter exact{}, filtered{0.5, 0.9};
    for (double time_s : {0.0, 12.5, 1.0e6}) {
        eager.fieldsAt(time_s);
        for (glm::dvec2 p : {glm::dvec2(0.0, 0.0), glm::dvec2(13.7, -250.2), glm::dvec2(1.0e4, 3.3e3)}) {
            // lazy has only the displacement fields here (its first query at this time).
            const glm::dvec3 d = lazy.displacementAt(p, time_s, exact);
            EXPECT_FALSE(lazy.displacementFieldsAt(time_s).hasDerivatives);
            EXPECT_EQ(d, eager.surfaceAt(p, time_s, exact).displacement_m);
            EXPECT_EQ(lazy.displacementAt(p, time_s, filtered), eager.surfaceAt(p, time_s, filtered).displacement_m);
        }
        // A normal asked for later in the frame transforms the rest.
        const glm::dvec2 p(-40.0, 77.0);
        const swell::SurfacePoint a = lazy.surfaceAt(p, time_s, exact), b = eager.surfaceAt(p, time_s, exact);
        EXPECT_EQ(a.displacement_m, b.displacement_m);
        EXPECT_EQ(a.normal, b.normal);
        for (int c = 0; c < kCascades; ++c)
            for (int v = 0; v < 8; ++v)
                EXPECT_EQ(lazy.fieldsAt(time_s).values[size_t(c)][size_t(v)], eager.fieldsAt(time_s).values[size_t(c)][size_t(v)]);
    }
}

// A query transforms only the texel columns its bilinear samples read, of
// the cascades its filter weighs, once a time: what keeps the floating
// bodies' water samples cheap. Its answers do not depend on what was made
// before them.
TEST(SpectralTwin, AQueryTransformsOnlyTheColumnsItReads)
{
    const auto field = testField();
    const swell::SurfaceFilter filter{0.5, 1.0};
    int weighed = 0;
    for (int c = 0; c < kCascades; ++c) {
        weighed += cascadeWeight(field->cascades[size_t(c)], filter.footprint_m) > 0.0 ? 1 : 0;
        ASSERT_EQ(filteredCascadeWeight(*field, c, filter.footprint_m), 0.0) << "the next test reads filtered fields";
    }
    ASSERT_GT(weighed, 0);
    ASSERT_LT(weighed, kCascades) << "the test needs a cascade the filter leaves out";

    const glm::dvec2 a(13.7, -250.2), b(-40.0, 77.0);
    const double time_s = 12.5;
    CpuSurface first(field), second(field), eager(field);
    // Its two columns (x0 and x0 + 1) of the two displacement pairs of each cascade it weighs.
    const glm::dvec3 da = first.displacementAt(a, time_s, filter);
    EXPECT_EQ(first.columnsTransformed(), weighed * 2 * 2);
    // Asked again, nothing more is made; a normal makes the two derivative pairs' columns.
    EXPECT_EQ(first.displacementAt(a, time_s, filter), da);
    EXPECT_EQ(first.columnsTransformed(), weighed * 2 * 2);
    const swell::SurfacePoint na = first.surfaceAt(a, time_s, filter);
    EXPECT_EQ(first.columnsTransformed(), weighed * 4 * 2);
    const swell::SurfacePoint nb = first.surfaceAt(b, time_s, filter);

    // The other order, and every field made first: the same answers, bit for bit.
    const swell::SurfacePoint nb2 = second.surfaceAt(b, time_s, filter);
    const swell::SurfacePoint na2 = second.surfaceAt(a, time_s, filter);
    eager.fieldsAt(time_s);
    const swell::SurfacePoint na3 = eager.surfaceAt(a, time_s, filter), nb3 = eager.surfaceAt(b, time_s, filter);
    EXPECT_EQ(na.displacement_m, na2.displacement_m);
    EXPECT_EQ(na.normal, na2.normal);
    EXPECT_EQ(nb.displacement_m, nb2.displacement_m);
    EXPECT_EQ(nb.normal, nb2.normal);
    EXPECT_EQ(na.displacement_m, na3.displacement_m);
    EXPECT_EQ(na.normal, na3.normal);
    EXPECT_EQ(nb.normal, nb3.normal);
    EXPECT_EQ(eager.columnsTransformed(), kCascades * 4 * kSize);

    // A new time starts again from nothing.
    const std::int64_t before = first.columnsTransformed();
    first.displacementAt(a, time_s + 1.0, filter);
    EXPECT_EQ(first.columnsTransformed() - before, weighed * 2 * 2);
}

// A query whose footprint reads a cascade's filtered field (its mip chain)
// makes only the texels of the chain it reads, from the columns under them,
// and answers bit for bit as a twin that made every field first.
TEST(SpectralTwin, AFilteredFieldIsMadeFromTheColumnsUnderItsTexels)
{
    const auto field = testField();
    // Cells as long as the first cascade's shortest wave: its exact field
    // weighs nothing there, its filtered field everything.
    const int filteredCascade = 0;
    const swell::SurfaceFilter filter{field->cascades[0].shortestWavelength_m(), 1.0};
    ASSERT_EQ(cascadeWeight(field->cascades[0], filter.footprint_m), 0.0);
    ASSERT_EQ(filteredCascadeWeight(*field, 0, filter.footprint_m), 1.0);
    const double level = displacementLevel(field->cascades[size_t(filteredCascade)], filter.footprint_m);
    ASSERT_GT(level, 1.0);
    ASSERT_LT(level, 6.0);
    // The columns under the four texels a row of each level's B-spline
    // reads, of two pairs.
    const int first = int(std::floor(level));
    const std::int64_t under = 2 * ((std::int64_t(4) << first) + (std::int64_t(4) << (first + 1)));

    const double time_s = 12.5;
    CpuSurface lazy(field), eager(field);
    eager.fieldsAt(time_s);
    for (glm::dvec2 p : {glm::dvec2(0.3, 0.1), glm::dvec2(13.7, -250.2), glm::dvec2(1.0e4, 3.3e3)}) {
        const std::int64_t before = lazy.columnsTransformed();
        const glm::dvec3 d = lazy.displacementAt(p, time_s, filter);
        EXPECT_EQ(d, eager.displacementAt(p, time_s, filter));
        // Every other cascade's exact columns, and the filtered one's under its texels.
        EXPECT_LE(lazy.columnsTransformed() - before, (kCascades - 1) * 2 * 2 + under);
    }
    EXPECT_LT(lazy.columnsTransformed(), kCascades * 2 * kSize / 2);
}

// An interactive view's twin shares each time's transforms with a worker
// thread (CpuSurface::fieldsAt with a Worker): whichever thread takes
// a cascade, every field is the one thread's fieldsAt(), bit for bit, at
// every time; each cascade is handed over once, complete, on the calling
// thread or the worker's. The caller waits in its first handover until the
// worker has handed one over, so that both threads make cascades in every
// call whatever the scheduling (each takes the next cascade not taken).
TEST(SpectralTwin, FieldsSplitAcrossTwoThreadsAreTheOneThreadsBitForBit)
{
    const auto field = testField();
    CpuSurface split(field), one(field);
    swell::detail::Worker worker;
    const std::thread::id caller = std::this_thread::get_id();
    for (double time_s : {0.0, 731.5, 731.5 + 1.0 / 60.0, 1.0e6}) {
        const CpuSurface::Fields& expected = one.fieldsAt(time_s);
        const std::int64_t before = split.columnsTransformed();
        std::array<std::atomic<int>, kCascades> handed{};
        std::array<std::atomic<bool>, kCascades> complete{};
        std::mutex mutex;
        std::condition_variable workerHanded;
        int byCaller = 0, byWorker = 0;
        const CpuSurface::Fields& fields =
            split.fieldsAt(time_s, worker, [&](const CpuSurface::Fields& f, int c) {
                ++handed[size_t(c)];
                bool same = true;
                for (int v = 0; v < 8; ++v)
                    same = same && f.values[size_t(c)][size_t(v)] == expected.values[size_t(c)][size_t(v)];
                complete[size_t(c)] = same;
                std::unique_lock lock(mutex);
                if (std::this_thread::get_id() != caller) {
                    ++byWorker;
                    workerHanded.notify_all();
                } else if (++byCaller == 1) {
                    EXPECT_TRUE(workerHanded.wait_for(lock, std::chrono::seconds(60), [&] { return byWorker > 0; }))
                        << "the worker made no cascade";
                }
            });
        EXPECT_EQ(fields.time_s, time_s);
        EXPECT_TRUE(fields.hasDerivatives);
        EXPECT_EQ(split.columnsTransformed() - before, kCascades * 4 * kSize);
        EXPECT_GE(byCaller, 1);
        EXPECT_GE(byWorker, 1);
        EXPECT_EQ(byCaller + byWorker, kCascades);
        for (int c = 0; c < kCascades; ++c) {
            EXPECT_EQ(handed[size_t(c)], 1) << "cascade " << c;
            EXPECT_TRUE(complete[size_t(c)]) << "cascade " << c << " at " << time_s << " s, when handed over";
            for (int v = 0; v < 8; ++v)
                EXPECT_EQ(fields.values[size_t(c)][size_t(v)], expected.values[size_t(c)][size_t(v)])
                    << "cascade " << c << ", field " << v << " at " << time_s << " s";
        }
    }
}

// The worker runs its half to the end whatever the calling thread's half
// does, and an exception from either half reaches the caller; the worker
// serves the next call after one.
TEST(Worker, RunsBothHalvesAndRethrowsEithersError)
{
    swell::detail::Worker worker;
    std::atomic<int> theirs = 0;
    int mine = 0;
    std::thread::id where;
    worker.run([&] { ++theirs, where = std::this_thread::get_id(); }, [&] { ++mine; });
    EXPECT_EQ(theirs, 1);
    EXPECT_EQ(mine, 1);
    EXPECT_NE(where, std::this_thread::get_id());
    EXPECT_THROW(worker.run([] { throw std::runtime_error("theirs"); }, [&] { ++mine; }), std::runtime_error);
    EXPECT_EQ(mine, 2);
    EXPECT_THROW(worker.run([&] { ++theirs; }, [] { throw std::logic_error("mine"); }), std::logic_error);
    EXPECT_EQ(theirs, 2); // it ran although the caller's half threw
    worker.run([&] { ++theirs; }, [&] { ++mine; });
    EXPECT_EQ(theirs, 3);
    EXPECT_EQ(mine, 3);
}

} // namespace

namespace {

// The normal the twin gives is that of the surface its displacements draw:
// the cross product of central differences of rest point + displacement along
// rest x and z. The cascades are looked up at warped points, so the slopes
// reach the rest point only through the warp's Jacobian (the chain rule):
// with the warp made 4 times stronger than drawn, so that leaving the
// Jacobian out would tilt the normals by about a quarter of their slope,
// they must still agree. One wave alone, 181 texels long: the slope of a
// bilinear displacement is constant across a texel, so it differs from the
// interpolated slope by up to k*texel/2 = 1.7% of the wave's largest slope.
TEST(SpectralTwin, NormalIsTheDrawnSurfacesThroughTheWarp)
{
    swell::WindSettings wind;
    wind.windSpeed_mps = 11.0;
    auto field = std::make_shared<SpectralField>(makeSpectralField(swell::SeaSpectrum(wind), 0.8, 3, 4.0));
    for (int c = 0; c < kCascades; ++c) {
        std::fill(field->h0[size_t(c)].begin(), field->h0[size_t(c)].end(), std::complex<float>(0.0f));
        std::fill(field->h0MinusConj[size_t(c)].begin(), field->h0MinusConj[size_t(c)].end(), std::complex<float>(0.0f));
    }
    const double patch_m = field->cascades[0].patch_m;
    // f = (1, 1): a wave along the diagonal, L0/sqrt(2) long, 2.2 m high.
    // Its partner at -k carries conj(h0(k)), so the fields stay real.
    field->h0[0][size_t(sampleIndex(1, 1))] = {1.0f, 0.5f};
    field->h0MinusConj[0][size_t(sampleIndex(-1, -1))] = {1.0f, -0.5f};
    const CpuSurface surface(field);
    const double texel_m = patch_m / kSize;
    const double h = 1e-3 * texel_m;
    double worst = 0.0, steepest = 0.0;
    constexpr int kTwinPoints = 400;
    for (int i = 0; i < kTwinPoints; ++i) {
        // Spread over ten patches, where the warp takes every value.
        const glm::dvec2 p = glm::dvec2(std::fmod(37.31 * i, 10.0), std::fmod(53.77 * i, 10.0)) * patch_m;
        auto at = [&](glm::dvec2 q) { return glm::dvec3(q.x, 0.0, q.y) + surface.displacementAt(q, 10.0, {}); };
        const glm::dvec3 alongX = (at(p + glm::dvec2(h, 0.0)) - at(p - glm::dvec2(h, 0.0))) / (2.0 * h);
        const glm::dvec3 alongZ = (at(p + glm::dvec2(0.0, h)) - at(p - glm::dvec2(0.0, h))) / (2.0 * h);
        const glm::dvec3 expected = glm::normalize(glm::cross(alongZ, alongX));
        const glm::dvec3 normal = surface.surfaceAt(p, 10.0, {}).normal;
        steepest = std::max(steepest, std::hypot(expected.x, expected.z));
        worst = std::max(worst, glm::length(normal - expected));
    }
    std::printf("one wave, warp x4: worst normal difference %.2e, %.3f of the steepest slope %.4f\n", worst,
                worst / steepest, steepest);
    EXPECT_LT(worst / steepest, 0.03);
}

} // namespace
