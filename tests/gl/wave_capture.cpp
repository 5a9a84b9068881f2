#include "wave_capture.h"

#include "swell/debug.h"
#include "swell/scene/grid.h"

#include <epoxy/gl.h>
#include <glm/geometric.hpp>

#include "swell/gl/handle.h"

namespace swell::test {

std::vector<WaterVertex> captureGpu(Renderer& renderer, const Camera& camera, double time_s)
{
    const int count = swell::RendererTesting::waterVertexCount(renderer);
    gl::Buffer buffer = gl::Buffer::create();
    glNamedBufferStorage(buffer.id(), GLsizeiptr(count) * 8 * 4, nullptr, 0);
    swell::RendererTesting::captureWaterVertices(renderer, camera, time_s, buffer.id());
    std::vector<float> data(size_t(count) * 8);
    glGetNamedBufferSubData(buffer.id(), 0, GLsizeiptr(data.size() * 4), data.data());
    const int lines = int(std::lround(std::sqrt(double(count))));
    const glm::dvec2 origin(camera.position_m.x, camera.position_m.z);
    std::vector<WaterVertex> out(static_cast<size_t>(count));
    for (int k = 0; k < count; ++k) {
        const float* v = &data[size_t(k) * 8];
        WaterVertex& w = out[size_t(k)];
        w.rest_m = origin + glm::dvec2(v[0], v[1]);
        w.position_m = glm::dvec3(origin.x, 0.0, origin.y) + glm::dvec3(v[2], v[3], v[4]);
        w.normal = glm::dvec3(v[5], v[6], v[7]);
        w.i = k % lines;
        w.j = k / lines;
    }
    return out;
}

std::vector<WaterVertex> computeCpu(const Renderer& renderer, const Camera& camera, double time_s)
{
    const Scene& scene = renderer.scene();
    const GridShape shape = gridShapeFor(scene.grid, scene.camera);
    const HorizonFade fade = horizonFadeFor(scene.grid, shape);
    const GridPlacement placement = placeGrid(shape, camera.position_m);
    const int lines = shape.cells + 1;
    std::vector<WaterVertex> out;
    out.reserve(size_t(lines) * size_t(lines));
    for (int j = 0; j < lines; ++j)
        for (int i = 0; i < lines; ++i) {
            const GridPoint point = gridPoint(shape, placement, i, j);
            WaterVertex w;
            w.i = i;
            w.j = j;
            w.snapMargin = point.snapMargin;
            w.latticeStep_m = std::max(point.latticeStep_m.x, point.latticeStep_m.y);
            w.rest_m = placement.center_m + point.offset_m;
            const double distance = glm::length(w.rest_m - glm::dvec2(camera.position_m.x, camera.position_m.z));
            const SurfacePoint p = renderer.waveModel().surfaceAt(
                w.rest_m, time_s, SurfaceFilter{point.cellSize_m, horizonFadeAt(fade, distance)});
            w.position_m = glm::dvec3(w.rest_m.x, 0.0, w.rest_m.y) + p.displacement_m;
            w.normal = p.normal;
            out.push_back(w);
        }
    return out;
}

} // namespace swell::test
