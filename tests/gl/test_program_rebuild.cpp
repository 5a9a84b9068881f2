// A scene change rebuilds exactly the programs whose own flags changed
// (render/programs.h, Magnum's per-shader flags): each change below, one
// setting at a time from the same scene, names the programs it must
// rebuild, and the programs built (counted by gl::buildProgram) are theirs
// alone; the rest are kept, not built again. A debug view switch must not
// rebuild FXAA, the sky's bake or the temporal resolve.
#include "gl/program_count.h"
#include "render/programs.h"
#include "render/surface_sources.h"
#include "support/gl_test.h"
#include "swell/renderer.h"
#include "swell/scene/scene.h"
#include "swell/surface_source.h"
#include "swell/wave_model.h"

#include <functional>
#include <map>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

namespace {

using namespace swell;
using Names = std::vector<std::string_view>;

class ProgramRebuild : public test::GlTest {};

// The GL programs behind each member of detail::Programs.
int glPrograms(const Names& names)
{
    const std::map<std::string_view, int> several{{"caustics", 3}, {"spray", 4}, {"bowSpray", 4}, {"temporal", 4}};
    int count = 0;
    for (const std::string_view name : names)
        count += several.contains(name) ? several.at(name) : 1;
    return count;
}

// A source whose code the programs compile (its heights do not matter here).
class FlatSource final : public SurfaceSource {
public:
    glm::dvec3 heightAt(glm::dvec2, double) const override { return glm::dvec3(0.0); }
    double reach_m(double) const override { return 0.0; }
    std::string glsl() const override
    {
        return "vec4 SWELL_SOURCE_FUNCTION(vec2 p_m, vec4 parameters[4]) { return vec4(0.0); }\n";
    }
    SurfaceSourceParameters gpuParameters(double, glm::dvec3) const override { return {}; }
};

struct ProgramRebuildChange {
    const char* name;
    std::function<void(Scene&)> edit;
    Names rebuilt; // in detail::Programs' order
    bool addsSource = false;
};

// The flags of `scene` as the renderer finds them: with its wave model's GPU half.
detail::ProgramFlags flagsOf(const Scene& scene, const gl::ShaderSources& sources, bool withSource)
{
    const std::unique_ptr<WaveModelGpu> gpu = makeWaveModel(scene)->createGpu(sources);
    std::vector<std::string> codes;
    if (withSource)
        codes.push_back(FlatSource().glsl());
    return detail::programFlagsOf(scene, *gpu, 0, codes);
}

// The water's programs that shade it: in one pass and in the shading pass
// of two (docs/RENDERING.md "The water in two passes").
#define SWELL_WATER_SHADING "water", "waterInAir", "waterDeferred", "waterDeferredInAir"
const Names kUnderwater{SWELL_WATER_SHADING, "waterline", "sky", "skyInAir", "underwaterHost", "mesh", "meshInAir"};
const Names kSurface{"water", "waterInAir", "waterVisibility", "waterDeferred", "waterDeferredInAir", "waterline", "capture", "probe"};

std::vector<ProgramRebuildChange> changes()
{
    Names cloudShadows = kUnderwater;
    cloudShadows.push_back("bowSpray");
    Names spectral = kSurface;
    spectral.insert(spectral.end(), {"caustics", "spray"});
    return {
        {"debug view", [](Scene& s) { s.debugView = DebugView::Normals; }, {SWELL_WATER_SHADING, "mesh", "meshInAir"}},
        {"caustics", [](Scene& s) { s.water.caustics = false; }, kUnderwater},
        {"shafts", [](Scene& s) { s.water.shafts = !s.water.shafts; }, kUnderwater},
        {"clouds' shadows",
         [](Scene& s) {
             s.sky.model = SkyModel::Physical;
             s.sky.clouds.cover = 0.5;
         },
         cloudShadows},
        {"reflection mode", [](Scene& s) { s.reflection.mode = ReflectionMode::FixedDistance; }, {SWELL_WATER_SHADING}},
        {"grid layout", [](Scene& s) { s.grid.layout = GridLayout::Paper; }, kSurface},
        {"a surface source", [](Scene&) {}, kSurface, true},
        {"wave model", [](Scene& s) { s.waves.model = WaveModelKind::Spectral; }, spectral},
    };
}

TEST_F(ProgramRebuild, EachSceneSettingRebuildsOnlyTheProgramsThatReadIt)
{
    gl::ShaderSources sources = gl::ShaderSources::embedded();
    const Scene base = defaultScene();
    const detail::ProgramFlags baseFlags = flagsOf(base, sources, false);
    const detail::Programs current = detail::buildChangedPrograms(sources, {}, baseFlags);
    for (const ProgramRebuildChange& change : changes()) {
        SCOPED_TRACE(change.name);
        Scene scene = base;
        change.edit(scene);
        const detail::ProgramFlags flags = flagsOf(scene, sources, change.addsSource);
        EXPECT_EQ(detail::changedPrograms(current, flags), change.rebuilt);
        const std::uint64_t before = gl::programsBuilt();
        const detail::Programs next = detail::buildChangedPrograms(sources, current, flags);
        EXPECT_EQ(gl::programsBuilt() - before, std::uint64_t(glPrograms(change.rebuilt)));
    }
}

TEST_F(ProgramRebuild, TheProgramsThatDidNotChangeAreKeptAsTheyWere)
{
    gl::ShaderSources sources = gl::ShaderSources::embedded();
    Scene scene = defaultScene();
    detail::Programs current = detail::buildChangedPrograms(sources, {}, flagsOf(scene, sources, false));
    const GLuint water = current.water.program().id(), fxaa = current.fxaa.program().id();
    const GLuint sky = current.sky.program().id(), skyBake = current.skyBake.program().id();
    scene.debugView = DebugView::Normals;
    detail::Programs next = detail::buildChangedPrograms(sources, current, flagsOf(scene, sources, false));
    EXPECT_FALSE(next.fxaa);
    detail::keepUnchangedPrograms(next, current);
    EXPECT_EQ(next.fxaa.program().id(), fxaa);
    EXPECT_EQ(next.sky.program().id(), sky);
    EXPECT_EQ(next.skyBake.program().id(), skyBake);
    EXPECT_TRUE(next.temporal && next.caustics && next.bowSpray);
    EXPECT_NE(next.water.program().id(), water);
    EXPECT_EQ(next.water.flags().debugView, DebugView::Normals);
    EXPECT_TRUE(detail::changedPrograms(next, next.flags).empty());
}

// The label pass's programs follow the colour programs' flags alike.
TEST_F(ProgramRebuild, TheLabelProgramsRebuildOnlyWhatChanged)
{
    gl::ShaderSources sources = gl::ShaderSources::embedded();
    Scene scene = defaultScene();
    std::optional<detail::LabelPrograms> labels;
    // The surface sources' files, as the colour programs' build writes them.
    detail::setSurfaceSourceFiles(sources, {});
    std::uint64_t before = gl::programsBuilt();
    detail::updateLabelPrograms(sources, labels, flagsOf(scene, sources, false));
    EXPECT_EQ(gl::programsBuilt() - before, 3u);
    const GLuint sky = labels->sky.program().id();
    scene.debugView = DebugView::Normals;
    before = gl::programsBuilt();
    detail::updateLabelPrograms(sources, labels, flagsOf(scene, sources, false));
    EXPECT_EQ(gl::programsBuilt() - before, 2u); // the water's and the meshes'
    EXPECT_EQ(labels->sky.program().id(), sky);
    EXPECT_TRUE(labels->water.flags().labelPass && labels->mesh.flags().debugView == DebugView::Normals);
}

// The renderer's scene changes take that path: a change builds its
// programs and, for a new wave model, the model's own, nothing else.
TEST_F(ProgramRebuild, TheRendererBuildsOnlyTheChangedPrograms)
{
    const gl::ShaderSources sources = gl::ShaderSources::embedded();
    const Scene base = defaultScene();
    Renderer renderer(base);
    for (const ProgramRebuildChange& change : changes()) {
        SCOPED_TRACE(change.name);
        Scene scene = base;
        change.edit(scene);
        // The programs the scene's wave model builds for itself, when it changes.
        std::uint64_t modelPrograms = 0;
        if (scene.waves.model != base.waves.model) {
            const std::unique_ptr<const WaveModel> model = makeWaveModel(scene);
            const std::uint64_t beforeModel = gl::programsBuilt();
            model->createGpu(sources);
            modelPrograms = gl::programsBuilt() - beforeModel;
            EXPECT_GT(modelPrograms, 0u);
        }
        const std::uint64_t before = gl::programsBuilt();
        const auto source = std::make_shared<const FlatSource>();
        if (change.addsSource)
            renderer.addSurfaceSource(source);
        else
            renderer.setScene(scene);
        EXPECT_EQ(gl::programsBuilt() - before, std::uint64_t(glPrograms(change.rebuilt)) + modelPrograms);
        // Back to the base scene for the next change.
        if (change.addsSource)
            renderer.removeSurfaceSource(source);
        else
            renderer.setScene(base);
    }
}

} // namespace
