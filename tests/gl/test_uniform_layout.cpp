// The C++ mirrors of the std140 blocks must match what the driver lays out.
#include "ocean/gerstner/gpu/gerstner_uniforms.h"
#include "render/caustics_map.h"
#include "render/cloud_shadow_map.h"
#include "render/gpu_types.h"
#include "render/surface_sources.h"
#include "render/wake_texture.h"
#include "objects/wake_surface.h"
#include "support/gl_test.h"
#include "swell/gl/shader.h"

#include <cstddef>
#include <string>

namespace {

class UniformLayout : public swell::test::GlTest {};

GLint offsetOf(GLuint program, const std::string& name)
{
    const GLuint index = glGetProgramResourceIndex(program, GL_UNIFORM, name.c_str());
    if (index == GL_INVALID_INDEX)
        return -1;
    const GLenum property = GL_OFFSET;
    GLint offset = -1;
    glGetProgramResourceiv(program, GL_UNIFORM, index, 1, &property, 1, nullptr, &offset);
    return offset;
}

GLint blockSize(GLuint program, const char* block)
{
    const GLuint index = glGetProgramResourceIndex(program, GL_UNIFORM_BLOCK, block);
    const GLenum property = GL_BUFFER_DATA_SIZE;
    GLint size = -1;
    glGetProgramResourceiv(program, GL_UNIFORM_BLOCK, index, 1, &property, 1, nullptr, &size);
    return size;
}

// A vertex shader that uses every field, so none is optimised out.
const char* kProbe = R"(#include "frame.glsl"
#include "ocean.glsl"
void main() {
    vec4 s = passViewProj[0] + passInvViewProj[0] + cameraViewProj[0] + cameraInvViewProj[0] + clipPlane
           + vec4(eyePosition, fresnelF0) + vec4(sunDirection, sunIntensity) + vec4(sunColor, fogSkyLayer_m)
           + vec4(fogColor, fogStart_m) + vec4(skyZenith, fogEnd_m) + vec4(skyHorizon, shininess)
           + vec4(waterDeep, specularStrength) + vec4(waterAbsorption, refractionDistortion)
           + vec4(gridCenter, gridRadius_m, gridCells) + vec4(gridSkirt_m, gridFinestStep_m, gridFadeStart_m, gridFadeEnd_m)
           + vec4(gridInnerScale_m, gridGrowth, reflectionFixedDistance_m, float(worldBoxCount))
           + vec4(viewportSize, viewportInvSize) + vec4(float(passEncodesSrgb), waveHeightDeviation_m, waveMeanSquareSlope, 0.0)
           + vec4(gridLevels[gl_VertexID].snapOffset_m, gridLevels[gl_VertexID].firstRing, gridMorph)
           + vec4(gridLevels[gl_VertexID].coarseSnapOffset_m, gridCoarseCenterShift)
           + vec4(gridLevels[gl_VertexID].coarseFirstRing, gridCoarseGrowth, waveReachVertical_m, float(eyeUnderwater))
           + vec4(viewportOrigin, depthNdcScale, depthNdcOffset) + vec4(depthFar, nearNdcZ, farNdcZ, projectionFocalY)
           + vec4(footprintScale, float(passMarksWater), 0.0, 0.0)
           + vec4(worldBoxes[gl_VertexID].min_m, 0.0) + vec4(worldBoxes[gl_VertexID].max_m, 0.0)
           + ambientSh[gl_VertexID] + vec4(fogExtinction_per_m, float(fogFromSky))
           + waveShape[gl_VertexID] + wavePhase[gl_VertexID] + vec4(waveCount);
    gl_Position = s;
}
)";

