// GPU copies of world meshes (see assets/mesh_data.h for the CPU side).
#pragma once

#include "assets/mesh_data.h"
#include "swell/gl/handle.h"

#include <vector>

namespace swell::detail {

class GpuMesh {
public:
    GpuMesh() = default;
    explicit GpuMesh(const MeshData& data);
    void draw() const;
    // Draws the index ranges (first index, count) in one call: a level's
    // tiles that a pass keeps (the island's, render/scene_world.cpp).
    void drawRanges(const std::vector<GLsizei>& counts, const std::vector<const void*>& offsets) const;
    std::uint32_t indexCount() const { return indexCount_; }

private:
    gl::VertexArray vao_;
    gl::Buffer vertices_, indices_;
    std::uint32_t indexCount_ = 0;
};

} // namespace swell::detail
