// The Gerstner model's uniform block, for the GLSL generator (ocean/gpu/model_blocks.h).
#include "ocean/gerstner/gpu/gerstner_uniforms.h"
#include "ocean/gpu/model_blocks.h"
#include "swell/gpu/bindings.h"

namespace swell::detail {

std::vector<gl::UniformBlock> gerstnerGlslBlocks()
{
    return {{&blockStructOf(static_cast<const GerstnerUniforms*>(nullptr)), "SWELL_BINDING_OCEAN",
             SWELL_BINDING_OCEAN, "gpu/gerstner_block.glsl", "src/ocean/gerstner/gpu/gerstner_uniforms.h"}};
}

} // namespace swell::detail
