// The wave models' own uniform blocks (each model's GPU half's interface to
// its GLSL file), for the GLSL generator and the test that checks it
// (render/gpu/glsl_files.h). Each model lists its blocks in its own folder,
// so that nothing outside the folder includes the model's internals.
#pragma once

#include "gl/block_layout.h"

#include <vector>

namespace swell::detail {

// ocean/gerstner/gpu/gerstner_blocks.cpp
std::vector<gl::UniformBlock> gerstnerGlslBlocks();
// ocean/spectral/gpu/spectral_blocks.cpp
std::vector<gl::UniformBlock> spectralGlslBlocks();
// ocean/coast/gpu/coast_blocks.cpp: the coast field's, which every model reads
std::vector<gl::UniformBlock> coastGlslBlocks();

} // namespace swell::detail
