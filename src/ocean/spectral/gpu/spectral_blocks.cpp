// The spectral model's uniform block, for the GLSL generator (ocean/gpu/model_blocks.h).
#include "ocean/gpu/model_blocks.h"
#include "ocean/spectral/gpu/spectral_uniforms.h"
#include "swell/gpu/bindings.h"

namespace swell::detail {

std::vector<gl::UniformBlock> spectralGlslBlocks()
{
    return {{&blockStructOf(static_cast<const spectral::SpectralUniforms*>(nullptr)), "SWELL_BINDING_OCEAN",
             SWELL_BINDING_OCEAN, "gpu/spectral_block.glsl", "src/ocean/spectral/gpu/spectral_uniforms.h"}};
}

} // namespace swell::detail
