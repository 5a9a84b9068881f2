// Building the renderer's programs for their flags, and their typed setters.
#include "render/shader_programs.h"

#include "gl/uniform_location.h"
#include "render/spray_kinematics.h"
#include "swell/error.h"

#include <glm/gtc/type_ptr.hpp>

namespace swell::detail {

namespace {

using gl::requiredUniform;

// A vertex and (optional) fragment stage built with the flags' defines.
template <class F>
gl::Program build(const gl::ShaderSources& sources, const F& flags, const char* vertex, const char* fragment)
{
    std::vector<gl::ShaderStage> stages{{GL_VERTEX_SHADER, vertex}};
    if (fragment)
        stages.push_back({GL_FRAGMENT_SHADER, fragment});
    return gl::buildProgram(sources, stages, flags.defines());
}

gl::Program buildCompute(const gl::ShaderSources& sources, const char* file, const std::vector<std::string>& defines)
{
    return gl::buildProgram(sources, {{GL_COMPUTE_SHADER, file}}, defines);
}

} // namespace

LabelRays::LabelRays(const gl::Program& program, bool labelPass)
    : rayFromPixel_(labelPass ? requiredUniform(program, "labelRayFromPixel", "labels.glsl") : -1)
{
}

void LabelRays::set(const gl::Program& program, const glm::dmat3& rayFromPixel) const
{
    glProgramUniformMatrix3dv(program.id(), rayFromPixel_, 1, GL_FALSE, glm::value_ptr(rayFromPixel));
}

WaterProgram::WaterProgram(const gl::ShaderSources& sources, const Flags& flags)
    : FlaggedProgram(build(sources, flags, flags.deferred ? "water_tiles.vert" : "water.vert", "water.frag"), flags),
      rays_(program_, flags.labelPass)
{
}

WaterVisibilityProgram::WaterVisibilityProgram(const gl::ShaderSources& sources, const Flags& flags)
    : FlaggedProgram(build(sources, flags, "water.vert", "water_visibility.frag"), flags),
      firstTriangle_(requiredUniform(program_, "firstTriangle", "water_visibility.frag"))
{
    // The cache's array of vertices: its stride is one vertex's size.
    const GLuint variable =
        glGetProgramResourceIndex(program_.id(), GL_BUFFER_VARIABLE, "cachedWaterVertices[0].v[0]");
    const GLenum property = GL_TOP_LEVEL_ARRAY_STRIDE;
    GLint stride = 0;
    if (variable != GL_INVALID_INDEX)
        glGetProgramResourceiv(program_.id(), GL_BUFFER_VARIABLE, variable, 1, &property, 1, nullptr, &stride);
    if (stride <= 0)
        throw Error("water_visibility.frag: the vertex cache's stride could not be read from the program");
    cachedVertexBytes_ = std::size_t(stride);
}

WaterTilesProgram::WaterTilesProgram(const gl::ShaderSources& sources, const Flags& flags)
    : FlaggedProgram(buildCompute(sources, "water_tiles.comp", flags.defines()), flags)
{
}

void WaterVisibilityProgram::setFirstTriangle(std::uint32_t triangle) const
{
    glProgramUniform1ui(program_.id(), firstTriangle_, triangle);
}

SkyProgram::SkyProgram(const gl::ShaderSources& sources, const Flags& flags)
    : FlaggedProgram(build(sources, flags, "sky.vert", "sky.frag"), flags), rays_(program_, flags.labelPass)
{
}

WaterlineProgram::WaterlineProgram(const gl::ShaderSources& sources, const Flags& flags)
    : FlaggedProgram(build(sources, flags, "water.vert", "waterline.frag"), flags)
{
}

UnderwaterHostProgram::UnderwaterHostProgram(const gl::ShaderSources& sources, const Flags& flags)
    : FlaggedProgram(build(sources, flags, "sky.vert", "underwater_host.frag"), flags)
{
}

WaterCaptureProgram::WaterCaptureProgram(const gl::ShaderSources& sources, const Flags& flags)
    : FlaggedProgram(gl::buildProgram(sources, {{GL_VERTEX_SHADER, "water.vert"}}, flags.defines(),
                                      {"vRestPoint", "vPosition", "vNormal"}),
                     flags)
{
}

SurfaceProbeProgram::SurfaceProbeProgram(const gl::ShaderSources& sources, const Flags& flags)
    : FlaggedProgram(buildCompute(sources, "surface_probe.comp", flags.defines()), flags)
{
}

FxaaProgram::FxaaProgram(const gl::ShaderSources& sources, const Flags& flags)
    : FlaggedProgram(build(sources, flags, "fullscreen.vert", "fxaa.frag"), flags)
{
}

HostCopyProgram::HostCopyProgram(const gl::ShaderSources& sources, const Flags& flags)
    : FlaggedProgram(build(sources, flags, "fullscreen.vert", "host_copy.frag"), flags),
      viewport_(requiredUniform(program_, "copyViewport", "host_copy.frag"))
{
}

void HostCopyProgram::setViewport(glm::ivec4 viewport) const
{
    glProgramUniform4f(program_.id(), viewport_, float(viewport.x), float(viewport.y), 1.0f / float(viewport.z),
                       1.0f / float(viewport.w));
}

MotionReprojection::MotionReprojection(const gl::Program& program, bool motionPass)
    : previousViewProj_(motionPass ? requiredUniform(program, "motionPreviousViewProj", "motion.glsl") : -1),
      weight_(motionPass ? requiredUniform(program, "motionWeight", "motion.glsl") : -1)
{
}

void MotionReprojection::set(const gl::Program& program, const glm::mat4& previousViewProj, bool moves) const
{
    glProgramUniformMatrix4fv(program.id(), previousViewProj_, 1, GL_FALSE, glm::value_ptr(previousViewProj));
    glProgramUniform1f(program.id(), weight_, moves ? 1.0f : 0.0f);
}

MeshProgram::MeshProgram(const gl::ShaderSources& sources, const Flags& flags)
    : FlaggedProgram(build(sources, flags, flags.motionPass ? "mesh_motion.vert" : "mesh.vert",
                           flags.motionPass ? "motion.frag" : "mesh.frag"),
                     flags),
      model_(requiredUniform(program_, "model", flags.motionPass ? "mesh_motion.vert" : "mesh.vert")),
      label_(flags.labelPass ? requiredUniform(program_, "label", "mesh.frag") : -1),
      // Left out of the variants that do not shade (the label pass, debug views).
      swashWets_(glGetUniformLocation(program_.id(), "swashWets")),
      previousModel_(flags.motionPass ? requiredUniform(program_, "previousModel", "mesh_motion.vert") : -1),
      motion_(program_, flags.motionPass)
{
}

void MeshProgram::setPreviousModel(const glm::mat4& model) const
{
    if (previousModel_ >= 0)
        glProgramUniformMatrix4fv(program_.id(), previousModel_, 1, GL_FALSE, glm::value_ptr(model));
}

WaterMotionProgram::WaterMotionProgram(const gl::ShaderSources& sources, const Flags& flags)
    : FlaggedProgram(build(sources, flags, "water_motion.vert", "motion.frag"), flags), motion_(program_, true)
{
}

WaterPreviousProgram::WaterPreviousProgram(const gl::ShaderSources& sources, const Flags& flags)
    : FlaggedProgram(build(sources, flags, "water_previous.vert", nullptr), flags)
{
}

SkyMotionProgram::SkyMotionProgram(const gl::ShaderSources& sources, const Flags& flags)
    : FlaggedProgram(build(sources, flags, "sky.vert", "sky_motion.frag"), flags), motion_(program_, true),
      readsHostDepth_(requiredUniform(program_, "motionSkyReadsHostDepth", "sky_motion.frag"))
{
}

void MeshProgram::setSwashWets(bool wets) const
{
    if (swashWets_ >= 0)
        glProgramUniform1f(program_.id(), swashWets_, wets ? 1.0f : 0.0f);
}

void MeshProgram::setLabel(glm::uvec2 classAndInstance) const
{
    if (label_ >= 0)
        glProgramUniform2ui(program_.id(), label_, classAndInstance.x, classAndInstance.y);
}

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

SkyBakeProgram::SkyBakeProgram(const gl::ShaderSources& sources, const Flags& flags)
    : FlaggedProgram(build(sources, flags, "fullscreen.vert", "sky_bake.frag"), flags),
      face_(requiredUniform(program_, "face", "sky_bake.frag"))
{
    if (flags.physical) {
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

void SkyBakeProgram::setFace(int face) const { glProgramUniform1i(program_.id(), face_, face); }

CloudShadowBakeProgram::CloudShadowBakeProgram(const gl::ShaderSources& sources, const Flags& flags)
    : FlaggedProgram(build(sources, flags, "fullscreen.vert", "cloud_shadow_bake.frag"), flags), clouds_(program_),
      corner_(requiredUniform(program_, "bakeCorner_m", "cloud_shadow_bake.frag")),
      texel_(requiredUniform(program_, "bakeTexel_m", "cloud_shadow_bake.frag")),
      sun_(requiredUniform(program_, "bakeSun", "cloud_shadow_bake.frag"))
{
}

void CloudShadowBakeProgram::set(const CloudSettings& clouds, glm::vec2 corner_m, float texel_m, glm::vec3 sun) const
{
    clouds_.set(program_, clouds);
    glProgramUniform2f(program_.id(), corner_, corner_m.x, corner_m.y);
    glProgramUniform1f(program_.id(), texel_, texel_m);
    glProgramUniform3f(program_.id(), sun_, sun.x, sun.y, sun.z);
}

CausticsPrograms::CausticsPrograms(const gl::ShaderSources& shaderSources, const Flags& flags)
    : sources(buildCompute(shaderSources, "caustics_sources.comp", flags.defines())),
      images(buildCompute(shaderSources, "caustics_images.comp", flags.defines())),
      splat(build(shaderSources, flags, "caustics.vert", "caustics.frag")), builtFor(flags)
{
}

SprayPasses::SprayPasses(const gl::ShaderSources& sources, const char* clumps, const std::vector<std::string>& defines)
    : clumps_(buildCompute(sources, clumps, defines)),
      list_(buildCompute(sources, "spray_list.comp", defines)),
      streaks_(buildCompute(sources, "spray_streaks.comp", defines)),
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

SprayProgram::SprayProgram(const gl::ShaderSources& sources, const Flags& flags)
    : SprayPasses(sources, "spray_clumps.comp", flags.defines()), flags_(flags),
      time_(requiredUniform(clumps(), "sprayTime_s", "spray_clumps_pass.glsl")),
      firstCell_(requiredUniform(clumps(), "sprayFirstCell", "spray_clumps_pass.glsl")),
      corner_(requiredUniform(clumps(), "sprayCorner_m", "spray_clumps_pass.glsl")),
      cornerFromGrid_(requiredUniform(clumps(), "sprayCornerFromGrid_m", "spray_clumps_pass.glsl")),
      wind_(requiredUniform(clumps(), "sprayWindSpeed_mps", "spray_clumps_pass.glsl")),
      amount_(requiredUniform(clumps(), "sprayAmount", "spray_clumps_pass.glsl"))
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

BowSprayProgram::BowSprayProgram(const gl::ShaderSources& sources, const Flags& flags)
    : SprayPasses(sources, "bow_spray_clumps.comp", flags.defines()), flags_(flags),
      time_(requiredUniform(clumps(), "sprayTime_s", "spray_clumps_pass.glsl")),
      windDirection_(requiredUniform(clumps(), "bowWindDirection", "bow_spray_clumps.comp")),
      wind_(requiredUniform(clumps(), "sprayWindSpeed_mps", "spray_clumps_pass.glsl")),
      hulls_(requiredUniform(clumps(), "bowHulls", "bow_spray_clumps.comp")),
      body_(requiredUniform(clumps(), "bowBody", "bow_spray_clumps.comp")),
      motion_(requiredUniform(clumps(), "bowMotion", "bow_spray_clumps.comp")),
      across_(requiredUniform(clumps(), "bowAcross", "bow_spray_clumps.comp")),
      stations_(requiredUniform(clumps(), "bowStations", "bow_spray_clumps.comp")),
      history_(requiredUniform(clumps(), "bowHistory", "bow_spray_clumps.comp")),
      lag_(requiredUniform(clumps(), "bowHistoryLag_s", "bow_spray_clumps.comp"))
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

} // namespace swell::detail
