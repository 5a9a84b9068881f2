// CoastGpu: the coast field's texels and block for the GPU (coast_gpu.h).
#include "ocean/coast/gpu/coast_gpu.h"

#include "ocean/coast/gpu/coast_uniforms.h"
#include "swell/gpu/bindings.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cstddef>

namespace swell::detail {

CoastGpu::CoastGpu(std::shared_ptr<const CoastField> field, WaveSet trains, CoastTrainDepths depths)
    : field_(std::move(field)), trains_(std::move(trains)), depths_(depths)
{
    buffer_ = gl::Buffer::create();
    glNamedBufferStorage(buffer_.id(), sizeof(CoastUniforms), nullptr, GL_DYNAMIC_STORAGE_BIT);
    uploadTexels();
    prepareView(glm::dvec2(0.0), 0.0); // a block to read before the first view's
}

void CoastGpu::prepareView(glm::dvec2 gridCenter_m, double time_s)
{
    CoastUniforms u{};
    if (field_) {
        const DepthGrid& grid = field_->depth();
        u.layers = int(field_->waveCount());
        u.origin_m = glm::vec2(grid.origin_m - gridCenter_m);
        u.size = grid.size;
        u.cell_m = float(grid.cell_m);
        u.edgeBand_cells = float(field_->edgeBand());
        u.trainsFullDepth_m = float(depths_.fullDepth_m);
        u.trainsNoneDepth_m = float(depths_.noneDepth_m);
        // The trains in the order of their layers: longest first, as the
        // shaders' LOD loop wants them.
        for (std::size_t i = 0; i < trains_.waves.size(); ++i) {
            const int layer = field_->layerOf(i);
            if (layer < 0)
                continue;
            const Wave& w = trains_.waves[i];
            // Exactly the k*d the CPU wave functions use.
            const glm::dvec2 kd = wavenumberVector(w);
            const double k = glm::length(kd);
            CoastTrainUniform& t = u.trains[layer];
            t.direction = glm::vec2(kd / k);
            t.wavenumber_rad_per_m = float(k);
            t.amplitude_m = float(w.amplitude_m);
            t.steepness = float(w.steepness);
            t.phase_rad = float(wrappedPhase(w, trains_.depth_m, gridCenter_m, time_s));
            t.wavelength_m = float(w.wavelength_m);
            t.layer = layer;
            u.trainCount = std::max(u.trainCount, layer + 1);
        }
    }
    glNamedBufferSubData(buffer_.id(), 0, sizeof(u), &u);
}

void CoastGpu::bind() const
{
    glBindBufferBase(GL_UNIFORM_BUFFER, SWELL_BINDING_COAST, buffer_.id());
    glBindTextureUnit(SWELL_UNIT_COAST_WAVES, waves_.id());
    glBindTextureUnit(SWELL_UNIT_COAST_COMMON, common_.id());
}

// Read with texelFetch, so nearest filtering and one level.
void CoastGpu::uploadTexels()
{
    const CoastField* coast = field_.get();
    const glm::ivec2 size = coast ? coast->depth().size : glm::ivec2(1);
    const int layers = coast ? std::max(int(coast->waveCount()), 1) : 1;
    waves_ = gl::Texture::create(GLenum(GL_TEXTURE_2D_ARRAY));
    glTextureStorage3D(waves_.id(), 1, GL_RGBA32F, size.x, size.y, layers);
    common_ = gl::Texture::create(GLenum(GL_TEXTURE_2D));
    glTextureStorage2D(common_.id(), 1, GL_RGBA32F, size.x, size.y);
    for (const gl::Texture* t : {&waves_, &common_}) {
        glTextureParameteri(t->id(), GL_TEXTURE_MIN_FILTER, GL_NEAREST);
        glTextureParameteri(t->id(), GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    }
    if (!coast) {
        const glm::vec4 open(0.0f, 1.0f, 1.0f, 0.0f);
        glTextureSubImage3D(waves_.id(), 0, 0, 0, 0, 1, 1, 1, GL_RGBA, GL_FLOAT, &open);
        glTextureSubImage2D(common_.id(), 0, 0, 0, 1, 1, GL_RGBA, GL_FLOAT, &open);
        return;
    }
    for (std::size_t l = 0; l < coast->waveCount(); ++l)
        glTextureSubImage3D(waves_.id(), 0, 0, 0, GLint(l), size.x, size.y, 1, GL_RGBA, GL_FLOAT,
                            coast->layer(l).data());
    glTextureSubImage2D(common_.id(), 0, 0, 0, size.x, size.y, GL_RGBA, GL_FLOAT, coast->common().data());
}

} // namespace swell::detail
