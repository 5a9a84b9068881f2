// The coast field on the GPU: its texels in the coast units and its block
// (shaders/coast_field.glsl), for any wave model; with the trains a model
// hands it in place of its own longest band (the spectral model's), or
// none (the Gerstner model's waves carry their own layers).
// Library-internal.
#pragma once

#include "swell/coast_field.h"
#include "swell/gl/handle.h"
#include "swell/scene/waves.h"

#include <glm/vec2.hpp>

#include <memory>

namespace swell::detail {

class CoastGpu {
public:
    // `field` may be null: no coast (the block says so, and the samplers
    // get one open-sea texel each so that they always have a texture of
    // their kind). `trains` must be the set the field was solved for, or
    // empty; `depths` says where the trains take over.
    CoastGpu(std::shared_ptr<const CoastField> field, WaveSet trains = {}, CoastTrainDepths depths = {});

    // The block for a view centred at gridCenter_m at time_s: the field's
    // place relative to the centre and the trains' phases there.
    void prepareView(glm::dvec2 gridCenter_m, double time_s);
    void bind() const;

private:
    void uploadTexels();

    std::shared_ptr<const CoastField> field_;
    WaveSet trains_;
    CoastTrainDepths depths_;
    gl::Buffer buffer_;
    gl::Texture waves_;
    gl::Texture common_;
};

} // namespace swell::detail
