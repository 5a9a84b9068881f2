// What each of the renderer's programs is compiled for: its own flags,
// holding only the #defines its shaders (through their includes) read
// (Magnum's PhongGL::Flag), so that a change rebuilds only the programs
// that read it: a debug view rebuilds the water and the meshes, never FXAA
// or the sky's bake. Every flag is one #define; the shaders that read one
// stop with #error where a program does not give it, so the flags below
// cannot forget a define a shader reads.
#pragma once

#include "swell/scene/scene.h"

#include <string>
#include <vector>

namespace swell::detail {

// What the water's vertex stage reads (water.vert: grid.glsl, ocean.glsl
// and the surface sources' generated code), in every program built from it.
struct SurfaceFlags {
    GridLayout gridLayout = GridLayout::Geometric; // SWELL_GRID_LAYOUT
    std::string oceanFile{}; // SWELL_OCEAN_FILE: the wave model's GLSL (WaveModelGpu::shaderFile)
    // SWELL_SURFACE_SOURCES: the GLSL of each surface source drawn (the
    // bodies' wake's first when the scene has one; render/surface_sources.h),
    // whose code the programs compile.
    std::vector<std::string> surfaceSources{};
    // SWELL_WATER_CACHES_VERTICES: water.vert keeps each vertex for the
    // water's shading pass (the visibility pass's; render/water_visibility.h).
    bool cachesVertices = false;
    bool operator==(const SurfaceFlags&) const = default;
    void addDefines(std::vector<std::string>& defines) const;
};

// What the light under the water reads (underwater.glsl and what it
// includes: light_shafts.glsl, caustics.glsl, cloud_shadow.glsl), in every
// program that shades a pixel that may look out from under the water.
struct UnderwaterFlags {
    bool caustics = true; // SWELL_CAUSTICS: the caustics map drawn and read (water.caustics)
    bool shafts = true;   // SWELL_SHAFTS: the sun's light scattered in the water column (water.shafts)
    // SWELL_CLOUD_SHADOWS: the sun's light shaded point by point by the
    // cloud layer's shadow map (physical sky with clouds; render/cloud_shadow_map.h).
    bool cloudShadows = false;
    // SWELL_SEEN_FROM_BELOW: false for the passes in which no pixel looks
    // out from below the water (the waterline mask says "above" everywhere:
    // the reflection and refraction passes, and a main pass whose near
    // plane lies wholly in the air). The underwater shading is compiled out
    // of them rather than branched over, since a software rasteriser runs
    // both sides of a branch for all the pixels it shades together.
    bool seenFromBelow = true;
    bool operator==(const UnderwaterFlags&) const = default;
    void addDefines(std::vector<std::string>& defines) const;
};

// A program whose shaders read no flag (FXAA, the temporal resolve, the
// cloud shadows' bake).
struct NoFlags {
    bool operator==(const NoFlags&) const = default;
    std::vector<std::string> defines() const { return {}; }
};

// The water (water.vert + water.frag).
struct WaterFlags {
    SurfaceFlags surface;
    UnderwaterFlags underwater;
    DebugView debugView = DebugView::Shaded;             // SWELL_DEBUG_VIEW
    ReflectionMode reflection = ReflectionMode::RayMarch; // SWELL_REFLECTION_MODE
    unsigned omittedTerms = 0; // SWELL_OMITTED_TERMS: SWELL_TERM_* bits (the benchmark's; RendererOptions)
    bool labelPass = false;    // SWELL_LABEL_PASS: writes labels (swell/dataset/labels.h), not a colour
    // SWELL_WATER_DEFERRED: the shading pass of the water drawn in two
    // (fullscreen.vert + water.frag reading the visibility pass's results;
    // render/water_visibility.h).
    bool deferred = false;
    bool operator==(const WaterFlags&) const = default;
    std::vector<std::string> defines() const;
};

// The waterline mask (water.vert + waterline.frag).
struct WaterlineFlags {
    SurfaceFlags surface;
    UnderwaterFlags underwater;
    bool operator==(const WaterlineFlags&) const = default;
    std::vector<std::string> defines() const;
};

// The water's vertices alone: their capture for tests (water.vert with
// transform feedback) and the frame's water queries (surface_probe.comp).
struct WaterVertexFlags {
    SurfaceFlags surface;
    bool operator==(const WaterVertexFlags&) const = default;
    std::vector<std::string> defines() const;
};

// The sky (sky.vert + sky.frag).
struct SkyFlags {
    UnderwaterFlags underwater;
    bool labelPass = false; // SWELL_LABEL_PASS
    bool operator==(const SkyFlags&) const = default;
    std::vector<std::string> defines() const;
};

// The host's geometry seen from under the water (sky.vert + underwater_host.frag).
struct UnderwaterHostFlags {
    UnderwaterFlags underwater;
    bool operator==(const UnderwaterHostFlags&) const = default;
    std::vector<std::string> defines() const;
};

// The world's meshes (mesh.vert + mesh.frag).
struct MeshFlags {
    UnderwaterFlags underwater;
    DebugView debugView = DebugView::Shaded; // SWELL_DEBUG_VIEW
    bool labelPass = false;                  // SWELL_LABEL_PASS
    // SWELL_MOTION_PASS: the host's motion vectors (mesh_motion.vert +
    // motion.frag, render/motion_vectors.h) in place of mesh.vert + mesh.frag.
    bool motionPass = false;
    bool operator==(const MeshFlags&) const = default;
    std::vector<std::string> defines() const;
};

// The caustics map's pass (built only when the scene draws caustics, so
// SWELL_CAUSTICS is 1 in it): its source grid reads the wave model.
struct CausticsFlags {
    std::string oceanFile{}; // SWELL_OCEAN_FILE
    bool operator==(const CausticsFlags&) const = default;
    std::vector<std::string> defines() const;
};

// The spray torn from the breaking crests: its clumps find the crests
// through the wave model's GLSL; its streaks are lit under the clouds' shadows.
struct CrestSprayFlags {
    std::string oceanFile{};   // SWELL_OCEAN_FILE
    bool cloudShadows = false; // SWELL_CLOUD_SHADOWS
    bool operator==(const CrestSprayFlags&) const = default;
    std::vector<std::string> defines() const;
};

// The spray from the bows of hulls under way (SWELL_BOW_SPRAY 1): it reads
// no wave model.
struct BowSprayFlags {
    bool cloudShadows = false; // SWELL_CLOUD_SHADOWS
    bool operator==(const BowSprayFlags&) const = default;
    std::vector<std::string> defines() const;
};

// One face of the procedural sky cubemap: the gradient sky, or the
// physical one (SWELL_SKY_PHYSICAL 1: the atmosphere and its clouds).
struct SkyBakeFlags {
    bool physical = false; // SWELL_SKY_PHYSICAL
    bool operator==(const SkyBakeFlags&) const = default;
    std::vector<std::string> defines() const;
};

// The SWELL_DEBUG_VIEW value of a debug view (swell/gpu/variants.h).
int debugViewDefine(DebugView view);

} // namespace swell::detail
