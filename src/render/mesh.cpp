// Uploading meshes and drawing them.
#include "render/mesh.h"

#include <cstddef>

namespace swell::detail {

GpuMesh::GpuMesh(const MeshData& data)
{
    vao_ = gl::VertexArray::create();
    vertices_ = gl::Buffer::create();
    indices_ = gl::Buffer::create();
    glNamedBufferStorage(vertices_.id(), GLsizeiptr(data.vertices.size() * sizeof(MeshVertex)),
                         data.vertices.empty() ? nullptr : data.vertices.data(), 0);
    glNamedBufferStorage(indices_.id(), GLsizeiptr(data.indices.size() * sizeof(std::uint32_t)),
                         data.indices.empty() ? nullptr : data.indices.data(), 0);
    glVertexArrayVertexBuffer(vao_.id(), 0, vertices_.id(), 0, sizeof(MeshVertex));
    glVertexArrayElementBuffer(vao_.id(), indices_.id());
    const GLuint offsets[] = {offsetof(MeshVertex, position), offsetof(MeshVertex, normal), offsetof(MeshVertex, color)};
    for (GLuint a = 0; a < 3; ++a) {
        glEnableVertexArrayAttrib(vao_.id(), a);
        glVertexArrayAttribFormat(vao_.id(), a, 3, GL_FLOAT, GL_FALSE, offsets[a]);
        glVertexArrayAttribBinding(vao_.id(), a, 0);
    }
    indexCount_ = std::uint32_t(data.indices.size());
}

void GpuMesh::draw() const
{
    if (indexCount_ == 0)
        return;
    glBindVertexArray(vao_.id());
    glDrawElements(GL_TRIANGLES, GLsizei(indexCount_), GL_UNSIGNED_INT, nullptr);
}

void GpuMesh::drawRanges(const std::vector<GLsizei>& counts, const std::vector<const void*>& offsets) const
{
    if (counts.empty())
        return;
    glBindVertexArray(vao_.id());
    glMultiDrawElements(GL_TRIANGLES, counts.data(), GL_UNSIGNED_INT, offsets.data(), GLsizei(counts.size()));
}

} // namespace swell::detail
