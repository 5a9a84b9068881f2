#include "render/resources.h"

#include "swell/gpu/bindings.h"

namespace swell::detail {

Resources::Resources(gl::ShaderSources shaders, unsigned omittedTerms)
    : sources(std::move(shaders)), omittedWaterTerms(omittedTerms), emptyVao(gl::VertexArray::create()),
      waterInTwoPasses(vertexShadersStoreBuffers())
{
    for (gl::Buffer& b : frameUbo_) {
        b = gl::Buffer::create();
        glNamedBufferStorage(b.id(), sizeof(FrameUniforms), nullptr, GL_DYNAMIC_STORAGE_BIT);
    }
}

void Resources::bindFrame(Pass pass, const FrameUniforms& f) const
{
    glNamedBufferSubData(frameUbo_[pass].id(), 0, sizeof(f), &f);
    glBindBufferBase(GL_UNIFORM_BUFFER, SWELL_BINDING_FRAME, frameUbo_[pass].id());
}

void Resources::buildGrid(const Scene& scene)
{
    gridShape = gridShapeFor(scene.grid, scene.camera);
    waterGrid.build(gridShape);
}

} // namespace swell::detail