TEST_F(UniformLayout, FrameAndGerstnerBlocksMatchTheirCppMirrors)
{
    auto files = std::map<std::string, std::string>();
    const swell::gl::ShaderSources embedded = swell::gl::ShaderSources::embedded();
    for (const char* f : {"frame.glsl", "ocean.glsl", "ocean/gerstner.glsl", "swell/shader_constants.h"})
        files[f] = embedded.file(f);
    files["probe.vert"] = kProbe;
    files["probe.frag"] = "out vec4 c; void main() { c = vec4(1.0); }\n";
    swell::gl::Program p = swell::gl::buildProgram(swell::gl::ShaderSources::fromMap(files),
                                                   {{GL_VERTEX_SHADER, "probe.vert"}, {GL_FRAGMENT_SHADER, "probe.frag"}},
                                                   {"SWELL_OCEAN_FILE \"ocean/gerstner.glsl\""});
    using F = swell::detail::FrameUniforms;
    using W = swell::detail::GerstnerUniforms;
#define SWELL_EXPECT_OFFSET(T, field) EXPECT_EQ(offsetOf(p.id(), #field), GLint(offsetof(T, field))) << #field
    SWELL_EXPECT_OFFSET(F, passViewProj);
    SWELL_EXPECT_OFFSET(F, passInvViewProj);
    SWELL_EXPECT_OFFSET(F, cameraViewProj);
    SWELL_EXPECT_OFFSET(F, cameraInvViewProj);
    SWELL_EXPECT_OFFSET(F, clipPlane);
    SWELL_EXPECT_OFFSET(F, eyePosition);
    SWELL_EXPECT_OFFSET(F, fresnelF0);
    SWELL_EXPECT_OFFSET(F, sunDirection);
    SWELL_EXPECT_OFFSET(F, sunIntensity);
    SWELL_EXPECT_OFFSET(F, sunColor);
    SWELL_EXPECT_OFFSET(F, fogSkyLayer_m);
    SWELL_EXPECT_OFFSET(F, fogColor);
    SWELL_EXPECT_OFFSET(F, fogStart_m);
    SWELL_EXPECT_OFFSET(F, skyZenith);
    SWELL_EXPECT_OFFSET(F, fogEnd_m);
    SWELL_EXPECT_OFFSET(F, skyHorizon);
    SWELL_EXPECT_OFFSET(F, shininess);
    SWELL_EXPECT_OFFSET(F, waterDeep);
    SWELL_EXPECT_OFFSET(F, specularStrength);
    SWELL_EXPECT_OFFSET(F, waterAbsorption);
    SWELL_EXPECT_OFFSET(F, refractionDistortion);
    SWELL_EXPECT_OFFSET(F, gridCenter);
    SWELL_EXPECT_OFFSET(F, gridRadius_m);
    SWELL_EXPECT_OFFSET(F, gridCells);
    SWELL_EXPECT_OFFSET(F, gridSkirt_m);
    SWELL_EXPECT_OFFSET(F, gridFinestStep_m);
    SWELL_EXPECT_OFFSET(F, gridFadeStart_m);
    SWELL_EXPECT_OFFSET(F, gridFadeEnd_m);
    SWELL_EXPECT_OFFSET(F, gridInnerScale_m);
    SWELL_EXPECT_OFFSET(F, gridGrowth);
    SWELL_EXPECT_OFFSET(F, reflectionFixedDistance_m);
    SWELL_EXPECT_OFFSET(F, worldBoxCount);
    SWELL_EXPECT_OFFSET(F, viewportSize);
    SWELL_EXPECT_OFFSET(F, viewportInvSize);
    SWELL_EXPECT_OFFSET(F, passEncodesSrgb);
    SWELL_EXPECT_OFFSET(F, waveHeightDeviation_m);
    SWELL_EXPECT_OFFSET(F, waveMeanSquareSlope);
    SWELL_EXPECT_OFFSET(F, gridMorph);
    SWELL_EXPECT_OFFSET(F, gridCoarseCenterShift);
    SWELL_EXPECT_OFFSET(F, gridCoarseGrowth);
    SWELL_EXPECT_OFFSET(F, waveReachVertical_m);
    SWELL_EXPECT_OFFSET(F, eyeUnderwater);
    SWELL_EXPECT_OFFSET(F, viewportOrigin);
    SWELL_EXPECT_OFFSET(F, depthNdcScale);
    SWELL_EXPECT_OFFSET(F, depthNdcOffset);
    SWELL_EXPECT_OFFSET(F, depthFar);
    SWELL_EXPECT_OFFSET(F, nearNdcZ);
    SWELL_EXPECT_OFFSET(F, farNdcZ);
    SWELL_EXPECT_OFFSET(F, projectionFocalY);
    SWELL_EXPECT_OFFSET(F, footprintScale);
    SWELL_EXPECT_OFFSET(F, passMarksWater);
    EXPECT_EQ(offsetOf(p.id(), "gridLevels[0].snapOffset_m"), GLint(offsetof(F, gridLevels)));
    EXPECT_EQ(offsetOf(p.id(), "gridLevels[1].coarseSnapOffset_m"),
              GLint(offsetof(F, gridLevels) + sizeof(swell::detail::GridLevelUniform) +
                    offsetof(swell::detail::GridLevelUniform, coarseSnapOffset_m)));
    EXPECT_EQ(offsetOf(p.id(), "gridLevels[1].coarseFirstRing"),
              GLint(offsetof(F, gridLevels) + sizeof(swell::detail::GridLevelUniform) +
                    offsetof(swell::detail::GridLevelUniform, coarseFirstRing)));
    EXPECT_EQ(offsetOf(p.id(), "gridLevels[1].firstRing"),
              GLint(offsetof(F, gridLevels) + sizeof(swell::detail::GridLevelUniform) +
                    offsetof(swell::detail::GridLevelUniform, firstRing)));
    EXPECT_EQ(offsetOf(p.id(), "worldBoxes[0].min_m"), GLint(offsetof(F, worldBoxes)));
    EXPECT_EQ(offsetOf(p.id(), "worldBoxes[1].max_m"),
              GLint(offsetof(F, worldBoxes) + sizeof(swell::detail::WorldBoxUniform) +
                    offsetof(swell::detail::WorldBoxUniform, max_m)));
    EXPECT_EQ(offsetOf(p.id(), "ambientSh[0]"), GLint(offsetof(F, ambientSh)));
    // (a vec4 array's stride is 16 bytes in std140, as glm::vec4's size)
    static_assert(sizeof(F::ambientSh) == 9 * 16);
    SWELL_EXPECT_OFFSET(F, fogExtinction_per_m);
    SWELL_EXPECT_OFFSET(F, fogFromSky);
    EXPECT_EQ(offsetOf(p.id(), "waveShape[0]"), GLint(offsetof(W, waveShape)));
    EXPECT_EQ(offsetOf(p.id(), "wavePhase[0]"), GLint(offsetof(W, wavePhase)));
    SWELL_EXPECT_OFFSET(W, waveCount);
#undef SWELL_EXPECT_OFFSET
    EXPECT_EQ(blockSize(p.id(), "Frame"), GLint(sizeof(F)));
    EXPECT_EQ(blockSize(p.id(), "GerstnerWaves"), GLint(sizeof(W)));
}

