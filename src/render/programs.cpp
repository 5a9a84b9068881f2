// Building the renderer's programs for a variant, and their typed setters.
#include "render/programs.h"

#include "gl/uniform_location.h"
#include "render/sky_light.h"
#include "render/spray_kinematics.h"
#include "render/surface_sources.h"
#include "swell/gpu/variants.h"

#include "swell/error.h"

#include <fmt/format.h>
#include <cmath>
#include <glm/gtc/type_ptr.hpp>

namespace swell::detail {

namespace {

int debugViewDefine(DebugView v)
{
    switch (v) {
    case DebugView::Shaded: return SWELL_VIEW_SHADED;
    case DebugView::Normals: return SWELL_VIEW_NORMALS;
    case DebugView::Reflection: return SWELL_VIEW_REFLECTION;
    case DebugView::Refraction: return SWELL_VIEW_REFRACTION;
    case DebugView::Lod: return SWELL_VIEW_LOD;
    case DebugView::Wireframe: return SWELL_VIEW_WIREFRAME;
    case DebugView::Foam: return SWELL_VIEW_FOAM;
    }
    return SWELL_VIEW_SHADED;
}

using gl::requiredUniform;

gl::Program build(const gl::ShaderSources& sources, const ShaderVariant& variant, const char* vertex,
                  const char* fragment, const std::vector<std::string>& extraDefines = {})
{
    std::vector<gl::ShaderStage> stages{{GL_VERTEX_SHADER, vertex}};
    if (fragment)
        stages.push_back({GL_FRAGMENT_SHADER, fragment});
    std::vector<std::string> defines = definesOf(variant);
    defines.insert(defines.end(), extraDefines.begin(), extraDefines.end());
    return gl::buildProgram(sources, stages, defines);
}

// The programs for passes in which no pixel looks out from below the water.
const std::vector<std::string> kInAir{"SWELL_SEEN_FROM_BELOW 0"};

} // namespace

ShaderVariant shaderVariantOf(const Scene& scene, std::string oceanFile, unsigned omittedWaterTerms,
                              std::vector<std::string> surfaceSources)
{
    return {scene.debugView, scene.reflection.mode, scene.grid.layout, std::move(oceanFile), omittedWaterTerms,
            std::move(surfaceSources), scene.water.caustics, scene.water.shafts, cloudShadowsOn(scene)};
}

std::vector<std::string> definesOf(const ShaderVariant& v)
{
    return {
        fmt::format("SWELL_DEBUG_VIEW {}", debugViewDefine(v.debugView)),
        fmt::format("SWELL_REFLECTION_MODE {}",
                    v.reflection == ReflectionMode::FixedDistance ? "SWELL_REFLECTION_FIXED" : "SWELL_REFLECTION_RAYMARCH"),
        fmt::format("SWELL_GRID_LAYOUT {}", v.gridLayout == GridLayout::Paper ? "SWELL_GRID_PAPER" : "SWELL_GRID_GEOMETRIC"),
        fmt::format("SWELL_OCEAN_FILE \"{}\"", v.oceanFile),
        fmt::format("SWELL_OMITTED_TERMS {}", v.omittedWaterTerms),
        fmt::format("SWELL_SURFACE_SOURCES {}", v.surfaceSources.size()),
        fmt::format("SWELL_CAUSTICS {}", v.caustics ? 1 : 0),
        fmt::format("SWELL_SHAFTS {}", v.shafts ? 1 : 0),
        fmt::format("SWELL_CLOUD_SHADOWS {}", v.cloudShadows ? 1 : 0),
    };
}

MeshProgram::MeshProgram(const gl::ShaderSources& sources, const ShaderVariant& variant,
                         const std::vector<std::string>& extraDefines)
    : program_(build(sources, variant, "mesh.vert", "mesh.frag", extraDefines)),
      model_(requiredUniform(program_, "model", "mesh.vert")),
      label_(gl::optionalUniform(program_, "label"))
{
}

void MeshProgram::setLabel(glm::uvec2 classAndInstance) const
{
    if (label_ >= 0)
        glProgramUniform2ui(program_.id(), label_, classAndInstance.x, classAndInstance.y);
}

void MeshProgram::use() const { glUseProgram(program_.id()); }

void MeshProgram::setModel(const glm::mat4& model) const
{
    glProgramUniformMatrix4fv(program_.id(), model_, 1, GL_FALSE, glm::value_ptr(model));
}

CloudUniforms::CloudUniforms(const gl::Program& program)
    : cover_(requiredUniform(program, "cloudCover", "clouds.glsl")),
      altitude_(requiredUniform(program, "cloudAltitude_m", "clouds.glsl")),
      opticalDepth_(requiredUniform(program, "cloudOpticalDepth", "clouds.glsl")),
      scale_(requiredUniform(program, "cloudScale_m", "clouds.glsl"))
{
}

void CloudUniforms::set(const gl::Program& program, const CloudSettings& clouds) const
{
    glProgramUniform1f(program.id(), cover_, float(clouds.cover));
    glProgramUniform1f(program.id(), altitude_, float(clouds.altitude_m));
    glProgramUniform1f(program.id(), opticalDepth_, float(clouds.opticalDepth));
    glProgramUniform1f(program.id(), scale_, float(clouds.scale_m));
}

SkyBakeProgram::SkyBakeProgram(const gl::ShaderSources& sources, const ShaderVariant& variant, bool physical)
    : program_(build(sources, variant, "fullscreen.vert", "sky_bake.frag",
                     {physical ? "SWELL_SKY_PHYSICAL 1" : "SWELL_SKY_PHYSICAL 0"})),
      face_(requiredUniform(program_, "face", "sky_bake.frag"))
{
    if (physical) {
        exposure_ = requiredUniform(program_, "skyExposure", "sky_bake.frag");
        mieScale_ = requiredUniform(program_, "atmosphereMieScale", "atmosphere.glsl");
        rayleighScale_ = requiredUniform(program_, "atmosphereRayleighScale", "atmosphere.glsl");
        clouds_ = CloudUniforms(program_);
    }
}

void SkyBakeProgram::setClouds(const CloudSettings& clouds) const { clouds_.set(program_, clouds); }

void SkyBakeProgram::setAtmosphere(double exposure, const AtmosphereSettings& atmosphere) const
{
    glProgramUniform1f(program_.id(), exposure_, float(exposure));
    glProgramUniform1f(program_.id(), mieScale_, float(atmosphere.mieScale));
    glProgramUniform1f(program_.id(), rayleighScale_, float(atmosphere.rayleighScale));
}

CloudShadowBakeProgram::CloudShadowBakeProgram(const gl::ShaderSources& sources, const ShaderVariant& variant)
    : program_(build(sources, variant, "fullscreen.vert", "cloud_shadow_bake.frag")),
      clouds_(program_),
      corner_(requiredUniform(program_, "bakeCorner_m", "cloud_shadow_bake.frag")),
      texel_(requiredUniform(program_, "bakeTexel_m", "cloud_shadow_bake.frag")),
      sun_(requiredUniform(program_, "bakeSun", "cloud_shadow_bake.frag"))
{
}

void CloudShadowBakeProgram::use() const { glUseProgram(program_.id()); }

void CloudShadowBakeProgram::set(const CloudSettings& clouds, glm::vec2 corner_m, float texel_m, glm::vec3 sun) const
{
    clouds_.set(program_, clouds);
    glProgramUniform2f(program_.id(), corner_, corner_m.x, corner_m.y);
    glProgramUniform1f(program_.id(), texel_, texel_m);
    glProgramUniform3f(program_.id(), sun_, sun.x, sun.y, sun.z);
}

void SkyBakeProgram::use() const { glUseProgram(program_.id()); }

void SkyBakeProgram::setFace(int face) const { glProgramUniform1i(program_.id(), face_, face); }

SprayPasses::SprayPasses(const gl::ShaderSources& sources, const std::vector<std::string>& defines)
    : clumps_(gl::buildProgram(sources, {{GL_COMPUTE_SHADER, "spray_clumps.comp"}}, defines)),
      list_(gl::buildProgram(sources, {{GL_COMPUTE_SHADER, "spray_list.comp"}}, defines)),
      streaks_(gl::buildProgram(sources, {{GL_COMPUTE_SHADER, "spray_streaks.comp"}}, defines)),
      draw_(gl::buildProgram(sources, {{GL_VERTEX_SHADER, "spray.vert"}, {GL_FRAGMENT_SHADER, "spray.frag"}},
                             defines)),
      listSlots_(requiredUniform(list_, "sprayListSlots", "spray_list.comp"))
{
}

void SprayPasses::useClumps() const { glUseProgram(clumps_.id()); }

void SprayPasses::useList(int slots) const
{
    glProgramUniform1i(list_.id(), listSlots_, slots);
    glUseProgram(list_.id());
}

void SprayPasses::useStreaks() const { glUseProgram(streaks_.id()); }

void SprayPasses::useDraw() const { glUseProgram(draw_.id()); }

SprayProgram::SprayProgram(const gl::ShaderSources& sources, const ShaderVariant& variant)
    : SprayPasses(sources, definesOf(variant)),
      time_(requiredUniform(clumps(), "sprayTime_s", "spray_clumps.comp")),
      firstCell_(requiredUniform(clumps(), "sprayFirstCell", "spray_clumps.comp")),
      corner_(requiredUniform(clumps(), "sprayCorner_m", "spray_clumps.comp")),
      cornerFromGrid_(requiredUniform(clumps(), "sprayCornerFromGrid_m", "spray_clumps.comp")),
      wind_(requiredUniform(clumps(), "sprayWindSpeed_mps", "spray_clumps.comp")),
      amount_(requiredUniform(clumps(), "sprayAmount", "spray_clumps.comp"))
{
}

void SprayProgram::set(double time_s, glm::ivec2 firstCell, glm::vec2 corner_m, glm::vec2 cornerFromGridCentre_m,
                       float windSpeed_mps, float amount) const
{
    // The time within a period of 4096 lifetimes (render/spray_kinematics.h):
    // a float holds it to the microsecond where the absolute time (hours)
    // would not.
    const glm::vec2 t = sprayPeriodTime(time_s);
    const GLuint id = clumps().id();
    glProgramUniform2f(id, time_, t.x, t.y);
    glProgramUniform2i(id, firstCell_, firstCell.x, firstCell.y);
    glProgramUniform2f(id, corner_, corner_m.x, corner_m.y);
    glProgramUniform2f(id, cornerFromGrid_, cornerFromGridCentre_m.x, cornerFromGridCentre_m.y);
    glProgramUniform1f(id, wind_, windSpeed_mps);
    glProgramUniform1f(id, amount_, amount);
}

namespace {

std::vector<std::string> bowSprayDefines(const ShaderVariant& variant)
{
    std::vector<std::string> defines = definesOf(variant);
    defines.push_back("SWELL_BOW_SPRAY 1");
    return defines;
}

} // namespace

BowSprayProgram::BowSprayProgram(const gl::ShaderSources& sources, const ShaderVariant& variant)
    : SprayPasses(sources, bowSprayDefines(variant)),
      time_(requiredUniform(clumps(), "sprayTime_s", "spray_clumps.comp")),
      windDirection_(requiredUniform(clumps(), "bowWindDirection", "spray_clumps.comp")),
      wind_(requiredUniform(clumps(), "sprayWindSpeed_mps", "spray_clumps.comp")),
      hulls_(requiredUniform(clumps(), "bowHulls", "spray_clumps.comp")),
      body_(requiredUniform(clumps(), "bowBody", "spray_clumps.comp")),
      motion_(requiredUniform(clumps(), "bowMotion", "spray_clumps.comp")),
      across_(requiredUniform(clumps(), "bowAcross", "spray_clumps.comp")),
      stations_(requiredUniform(clumps(), "bowStations", "spray_clumps.comp")),
      history_(requiredUniform(clumps(), "bowHistory", "spray_clumps.comp")),
      lag_(requiredUniform(clumps(), "bowHistoryLag_s", "spray_clumps.comp"))
{
}

void BowSprayProgram::set(double time_s, glm::vec2 windDirection, float windSpeed_mps, const BowSprayHulls& h) const
{
    const GLuint id = clumps().id();
    const glm::vec2 t = sprayPeriodTime(time_s); // as the crest spray's (SprayProgram::set)
    glProgramUniform2f(id, time_, t.x, t.y);
    glProgramUniform2f(id, windDirection_, windDirection.x, windDirection.y);
    glProgramUniform1f(id, wind_, windSpeed_mps);
    glProgramUniform1i(id, hulls_, h.count);
    glProgramUniform1iv(id, body_, GLsizei(h.body.size()), h.body.data());
    glProgramUniform4fv(id, motion_, GLsizei(h.motion.size()), glm::value_ptr(h.motion[0]));
    glProgramUniform4fv(id, across_, GLsizei(h.across.size()), glm::value_ptr(h.across[0]));
    glProgramUniform2fv(id, stations_, GLsizei(h.stations.size()), glm::value_ptr(h.stations[0]));
    glProgramUniform4fv(id, history_, GLsizei(h.history.size()), glm::value_ptr(h.history[0]));
    glProgramUniform1f(id, lag_, h.historyLag_s);
}

void BlockProgram::use() const { glUseProgram(program_.id()); }

LabelProgram::LabelProgram(gl::Program program)
    : program_(std::move(program)), rayFromPixel_(gl::optionalUniform(program_, "labelRayFromPixel"))
{
}

void LabelProgram::use() const { glUseProgram(program_.id()); }

void LabelProgram::setRayFromPixel(const glm::dmat3& rayFromPixel) const
{
    glProgramUniformMatrix3dv(program_.id(), rayFromPixel_, 1, GL_FALSE, glm::value_ptr(rayFromPixel));
}

CausticsPrograms buildCausticsPrograms(const gl::ShaderSources& sources, const ShaderVariant& variant)
{
    const std::vector<std::string> defines = definesOf(variant);
    CausticsPrograms p;
    p.sources = BlockProgram(gl::buildProgram(sources, {{GL_COMPUTE_SHADER, "caustics_sources.comp"}}, defines));
    p.images = BlockProgram(gl::buildProgram(sources, {{GL_COMPUTE_SHADER, "caustics_images.comp"}}, defines));
    p.splat = BlockProgram(
        gl::buildProgram(sources, {{GL_VERTEX_SHADER, "caustics.vert"}, {GL_FRAGMENT_SHADER, "caustics.frag"}}, defines));
    return p;
}

LabelPrograms buildLabelPrograms(const gl::ShaderSources& sources, const ShaderVariant& variant)
{
    const std::vector<std::string> labels{"SWELL_LABEL_PASS 1"};
    LabelPrograms p;
    p.water = LabelProgram(build(sources, variant, "water.vert", "water.frag", labels));
    p.sky = LabelProgram(build(sources, variant, "sky.vert", "sky.frag", labels));
    p.mesh = MeshProgram(sources, variant, labels);
    return p;
}

Programs buildPrograms(gl::ShaderSources& sources, const ShaderVariant& variant)
{
    setSurfaceSourceFiles(sources, variant.surfaceSources);
    Programs p;
    p.water = BlockProgram(build(sources, variant, "water.vert", "water.frag"));
    p.sky = BlockProgram(build(sources, variant, "sky.vert", "sky.frag"));
    p.waterline = BlockProgram(build(sources, variant, "water.vert", "waterline.frag"));
    p.fxaa = BlockProgram(build(sources, variant, "fullscreen.vert", "fxaa.frag"));
    p.temporal = TemporalPrograms(build(sources, variant, "fullscreen.vert", "temporal_neighbourhood.frag"),
                                  build(sources, variant, "fullscreen.vert", "temporal_resolve.frag",
                                        {"SWELL_TEMPORAL_HALF_SIZE_OR_LESS 1"}),
                                  build(sources, variant, "fullscreen.vert", "temporal_resolve.frag"),
                                  build(sources, variant, "fullscreen.vert", "temporal_present.frag"));
    p.underwaterHost = BlockProgram(build(sources, variant, "sky.vert", "underwater_host.frag"));
    p.mesh = MeshProgram(sources, variant);
    p.waterInAir = BlockProgram(build(sources, variant, "water.vert", "water.frag", kInAir));
    p.skyInAir = BlockProgram(build(sources, variant, "sky.vert", "sky.frag", kInAir));
    p.meshInAir = MeshProgram(sources, variant, kInAir);
    p.skyBake = SkyBakeProgram(sources, variant);
    if (variant.caustics)
        p.caustics = buildCausticsPrograms(sources, variant);
    if (variant.oceanFile == "ocean/spectral.glsl")
        p.spray = SprayProgram(sources, variant);
    p.bowSpray = BowSprayProgram(sources, variant);
    p.capture = BlockProgram(gl::buildProgram(sources, {{GL_VERTEX_SHADER, "water.vert"}}, definesOf(variant),
                                              {"vRestPoint", "vPosition", "vNormal"}));
    p.probe = BlockProgram(gl::buildProgram(sources, {{GL_COMPUTE_SHADER, "surface_probe.comp"}}, definesOf(variant)));
    return p;
}

} // namespace swell::detail
