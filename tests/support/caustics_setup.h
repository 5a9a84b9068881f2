// The caustics map a wave model's GPU half (which the test makes from the
// model) draws for a sun at the origin, at time 20 s, as the frame draws it
// (render/caustics_map.h), and compute probes that
// read it through the shaders' own functions: what the caustics' and the
// shafts of light's tests measure. Needs a current GL 4.5 context.
#pragma once

#include "render/caustics_map.h"
#include "render/programs.h"
#include "support/shader_probe.h"
#include "swell/gl/shader.h"
#include "swell/gl/shader_sources.h"
#include "swell/wave_model_gpu.h"

#include <memory>
#include <string>
#include <utility>

namespace swell::test {

class DrawnCausticsMap {
public:
    DrawnCausticsMap(std::unique_ptr<WaveModelGpu> gpu, glm::vec3 sunDirection)
        : sources_(gl::ShaderSources::embedded()), gpu_(std::move(gpu))
    {
        gpu_->prepareFrame(glm::dvec2(0.0), 20.0);
        gpu_->prepareView(glm::dvec2(0.0));
        gpu_->bind();
        const detail::CausticsPrograms program(sources_, detail::CausticsFlags{gpu_->shaderFile()});
        map_.place(glm::dvec3(0.0), glm::vec2(0.0f), sunDirection);
        triangles_ = map_.render(program);
        glBindFramebuffer(GL_FRAMEBUFFER, 0);
    }

    const detail::CausticsMap& map() const { return map_; }
    // The surface's triangles drawn into the map.
    long long triangles() const { return triangles_; }

    // A compute program from `text` that may include any of the shaders'
    // files (support/shader_probe.h), built as the programs that read the
    // map are: with the map drawn and the shafts of light on.
    gl::Program probe(const char* text) const
    {
        return buildShaderProbe(text, {"SWELL_CAUSTICS 1", "SWELL_SHAFTS 1"});
    }

private:
    gl::ShaderSources sources_;
    std::unique_ptr<WaveModelGpu> gpu_;
    detail::CausticsMap map_;
    long long triangles_ = 0;
};

} // namespace swell::test
