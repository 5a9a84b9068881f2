// GerstnerModel: the Gerstner sum's GPU half, which uploads the waves
// longest first with their phases at the grid centre; its CPU queries are
// GerstnerSurface's (ocean/gerstner/gerstner_surface.cpp).
#include "swell/gerstner_model.h"

#include "swell/coast_field.h"

#include "ocean/coast/gpu/coast_gpu.h"
#include "ocean/gerstner/gpu/gerstner_uniforms.h"
#include "swell/gl/handle.h"
#include "swell/gpu/bindings.h"
#include "swell/gpu/limits.h"
#include "swell/wave_model_gpu.h"

#include <fmt/format.h>
#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <vector>

namespace swell {

namespace {

class GerstnerGpu final : public WaveModelGpu {
public:
    explicit GerstnerGpu(const WaveSet& waves) : waves_(waves), coast_(waves.coast)
    {
        buffer_ = gl::Buffer::create();
        glNamedBufferStorage(buffer_.id(), sizeof(detail::GerstnerUniforms), nullptr, GL_DYNAMIC_STORAGE_BIT);
        // Longest first: the shaders stop at the first wave their cells or
        // pixels cannot resolve, since every later one is shorter still.
        const int count = std::min<int>(int(waves_.waves.size()), SWELL_MAX_WAVES);
        for (int i = 0; i < count; ++i)
            order_.push_back(&waves_.waves[size_t(i)]);
        std::stable_sort(order_.begin(), order_.end(),
                         [](const Wave* a, const Wave* b) { return a->wavelength_m > b->wavelength_m; });
        // Mean square slope of each wave and every shorter one: what a pixel
        // that resolves none of them must add as roughness. A wave of slope
        // amplitude k*a has slope variance (k*a)^2/2. The waves never
        // change, so neither does this: found once, not per view.
        tailSlopeVariance_.assign(order_.size(), 0.0);
        double tail = 0.0;
        for (std::size_t i = order_.size(); i-- > 0;) {
            const double ka = glm::length(wavenumberVector(*order_[i])) * order_[i]->amplitude_m;
            tail += 0.5 * ka * ka;
            tailSlopeVariance_[i] = tail;
        }
        for (const Wave* w : order_)
            coastLayer_.push_back(waves_.coast ? waves_.coast->layerOf(std::size_t(w - waves_.waves.data())) : -1);
    }

    std::string shaderFile() const override { return "ocean/gerstner.glsl"; }

    // A Gerstner sum has no state: the step is the time, the view's upload
    // all there is.
    void prepareFrame(glm::dvec2 gridCenter_m, double time_s) override
    {
        time_s_ = time_s;
        prepareView(gridCenter_m);
    }

    void prepareView(glm::dvec2 gridCenter_m) override { upload(gridCenter_m, time_s_); }

    // Stateless: any time's phases are as exact as the current ones.
    bool prepareEarlierView(glm::dvec2 gridCenter_m, double earlier_s) override
    {
        upload(gridCenter_m, earlier_s);
        return true;
    }

    void bind() const override
    {
        glBindBufferBase(GL_UNIFORM_BUFFER, SWELL_BINDING_OCEAN, buffer_.id());
        coast_.bind();
    }

private:
    // The waves' block for a grid centred at gridCenter_m at time_s.
    void upload(glm::dvec2 gridCenter_m, double time_s)
    {
        detail::GerstnerUniforms u{};
        const int count = int(order_.size());
        for (int i = 0; i < count; ++i) {
            const Wave& w = *order_[size_t(i)];
            // Exactly the k*d the CPU wave functions use.
            const glm::dvec2 kd = wavenumberVector(w);
            const double k = glm::length(kd);
            const glm::dvec2 d = kd / k;
            detail::GerstnerWaveUniform& g = u.waves[i];
            g.direction = glm::vec2(d);
            g.wavenumber_rad_per_m = float(k);
            g.amplitude_m = float(w.amplitude_m);
            g.steepness = float(w.steepness);
            g.phase_rad = float(wrappedPhase(w, waves_.depth_m, gridCenter_m, time_s));
            g.wavelength_m = float(w.wavelength_m);
            g.tailSlopeVariance = float(tailSlopeVariance_[size_t(i)]);
            g.coastLayer = coastLayer_[size_t(i)];
        }
        u.waveCount = count;
        coast_.prepareView(gridCenter_m, time_s);
        glNamedBufferSubData(buffer_.id(), 0, sizeof(u), &u);
    }

    WaveSet waves_;
    std::vector<const Wave*> order_; // into waves_, longest first
    std::vector<double> tailSlopeVariance_; // of each wave in order_ and every shorter one
    std::vector<int> coastLayer_;           // of each wave in order_: its coast field's layer, -1 none
    gl::Buffer buffer_;
    detail::CoastGpu coast_; // its field's texels and place, no trains
    double time_s_ = 0.0; // the time prepareFrame() reached, s
};

} // namespace

GerstnerModel::GerstnerModel(WaveSet waves) : GerstnerSurface(std::move(waves)) {}

std::string_view GerstnerModel::name() const { return "gerstner"; }

std::string GerstnerModel::summary() const
{
    const WaveSet& set = waves();
    if (set.waves.empty())
        return "no waves";
    double shortest = set.waves.front().wavelength_m, longest = shortest;
    for (const Wave& w : set.waves) {
        shortest = std::min(shortest, w.wavelength_m);
        longest = std::max(longest, w.wavelength_m);
    }
    return fmt::format("{} Gerstner waves, {:.3g} .. {:.3g} m", set.waves.size(), shortest, longest);
}

std::unique_ptr<WaveModelGpu> GerstnerModel::createGpu(const gl::ShaderSources&) const
{
    return std::make_unique<GerstnerGpu>(waves());
}

} // namespace swell
