#include "ocean/spectral/field_texels.h"

#include <cstddef>

namespace swell::spectral {

void fieldTexels(const CpuSurface::Fields& fields, int cascades, FieldTexels& out)
{
    const std::size_t texels = std::size_t(kSize) * kSize;
    out.displacement.resize(4 * texels * std::size_t(cascades));
    out.derivatives.resize(out.displacement.size());
    out.slopeMoments.resize(out.displacement.size());
    for (int c = 0; c < cascades; ++c) {
        const auto& v = fields.values[std::size_t(c)];
        float* displacement = out.displacement.data() + 4 * texels * std::size_t(c);
        float* derivatives = out.derivatives.data() + 4 * texels * std::size_t(c);
        float* moments = out.slopeMoments.data() + 4 * texels * std::size_t(c);
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
            moments[4 * i + 3] = 0.0f;
        }
    }
}

} // namespace swell::spectral
