// Every program the renderer builds, in every variant: each debug view, each
// reflection mode, each grid layout, and each wave model's GLSL file (every
// embedded file under ocean/, so a new model is covered by adding its file).
// A variant the scenes of the other tests never select still has to compile.
#include "objects/wake_surface.h"
#include "render/programs.h"
#include "support/gl_test.h"
#include "swell/gpu/variants.h"

#include <array>
#include <string>
#include <vector>

namespace {

using swell::DebugView;
using swell::GridLayout;
using swell::ReflectionMode;

class AllVariants : public swell::test::GlTest {};

std::vector<std::string> oceanFiles(const swell::gl::ShaderSources& sources)
{
    std::vector<std::string> files;
    for (const std::string& name : sources.fileNames())
        if (name.starts_with("ocean/") && name.ends_with(".glsl"))
            files.push_back(name);
    return files;
}

TEST_F(AllVariants, EveryProgramCompilesAndLinksInEveryVariant)
{
    swell::gl::ShaderSources sources = swell::gl::ShaderSources::embedded();
    const std::vector<std::string> models = oceanFiles(sources);
    // Gerstner and flat water at least: a glob that found nothing would pass vacuously.
    ASSERT_GE(models.size(), 2u);
    constexpr std::array views{DebugView::Shaded, DebugView::Normals,   DebugView::Reflection, DebugView::Refraction,
                               DebugView::Lod,    DebugView::Wireframe, DebugView::Foam};
    int built = 0;
    for (const std::string& model : models)
        for (const DebugView view : views)
            for (const ReflectionMode reflection : {ReflectionMode::FixedDistance, ReflectionMode::RayMarch})
                for (const GridLayout layout : {GridLayout::Geometric, GridLayout::Paper}) {
                    swell::detail::ShaderVariant variant{view, reflection, layout, model};
                    variant.surfaceSources = {swell::detail::WakeSurfaceSource::code()};
                    SCOPED_TRACE(model + ", debug view " + std::to_string(int(view)) + ", reflection " +
                                 std::to_string(int(reflection)) + ", layout " + std::to_string(int(layout)));
                    swell::detail::Programs programs;
                    EXPECT_NO_THROW(programs = swell::detail::buildPrograms(sources, variant));
                    EXPECT_TRUE(programs.water && programs.sky && programs.capture && programs.caustics);
                    ++built;
                }
    EXPECT_EQ(built, int(models.size()) * int(views.size()) * 2 * 2);
}

// Without the wake or any surface source (wake.enabled = false; the variants above have the wake), with
// every model and debug view, and without the caustics (water.caustics = false: the world's
// shading reads no map, and the caustics pass is not built); the shafts of light
// (water.shafts) on and off in turn, by debug view, the caustics' mean alone when on;
// the cloud layer's shadows (render/cloud_shadow_map.h) with the debug views that
// have no shafts.
TEST_F(AllVariants, EveryProgramCompilesWithoutTheWake)
{
    swell::gl::ShaderSources sources = swell::gl::ShaderSources::embedded();
    const std::vector<std::string> models = oceanFiles(sources);
    ASSERT_GE(models.size(), 2u);
    int built = 0;
    for (const std::string& model : models)
        for (const DebugView view : {DebugView::Shaded, DebugView::Normals, DebugView::Reflection, DebugView::Refraction,
                                     DebugView::Lod, DebugView::Wireframe, DebugView::Foam}) {
            swell::detail::ShaderVariant variant{view, ReflectionMode::RayMarch, GridLayout::Geometric, model};
            variant.surfaceSources.clear();
            variant.caustics = false;
            variant.shafts = int(view) % 2 == 0;
            variant.cloudShadows = !variant.shafts;
            SCOPED_TRACE(model + ", debug view " + std::to_string(int(view)) + ", no wake, no caustics, shafts " +
                         std::to_string(int(variant.shafts)) + ", cloud shadows " + std::to_string(int(variant.cloudShadows)));
            swell::detail::Programs programs;
            EXPECT_NO_THROW(programs = swell::detail::buildPrograms(sources, variant));
            EXPECT_TRUE(programs.water && programs.capture);
            EXPECT_FALSE(programs.caustics);
            ++built;
        }
    EXPECT_EQ(built, int(models.size()) * 7);
}

// The benchmark's variants: each water shading term left out alone, and all
// of them, with every model and both reflection modes.
TEST_F(AllVariants, EveryWaterTermCanBeLeftOut)
{
    swell::gl::ShaderSources sources = swell::gl::ShaderSources::embedded();
    const std::vector<std::string> models = oceanFiles(sources);
    ASSERT_GE(models.size(), 2u);
    int built = 0;
    for (const std::string& model : models)
        for (const ReflectionMode reflection : {ReflectionMode::FixedDistance, ReflectionMode::RayMarch})
            for (unsigned term = 1; term <= SWELL_TERM_ALL; term = term == SWELL_TERM_FILTERING ? SWELL_TERM_ALL : term * 2) {
                swell::detail::ShaderVariant variant{DebugView::Shaded, reflection, GridLayout::Geometric, model};
                variant.surfaceSources = {swell::detail::WakeSurfaceSource::code()};
                variant.omittedWaterTerms = term;
                SCOPED_TRACE(model + ", reflection " + std::to_string(int(reflection)) + ", terms left out " +
                             std::to_string(term));
                swell::detail::Programs programs;
                EXPECT_NO_THROW(programs = swell::detail::buildPrograms(sources, variant));
                EXPECT_TRUE(programs.water);
                ++built;
            }
    // Eight single terms and all of them together.
    EXPECT_EQ(built, int(models.size()) * 2 * 9);
}

} // namespace

namespace {

// The physical sky's bake, built only when a scene first asks for it
// (render/programs.h), so no variant above compiles it.
TEST_F(AllVariants, ThePhysicalSkyBakeCompilesAndLinks)
{
    const swell::gl::ShaderSources sources = swell::gl::ShaderSources::embedded();
    swell::detail::SkyBakeProgram program;
    EXPECT_NO_THROW(program = swell::detail::SkyBakeProgram(sources, swell::detail::ShaderVariant{}, true));
    EXPECT_TRUE(program);
}

} // namespace
