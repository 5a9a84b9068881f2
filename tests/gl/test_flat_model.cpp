// A second wave model plugs in through the interface alone: flat water,
// drawn by the same water shaders, lies exactly on the rest plane with its
// normals straight up, and mirrors the island as a calm sea does.
#include "support/gl_test.h"
#include "swell/debug.h"
#include "swell/flat_model.h"
#include "swell/gl/handle.h"
#include "swell/renderer.h"

#include <epoxy/gl.h>

#include <vector>

namespace {

using namespace swell;

class FlatModelTest : public test::GlTest {};

TEST_F(FlatModelTest, TheGpuDrawsTheRestPlaneWithNormalsUp)
{
    Renderer renderer(defaultScene());
    renderer.setWaveModel(std::make_shared<FlatModel>());
    const Camera camera = cameraAt(defaultScene().camera, 10.0);
    const int count = swell::RendererTesting::waterVertexCount(renderer);
    gl::Buffer buffer = gl::Buffer::create();
    glNamedBufferStorage(buffer.id(), GLsizeiptr(count) * 8 * 4, nullptr, 0);
    swell::RendererTesting::captureWaterVertices(renderer, camera, 10.0, buffer.id());
    std::vector<float> data(size_t(count) * 8);
    glGetNamedBufferSubData(buffer.id(), 0, GLsizeiptr(data.size() * 4), data.data());
    int off = 0;
    for (int k = 0; k < count; ++k) {
        const float* v = &data[size_t(k) * 8];
        // rest (2), position (3), normal (3): the position is the rest point at height 0.
        off += v[3] != 0.0f || v[2] != v[0] || v[4] != v[1] || v[5] != 0.0f || v[6] != 1.0f || v[7] != 0.0f;
    }
    EXPECT_EQ(off, 0) << "of " << count << " vertices";
}

TEST_F(FlatModelTest, RendersWithoutTheScenesWaves)
{
    Scene scene = defaultScene();
    scene.objects.clear();
    Renderer renderer(scene);
    renderer.setWaveModel(std::make_shared<FlatModel>());
    const Image image = renderer.renderImage(cameraAt(scene.camera, 5.0), 5.0, {160, 90});
    // Two frames at different times are the same: nothing on flat water moves.
    const Image later = renderer.renderImage(cameraAt(scene.camera, 5.0), 25.0, {160, 90});
    EXPECT_TRUE(image.rgba == later.rgba);
    Renderer waves(scene);
    EXPECT_FALSE(waves.renderImage(cameraAt(scene.camera, 5.0), 25.0, {160, 90}).rgba == later.rgba);
}

} // namespace
