// The storm's whitecaps at Monahan & O'Muircheartaigh's (1980) cover at
// every time, not only on average (issue #47, item 1): in every 1 s window
// of a 60 s clip of the storm preset (20 m/s), the share of the visible sea
// its labels call whitecap_foam within 1.5 times Monahan's, from the
// preset's camera (10 m up, where half the sea's pixels lie within 22 m)
// and from 300 m straight above it.
//
// Disabled: red. With foam made where J is among the sea's lowest (this
// build), the preset's camera sees 0.06 to 4.84 times Monahan's cover
// (0.0068 to 0.51 of its sea) and 300 m up 0.57 to 0.84 times: the sea
// the camera sees lies half within 22 m, less than one 300 m wave, and a
// long wave's compressed phase lowers J over a whole face. A breaking
// score against each texel's neighbourhood (branch helper-foam-score)
// spread the breaking evenly but, calibrated to the mean covered share
// (Whitecaps.CoverFollowsMonahan), left most foam as lace under half a
// pixel, which the labels do not count (0 to 0.25 and 0 to 0.01), and
// calibrated to the labels put lace over the whole sea (mean cover 3.9
// times Monahan's; windows 0.79 to 1.75 and 1.19 to 1.36).
// docs/RENDERING.md, "Whitecaps", has the numbers. Small frames and labels
// only: about 40 s on 2 loaded cores.
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
