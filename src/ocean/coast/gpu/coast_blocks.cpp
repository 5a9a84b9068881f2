// The coast field's uniform block, for the GLSL generator (ocean/gpu/model_blocks.h).
#include "ocean/coast/gpu/coast_uniforms.h"
#include "ocean/gpu/model_blocks.h"
#include "swell/gpu/bindings.h"

namespace swell::detail {

std::vector<gl::UniformBlock> coastGlslBlocks()
{
    return {{&blockStructOf(static_cast<const CoastUniforms*>(nullptr)), "SWELL_BINDING_COAST", SWELL_BINDING_COAST,
             "gpu/coast_block.glsl", "src/ocean/coast/gpu/coast_uniforms.h"}};
}

} // namespace swell::detail
