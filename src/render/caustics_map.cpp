// The caustics map (caustics_map.h).
#include "render/caustics_map.h"

#include "render/gl_state.h"
#include "render/programs.h"

#include <glm/common.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <vector>

namespace swell::detail {

namespace {

// The slices' images drift from the surface point along the sun's refracted
// ray, and the waves move them about it: the source grid reaches this share
// of the map's side past the drifted square on every side, so that every
// texel receives the light of every cell that can reach it.
constexpr double kSourceMargin = 0.1;

// The map's mip levels: down to 1 x 1 texel.
constexpr int kLevels = [] {
    int levels = 1;
    for (int size = SWELL_CAUSTICS_SIZE; size > 1; size /= 2)
        ++levels;
    return levels;
}();

} // namespace

void CausticsMap::create()
{
    texture_ = gl::Texture::create(GLenum(GL_TEXTURE_2D_ARRAY));
    // A mip chain: a far floor averages the pattern rather than alias it.
    glTextureStorage3D(texture_.id(), kLevels, GL_R32F, SWELL_CAUSTICS_SIZE, SWELL_CAUSTICS_SIZE, SWELL_CAUSTICS_SLICES);
    glTextureParameteri(texture_.id(), GL_TEXTURE_MIN_FILTER, GL_LINEAR_MIPMAP_LINEAR);
    glTextureParameteri(texture_.id(), GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    glTextureParameteri(texture_.id(), GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
    glTextureParameteri(texture_.id(), GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
    framebuffer_ = gl::Framebuffer::create();
    glNamedFramebufferTexture(framebuffer_.id(), GL_COLOR_ATTACHMENT0, texture_.id(), 0); // layered: gl_Layer picks the slice
    block_ = gl::Buffer::create();
    glNamedBufferStorage(block_.id(), sizeof(CausticsUniforms), nullptr, GL_DYNAMIC_STORAGE_BIT);
    // Two triangles a cell, wound so that a level one's area vector
    // cross(v2 - v0, v1 - v0) points up (caustics.geom).
    const std::uint32_t perSide = SWELL_CAUSTICS_CELLS + 1;
    std::vector<std::uint32_t> indices;
    indices.reserve(std::size_t(SWELL_CAUSTICS_CELLS) * SWELL_CAUSTICS_CELLS * 6);
    for (std::uint32_t j = 0; j < SWELL_CAUSTICS_CELLS; ++j)
        for (std::uint32_t i = 0; i < SWELL_CAUSTICS_CELLS; ++i) {
            const std::uint32_t v00 = j * perSide + i, v10 = v00 + 1, v01 = v00 + perSide, v11 = v01 + 1;
            indices.insert(indices.end(), {v00, v10, v01, v10, v11, v01});
        }
    indices_ = gl::Buffer::create();
    glNamedBufferStorage(indices_.id(), GLsizeiptr(indices.size() * sizeof(std::uint32_t)), indices.data(), 0);
    vertexArray_ = gl::VertexArray::create();
    glVertexArrayElementBuffer(vertexArray_.id(), indices_.id());
    indexCount_ = GLsizei(indices.size());
}

void CausticsMap::place(glm::dvec3 origin_m, glm::vec2 gridCenter_m, glm::vec3 sun)
{
    if (!texture_)
        create();
    CausticsUniforms u;
    u.sun = sun;
    u.gridCenter_m = gridCenter_m;
    const double extent_m = SWELL_CAUSTICS_EXTENT_M;
    const double texel_m = extent_m / SWELL_CAUSTICS_SIZE;
    const glm::dvec2 eye(origin_m.x, origin_m.z);
    // Snapped to whole texels of the world, in double, then made relative
    // to the render origin (the eye's x, z).
    const glm::dvec2 corner = glm::floor((eye - 0.5 * extent_m) / texel_m) * texel_m;
    u.mapCorner_m = glm::vec2(corner - eye);
    u.mapSize_m = float(extent_m);
    for (int k = 0; k < SWELL_CAUSTICS_SLICES; ++k)
        u.sliceDepth_m[k] = kCausticsSliceDepths_m[std::size_t(k)];
    // Where a level surface's rays come from for the first and last slice:
    // the source square covers both drifts, with the margin, on whole cells
    // of the world (so the pattern does not swim as the camera moves).
    const glm::dvec3 s = glm::normalize(glm::dvec3(sun));
    const double sinT = std::sqrt(std::max(1.0 - s.y * s.y, 0.0)) / SWELL_WATER_IOR;
    const double tanT = sinT / std::sqrt(1.0 - sinT * sinT);
    const glm::dvec2 along = glm::length(glm::dvec2(s.x, s.z)) > 1e-9 ? -glm::normalize(glm::dvec2(s.x, s.z)) : glm::dvec2(0.0);
    const glm::dvec2 nearDrift = along * tanT * double(kCausticsSliceDepths_m.front());
    const glm::dvec2 farDrift = along * tanT * double(kCausticsSliceDepths_m.back());
    const glm::dvec2 lo = corner - glm::max(nearDrift, farDrift) - kSourceMargin * extent_m;
    const glm::dvec2 hi = corner + extent_m - glm::min(nearDrift, farDrift) + kSourceMargin * extent_m;
    const double cell_m = std::max(hi.x - lo.x, hi.y - lo.y) / SWELL_CAUSTICS_CELLS;
    const glm::dvec2 sourceCorner = glm::floor(lo / cell_m) * cell_m;
    // The cell size changes with the sun only; the grid is a whole number
    // of them from the world's origin, so it stays put while the sun does.
    u.cellSize_m = float(cell_m);
    u.sourceCorner_m = glm::vec2(sourceCorner - eye);
    u.cells = SWELL_CAUSTICS_CELLS;
    uniforms_ = u;
    glNamedBufferSubData(block_.id(), 0, sizeof(u), &u);
}

long long CausticsMap::render(const BlockProgram& program)
{
    glBindFramebuffer(GL_FRAMEBUFFER, framebuffer_.id());
    glViewport(0, 0, SWELL_CAUSTICS_SIZE, SWELL_CAUSTICS_SIZE);
    const float zero[4] = {0.0f, 0.0f, 0.0f, 0.0f};
    glClearNamedFramebufferfv(framebuffer_.id(), GL_COLOR, 0, zero);
    glDisable(GL_DEPTH_TEST);
    glDepthMask(GL_FALSE);
    glDisable(GL_CULL_FACE); // folded cells (past a focus) land mirrored
    glDisable(GL_SCISSOR_TEST);
    glDisable(GL_RASTERIZER_DISCARD);
    glDisable(GL_CLIP_DISTANCE0);
    glPolygonMode(GL_FRONT_AND_BACK, GL_FILL);
    glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
    glClipControl(GL_LOWER_LEFT, GL_NEGATIVE_ONE_TO_ONE);
    glEnable(GL_BLEND);
    glBlendEquation(GL_FUNC_ADD);
    glBlendFunc(GL_ONE, GL_ONE);
    glBindBufferBase(GL_UNIFORM_BUFFER, SWELL_BINDING_CAUSTICS, block_.id());
    glBindTextureUnit(SWELL_UNIT_CAUSTICS, 0); // never the target itself
    program.use();
    glBindVertexArray(vertexArray_.id());
    glDrawElements(GL_TRIANGLES, indexCount_, GL_UNSIGNED_INT, nullptr);
    unbindGeometryStageProgram();
    glGenerateTextureMipmap(texture_.id());
    glDisable(GL_BLEND);
    glDepthMask(GL_TRUE);
    glEnable(GL_DEPTH_TEST);
    return indexCount_ / 3;
}

GpuWork CausticsMap::renderWork()
{
    constexpr long long kR32f = 4; // bytes a texel
    long long texels = 0;
    for (long long size = SWELL_CAUSTICS_SIZE; size >= 1; size /= 2)
        texels += size * size * SWELL_CAUSTICS_SLICES;
    GpuWork work;
    work.mipmaps = 1;
    work.bytesWritten = texels * kR32f;
    return work;
}

void CausticsMap::bind() const
{
    glBindTextureUnit(SWELL_UNIT_CAUSTICS, texture_.id());
    glBindBufferBase(GL_UNIFORM_BUFFER, SWELL_BINDING_CAUSTICS, block_.id());
}

} // namespace swell::detail