// The Caustics block (caustics.glsl), every field used.
const char* kCausticsProbe = R"(#include "caustics.glsl"
void main() {
    gl_Position = vec4(causticsSun, causticsMapSize_m) + vec4(causticsMapCorner_m, causticsSourceCorner_m)
                + vec4(causticsGridCenter_m, causticsCellSize_m, float(causticsCells)) + causticsSliceDepth_m;
}
)";

TEST_F(UniformLayout, CausticsBlockMatchesItsCppMirror)
{
    auto files = std::map<std::string, std::string>();
    const swell::gl::ShaderSources embedded = swell::gl::ShaderSources::embedded();
    for (const char* f : {"caustics.glsl", "water_optics.glsl", "swell/shader_constants.h"})
        files[f] = embedded.file(f);
    files["probe.vert"] = kCausticsProbe;
    files["probe.frag"] = "out vec4 c; void main() { c = vec4(1.0); }\n";
    swell::gl::Program p = swell::gl::buildProgram(swell::gl::ShaderSources::fromMap(files),
                                                   {{GL_VERTEX_SHADER, "probe.vert"}, {GL_FRAGMENT_SHADER, "probe.frag"}},
                                                   {"SWELL_CAUSTICS 0"});
    using C = swell::detail::CausticsUniforms;
    EXPECT_EQ(offsetOf(p.id(), "causticsSun"), GLint(offsetof(C, sun)));
    EXPECT_EQ(offsetOf(p.id(), "causticsMapSize_m"), GLint(offsetof(C, mapSize_m)));
    EXPECT_EQ(offsetOf(p.id(), "causticsMapCorner_m"), GLint(offsetof(C, mapCorner_m)));
    EXPECT_EQ(offsetOf(p.id(), "causticsSourceCorner_m"), GLint(offsetof(C, sourceCorner_m)));
    EXPECT_EQ(offsetOf(p.id(), "causticsGridCenter_m"), GLint(offsetof(C, gridCenter_m)));
    EXPECT_EQ(offsetOf(p.id(), "causticsCellSize_m"), GLint(offsetof(C, cellSize_m)));
    EXPECT_EQ(offsetOf(p.id(), "causticsCells"), GLint(offsetof(C, cells)));
    EXPECT_EQ(offsetOf(p.id(), "causticsSliceDepth_m"), GLint(offsetof(C, sliceDepth_m)));
    EXPECT_EQ(blockSize(p.id(), "Caustics"), GLint(sizeof(C)));
}

// The CloudShadow block (cloud_shadow.glsl), every field used.
const char* kCloudShadowProbe = R"(#include "cloud_shadow.glsl"
void main() {
    gl_Position = vec4(cloudShadowCorner_m, cloudShadowSize_m, cloudShadowSkySun);
}
)";

