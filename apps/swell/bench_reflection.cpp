// `swell bench`: what each reflection lookup costs the water pass. The
// default scene is drawn along the same camera path by one renderer per
// mode, frame for frame in turn, so both modes see the same machine load;
// only the water pass differs between them (the reflection texture itself is
// drawn the same way in both).
#include "bench.h"

#include <string>
#include <utility>

namespace swell::app::bench {

namespace {

const char* modeName(ReflectionMode mode)
{
    return mode == ReflectionMode::FixedDistance ? "fixed" : "raymarch";
}

} // namespace

std::vector<ReflectionModeCost> measureReflectionModes(const Scene& scene, PassRecorder& recorder, int frames,
                                                       glm::ivec2 size, unsigned framebuffer,
                                                       const std::vector<Camera>& cameras,
                                                       const std::vector<double>& times_s)
{
    std::vector<ReflectionModeCost> costs;
    std::vector<std::unique_ptr<Renderer>> renderers;
    for (ReflectionMode mode : {ReflectionMode::FixedDistance, ReflectionMode::RayMarch}) {
        Scene s = scene;
        s.reflection.mode = mode;
        renderers.push_back(std::make_unique<Renderer>(s));
        costs.push_back({modeName(mode), {}, {}});
    }
    for (int k = 0; k < frames; ++k) {
        const size_t i = size_t(k) % cameras.size();
        for (size_t m = 0; m < renderers.size(); ++m) {
            renderers[m]->setPassObserver(&recorder);
            const FrameSample frame =
                recorder.recordFrame([&] { renderers[m]->render(cameras[i], times_s[i], size, framebuffer); });
            renderers[m]->setPassObserver(nullptr);
            if (const PassSample* water = frame.find("water")) {
                costs[m].waterWall_ms.push_back(water->wall_ms);
                costs[m].waterCpu_ms.push_back(water->cpu_ms);
            }
        }
    }
    return costs;
}

} // namespace swell::app::bench
