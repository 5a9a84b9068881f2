#include "ocean/spectral/field_texels.h"

#include <cstddef>

namespace swell::spectral {

void sizeFieldTexels(int cascades, FieldTexels& out)
{
    const std::size_t floats = 4 * std::size_t(kSize) * kSize * std::size_t(cascades);
    out.displacement.resize(floats);
    out.derivatives.resize(floats);
    out.slopeMoments.resize(floats);
}

void cascadeTexels(const CpuSurface::Fields& fields, int cascade, FieldTexels& out)
{
    const std::size_t texels = std::size_t(kSize) * kSize;
    const auto& v = fields.values[std::size_t(cascade)];
    float* displacement = out.displacement.data() + 4 * texels * std::size_t(cascade);
    float* derivatives = out.derivatives.data() + 4 * texels * std::size_t(cascade);
    float* moments = out.slopeMoments.data() + 4 * texels * std::size_t(cascade);
    for (std::size_t i = 0; i < texels; ++i) {
        for (std::size_t f = 0; f < 4; ++f) {
            displacement[4 * i + f] = v[f][i];
            derivatives[4 * i + f] = v[4 + f][i];
        }
        // As the column pass: in float, from the derivatives' slopes.
        const float sx = v[4][i], sz = v[5][i];
        moments[4 * i + 0] = sx * sx;
        moments[4 * i + 1] = sz * sz;
        moments[4 * i + 2] = sx * sz;
        moments[4 * i + 3] = v[3][i]; // dDx/dz, filtered with the slopes
    }
}

void fieldTexels(const CpuSurface::Fields& fields, int cascades, FieldTexels& out)
{
    sizeFieldTexels(cascades, out);
    for (int c = 0; c < cascades; ++c)
        cascadeTexels(fields, c, out);
}

} // namespace swell::spectral
