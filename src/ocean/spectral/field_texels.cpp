#include "ocean/spectral/field_texels.h"

#include <cstddef>
#include <cstring>

namespace swell::spectral {

std::uint16_t halfFloatBits(float value)
{
    // In integers on the float's bits (exact whatever the FPU's modes).
    std::uint32_t bits;
    std::memcpy(&bits, &value, sizeof bits);
    const std::uint32_t sign = (bits >> 16) & 0x8000u;
    const std::uint32_t magnitude = bits & 0x7fffffffu;
    if (magnitude > 0x7f800000u) // NaN, quiet
        return std::uint16_t(sign | 0x7e00u);
    if (magnitude == 0x7f800000u) // infinity
        return std::uint16_t(sign | 0x7c00u);
    if (magnitude >= 0x47800000u) // 2^16 and up: toward zero, the largest half (65504)
        return std::uint16_t(sign | 0x7bffu);
    if (magnitude < 0x38800000u) {
        // Below 2^-14: a subnormal half, a whole multiple of 2^-24 (the
        // float's significand, implicit bit included, shifted to that unit,
        // the rest dropped); under 2^-24 (float subnormals too), zero.
        if (magnitude < 0x33800000u)
            return std::uint16_t(sign);
        const std::uint32_t significand = (magnitude & 0x7fffffu) | 0x800000u;
        return std::uint16_t(sign | (significand >> (126u - (magnitude >> 23))));
    }
    // A normal half: the exponent rebiased (127 to 15), 10 of the 23
    // significand bits kept, the 13 others dropped.
    return std::uint16_t(sign | ((magnitude - ((127u - 15u) << 23)) >> 13));
}

void sizeFieldTexels(int cascades, FieldTexels& out)
{
    const std::size_t values = 4 * std::size_t(kSize) * kSize * std::size_t(cascades);
    out.displacement.resize(values);
    out.derivatives.resize(values);
    out.slopes.resize(2 * values);
}

void cascadeTexels(const CpuSurface::Fields& fields, int cascade, int cascades, FieldTexels& out)
{
    const std::size_t texels = std::size_t(kSize) * kSize;
    const auto& v = fields.values[std::size_t(cascade)];
    float* displacement = out.displacement.data() + 4 * texels * std::size_t(cascade);
    float* derivatives = out.derivatives.data() + 4 * texels * std::size_t(cascade);
    std::uint16_t* slopes = out.slopes.data() + 4 * texels * std::size_t(cascade);
    std::uint16_t* moments = out.slopes.data() + 4 * texels * std::size_t(cascades + cascade);
    for (std::size_t i = 0; i < texels; ++i) {
        for (std::size_t f = 0; f < 4; ++f) {
            displacement[4 * i + f] = v[f][i];
            derivatives[4 * i + f] = v[4 + f][i];
            slopes[4 * i + f] = halfFloatBits(v[4 + f][i]);
        }
        // As the column pass: in float, from the derivatives' slopes.
        const float sx = v[4][i], sz = v[5][i];
        moments[4 * i + 0] = halfFloatBits(sx * sx);
        moments[4 * i + 1] = halfFloatBits(sz * sz);
        moments[4 * i + 2] = halfFloatBits(sx * sz);
        moments[4 * i + 3] = 0; // +0.0
    }
}

} // namespace swell::spectral
