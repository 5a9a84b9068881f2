// The renderer's shader programs, one typed class each, built for flags of
// their own (render/program_flags.h): uniform locations are looked up once,
// by name, when the program is built (gl/uniform_location.h), and set
// through typed setters. Everything else a program reads comes from the
// Frame uniform block and the wave model's own bindings. Variants are
// #defines prepended from the flags, never uniforms used as switches.
#pragma once

#include "render/program_flags.h"
#include "swell/gl/shader.h"
#include "swell/gpu/spray.h"
#include "swell/scene/scene.h"

#include <glm/mat3x3.hpp>
#include <glm/mat4x4.hpp>
#include <glm/vec2.hpp>
#include <glm/vec4.hpp>

#include <array>
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace swell::detail {

// A program built for flags F, and the flags it was built for; empty until
// built.
template <class F>
class FlaggedProgram {
public:
    using Flags = F;
    explicit operator bool() const { return bool(program_); }
    const Flags& flags() const { return flags_; }
    const gl::Program& program() const { return program_; }
    void use() const { glUseProgram(program_.id()); }

protected:
    FlaggedProgram() = default;
    FlaggedProgram(gl::Program program, const Flags& flags) : program_(std::move(program)), flags_(flags) {}
    gl::Program program_;
    Flags flags_{};
};

// The label pass's programs of the water and the sky measure each pixel's
// range along its ray in double precision (shaders/labels.glsl), which the
// pass sets.
class LabelRays {
public:
    LabelRays() = default;
    LabelRays(const gl::Program& program, bool labelPass);
    // Window pixel (relative to the viewport's corner, 1) to the pixel's ray
    // direction in world axes (not normalised). The label pass's programs only.
    void set(const gl::Program& program, const glm::dmat3& rayFromPixel) const;

private:
    GLint rayFromPixel_ = -1;
};

// The water (water.vert + water.frag), its label pass's, and the shading
// pass of the water drawn in two (fullscreen.vert + water.frag; flags.deferred).
class WaterProgram : public FlaggedProgram<WaterFlags> {
public:
    WaterProgram() = default;
    WaterProgram(const gl::ShaderSources& sources, const Flags& flags);
    void setRayFromPixel(const glm::dmat3& rayFromPixel) const { rays_.set(program_, rayFromPixel); }

private:
    LabelRays rays_;
};

// The water's visibility pass (water.vert keeping its vertices +
// water_visibility.frag; render/water_visibility.h).
class WaterVisibilityProgram : public FlaggedProgram<WaterVertexFlags> {
public:
    WaterVisibilityProgram() = default;
    WaterVisibilityProgram(const gl::ShaderSources& sources, const Flags& flags);
    // The first triangle of the range drawn next (WaterGrid::drawRanges).
    void setFirstTriangle(std::uint32_t triangle) const;
    // The bytes a vertex takes in the vertex cache (water_vertex_cache.glsl).
    std::size_t cachedVertexBytes() const { return cachedVertexBytes_; }

private:
    GLint firstTriangle_ = -1;
    std::size_t cachedVertexBytes_ = 0;
};

// The list of the screen tiles that show water (water_tiles.comp).
class WaterTilesProgram : public FlaggedProgram<NoFlags> {
public:
    WaterTilesProgram() = default;
    WaterTilesProgram(const gl::ShaderSources& sources, const Flags& flags);
};

// The sky (sky.vert + sky.frag), and its label pass's.
class SkyProgram : public FlaggedProgram<SkyFlags> {
public:
    SkyProgram() = default;
    SkyProgram(const gl::ShaderSources& sources, const Flags& flags);
    void setRayFromPixel(const glm::dmat3& rayFromPixel) const { rays_.set(program_, rayFromPixel); }

private:
    LabelRays rays_;
};

// Programs with no uniforms of their own (all from the Frame block): the
// waterline mask (water.vert + waterline.frag), the host's geometry under
// the water (sky.vert + underwater_host.frag), the water's vertex capture
// for tests (water.vert with transform feedback), the frame's water queries
// (surface_probe.comp, render/surface_probe.h) and the FXAA filter
// (fullscreen.vert + fxaa.frag).
class WaterlineProgram : public FlaggedProgram<WaterlineFlags> {
public:
    WaterlineProgram() = default;
    WaterlineProgram(const gl::ShaderSources& sources, const Flags& flags);
};

class UnderwaterHostProgram : public FlaggedProgram<UnderwaterHostFlags> {
public:
    UnderwaterHostProgram() = default;
    UnderwaterHostProgram(const gl::ShaderSources& sources, const Flags& flags);
};

class WaterCaptureProgram : public FlaggedProgram<WaterVertexFlags> {
public:
    WaterCaptureProgram() = default;
    WaterCaptureProgram(const gl::ShaderSources& sources, const Flags& flags);
};

class SurfaceProbeProgram : public FlaggedProgram<WaterVertexFlags> {
public:
    SurfaceProbeProgram() = default;
    SurfaceProbeProgram(const gl::ShaderSources& sources, const Flags& flags);
};

class FxaaProgram : public FlaggedProgram<NoFlags> {
public:
    FxaaProgram() = default;
    FxaaProgram(const gl::ShaderSources& sources, const Flags& flags);
};

// draw()'s picture moved between the host's framebuffer and a view's own
// target (fullscreen.vert + host_copy.frag; render/view_passes.h).
class HostCopyProgram : public FlaggedProgram<NoFlags> {
public:
    HostCopyProgram() = default;
    HostCopyProgram(const gl::ShaderSources& sources, const Flags& flags);
    // The viewport drawn (its lower-left corner and size, pixels).
    void setViewport(glm::ivec4 viewport) const;

private:
    GLint viewport_ = -1;
};

// The host's motion vectors' programs (render/motion_vectors.h) all take
// the previous draw's view and projection (shaders/motion.glsl).
class MotionReprojection {
public:
    MotionReprojection() = default;
    MotionReprojection(const gl::Program& program, bool motionPass);
    // Positions relative to this draw's render origin to the previous
    // draw's clip space; `moves` false: no previous draw, every vector 0.
    void set(const gl::Program& program, const glm::mat4& previousViewProj, bool moves) const;

private:
    GLint previousViewProj_ = -1, weight_ = -1;
};

// World geometry: mesh.vert + mesh.frag; the host's motion vectors'
// (flags.motionPass): mesh_motion.vert + motion.frag.
class MeshProgram : public FlaggedProgram<MeshFlags> {
public:
    MeshProgram() = default;
    MeshProgram(const gl::ShaderSources& sources, const Flags& flags);
    // Object to render-origin-relative world transform, m.
    void setModel(const glm::mat4& model) const;
    // The motion vectors' program only (nothing elsewhere): the same
    // object's transform at the previous draw, to this draw's render origin.
    void setPreviousModel(const glm::mat4& model) const;
    void setPreviousViewProj(const glm::mat4& previousViewProj, bool moves) const
    {
        motion_.set(program_, previousViewProj, moves);
    }
    // The label pass's program only (nothing elsewhere): the semantic class
    // and instance the next draws write (swell/dataset/labels.h).
    void setLabel(glm::uvec2 classAndInstance) const;
    // Whether the next draws are ground the sea runs up (the island, the
    // seabed), whose sand the swash wets (shaders/swash.glsl), or objects.
    void setSwashWets(bool wets) const;

private:
    GLint model_ = -1;
    GLint label_ = -1; // the label pass's program only
    GLint swashWets_ = -1; // the shading variants only
    GLint previousModel_ = -1; // the motion vectors' program only
    MotionReprojection motion_;
};

// The host's motion vectors on the water: water_motion.vert + motion.frag
// (reading the previous vertices), and water_previous.vert alone (writing them).
class WaterMotionProgram : public FlaggedProgram<WaterVertexFlags> {
public:
    WaterMotionProgram() = default;
    WaterMotionProgram(const gl::ShaderSources& sources, const Flags& flags);
    void setPreviousViewProj(const glm::mat4& previousViewProj, bool moves) const
    {
        motion_.set(program_, previousViewProj, moves);
    }

private:
    MotionReprojection motion_;
};

class WaterPreviousProgram : public FlaggedProgram<WaterVertexFlags> {
public:
    WaterPreviousProgram() = default;
    WaterPreviousProgram(const gl::ShaderSources& sources, const Flags& flags);
};

// ... and on Swell's sky: sky.vert + sky_motion.frag.
class SkyMotionProgram : public FlaggedProgram<NoFlags> {
public:
    SkyMotionProgram() = default;
    SkyMotionProgram(const gl::ShaderSources& sources, const Flags& flags);
    // Whether it tests the host's depth copy (SWELL_UNIT_HOST_DEPTH) for
    // the host's geometry rather than the depth test for the far plane.
    void setReadsHostDepth(bool reads) const { glProgramUniform1i(program_.id(), readsHostDepth_, reads ? 1 : 0); }
    void setPreviousViewProj(const glm::mat4& previousViewProj, bool moves) const
    {
        motion_.set(program_, previousViewProj, moves);
    }

private:
    MotionReprojection motion_;
    GLint readsHostDepth_ = -1;
};

// The cloud layer's uniforms (shaders/clouds.glsl) in a program that
// includes it: found once, set from the scene's CloudSettings.
class CloudUniforms {
public:
    CloudUniforms() = default;
    explicit CloudUniforms(const gl::Program& program);
    void set(const gl::Program& program, const CloudSettings& clouds) const;

private:
    GLint cover_ = -1, altitude_ = -1, opticalDepth_ = -1, scale_ = -1;
};

// One face of the procedural sky cubemap: fullscreen.vert + sky_bake.frag,
// the gradient sky, or the physical one (the atmosphere, atmosphere.glsl).
class SkyBakeProgram : public FlaggedProgram<SkyBakeFlags> {
public:
    SkyBakeProgram() = default;
    SkyBakeProgram(const gl::ShaderSources& sources, const Flags& flags);
    SkyBakeProgram(const gl::ShaderSources& sources, bool physical) : SkyBakeProgram(sources, Flags{physical}) {}
    // 0..5: +x, -x, +y, -y, +z, -z.
    void setFace(int face) const;
    // The physical sky's only: SkySettings::exposure and the atmosphere's
    // densities (the ground's albedo is in the tables the C++ model builds).
    void setAtmosphere(double exposure, const AtmosphereSettings& atmosphere) const;
    // The physical sky's only: its cloud layer (shaders/clouds.glsl).
    void setClouds(const CloudSettings& clouds) const;

private:
    GLint face_ = -1;
    GLint exposure_ = -1, mieScale_ = -1, rayleighScale_ = -1;
    CloudUniforms clouds_;
};

// The cloud layer's shadow map's bake (fullscreen.vert +
// cloud_shadow_bake.frag; render/cloud_shadow_map.h): the layer's
// settings, where the map's texel (0, 0) lies and the sun.
class CloudShadowBakeProgram : public FlaggedProgram<NoFlags> {
public:
    CloudShadowBakeProgram() = default;
    explicit CloudShadowBakeProgram(const gl::ShaderSources& sources, const Flags& flags = {});
    // corner_m: texel (0, 0)'s outer corner, absolute world x, z, m;
    // texel_m: a texel's width, m; sun: towards it, unit.
    void set(const CloudSettings& clouds, glm::vec2 corner_m, float texel_m, glm::vec3 sun) const;

private:
    CloudUniforms clouds_;
    GLint corner_ = -1, texel_ = -1, sun_ = -1;
};

// A program of several (the caustics pass's, the spray's) whose own
// uniforms, if any, its owner finds.
class BlockProgram {
public:
    BlockProgram() = default;
    explicit BlockProgram(gl::Program program) : program_(std::move(program)) {}
    void use() const { glUseProgram(program_.id()); }
    explicit operator bool() const { return bool(program_); }

private:
    gl::Program program_;
};

// The caustics map's pass (render/caustics_map.h): the refracted source
// grid (caustics_sources.comp, the wave model's GLSL), the slices' triangles
// (caustics_images.comp), and their draw (caustics.vert, .frag).
struct CausticsPrograms {
    using Flags = CausticsFlags;
    CausticsPrograms() = default;
    CausticsPrograms(const gl::ShaderSources& sources, const Flags& flags);
    BlockProgram sources, images, splat;
    Flags builtFor{};
    explicit operator bool() const { return bool(splat); }
    const Flags& flags() const { return builtFor; }
};

// The spray's passes (render/spray_passes.cpp), for the crests' spray or
// the bows': every slot's clump (`clumps`: spray_clumps.comp or
// bow_spray_clumps.comp), the list of the living (spray_list.comp), their
// streaks (spray_streaks.comp) and the draw of them (spray.vert, spray.frag).
class SprayPasses {
public:
    SprayPasses() = default;
    SprayPasses(const gl::ShaderSources& sources, const char* clumps, const std::vector<std::string>& defines);
    explicit operator bool() const { return bool(clumps_); }
    const gl::Program& clumps() const { return clumps_; }
    void useClumps() const;
    // slots: the records spray_clumps.comp wrote.
    void useList(int slots) const;
    void useStreaks() const;
    void useDraw() const;

private:
    gl::Program clumps_, list_, streaks_, draw_;
    GLint listSlots_ = -1;
};

// The crests' spray: its clumps' own uniforms are the simulated time, the
// wind and the lattice's place.
class SprayProgram : public SprayPasses {
public:
    using Flags = CrestSprayFlags;
    SprayProgram() = default;
    SprayProgram(const gl::ShaderSources& sources, const Flags& flags);
    const Flags& flags() const { return flags_; }
    // time_s: the simulated time (the particles are a function of it alone);
    // firstCell: the world index of the lattice's first cell, its corner
    // relative to the render origin (m) and to the grid centre (m);
    // the wind's speed at 10 m (m/s); amount 0..1.
    void set(double time_s, glm::ivec2 firstCell, glm::vec2 corner_m, glm::vec2 cornerFromGridCentre_m,
             float windSpeed_mps, float amount) const;

private:
    Flags flags_{};
    GLint time_ = -1, firstCell_ = -1, corner_ = -1, cornerFromGrid_ = -1, wind_ = -1, amount_ = -1;
};

// The bow's spray (the spray's files built with SWELL_BOW_SPRAY): the
// hulls under way for the frame (objects/bow_spray.h, bow_spray_clumps.comp's uniforms).
struct BowSprayHulls {
    int count = 0;
    std::array<int, SWELL_BOW_SPRAY_HULLS> body{};        // object indices
    std::array<glm::vec4, SWELL_BOW_SPRAY_HULLS> motion{}; // velocity (x, z), m/s; heading (x, z)
    std::array<glm::vec4, SWELL_BOW_SPRAY_HULLS> across{}; // towards the first side (x, z); speed, m/s; the flare's cotangent
    std::array<glm::vec2, SWELL_BOW_SPRAY_HULLS * 2 * SWELL_BOW_SPRAY_STATIONS> stations{}; // relative to the render origin, m
    std::array<glm::vec4, SWELL_BOW_SPRAY_HULLS * SWELL_BOW_SPRAY_HISTORY> history{};     // share, plunge m/s, the sheet's height m
    float historyLag_s = 0.0f;
};

class BowSprayProgram : public SprayPasses {
public:
    using Flags = BowSprayFlags;
    BowSprayProgram() = default;
    BowSprayProgram(const gl::ShaderSources& sources, const Flags& flags);
    const Flags& flags() const { return flags_; }
    // time_s: the simulated time; the wind's direction (x, z, unit) and
    // speed at 10 m (m/s); the hulls.
    void set(double time_s, glm::vec2 windDirection, float windSpeed_mps, const BowSprayHulls& hulls) const;

private:
    Flags flags_{};
    GLint time_ = -1, windDirection_ = -1, wind_ = -1, hulls_ = -1, body_ = -1, motion_ = -1, across_ = -1,
          stations_ = -1, history_ = -1, lag_ = -1;
};

} // namespace swell::detail
