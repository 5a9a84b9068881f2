// The renderer's programs as a set: each one's flags from the scene, and a
// rebuild that builds only what changed.
#include "render/programs.h"

#include "render/sky_light.h"
#include "render/surface_sources.h"

#include <utility>

namespace swell::detail {

namespace {

// Whether `slot` holds a program built for `wanted` (none: not wanted).
template <class P>
bool builtFor(const P& slot, const std::optional<typename P::Flags>& wanted)
{
    return wanted && slot && slot.flags() == *wanted;
}

// Each program of a set: its name, its slot in `a` and in `b`, and the
// flags `f` wants it built for (none: not built). The one list of them.
template <class A, class B, class Visit>
void forEachProgram(A& a, B& b, const ProgramFlags& f, Visit visit)
{
    using std::optional;
    visit("water", a.water, b.water, optional(f.water));
    visit("waterInAir", a.waterInAir, b.waterInAir, optional(f.waterInAir));
    visit("waterVisibility", a.waterVisibility, b.waterVisibility, optional(f.waterVisibility));
    visit("waterDeferred", a.waterDeferred, b.waterDeferred, optional(f.waterDeferred));
    visit("waterDeferredInAir", a.waterDeferredInAir, b.waterDeferredInAir, optional(f.waterDeferredInAir));
    visit("waterTiles", a.waterTiles, b.waterTiles, optional(NoFlags{}));
    visit("waterline", a.waterline, b.waterline, optional(f.waterline));
    visit("capture", a.capture, b.capture, optional(f.capture));
    visit("probe", a.probe, b.probe, optional(f.probe));
    visit("sky", a.sky, b.sky, optional(f.sky));
    visit("skyInAir", a.skyInAir, b.skyInAir, optional(f.skyInAir));
    visit("underwaterHost", a.underwaterHost, b.underwaterHost, optional(f.underwaterHost));
    visit("mesh", a.mesh, b.mesh, optional(f.mesh));
    visit("meshInAir", a.meshInAir, b.meshInAir, optional(f.meshInAir));
    visit("fxaa", a.fxaa, b.fxaa, optional(NoFlags{}));
    visit("hostCopy", a.hostCopy, b.hostCopy, optional(NoFlags{}));
    visit("skyBake", a.skyBake, b.skyBake, optional(SkyBakeFlags{false}));
    visit("caustics", a.caustics, b.caustics, f.caustics);
    visit("spray", a.spray, b.spray, f.spray);
    visit("bowSpray", a.bowSpray, b.bowSpray, optional(f.bowSpray));
}

// Builds into `next` what `current` does not hold built for `wanted`.
struct BuildChanged {
    const gl::ShaderSources& sources;
    template <class P>
    void operator()(std::string_view, P& next, const P& current, const std::optional<typename P::Flags>& wanted) const
    {
        if (wanted && !builtFor(current, wanted))
            next = P(sources, *wanted);
    }
};

// Moves from `current` what `next` was left without because it did not change.
struct KeepUnchanged {
    template <class P>
    void operator()(std::string_view, P& next, P& current, const std::optional<typename P::Flags>& wanted) const
    {
        if (!next && builtFor(current, wanted))
            next = std::move(current);
    }
};

gl::Program buildFullscreen(const gl::ShaderSources& sources, const char* fragment,
                            const std::vector<std::string>& defines = {})
{
    return gl::buildProgram(sources, {{GL_VERTEX_SHADER, "fullscreen.vert"}, {GL_FRAGMENT_SHADER, fragment}}, defines);
}

// The temporal resolve's programs (no flags: built once).
TemporalPrograms buildTemporalPrograms(const gl::ShaderSources& sources)
{
    return TemporalPrograms(buildFullscreen(sources, "temporal_neighbourhood.frag"),
                            buildFullscreen(sources, "temporal_resolve.frag", {"SWELL_TEMPORAL_HALF_SIZE_OR_LESS 1"}),
                            buildFullscreen(sources, "temporal_resolve.frag"),
                            buildFullscreen(sources, "temporal_present.frag"));
}

} // namespace

ProgramFlags programFlagsOf(const Scene& scene, const WaveModelGpu& model, unsigned omittedWaterTerms,
                            std::vector<std::string> surfaceSources)
{
    const std::string oceanFile = model.shaderFile();
    const bool cloudShadows = cloudShadowsOn(scene);
    const SurfaceFlags surface{scene.grid.layout, oceanFile, std::move(surfaceSources)};
    const UnderwaterFlags underwater{scene.water.caustics, scene.water.shafts, cloudShadows, true};
    UnderwaterFlags inAir = underwater;
    inAir.seenFromBelow = false;
    ProgramFlags f;
    f.water = {surface, underwater, scene.debugView, scene.reflection.mode, omittedWaterTerms, false};
    f.waterInAir = f.water;
    f.waterInAir.underwater = inAir;
    f.waterVisibility = {surface};
    f.waterVisibility.surface.cachesVertices = true;
    f.waterDeferred = f.water;
    f.waterDeferred.deferred = true;
    f.waterDeferredInAir = f.waterInAir;
    f.waterDeferredInAir.deferred = true;
    f.waterline = {surface, underwater};
    f.capture = f.probe = {surface};
    f.sky = {underwater, false};
    f.skyInAir = {inAir, false};
    f.underwaterHost = {underwater};
    f.mesh = {underwater, scene.debugView, false};
    f.meshInAir = {inAir, scene.debugView, false};
    f.bowSpray = {cloudShadows};
    if (scene.water.caustics)
        f.caustics = CausticsFlags{oceanFile};
    if (model.crestSpray())
        f.spray = CrestSprayFlags{oceanFile, cloudShadows};
    return f;
}

std::vector<std::string_view> changedPrograms(const Programs& current, const ProgramFlags& wanted)
{
    std::vector<std::string_view> names;
    forEachProgram(current, current, wanted, [&](std::string_view name, const auto& slot, const auto&, const auto& flags) {
        if (flags && !builtFor(slot, flags))
            names.push_back(name);
    });
    if (!current.temporal)
        names.push_back("temporal");
    return names;
}

Programs buildChangedPrograms(gl::ShaderSources& sources, const Programs& current, const ProgramFlags& wanted)
{
    setSurfaceSourceFiles(sources, wanted.water.surface.surfaceSources);
    Programs next;
    forEachProgram(next, current, wanted, BuildChanged{sources});
    if (!current.temporal)
        next.temporal = buildTemporalPrograms(sources);
    next.flags = wanted;
    return next;
}

void keepUnchangedPrograms(Programs& next, Programs& current) noexcept
{
    forEachProgram(next, current, next.flags, KeepUnchanged{});
    if (!next.temporal)
        next.temporal = std::move(current.temporal);
}

void updateLabelPrograms(const gl::ShaderSources& sources, std::optional<LabelPrograms>& labels,
                         const ProgramFlags& flags)
{
    std::optional<WaterFlags> water = flags.water;
    std::optional<SkyFlags> sky = flags.sky;
    std::optional<MeshFlags> mesh = flags.mesh;
    water->labelPass = sky->labelPass = mesh->labelPass = true;
    LabelPrograms none;
    LabelPrograms& current = labels ? *labels : none;
    LabelPrograms next;
    const BuildChanged build{sources};
    build("water", next.water, current.water, water);
    build("sky", next.sky, current.sky, sky);
    build("mesh", next.mesh, current.mesh, mesh);
    const KeepUnchanged keep;
    keep("water", next.water, current.water, water);
    keep("sky", next.sky, current.sky, sky);
    keep("mesh", next.mesh, current.mesh, mesh);
    labels = std::move(next);
}

void updateMotionPrograms(const gl::ShaderSources& sources, std::optional<MotionPrograms>& motion,
                          const ProgramFlags& flags)
{
    // The water's vertices as the colour programs place them (never kept
    // for a shading pass: the motion pass draws the grid in one pass).
    std::optional<WaterVertexFlags> water = WaterVertexFlags{flags.water.surface};
    water->surface.cachesVertices = false;
    const std::optional<NoFlags> sky = NoFlags{};
    std::optional<MeshFlags> mesh = flags.mesh;
    mesh->labelPass = false;
    mesh->motionPass = true;
    MotionPrograms none;
    MotionPrograms& current = motion ? *motion : none;
    MotionPrograms next;
    const BuildChanged build{sources};
    build("waterPrevious", next.waterPrevious, current.waterPrevious, water);
    build("water", next.water, current.water, water);
    build("sky", next.sky, current.sky, sky);
    build("mesh", next.mesh, current.mesh, mesh);
    const KeepUnchanged keep;
    keep("waterPrevious", next.waterPrevious, current.waterPrevious, water);
    keep("water", next.water, current.water, water);
    keep("sky", next.sky, current.sky, sky);
    keep("mesh", next.mesh, current.mesh, mesh);
    motion = std::move(next);
}

} // namespace swell::detail
