// The texels the spectral FFT's column pass writes (shaders/ocean/
// spectral_fft.comp), made from the CPU twin's fields instead: for a
// software rasteriser's interactive view, where the CPU's FFTs cost a
// fraction of the same passes run as compute shaders on the CPU.
#pragma once

#include "ocean/spectral/spectral_cpu.h"

#include <cstdint>
#include <vector>

namespace swell::spectral {

// Per cascade c < cascades, RGBA texels of kSize^2, x fastest then z, layer
// by layer, as the column pass stores them:
// - displacement layer c: (Dx, Dy, Dz, dDx/dz), floats;
// - derivatives layer c: (dDy/dx, dDy/dz, dDx/dx, dDz/dz), floats;
// - slopes layer c: the derivatives again (the shading's copy), and slopes
//   layer cascades + c: the slopes' second moments ((dDy/dx)^2, (dDy/dz)^2,
//   dDy/dx * dDy/dz, 0, products in float as the column pass makes them),
//   which LEAN mapping filters (Olano & Baker 2010, sec. 3); both in the
//   texture's half floats (halfFloatBits), so that the upload is a copy and
//   the conversion is done where the texels are made, on either thread of
//   the split (the GL's own conversion on the context's thread was a
//   quarter of the upload's time).
struct FieldTexels {
    std::vector<float> displacement, derivatives;
    std::vector<std::uint16_t> slopes; // 2 * cascades layers
};
// Made in two steps, for a caller that makes the cascades' texels on more
// than one thread: sizes `out` for `cascades` cascades (first, on one
// thread), then writes cascade c's texels alone (each cascade on any thread).
void sizeFieldTexels(int cascades, FieldTexels& out);
void cascadeTexels(const CpuSurface::Fields& fields, int cascade, int cascades, FieldTexels& out);

// A float as a half float (IEEE 754 binary16), rounded toward zero, as
// Mesa's upload of floats to a half-float texture stores it (its format
// packing rounds toward zero, not to nearest: measured, and held to it bit
// for bit by tests/gl/test_spectral_fields.cpp on a whole frame's texels):
// infinities and NaN kept, a finite value too large to the largest half,
// tiny ones to subnormals or zero.
std::uint16_t halfFloatBits(float value);

} // namespace swell::spectral
