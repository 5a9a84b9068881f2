// FlatModel: no displacement anywhere, normal straight up; its GPU half
// uploads nothing but an empty coast field (ocean/coast/gpu/coast_gpu.h), so
// that water shaders reading the coast read "no coast" under every model.
#include "swell/flat_model.h"

#include "ocean/coast/gpu/coast_gpu.h"
#include "swell/wave_model_gpu.h"

namespace swell {

namespace {

class FlatGpu final : public WaveModelGpu {
public:
    std::string shaderFile() const override { return "ocean/flat.glsl"; }
    // The empty field's block, written once when it was made, holds for every view.
    void prepareFrame(glm::dvec2, double) override {}
    void prepareView(glm::dvec2) override {}
    void bind() const override { coast_.bind(); }
    // The flat sea is the same at every time.
    bool prepareEarlierView(glm::dvec2, double) override { return true; }

private:
    detail::CoastGpu coast_{nullptr};
};

} // namespace

std::string_view FlatModel::name() const { return "flat"; }
std::string FlatModel::summary() const { return "flat water"; }

SurfacePoint FlatModel::surfaceAt(glm::dvec2, double, const SurfaceFilter&) const { return {}; }

glm::dvec2 FlatModel::restPointUnder(glm::dvec2 worldPoint_m, double, const SurfaceFilter&) const { return worldPoint_m; }

std::unique_ptr<WaveModelGpu> FlatModel::createGpu(const gl::ShaderSources&) const
{
    return std::make_unique<FlatGpu>();
}

} // namespace swell
