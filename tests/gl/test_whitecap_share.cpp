// The storm's whitecaps at Monahan & O'Muircheartaigh's (1980) cover at
// every time, not only on average (issue #47, item 1): in every 1 s window
// of a 60 s clip of the storm preset (20 m/s), the share of the visible sea
// its labels call whitecap_foam within 1.5 times Monahan's, from the
// preset's camera (10 m up, where half the sea's pixels lie within 22 m)
// and from 300 m straight above it.
//
// Disabled: red. Designs measured (docs/RENDERING.md, "Whitecaps"):
// - foam where J is among the sea's lowest share (before issue 47): from
//   the preset's camera 0.06 to 4.84 times Monahan's, from 300 m 0.57 to
//   0.84: a long wave's compressed phase lowered J over whole faces;
// - this build: J scored against its own 5 x 5 texels, each breaking
//   spread over 3 x 3, the ramp found per sea so a still covers Monahan's
//   share, labels by the point each pixel's ray meets: 0.21 to 2.10 and
//   0.81 to 0.93 (the preset's camera, 10 m up, sees half its sea within
//   22 m, where a few 5.6 m breakings and their trails come and go);
// - the same without the spread and with a ramp six times softer: 0.67
//   to 1.29 and 0.94 to 1.01, but no breaking is dense and from 300 m the
//   sea is an even haze of lace, not whitecaps (not kept).
// Small frames and labels only: about 30 s on 2 loaded cores.
#include "support/gl_test.h"
#include "support/whitecap_share.h"

#include <gtest/gtest.h>

namespace {

class WhitecapShare : public swell::test::GlTest {};

constexpr double kAllowedFactor = 1.5; // the issue's

TEST_F(WhitecapShare, DISABLED_TheStormHoldsMonahansCoverInEverySecond)
{
    constexpr double kWind_mps = 20.0; // the preset's own
    const swell::test::WhitecapShares shares = swell::test::stormWhitecapShares(kWind_mps, 60.0, {160, 90});
    EXPECT_LE(swell::test::largestMissFactor("the preset's camera", kWind_mps, shares.presetCamera), kAllowedFactor);
    EXPECT_LE(swell::test::largestMissFactor("300 m up", kWind_mps, shares.from300m), kAllowedFactor);
}

} // namespace