TEST_F(UniformLayout, CloudShadowBlockMatchesItsCppMirror)
{
    auto files = std::map<std::string, std::string>();
    const swell::gl::ShaderSources embedded = swell::gl::ShaderSources::embedded();
    for (const std::string& f : embedded.fileNames())
        files[f] = embedded.file(f);
    files["probe.vert"] = kCloudShadowProbe;
    files["probe.frag"] = "out vec4 c; void main() { c = vec4(1.0); }\n";
    swell::gl::Program p = swell::gl::buildProgram(swell::gl::ShaderSources::fromMap(files),
                                                   {{GL_VERTEX_SHADER, "probe.vert"}, {GL_FRAGMENT_SHADER, "probe.frag"}},
                                                   {"SWELL_CLOUD_SHADOWS 1"});
    using C = swell::detail::CloudShadowUniforms;
    EXPECT_EQ(offsetOf(p.id(), "cloudShadowCorner_m"), GLint(offsetof(C, corner_m)));
    EXPECT_EQ(offsetOf(p.id(), "cloudShadowSize_m"), GLint(offsetof(C, size_m)));
    EXPECT_EQ(offsetOf(p.id(), "cloudShadowSkySun"), GLint(offsetof(C, skySun)));
    EXPECT_EQ(blockSize(p.id(), "CloudShadow"), GLint(sizeof(C)));
}

// The surface sources' block (with the lattices of their foam's texture)
// and the wake's, as the water programs see them: the wake's code as the
// one source.
const char* kSourcesProbe = R"(#include "surface_sources.glsl"
void main() {
    vec4 s = surfaceSourceParameters[gl_VertexID] + sourceFoamNoise[gl_VertexID].map
           + vec4(sourceFoamNoise[gl_VertexID].offset_cells, sourceFoamNoise[gl_VertexID].cyclesPerMetre, sourceBreakingFoamAmount)
           + surfaceSourcesAt(vec2(gl_VertexID)) + vec4(wakeCorner_m, wakeCellSize_m, float(wakeCells));
    gl_Position = s;
}
)";

TEST_F(UniformLayout, SurfaceSourcesAndWakeBlocksMatchTheirCppMirrors)
{
    auto files = std::map<std::string, std::string>();
    const swell::gl::ShaderSources embedded = swell::gl::ShaderSources::embedded();
    for (const char* f : {"whitecap_foam.glsl", "wake.glsl", "swell/shader_constants.h"})
        files[f] = embedded.file(f);
    files["probe.vert"] = kSourcesProbe;
    files["probe.frag"] = "out vec4 c; void main() { c = vec4(1.0); }\n";
    swell::gl::ShaderSources sources = swell::gl::ShaderSources::fromMap(files);
    swell::detail::setSurfaceSourceFiles(sources, {swell::detail::WakeSurfaceSource::code()});
    swell::gl::Program p = swell::gl::buildProgram(sources, {{GL_VERTEX_SHADER, "probe.vert"}, {GL_FRAGMENT_SHADER, "probe.frag"}},
                                                   {"SWELL_SURFACE_SOURCES 1"});
    using S = swell::detail::SurfaceSourcesUniforms;
    using N = S::FoamNoise;
    EXPECT_EQ(offsetOf(p.id(), "surfaceSourceParameters[0]"), GLint(offsetof(S, parameters)));
    for (int i : {0, 1, SWELL_FOAM_NOISE_MAPS - 1}) {
        const std::string lattice = "sourceFoamNoise[" + std::to_string(i) + "].";
        const GLint at = GLint(offsetof(S, foamNoise) + sizeof(N) * std::size_t(i));
        EXPECT_EQ(offsetOf(p.id(), lattice + "map"), at + GLint(offsetof(N, map))) << lattice;
        EXPECT_EQ(offsetOf(p.id(), lattice + "offset_cells"), at + GLint(offsetof(N, offset_cells))) << lattice;
        EXPECT_EQ(offsetOf(p.id(), lattice + "cyclesPerMetre"), at + GLint(offsetof(N, cyclesPerMetre))) << lattice;
    }
    EXPECT_EQ(offsetOf(p.id(), "sourceBreakingFoamAmount"), GLint(offsetof(S, breakingFoamAmount)));
    EXPECT_EQ(blockSize(p.id(), "SurfaceSources"), GLint(sizeof(S)));
    using W = swell::detail::WakeUniforms;
    EXPECT_EQ(offsetOf(p.id(), "wakeCorner_m"), GLint(offsetof(W, corner_m)));
    EXPECT_EQ(offsetOf(p.id(), "wakeCellSize_m"), GLint(offsetof(W, cellSize_m)));
    EXPECT_EQ(offsetOf(p.id(), "wakeCells"), GLint(offsetof(W, cells)));
    EXPECT_EQ(blockSize(p.id(), "Wake"), GLint(sizeof(W)));
}

} // namespace
