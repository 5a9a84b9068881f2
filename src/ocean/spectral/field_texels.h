// The texels the spectral FFT's column pass writes (shaders/ocean/
// spectral_fft.comp), made from the CPU twin's fields instead: for a
// software rasteriser's interactive view, where the CPU's FFTs cost a
// fraction of the same passes run as compute shaders on the CPU.
#pragma once

#include "ocean/spectral/spectral_cpu.h"

#include <vector>

namespace swell::spectral {

// Per cascade c < cascades, RGBA texels of kSize^2, x fastest then z, layer
// by layer, as the column pass stores them:
// - displacement layer c: (Dx, Dy, Dz, dDx/dz);
// - derivatives layer c: (dDy/dx, dDy/dz, dDx/dx, dDz/dz);
// - slopes layer c: the derivatives again (the shading's copy), and slopes
//   layer kCascades + c: the slopes' second moments ((dDy/dx)^2, (dDy/dz)^2,
//   dDy/dx * dDy/dz) and the cross derivative dDx/dz beside them (so that
//   it is filtered with the other derivatives), which LEAN mapping filters
//   (Olano & Baker 2010, sec. 3). The slopes' moment layers are written after all cascades'
//   derivative layers: `slopeMoments` holds them apart.
struct FieldTexels {
    std::vector<float> displacement, derivatives, slopeMoments;
};
void fieldTexels(const CpuSurface::Fields& fields, int cascades, FieldTexels& out);
// The same in two steps, for a caller that makes the cascades' texels on
// more than one thread: sizes `out` for `cascades` cascades (first, on one
// thread), then writes cascade c's texels alone (each cascade on any thread).
void sizeFieldTexels(int cascades, FieldTexels& out);
void cascadeTexels(const CpuSurface::Fields& fields, int cascade, FieldTexels& out);

} // namespace swell::spectral
