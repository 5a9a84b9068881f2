// Baking the procedural sky into a cubemap: six fullscreen draws, one per face.
#include "render/sky_cubemap.h"

#include "swell/error.h"
#include "swell/shader_constants.h"

namespace swell::detail {

SkyBakeKey skyBakeKeyOf(const Scene& scene)
{
    return {scene.sky.zenithColor, scene.sky.horizonColor, scene.sun.direction, scene.sun.color, scene.sun.intensity};
}

void bakeProceduralSky(const SkyBakeProgram& program, gl::Texture& cube, GLuint emptyVao)
{
    if (!cube) {
        cube = gl::Texture::create(GLenum(GL_TEXTURE_CUBE_MAP));
        // Half floats: the glow around a bright sun exceeds 1.
        glTextureStorage2D(cube.id(), 1, GL_RGBA16F, kSkyFaceSize, kSkyFaceSize);
        glTextureParameteri(cube.id(), GL_TEXTURE_MIN_FILTER, GL_LINEAR);
        glTextureParameteri(cube.id(), GL_TEXTURE_MAG_FILTER, GL_LINEAR);
        glTextureParameteri(cube.id(), GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
        glTextureParameteri(cube.id(), GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
    }
    const gl::Framebuffer framebuffer = gl::Framebuffer::create();
    glBindFramebuffer(GL_FRAMEBUFFER, framebuffer.id());
    glViewport(0, 0, kSkyFaceSize, kSkyFaceSize);
    glDisable(GL_DEPTH_TEST);
    glDisable(GL_BLEND);
    glDisable(GL_CULL_FACE);
    glDisable(GL_SCISSOR_TEST);
    glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
    // Nothing may sample the cubemap while it is drawn into.
    glBindTextureUnit(SWELL_UNIT_SKY, 0);
    program.use();
    glBindVertexArray(emptyVao);
    for (int face = 0; face < kSkyFaces; ++face) {
        glNamedFramebufferTextureLayer(framebuffer.id(), GL_COLOR_ATTACHMENT0, cube.id(), 0, face);
        if (glCheckNamedFramebufferStatus(framebuffer.id(), GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE)
            throw Error("swell::detail::bakeProceduralSky(): framebuffer incomplete");
        program.setFace(face);
        glDrawArrays(GL_TRIANGLES, 0, 3);
    }
    glEnable(GL_DEPTH_TEST);
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
}

} // namespace swell::detail
