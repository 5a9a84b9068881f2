// The renderer's programs as a set: what each is compiled for, found from
// the scene and the wave model (programFlagsOf), and their rebuild when
// that changes, which builds only the programs whose own flags changed and
// keeps the rest (render/program_flags.h says what each program's flags
// hold; render/shader_programs.h are the programs).
#pragma once

#include "render/program_flags.h"
#include "render/shader_programs.h"
#include "render/temporal_resolve.h"
#include "swell/gl/shader.h"
#include "swell/scene/scene.h"
#include "swell/wave_model_gpu.h"

#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace swell::detail {

// Each program's flags. Programs built for passes in which no pixel looks
// out from below the water (...InAir) have seenFromBelow false.
struct ProgramFlags {
    WaterFlags water, waterInAir;
    // The water drawn in two passes (render/water_visibility.h): its
    // visibility pass, and its shading pass's programs.
    WaterVertexFlags waterVisibility;
    WaterFlags waterDeferred, waterDeferredInAir;
    WaterlineFlags waterline;
    WaterVertexFlags capture, probe;
    SkyFlags sky, skyInAir;
    UnderwaterHostFlags underwaterHost;
    MeshFlags mesh, meshInAir;
    BowSprayFlags bowSpray;
    // None: the scene draws no caustics (water.caustics = false).
    std::optional<CausticsFlags> caustics;
    // None: the wave model breaks no crests (WaveModelGpu::crestSpray).
    std::optional<CrestSprayFlags> spray;
    // FXAA, the host's picture's copy, the temporal resolve and the
    // gradient sky's bake read no flags.
    bool operator==(const ProgramFlags&) const = default;
};

// The flags a scene asks for, drawn with the wave model `model` (its GLSL
// file, and whether its crests break), the water shading terms left out
// (RendererOptions::omittedWaterTerms) and the surface sources' GLSL.
ProgramFlags programFlagsOf(const Scene& scene, const WaveModelGpu& model, unsigned omittedWaterTerms,
                            std::vector<std::string> surfaceSources);

struct Programs {
    WaterProgram water, waterInAir;
    WaterVisibilityProgram waterVisibility;
    WaterProgram waterDeferred, waterDeferredInAir;
    WaterTilesProgram waterTiles;
    WaterlineProgram waterline;
    WaterCaptureProgram capture;
    SurfaceProbeProgram probe;
    SkyProgram sky, skyInAir;
    // The host's geometry seen from under the water.
    UnderwaterHostProgram underwaterHost;
    MeshProgram mesh, meshInAir;
    FxaaProgram fxaa;
    HostCopyProgram hostCopy;
    SkyBakeProgram skyBake; // the gradient sky's
    // The caustics map's pass (render/caustics_map.h); empty when the
    // scene draws no caustics.
    CausticsPrograms caustics;
    // The spray from the breaking crests: empty for a wave model whose
    // crests do not break.
    SprayProgram spray;
    // The spray from the bows of hulls under way (any wave model: it needs
    // the wind alone).
    BowSprayProgram bowSpray;
    // The temporal resolve (fullscreen.vert + temporal_neighbourhood.frag,
    // then temporal_resolve.frag, and temporal_present.frag for an output
    // a blit does not suit; render/temporal_resolve.h).
    TemporalPrograms temporal;
    // What they were built for.
    ProgramFlags flags;
};

// The programs of `current` that flags `wanted` would build again (their
// flags differ, or they are not built yet), by member name: "water",
// "caustics", ... (what the rebuild below builds; tests name them).
std::vector<std::string_view> changedPrograms(const Programs& current, const ProgramFlags& wanted);

// Builds each program whose flags in `wanted` differ from those it has in
// `current` (all of them for an empty `current`), the surface sources'
// files written into `sources` first; the programs that did not change are
// left empty in the result, for keepUnchangedPrograms() to move across once
// everything that can fail has been built. Throws swell::InputError naming
// the shader file and line when a program fails to build, `current` left
// as it was.
Programs buildChangedPrograms(gl::ShaderSources& sources, const Programs& current, const ProgramFlags& wanted);

// Completes `next` (built by buildChangedPrograms from `current`) with the
// programs of `current` whose flags did not change. Cannot fail.
void keepUnchangedPrograms(Programs& next, Programs& current) noexcept;

// The label pass's programs (swell/dataset/labels.h): water, sky and meshes built
// with SWELL_LABEL_PASS 1, writing each pixel's range, normal, class and
// instance (shaders/labels.glsl) instead of a colour, for the flags of the
// colour programs. Built when labels are first asked for, not with every
// renderer.
struct LabelPrograms {
    WaterProgram water;
    SkyProgram sky;
    MeshProgram mesh;
};

// The host's motion vectors' programs (render/motion_vectors.h), built
// when a draw first asks for them, for the colour programs' flags.
struct MotionPrograms {
    WaterPreviousProgram waterPrevious;
    WaterMotionProgram water;
    SkyMotionProgram sky;
    MeshProgram mesh;
};

// Makes `motion` the motion vectors' programs for `flags`, building only
// those whose flags changed; `motion` as it was where one fails to build.
void updateMotionPrograms(const gl::ShaderSources& sources, std::optional<MotionPrograms>& motion,
                          const ProgramFlags& flags);

// Makes `labels` the label programs for `flags` (the colour programs'),
// building only those whose flags changed; `labels` as it was where one
// fails to build.
void updateLabelPrograms(const gl::ShaderSources& sources, std::optional<LabelPrograms>& labels,
                         const ProgramFlags& flags);

} // namespace swell::detail
