// Every program the renderer builds, over its own flags (render/
// program_flags.h): one loop per program, each of its flags taking every
// value, with every wave model's GLSL file where the program reads the
// model (every embedded file under ocean/, so a new model is covered by
// adding its file). A flag combination the scenes of the other tests
// never select still has to compile: a shader that reads a define its
// program's flags do not give stops with #error, so these also hold each
// program's flags to what its shaders read.
#include "objects/wake_surface.h"
#include "render/programs.h"
#include "render/surface_sources.h"
#include "support/gl_test.h"
#include "swell/gpu/variants.h"

#include <array>
#include <string>
#include <vector>

namespace {

using namespace swell;
using namespace swell::detail;

class AllVariants : public test::GlTest {};

constexpr std::array kViews{DebugView::Shaded, DebugView::Normals,   DebugView::Reflection, DebugView::Refraction,
                            DebugView::Lod,    DebugView::Wireframe, DebugView::Foam};

std::vector<std::string> oceanFiles(const gl::ShaderSources& sources)
{
    std::vector<std::string> files;
    for (const std::string& name : sources.fileNames())
        if (name.starts_with("ocean/") && name.ends_with(".glsl"))
            files.push_back(name);
    return files;
}

// The 16 combinations of the underwater flags, by the bits of i.
UnderwaterFlags underwaterFlags(unsigned i)
{
    return {(i & 1u) != 0, (i & 2u) != 0, (i & 4u) != 0, (i & 8u) != 0};
}

// The water's vertex flags: a model, a layout and the surface sources (the
// wake's, or none), by i.
SurfaceFlags surfaceFlags(const std::vector<std::string>& models, unsigned i)
{
    std::vector<std::string> sources;
    if (i % 2 == 1)
        sources.push_back(WakeSurfaceSource::code());
    return {(i / 2) % 2 == 0 ? GridLayout::Geometric : GridLayout::Paper, models[(i / 4) % models.size()], sources};
}

std::string traceOf(unsigned i) { return "combination " + std::to_string(i); }

class EveryProgram : public AllVariants {
protected:
    void SetUp() override
    {
        AllVariants::SetUp();
        // Gerstner and flat water at least: a glob that found nothing would pass vacuously.
        ASSERT_GE(models.size(), 2u);
        // The surface sources' files, written as the renderer writes them.
        setSurfaceSourceFiles(sources, {WakeSurfaceSource::code()});
    }
    gl::ShaderSources sources = gl::ShaderSources::embedded();
    const std::vector<std::string> models = oceanFiles(sources);
};

// Every model, debug view, reflection mode and grid layout; the underwater
// flags, the sources and the label pass through all their values among them.
TEST_F(EveryProgram, TheWaterCompilesForEachFlag)
{
    unsigned i = 0;
    for (const std::string& model : models)
        for (const DebugView view : kViews)
            for (const ReflectionMode reflection : {ReflectionMode::FixedDistance, ReflectionMode::RayMarch})
                for (const GridLayout layout : {GridLayout::Geometric, GridLayout::Paper}) {
                    SurfaceFlags surface = surfaceFlags(models, i);
                    surface.oceanFile = model;
                    surface.gridLayout = layout;
                    // The label pass's, and the shading pass of the water
                    // in two (never both: the label pass draws in one).
                    WaterFlags flags{surface, underwaterFlags(i), view, reflection, 0, i % 5 == 2};
                    flags.deferred = i % 5 == 1;
                    SCOPED_TRACE(model + ", debug view " + std::to_string(int(view)) + ", " + traceOf(i));
                    EXPECT_TRUE(WaterProgram(sources, flags));
                    ++i;
                }
    EXPECT_EQ(i, models.size() * kViews.size() * 2 * 2);
}

// The benchmark's variants: each water shading term left out alone, and
// all of them, with every model and both reflection modes.
TEST_F(EveryProgram, TheWaterCompilesWithEachTermLeftOut)
{
    int built = 0;
    for (const std::string& model : models)
        for (const ReflectionMode reflection : {ReflectionMode::FixedDistance, ReflectionMode::RayMarch})
            for (unsigned term = 1; term <= SWELL_TERM_ALL; term = term == SWELL_TERM_FILTERING ? SWELL_TERM_ALL : term * 2) {
                WaterFlags flags;
                flags.surface = {GridLayout::Geometric, model, {WakeSurfaceSource::code()}};
                flags.reflection = reflection;
                flags.omittedTerms = term;
                // The ray-marched reflection's in the shading pass of the water in two.
                flags.deferred = reflection == ReflectionMode::RayMarch;
                SCOPED_TRACE(model + ", terms left out " + std::to_string(term));
                EXPECT_TRUE(WaterProgram(sources, flags));
                ++built;
            }
    // Eight single terms and all of them together.
    EXPECT_EQ(built, int(models.size()) * 2 * 9);
}

TEST_F(EveryProgram, TheWaterlineMaskCompilesForEachFlag)
{
    for (unsigned i = 0; i < 16 || i < 4 * models.size(); ++i) {
        SCOPED_TRACE(traceOf(i));
        EXPECT_TRUE(WaterlineProgram(sources, {surfaceFlags(models, i), underwaterFlags(i)}));
    }
}

TEST_F(EveryProgram, TheWaterVertexCaptureAndTheQueriesCompileForEachFlag)
{
    for (unsigned i = 0; i < 4 * models.size(); ++i) {
        SCOPED_TRACE(traceOf(i));
        EXPECT_TRUE(WaterCaptureProgram(sources, {surfaceFlags(models, i)}));
        SurfaceFlags visibility = surfaceFlags(models, i);
        visibility.cachesVertices = true;
        EXPECT_TRUE(WaterVisibilityProgram(sources, {visibility}));
        EXPECT_TRUE(SurfaceProbeProgram(sources, {surfaceFlags(models, i)}));
    }
}

TEST_F(EveryProgram, TheSkyCompilesForEachFlag)
{
    for (unsigned i = 0; i < 32; ++i) {
        SCOPED_TRACE(traceOf(i));
        EXPECT_TRUE(SkyProgram(sources, {underwaterFlags(i), i >= 16}));
    }
}

TEST_F(EveryProgram, TheHostsGeometryUnderTheWaterCompilesForEachFlag)
{
    for (unsigned i = 0; i < 16; ++i) {
        SCOPED_TRACE(traceOf(i));
        EXPECT_TRUE(UnderwaterHostProgram(sources, {underwaterFlags(i)}));
    }
}

TEST_F(EveryProgram, TheMeshesCompileForEachFlag)
{
    for (unsigned i = 0; i < 2 * kViews.size() * 2; ++i) {
        SCOPED_TRACE(traceOf(i));
        EXPECT_TRUE(MeshProgram(sources, {underwaterFlags(i), kViews[i % kViews.size()], (i / kViews.size()) % 2 == 1}));
    }
}

TEST_F(EveryProgram, TheCausticsPassCompilesForEachModel)
{
    for (const std::string& model : models) {
        SCOPED_TRACE(model);
        EXPECT_TRUE(CausticsPrograms(sources, {model}));
    }
}

// The crests' spray is built for models whose crests break
// (WaveModelGpu::crestSpray): the spectral model's.
TEST_F(EveryProgram, TheSprayCompilesForEachFlag)
{
    for (const bool cloudShadows : {false, true}) {
        SCOPED_TRACE(cloudShadows ? "cloud shadows" : "no cloud shadows");
        EXPECT_TRUE(SprayProgram(sources, {"ocean/spectral.glsl", cloudShadows}));
        EXPECT_TRUE(BowSprayProgram(sources, {cloudShadows}));
    }
}

// The programs without flags, and the physical sky's bake, built only when
// a scene first asks for it.
TEST_F(EveryProgram, TheProgramsWithoutFlagsCompile)
{
    EXPECT_TRUE(FxaaProgram(sources, {}));
    EXPECT_TRUE(CloudShadowBakeProgram(sources));
    for (const bool physical : {false, true})
        EXPECT_TRUE(SkyBakeProgram(sources, physical));
    // The temporal resolve's, with everything else, for the first model's file.
    detail::ProgramFlags flags;
    for (WaterFlags* water : {&flags.water, &flags.waterInAir, &flags.waterDeferred, &flags.waterDeferredInAir})
        water->surface.oceanFile = models.front();
    flags.waterDeferred.deferred = flags.waterDeferredInAir.deferred = true;
    flags.waterVisibility.surface.cachesVertices = true;
    for (SurfaceFlags* surface : {&flags.waterline.surface, &flags.capture.surface, &flags.probe.surface,
                                  &flags.waterVisibility.surface})
        surface->oceanFile = models.front();
    flags.caustics = CausticsFlags{models.front()};
    const detail::Programs all = buildChangedPrograms(sources, {}, flags);
    EXPECT_TRUE(all.temporal && all.water && all.waterDeferred && all.waterVisibility && all.waterTiles && all.caustics &&
                !all.spray);
}

} // namespace
