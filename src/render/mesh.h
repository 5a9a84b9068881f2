// GPU copies of world meshes (see assets/mesh_data.h for the CPU side).
#pragma once

#include "assets/mesh_data.h"
#include "swell/gl/handle.h"

namespace swell::detail {

class GpuMesh {
public:
    GpuMesh() = default;
    explicit GpuMesh(const MeshData& data);
    void draw() const;
    std::uint32_t indexCount() const { return indexCount_; }

private:
    gl::VertexArray vao_;
    gl::Buffer vertices_, indices_;
    std::uint32_t indexCount_ = 0;
};

} // namespace swell::detail
