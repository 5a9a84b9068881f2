// The renderer's shader programs, one typed class each: uniform locations are
// looked up once, by name, when the program is built, and set through typed
// setters. Everything else a program reads comes from the Frame uniform block
// and the wave model's own bindings. Variants are #defines prepended from a
// ShaderVariant, never uniforms used as switches.
#pragma once

#include "render/temporal_resolve.h"
#include "swell/gl/shader.h"
#include "swell/scene.h"
#include "swell/gpu/spray.h"

#include <glm/mat3x3.hpp>
#include <glm/mat4x4.hpp>
#include <glm/vec2.hpp>
#include <glm/vec4.hpp>

#include <array>
#include <string>
#include <vector>

namespace swell::detail {

// What the programs are compiled for. Each field is one #define.
struct ShaderVariant {
    DebugView debugView = DebugView::Shaded;           // SWELL_DEBUG_VIEW
    ReflectionMode reflection = ReflectionMode::RayMarch; // SWELL_REFLECTION_MODE
    GridLayout gridLayout = GridLayout::Geometric;     // SWELL_GRID_LAYOUT
    std::string oceanFile = "ocean/gerstner.glsl";     // SWELL_OCEAN_FILE: the wave model's GLSL
    unsigned omittedWaterTerms = 0;                    // SWELL_OMITTED_TERMS: SWELL_TERM_* bits (benchmark)
    // SWELL_SURFACE_SOURCES: the GLSL of each surface source drawn (the bodies'
    // wake's first when the scene has one; render/surface_sources.h).
    std::vector<std::string> surfaceSources{};
    bool caustics = true;                              // SWELL_CAUSTICS: the caustics map drawn and read (water.caustics)
    bool shafts = true;                                // SWELL_SHAFTS: the sun's light scattered in the water column (water.shafts)
    // SWELL_CLOUD_SHADOWS: the sun's light shaded point by point by the
    // cloud layer's shadow map (physical sky with clouds; render/cloud_shadow_map.h)
    bool cloudShadows = false;
    bool operator==(const ShaderVariant&) const = default;
};

// The variant a scene asks for, with the wave model's GLSL file and the
// water shading terms left out (RendererOptions::omittedWaterTerms).
ShaderVariant shaderVariantOf(const Scene& scene, std::string oceanFile, unsigned omittedWaterTerms,
                              std::vector<std::string> surfaceSources);

// The #define lines (without "#define ") for a variant.
std::vector<std::string> definesOf(const ShaderVariant& variant);

// World geometry: mesh.vert + mesh.frag.
class MeshProgram {
public:
    MeshProgram() = default;
    // extraDefines: #define lines (without "#define ") added to the variant's.
    MeshProgram(const gl::ShaderSources& sources, const ShaderVariant& variant,
                const std::vector<std::string>& extraDefines = {});
    void use() const;
    // Object to render-origin-relative world transform, m.
    void setModel(const glm::mat4& model) const;
    // The label pass's program only (nothing elsewhere): the semantic class
    // and instance the next draws write (swell/labels.h).
    void setLabel(glm::uvec2 classAndInstance) const;

private:
    gl::Program program_;
    GLint model_ = -1;
    GLint label_ = -1; // the label pass's programs only
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
// the gradient sky, or with physical set (SWELL_SKY_PHYSICAL 1) the
// atmosphere (atmosphere.glsl).
class SkyBakeProgram {
public:
    SkyBakeProgram() = default;
    SkyBakeProgram(const gl::ShaderSources& sources, const ShaderVariant& variant, bool physical = false);
    explicit operator bool() const { return bool(program_); }
    void use() const;
    // 0..5: +x, -x, +y, -y, +z, -z.
    void setFace(int face) const;
    // The physical sky's only: SkySettings::exposure and the atmosphere's
    // densities (the ground's albedo is in the tables the C++ model builds).
    void setAtmosphere(double exposure, const AtmosphereSettings& atmosphere) const;
    // The physical sky's only: its cloud layer (shaders/clouds.glsl).
    void setClouds(const CloudSettings& clouds) const;

private:
    gl::Program program_;
    GLint face_ = -1;
    GLint exposure_ = -1, mieScale_ = -1, rayleighScale_ = -1;
    CloudUniforms clouds_;
};

// The cloud layer's shadow map's bake (fullscreen.vert +
// cloud_shadow_bake.frag; render/cloud_shadow_map.h): the layer's
// settings, where the map's texel (0, 0) lies and the sun.
class CloudShadowBakeProgram {
public:
    CloudShadowBakeProgram() = default;
    CloudShadowBakeProgram(const gl::ShaderSources& sources, const ShaderVariant& variant);
    explicit operator bool() const { return bool(program_); }
    void use() const;
    // corner_m: texel (0, 0)'s outer corner, absolute world x, z, m;
    // texel_m: a texel's width, m; sun: towards it, unit.
    void set(const CloudSettings& clouds, glm::vec2 corner_m, float texel_m, glm::vec3 sun) const;

private:
    gl::Program program_;
    CloudUniforms clouds_;
    GLint corner_ = -1, texel_ = -1, sun_ = -1;
};

// Programs with no uniforms of their own (all from the Frame block): the sky
// (fullscreen.vert + sky.frag), the water (water.vert + water.frag), the
// waterline mask (water.vert + waterline.frag), the FXAA filter
// (fullscreen.vert + fxaa.frag), the water's vertex capture for tests
// (water.vert with transform feedback) and the frame's water queries
// (surface_probe.comp, render/surface_probe.h).
class BlockProgram {
public:
    BlockProgram() = default;
    explicit BlockProgram(gl::Program program) : program_(std::move(program)) {}
    void use() const;
    explicit operator bool() const { return bool(program_); }

private:
    gl::Program program_;
};

// The caustics map's pass (render/caustics_map.h): the refracted source
// grid (caustics_sources.comp, the wave model's GLSL), the slices' triangles
// (caustics_images.comp), and their draw (caustics.vert, .frag).
struct CausticsPrograms {
    BlockProgram sources, images, splat;
    explicit operator bool() const { return bool(splat); }
};

// The spray's passes (render/spray_passes.cpp), for the crests' spray or
// the bows': every slot's clump (spray_clumps.comp), the list of the
// living (spray_list.comp), their streaks (spray_streaks.comp) and the
// draw of them (spray.vert, spray.frag).
class SprayPasses {
public:
    SprayPasses() = default;
    SprayPasses(const gl::ShaderSources& sources, const std::vector<std::string>& defines);
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
    SprayProgram() = default;
    SprayProgram(const gl::ShaderSources& sources, const ShaderVariant& variant);
    // time_s: the simulated time (the particles are a function of it alone);
    // firstCell: the world index of the lattice's first cell, its corner
    // relative to the render origin (m) and to the grid centre (m);
    // the wind's speed at 10 m (m/s); amount 0..1.
    void set(double time_s, glm::ivec2 firstCell, glm::vec2 corner_m, glm::vec2 cornerFromGridCentre_m,
             float windSpeed_mps, float amount) const;

private:
    GLint time_ = -1, firstCell_ = -1, corner_ = -1, cornerFromGrid_ = -1, wind_ = -1, amount_ = -1;
};

// The bow's spray (the spray's files built with SWELL_BOW_SPRAY): the
// hulls under way for the frame (objects/bow_spray.h, spray_clumps.comp's uniforms).
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
    BowSprayProgram() = default;
    BowSprayProgram(const gl::ShaderSources& sources, const ShaderVariant& variant);
    // time_s: the simulated time; the wind's direction (x, z, unit) and
    // speed at 10 m (m/s); the hulls.
    void set(double time_s, glm::vec2 windDirection, float windSpeed_mps, const BowSprayHulls& hulls) const;

private:
    GLint time_ = -1, windDirection_ = -1, wind_ = -1, hulls_ = -1, body_ = -1, motion_ = -1, across_ = -1,
          stations_ = -1, history_ = -1, lag_ = -1;
};

struct Programs {
    BlockProgram water, sky, waterline, fxaa, capture, probe;
    // The host's geometry seen from under the water (sky.vert + underwater_host.frag).
    BlockProgram underwaterHost;
    MeshProgram mesh;
    SkyBakeProgram skyBake;
    // water, sky and mesh again, built with SWELL_SEEN_FROM_BELOW 0 for the
    // passes in which no pixel looks out from below the water (the waterline
    // mask says "above" everywhere: the reflection and refraction passes, and
    // a main pass whose near plane lies wholly in the air). The underwater
    // shading is compiled out of them rather than branched over, since a
    // software rasteriser runs both sides of a branch for all the pixels it
    // shades together.
    BlockProgram waterInAir, skyInAir;
    MeshProgram meshInAir;
    // The caustics map's pass (render/caustics_map.h); empty when the
    // variant has no caustics.
    CausticsPrograms caustics;
    // The spray (spectral model only: the others have no breaking crests).
    SprayProgram spray;
    // The spray from the bows of hulls under way (any wave model: it needs
    // the wind alone).
    BowSprayProgram bowSpray;
    // The temporal resolve (fullscreen.vert + temporal_neighbourhood.frag,
    // then temporal_resolve.frag, and temporal_present.frag for an output
    // a blit does not suit; render/temporal_resolve.h).
    TemporalPrograms temporal;
};

// The caustics pass's programs for a variant.
CausticsPrograms buildCausticsPrograms(const gl::ShaderSources& sources, const ShaderVariant& variant);

// The label pass's programs (swell/labels.h): water, sky and meshes built
// with SWELL_LABEL_PASS 1, writing each pixel's range, normal, class and
// instance (shaders/labels.glsl) instead of a colour. Built when labels are
// first asked for, not with every renderer.
// The water's and the sky's: their ranges are measured along each pixel's
// ray in double precision (labels.glsl), which the pass sets.
class LabelProgram {
public:
    LabelProgram() = default;
    explicit LabelProgram(gl::Program program);
    void use() const;
    // Window pixel (relative to the viewport's corner, 1) to the pixel's ray
    // direction in world axes (not normalised).
    void setRayFromPixel(const glm::dmat3& rayFromPixel) const;

private:
    gl::Program program_;
    GLint rayFromPixel_ = -1;
};

struct LabelPrograms {
    LabelProgram water, sky;
    MeshProgram mesh;
};

LabelPrograms buildLabelPrograms(const gl::ShaderSources& sources, const ShaderVariant& variant);

// Compiles and links every program for a variant, its surface sources' files
// written into `sources` first. Throws swell::InputError naming the shader
// file and line when one fails.
Programs buildPrograms(gl::ShaderSources& sources, const ShaderVariant& variant);

} // namespace swell::detail
