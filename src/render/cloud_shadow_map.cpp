#include "render/cloud_shadow_map.h"

#include "render/programs.h"
#include "swell/error.h"
#include "swell/gpu/bindings.h"
#include "swell/gpu/sky.h"

#include <glm/common.hpp>

#include <cmath>

namespace swell::detail {

void CloudShadowMap::create()
{
    texture_ = gl::Texture::create(GLenum(GL_TEXTURE_2D));
    int levels = 1;
    for (int size = SWELL_CLOUD_SHADOW_SIZE; size > 1; size /= 2)
        ++levels;
    // 32-bit floats: the transmittance under a deck spans 1 to 1e-20 and
    // less, and the test compares texels with the C++ model.
    glTextureStorage2D(texture_.id(), levels, GL_R32F, SWELL_CLOUD_SHADOW_SIZE, SWELL_CLOUD_SHADOW_SIZE);
    glTextureParameteri(texture_.id(), GL_TEXTURE_MIN_FILTER, GL_LINEAR_MIPMAP_LINEAR);
    glTextureParameteri(texture_.id(), GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    glTextureParameteri(texture_.id(), GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
    glTextureParameteri(texture_.id(), GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
    framebuffer_ = gl::Framebuffer::create();
    glNamedFramebufferTexture(framebuffer_.id(), GL_COLOR_ATTACHMENT0, texture_.id(), 0);
    if (glCheckNamedFramebufferStatus(framebuffer_.id(), GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE)
        throw Error("swell::detail::CloudShadowMap: framebuffer incomplete");
    block_ = gl::Buffer::create();
    glNamedBufferStorage(block_.id(), sizeof(CloudShadowUniforms), nullptr, GL_DYNAMIC_STORAGE_BIT);
}

bool CloudShadowMap::update(const CloudShadowBakeProgram& program, GLuint emptyVao, const CloudSettings& clouds,
                            glm::vec3 sun, glm::dvec3 origin_m, float skySun)
{
    if (!texture_)
        create();
    // The texel the render origin lies in; the map is centred on it again
    // once the origin has gone SWELL_CLOUD_SHADOW_REBAKE of the side from
    // the centre of the last bake.
    const glm::ivec2 originTexel(int(std::floor(origin_m.x / kCloudShadowTexel_m)),
                                 int(std::floor(origin_m.z / kCloudShadowTexel_m)));
    constexpr int kHalf = SWELL_CLOUD_SHADOW_SIZE / 2;
    const int reach = int(SWELL_CLOUD_SHADOW_REBAKE * SWELL_CLOUD_SHADOW_SIZE);
    Key key{clouds, sun, bakedCornerTexel_};
    const glm::ivec2 offCentre = glm::abs(originTexel - (bakedCornerTexel_ + kHalf));
    if (!baked_ || offCentre.x > reach || offCentre.y > reach)
        key.cornerTexel = originTexel - kHalf;
    const bool bake = !baked_ || *baked_ != key;
    if (bake) {
        glBindTextureUnit(SWELL_UNIT_CLOUD_SHADOW, 0); // never the target itself
        glBindFramebuffer(GL_FRAMEBUFFER, framebuffer_.id());
        glViewport(0, 0, SWELL_CLOUD_SHADOW_SIZE, SWELL_CLOUD_SHADOW_SIZE);
        glDisable(GL_DEPTH_TEST);
        glDisable(GL_BLEND);
        glDisable(GL_CULL_FACE);
        glDisable(GL_SCISSOR_TEST);
        glDisable(GL_CLIP_DISTANCE0);
        glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
        glClipControl(GL_LOWER_LEFT, GL_NEGATIVE_ONE_TO_ONE);
        program.use();
        program.set(clouds, glm::vec2(glm::dvec2(key.cornerTexel) * kCloudShadowTexel_m), float(kCloudShadowTexel_m),
                    sun);
        glBindVertexArray(emptyVao);
        glDrawArrays(GL_TRIANGLES, 0, 3);
        glGenerateTextureMipmap(texture_.id());
        glEnable(GL_DEPTH_TEST);
        glBindFramebuffer(GL_FRAMEBUFFER, 0);
        baked_ = key;
        bakedCornerTexel_ = key.cornerTexel;
    }
    CloudShadowUniforms u;
    u.corner_m = glm::vec2(glm::dvec2(bakedCornerTexel_) * kCloudShadowTexel_m - glm::dvec2(origin_m.x, origin_m.z));
    u.size_m = float(SWELL_CLOUD_SHADOW_EXTENT_M);
    u.skySun = skySun;
    uniforms_ = u;
    glNamedBufferSubData(block_.id(), 0, sizeof(u), &u);
    return bake;
}

void CloudShadowMap::bind() const
{
    glBindTextureUnit(SWELL_UNIT_CLOUD_SHADOW, texture_.id());
    glBindBufferBase(GL_UNIFORM_BUFFER, SWELL_BINDING_CLOUD_SHADOW, block_.id());
}

} // namespace swell::detail
