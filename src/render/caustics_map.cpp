// The caustics map (caustics_map.h).
#include "render/caustics_map.h"

#include "render/gl_state.h"
#include "render/programs.h"
#include "swell/constants.h"
#include "swell/gpu/bindings.h"
#include "swell/gpu/underwater.h"

#include <glm/common.hpp>

#include <algorithm>
#include <cmath>

namespace swell::detail {

namespace {

// The slices' images drift from the surface point along the sun's refracted
// ray, and the waves move them about it: the source grid reaches this share
// of the map's side past the drifted square on every side, so that every
// texel receives the light of every cell that can reach it.
constexpr double kSourceMargin = 0.1;

// The source grid's points and triangles, the bytes of a point's record
// (caustics_sources.comp: two vec4) and of a slice's triangle corner
// (caustics_images.comp: one vec4), the corners of a slice.
constexpr long long kSourcePoints = (SWELL_CAUSTICS_CELLS + 1) * (SWELL_CAUSTICS_CELLS + 1);
constexpr long long kTriangles = 2 * SWELL_CAUSTICS_CELLS * SWELL_CAUSTICS_CELLS;
constexpr long long kSourceBytes = 32, kCornerBytes = 16;
constexpr long long kCornersPerSlice = 3 * kTriangles;
// The draw order's stride permutes the triangles only while their count is a power of two.
static_assert((kTriangles & (kTriangles - 1)) == 0 && SWELL_CAUSTICS_ORDER_STRIDE % 2 == 1);

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
    for (int k = 0; k < SWELL_CAUSTICS_SLICES; ++k) {
        sliceFramebuffers_[size_t(k)] = gl::Framebuffer::create();
        glNamedFramebufferTextureLayer(sliceFramebuffers_[size_t(k)].id(), GL_COLOR_ATTACHMENT0, texture_.id(), 0, k);
    }
    block_ = gl::Buffer::create();
    glNamedBufferStorage(block_.id(), sizeof(CausticsUniforms), nullptr, GL_DYNAMIC_STORAGE_BIT);
    sources_ = gl::Buffer::create();
    glNamedBufferStorage(sources_.id(), kSourcePoints * kSourceBytes, nullptr, 0);
    images_ = gl::Buffer::create();
    glNamedBufferStorage(images_.id(), kCornersPerSlice * SWELL_CAUSTICS_SLICES * kCornerBytes, nullptr, 0);
    vertexArray_ = gl::VertexArray::create();
    glVertexArrayVertexBuffer(vertexArray_.id(), 0, images_.id(), 0, GLsizei(kCornerBytes));
    glEnableVertexArrayAttrib(vertexArray_.id(), 0);
    glVertexArrayAttribFormat(vertexArray_.id(), 0, 4, GL_FLOAT, GL_FALSE, 0);
    glVertexArrayAttribBinding(vertexArray_.id(), 0, 0);
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
    const double sinT = std::sqrt(std::max(1.0 - s.y * s.y, 0.0)) / kWaterIor;
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

long long CausticsMap::render(const CausticsPrograms& programs)
{
    glBindBufferBase(GL_UNIFORM_BUFFER, SWELL_BINDING_CAUSTICS, block_.id());
    glBindTextureUnit(SWELL_UNIT_CAUSTICS, 0); // never the target itself
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, SWELL_STORAGE_CAUSTICS_SOURCES, sources_.id());
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, SWELL_STORAGE_CAUSTICS_IMAGES, images_.id());
    programs.sources.use();
    glDispatchCompute(GLuint((kSourcePoints + SWELL_CAUSTICS_GROUP - 1) / SWELL_CAUSTICS_GROUP), 1, 1);
    glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);
    programs.images.use();
    glDispatchCompute(GLuint((kTriangles + SWELL_CAUSTICS_GROUP - 1) / SWELL_CAUSTICS_GROUP), 1, 1);
    glMemoryBarrier(GL_VERTEX_ATTRIB_ARRAY_BARRIER_BIT);
    releaseProgramStages();

    const float zero = 0.0f;
    glClearTexImage(texture_.id(), 0, GL_RED, GL_FLOAT, &zero);
    glViewport(0, 0, SWELL_CAUSTICS_SIZE, SWELL_CAUSTICS_SIZE);
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
    programs.splat.use();
    glBindVertexArray(vertexArray_.id());
    for (int k = 0; k < SWELL_CAUSTICS_SLICES; ++k) {
        glBindFramebuffer(GL_FRAMEBUFFER, sliceFramebuffers_[size_t(k)].id());
        glDrawArrays(GL_TRIANGLES, GLint(k * kCornersPerSlice), GLsizei(kCornersPerSlice));
    }
    glGenerateTextureMipmap(texture_.id());
    glDisable(GL_BLEND);
    glDepthMask(GL_TRUE);
    glEnable(GL_DEPTH_TEST);
    return kTriangles;
}

GpuWork CausticsMap::renderWork()
{
    constexpr long long kR32f = 4; // bytes a texel
    long long texels = 0;
    for (long long size = SWELL_CAUSTICS_SIZE; size >= 1; size /= 2)
        texels += size * size * SWELL_CAUSTICS_SLICES;
    GpuWork work;
    work.dispatches = 2;
    work.barriers = 2;
    work.mipmaps = 1;
    work.bytesWritten = texels * kR32f + kSourcePoints * kSourceBytes + kCornersPerSlice * SWELL_CAUSTICS_SLICES * kCornerBytes;
    return work;
}

void CausticsMap::bind() const
{
    glBindTextureUnit(SWELL_UNIT_CAUSTICS, texture_.id());
    glBindBufferBase(GL_UNIFORM_BUFFER, SWELL_BINDING_CAUSTICS, block_.id());
}

} // namespace swell::detail
