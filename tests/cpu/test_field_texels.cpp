// The interactive view's slopes are converted to half floats on the CPU
// (spectral::halfFloatBits) and uploaded as they are, where the GL used to
// convert floats: the conversion must be the GL's, toward zero
// (tests/gl/test_spectral_fields.cpp holds it to Mesa's on a whole frame's
// texels; these are the cases a frame may not hold).
#include "ocean/spectral/field_texels.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <limits>

namespace {

using swell::spectral::halfFloatBits;

TEST(FieldTexels, HalfFloatsRoundTowardZero)
{
    EXPECT_EQ(halfFloatBits(0.0f), 0x0000);
    EXPECT_EQ(halfFloatBits(-0.0f), 0x8000);
    EXPECT_EQ(halfFloatBits(1.0f), 0x3c00);
    EXPECT_EQ(halfFloatBits(-2.0f), 0xc000);
    EXPECT_EQ(halfFloatBits(65504.0f), 0x7bff); // the largest half
    // Between two halves, the one nearer zero, however near the other:
    // just under 1 + 2^-10 (and under 2), halfway, and above.
    EXPECT_EQ(halfFloatBits(std::nextafter(1.0f + std::ldexp(1.0f, -10), 0.0f)), 0x3c00);
    EXPECT_EQ(halfFloatBits(1.0f + 3.0f * std::ldexp(1.0f, -11)), 0x3c01);
    EXPECT_EQ(halfFloatBits(-(1.0f + 3.0f * std::ldexp(1.0f, -11))), 0xbc01);
    EXPECT_EQ(halfFloatBits(std::nextafter(2.0f, 0.0f)), 0x3fff);
    EXPECT_EQ(halfFloatBits(0.1f), 0x2e66);
    // Past the largest half: toward zero it stays the largest; infinities stay.
    EXPECT_EQ(halfFloatBits(65519.0f), 0x7bff);
    EXPECT_EQ(halfFloatBits(65536.0f), 0x7bff);
    EXPECT_EQ(halfFloatBits(-1e30f), 0xfbff);
    EXPECT_EQ(halfFloatBits(std::numeric_limits<float>::infinity()), 0x7c00);
    EXPECT_EQ(halfFloatBits(-std::numeric_limits<float>::infinity()), 0xfc00);
    EXPECT_EQ(halfFloatBits(std::numeric_limits<float>::quiet_NaN()) & 0x7e00, 0x7e00);
    // Subnormal halves, whole multiples of 2^-24, and the smallest normal 2^-14.
    EXPECT_EQ(halfFloatBits(std::ldexp(1.0f, -14)), 0x0400);
    EXPECT_EQ(halfFloatBits(std::nextafter(std::ldexp(1.0f, -14), 0.0f)), 0x03ff);
    EXPECT_EQ(halfFloatBits(std::ldexp(1.0f, -24)), 0x0001);
    EXPECT_EQ(halfFloatBits(std::ldexp(3.0f, -24)), 0x0003);
    EXPECT_EQ(halfFloatBits(std::ldexp(7.0f, -25)), 0x0003);
    EXPECT_EQ(halfFloatBits(std::nextafter(std::ldexp(1.0f, -24), 0.0f)), 0x0000);
    EXPECT_EQ(halfFloatBits(std::numeric_limits<float>::denorm_min()), 0x0000);
    EXPECT_EQ(halfFloatBits(-std::ldexp(1.0f, -24)), 0x8001);
    // Every half's own value converts back to its bits, and every float up to the next half to the same bits.
    for (std::uint32_t h = 0; h < 0x7c00; ++h) {
        const float value = h < 0x400 ? std::ldexp(float(h), -24)
                                      : std::ldexp(1.0f + float(h & 0x3ff) / 1024.0f, int(h >> 10) - 15);
        ASSERT_EQ(halfFloatBits(value), h) << value;
        ASSERT_EQ(halfFloatBits(-value), h | 0x8000) << -value;
        if (h + 1 < 0x7c00) {
            const float next = h + 1 < 0x400 ? std::ldexp(float(h + 1), -24)
                                             : std::ldexp(1.0f + float((h + 1) & 0x3ff) / 1024.0f, int((h + 1) >> 10) - 15);
            ASSERT_EQ(halfFloatBits(std::nextafter(next, 0.0f)), h) << next;
        }
    }
}

} // namespace
