#include "render/water_visibility.h"

#include "swell/gpu/bindings.h"

namespace swell::detail {

GLuint WaterVisibility::begin(GLuint framebuffer, glm::ivec4 viewport)
{
    const GLuint depth = depth_.copyDepth(framebuffer, viewport);
    const glm::ivec2 size(viewport.z, viewport.w);
    if (!triangles_ || size != size_) {
        triangles_ = gl::Texture::create(GLenum(GL_TEXTURE_2D));
        glTextureStorage2D(triangles_.id(), 1, GL_R32UI, size.x, size.y);
        // An integer texture is complete only with nearest filtering.
        glTextureParameteri(triangles_.id(), GL_TEXTURE_MIN_FILTER, GL_NEAREST);
        glTextureParameteri(triangles_.id(), GL_TEXTURE_MAG_FILTER, GL_NEAREST);
        framebuffer_ = gl::Framebuffer::create();
        tiles_ = gl::Buffer::create();
        size_ = size;
        const glm::ivec2 grid = tileGrid();
        glNamedBufferStorage(tiles_.id(), GLsizeiptr(sizeof(GLuint) * (4 + std::size_t(grid.x) * std::size_t(grid.y))),
                             nullptr, GL_DYNAMIC_STORAGE_BIT);
        glNamedFramebufferTexture(framebuffer_.id(), GL_COLOR_ATTACHMENT0, triangles_.id(), 0);
        size_ = size;
    }
    // Attached every frame: the copy's texture is made again when the main
    // pass's depth format or size changes, and a new texture may take a
    // deleted one's name.
    GLint format = 0;
    glGetTextureLevelParameteriv(depth, 0, GL_TEXTURE_INTERNAL_FORMAT, &format);
    const bool stencil = format == GL_DEPTH24_STENCIL8 || format == GL_DEPTH32F_STENCIL8;
    glNamedFramebufferTexture(framebuffer_.id(), GL_DEPTH_STENCIL_ATTACHMENT, 0, 0);
    glNamedFramebufferTexture(framebuffer_.id(), stencil ? GL_DEPTH_STENCIL_ATTACHMENT : GL_DEPTH_ATTACHMENT, depth, 0);
    depthTexture_ = depth;
    const GLuint none = 0;
    glClearNamedFramebufferuiv(framebuffer_.id(), GL_COLOR, 0, &none);
    // glDrawArraysIndirect's: a point a tile, no tile yet.
    const GLuint command[4] = {0, 1, 0, 0};
    glNamedBufferSubData(tiles_.id(), 0, sizeof(command), command);
    return framebuffer_.id();
}

GpuWork WaterVisibility::passWork() const
{
    GpuWork work;
    work.dispatches = 1;
    work.barriers = 2;
    work.bytesWritten = 4LL * size_.x * size_.y + 16;
    return work;
}

glm::ivec2 WaterVisibility::tileGrid() const
{
    return (size_ + SWELL_WATER_TILE - 1) / SWELL_WATER_TILE;
}

void WaterVertexCache::bind(std::size_t vertices, std::size_t stride)
{
    const std::size_t bytes = vertices * stride;
    if (!buffer_ || bytes > bytes_) {
        buffer_ = gl::Buffer::create();
        glNamedBufferStorage(buffer_.id(), GLsizeiptr(bytes), nullptr, 0);
        bytes_ = bytes;
    }
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, SWELL_STORAGE_WATER_VERTICES, buffer_.id());
}

bool vertexShadersStoreBuffers()
{
    GLint blocks = 0;
    glGetIntegerv(GL_MAX_VERTEX_SHADER_STORAGE_BLOCKS, &blocks);
    return blocks > 0;
}

} // namespace swell::detail
