// The water drawn in two passes, so that each water pixel is shaded once.
//
// Drawn as one pass, the water's fragment shader runs for every 2 x 2 quad
// (a software rasteriser: every block of pixels) that a triangle touches,
// so a grid whose triangles are a few pixels wide shades each water pixel
// 1.8 times at full scale and 3.35 times at the viewer's 0.3 (issue 45;
// docs/PERFORMANCE.md). Here the grid is rasterised first with a fragment
// shader that only writes which triangle a pixel shows (a visibility
// buffer: Burns & Hunt 2013, "The Visibility Buffer"), while its vertex
// shader keeps every vertex it shades in a buffer (the vertex cache); a
// compute pass lists the 8 x 8 screen tiles that show water; then the
// shading pass, a point over each such tile, reads for each pixel its
// triangle's three vertices, interpolates them at the pixel's centre as
// the rasteriser would (perspective-correct, shaders/water_deferred.glsl)
// and shades it with the same code (water.frag with SWELL_WATER_DEFERRED).
//
// The visibility pass draws into its own target of the viewport's size: a
// triangle per pixel and a copy of the main pass's depth, which it tests
// against and writes; the shading pass writes that depth back into the
// main pass's framebuffer with each water pixel's colour, so what is drawn
// after the water (the sky, the spray) is tested against the same depth
// as after the single pass. A multisampled main pass and the wireframe
// view keep the single pass (render/water_pass.cpp).
#pragma once

#include "render/host_copy.h"
#include "swell/debug.h"
#include "swell/gl/handle.h"

#include <glm/vec2.hpp>
#include <glm/vec4.hpp>

#include <cstddef>

namespace swell::detail {

// A view's targets for its water's visibility pass.
class WaterVisibility {
public:
    // Prepares the pass for a main pass drawn into `framebuffer` over
    // `viewport`: the targets sized to the viewport, that framebuffer's
    // depth copied in, no triangle anywhere. Returns the framebuffer the
    // visibility pass draws into (over 0, 0 and the viewport's size).
    GLuint begin(GLuint framebuffer, glm::ivec4 viewport);
    // 1 + the grid triangle each pixel shows (0: none), GL_R32UI.
    GLuint triangles() const { return triangles_.id(); }
    // The depth the visibility pass left, in the main pass's depth format.
    GLuint depth() const { return depthTexture_; }
    // The tiles that show water (shaders/water_tiles.comp): an indirect
    // draw command of a point a tile, reset to none by begin(), then each
    // tile's place.
    GLuint tiles() const { return tiles_.id(); }
    // The tiles across and down the viewport.
    glm::ivec2 tileGrid() const;
    // What a frame's visibility pass does beside its draws (FrameCounters::
    // viewsGpu): the tile list's dispatch and the two barriers round it, the
    // triangles' clear (4 bytes a pixel) and the draw command's reset (16
    // bytes). The tile list's entries, one for each tile that shows water,
    // are counted by the GPU alone and not here.
    GpuWork passWork() const;

private:
    HostCopy depth_;
    gl::Texture triangles_;
    gl::Buffer tiles_;
    gl::Framebuffer framebuffer_;
    GLuint depthTexture_ = 0;
    glm::ivec2 size_{0};
};

// The buffer the visibility pass keeps the water's vertices in
// (shaders/water_vertex_cache.glsl), shared by every view: each view's
// visibility pass writes it before its own shading pass reads it.
class WaterVertexCache {
public:
    // Makes room for `vertices` vertices of `stride` bytes and binds the
    // buffer for the passes.
    void bind(std::size_t vertices, std::size_t stride);

private:
    gl::Buffer buffer_;
    std::size_t bytes_ = 0;
};

// Whether this GL lets a vertex shader write a storage buffer (GL 4.5
// leaves it optional: GL_MAX_VERTEX_SHADER_STORAGE_BLOCKS may be 0); the
// water is then drawn in one pass.
bool vertexShadersStoreBuffers();

} // namespace swell::detail
