// The C++ mirrors of the std140 blocks must match what the driver lays out.
#include "render/gpu_types.h"
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
#include "waves.glsl"
void main() {
    vec4 s = passViewProj[0] + passInvViewProj[0] + cameraViewProj[0] + cameraInvViewProj[0] + clipPlane
           + eyePosition + sunDirection + sunColor + fogColor + fogRange + skyZenith + skyHorizon + waterDeep
           + waterAbsorption + waterOptics + gridShape + gridFade + gridCenter + gridLayout + snapOffsets[gl_VertexID]
           + reflectionParams + worldBoxes[gl_VertexID] + viewport + passFlags + waveShape[gl_VertexID] + wavePhase[gl_VertexID] + vec4(waveCount);
    gl_Position = s;
}
)";

TEST_F(UniformLayout, FrameAndWaveBlocksMatchTheirCppMirrors)
{
    auto files = std::map<std::string, std::string>();
    const swell::gl::ShaderSources embedded = swell::gl::ShaderSources::embedded();
    for (const char* f : {"frame.glsl", "waves.glsl", "swell/shader_constants.h"})
        files[f] = embedded.file(f);
    files["probe.vert"] = kProbe;
    files["probe.frag"] = "out vec4 c; void main() { c = vec4(1.0); }\n";
    swell::gl::Program p = swell::gl::buildProgram(swell::gl::ShaderSources::fromMap(files),
                                                   {{GL_VERTEX_SHADER, "probe.vert"}, {GL_FRAGMENT_SHADER, "probe.frag"}});
    using F = swell::detail::FrameUniforms;
    using W = swell::detail::WaveUniforms;
#define SWELL_EXPECT_OFFSET(T, field) EXPECT_EQ(offsetOf(p.id(), #field), GLint(offsetof(T, field))) << #field
    SWELL_EXPECT_OFFSET(F, passViewProj);
    SWELL_EXPECT_OFFSET(F, passInvViewProj);
    SWELL_EXPECT_OFFSET(F, cameraViewProj);
    SWELL_EXPECT_OFFSET(F, cameraInvViewProj);
    SWELL_EXPECT_OFFSET(F, clipPlane);
    SWELL_EXPECT_OFFSET(F, eyePosition);
    SWELL_EXPECT_OFFSET(F, sunDirection);
    SWELL_EXPECT_OFFSET(F, sunColor);
    SWELL_EXPECT_OFFSET(F, fogColor);
    SWELL_EXPECT_OFFSET(F, fogRange);
    SWELL_EXPECT_OFFSET(F, skyZenith);
    SWELL_EXPECT_OFFSET(F, skyHorizon);
    SWELL_EXPECT_OFFSET(F, waterDeep);
    SWELL_EXPECT_OFFSET(F, waterAbsorption);
    SWELL_EXPECT_OFFSET(F, waterOptics);
    SWELL_EXPECT_OFFSET(F, gridShape);
    SWELL_EXPECT_OFFSET(F, gridFade);
    SWELL_EXPECT_OFFSET(F, gridCenter);
    SWELL_EXPECT_OFFSET(F, gridLayout);
    EXPECT_EQ(offsetOf(p.id(), "snapOffsets[0]"), GLint(offsetof(F, snapOffsets)));
    SWELL_EXPECT_OFFSET(F, reflectionParams);
    SWELL_EXPECT_OFFSET(F, worldBoxes);
    SWELL_EXPECT_OFFSET(F, viewport);
    SWELL_EXPECT_OFFSET(F, passFlags);
    EXPECT_EQ(offsetOf(p.id(), "waveShape[0]"), GLint(offsetof(W, waveShape)));
    EXPECT_EQ(offsetOf(p.id(), "wavePhase[0]"), GLint(offsetof(W, wavePhase)));
    SWELL_EXPECT_OFFSET(W, waveCount);
#undef SWELL_EXPECT_OFFSET
    EXPECT_EQ(blockSize(p.id(), "Frame"), GLint(sizeof(F)));
    EXPECT_EQ(blockSize(p.id(), "Waves"), GLint(sizeof(W)));
}

} // namespace
