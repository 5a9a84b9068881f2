// The spectral model's GPU images (spectral_gpu.cpp): their formats and
// the bytes a texel and a mip chain take. In a gpu/ folder: it names GL's
// formats.
#pragma once

#include <epoxy/gl.h>

#include <algorithm>

namespace swell::spectral {

// The images' formats, named once: the textures are made, bound and counted
// (WaveModelGpu::Work::bytesWritten) with these. The compute shaders'
// layout qualifiers name the same.
inline constexpr GLenum kInitialFormat = GL_RGBA32F;  // h0(k) and conj(h0(-k))
inline constexpr GLenum kOmegaFormat = GL_RG32UI;     // w(k) as a double's two words
// The displacement's and the derivatives' spectra, then fields: the FFTs
// work in place on these, in full float (the queries' millimetre stands on
// the displacement; the foam's steps read the derivatives' base level).
inline constexpr GLenum kSpectrumFormat = GL_RGBA32F;
// The shading's copy of the derivatives, with the slopes' second moments
// (as many layers again) so that one mip chain filters both: what every
// water pixel filters four times over. Half floats halve the bytes each
// filtered fetch reads and the chain's; their 11 significant bits hold a
// slope to 1/2048 of itself, far below what a normal or a highlight's
// spread shows (tests/gl/test_spectral_fields.cpp holds them to that).
inline constexpr GLenum kSlopeFormat = GL_RGBA16F;
inline constexpr GLenum kFoamFormat = GL_R16F;

// Bytes a texel of `format` takes (the formats above).
inline constexpr long long texelBytes(GLenum format)
{
    switch (format) {
    case GL_RGBA32F: return 16;
    case GL_RG32UI: return 8;
    case GL_RGBA16F: return 8;
    case GL_R16F: return 2;
    default: return 0;
    }
}

static_assert(texelBytes(kInitialFormat) > 0 && texelBytes(kOmegaFormat) > 0 && texelBytes(kSpectrumFormat) > 0 &&
              texelBytes(kSlopeFormat) > 0 && texelBytes(kFoamFormat) > 0);

// Texels of the levels `first` .. `levels` - 1 of a square mip chain of
// `size`^2 at its base, each with `layers` layers.
inline constexpr long long mipTexels(int size, int levels, int layers, int first = 0)
{
    long long texels = 0;
    for (int level = first; level < levels; ++level)
        texels += (long long)std::max(size >> level, 1) * std::max(size >> level, 1) * layers;
    return texels;
}

} // namespace swell::spectral
