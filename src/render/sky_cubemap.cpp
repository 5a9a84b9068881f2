// Baking the procedural sky into a cubemap: six fullscreen draws, one per face.
#include "render/sky_cubemap.h"

#include "swell/error.h"
#include "swell/gpu/bindings.h"
#include "swell/gpu/sky.h"

namespace swell::detail {

SkyBakeKey skyBakeKeyOf(const Scene& scene)
{
    if (scene.sky.model == SkyModel::Physical)
        return {SkyModel::Physical, {}, {}, scene.sun.direction, {}, 0.0, scene.sky.exposure, scene.sky.atmosphere,
                scene.sky.clouds};
    return {SkyModel::Gradient, scene.sky.zenithColor, scene.sky.horizonColor, scene.sun.direction, scene.sun.color,
            scene.sun.intensity};
}

namespace {

gl::Texture tableTexture(int width, int height, const std::vector<float>& rgb)
{
    gl::Texture t = gl::Texture::create(GLenum(GL_TEXTURE_2D));
    // 32-bit floats: transmittance spans 1 to below 1e-5 towards the horizon.
    glTextureStorage2D(t.id(), 1, GL_RGB32F, width, height);
    glTextureSubImage2D(t.id(), 0, 0, 0, width, height, GL_RGB, GL_FLOAT, rgb.data());
    glTextureParameteri(t.id(), GL_TEXTURE_MIN_FILTER, GL_LINEAR);
    glTextureParameteri(t.id(), GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    glTextureParameteri(t.id(), GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
    glTextureParameteri(t.id(), GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
    return t;
}

// The same as layers of an array texture, so that no filter mixes them.
gl::Texture layeredTableTexture(int width, int height, int layers, const std::vector<float>& rgb)
{
    gl::Texture t = gl::Texture::create(GLenum(GL_TEXTURE_2D_ARRAY));
    glTextureStorage3D(t.id(), 1, GL_RGB32F, width, height, layers);
    glTextureSubImage3D(t.id(), 0, 0, 0, 0, width, height, layers, GL_RGB, GL_FLOAT, rgb.data());
    glTextureParameteri(t.id(), GL_TEXTURE_MIN_FILTER, GL_LINEAR);
    glTextureParameteri(t.id(), GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    glTextureParameteri(t.id(), GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
    glTextureParameteri(t.id(), GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
    return t;
}

} // namespace

void AtmosphereTextures::upload(const Atmosphere& atmosphere)
{
    // Rows of RGB floats are 4-byte aligned; the host's setting is put back.
    GLint unpackAlignment = 4;
    glGetIntegerv(GL_UNPACK_ALIGNMENT, &unpackAlignment);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
    transmittance = tableTexture(SWELL_TRANSMITTANCE_MU_SIZE, SWELL_TRANSMITTANCE_R_SIZE, atmosphere.transmittanceTable());
    multipleScattering = layeredTableTexture(SWELL_MULTISCATTER_SIZE, SWELL_MULTISCATTER_SIZE, SWELL_MULTISCATTER_LAYERS,
                                             atmosphere.multipleScatteringTable());
    glPixelStorei(GL_UNPACK_ALIGNMENT, unpackAlignment);
}

void AtmosphereTextures::bind() const
{
    glBindTextureUnit(SWELL_UNIT_SKY_TRANSMITTANCE, transmittance.id());
    glBindTextureUnit(SWELL_UNIT_SKY_MULTISCATTER, multipleScattering.id());
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
