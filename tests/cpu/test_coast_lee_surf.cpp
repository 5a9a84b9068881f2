// The surf's measure in a breakwater's lee (swell/coast_field.h,
// CoastCommonSample::breaking): the share of the shoaled height that
// breaking took, so none where no wave breaks. A diffracted wave is lower
// than the rays' because less of it reaches the lee, not because it broke:
// a lee in deep water, where the waves are far below the breaker index
// times the depth, shows no surf, and the surf's whitewater is not drawn
// over a sheltered basin (the harbour preset's showed `surf` on 5.5% of a
// view of its basin at 1.2 to 1.6 m, where the diffracted swell is a
// fifth of the breaking height).
#include "support/numbers.h"

#include "swell/coast_field.h"
#include "swell/constants.h"
#include "swell/scene/waves.h"

#include <glm/geometric.hpp>
#include <gtest/gtest.h>

#include <cmath>

namespace {

using swell::test::kDeg;

// Water 20 m deep everywhere but a breakwater of dry cells three wide
// along +z from (400, 400) m to the grid's edge.
swell::DepthGrid leeSurfHarbour()
{
    swell::DepthGrid g;
    g.cell_m = 2.0;
    g.size = {400, 400};
    g.outsideDepth_m = 20.0;
    g.depth_m.assign(std::size_t(400) * 400, 20.0f);
    for (int j = 0; j < 400; ++j)
        for (int i = 0; i < 400; ++i)
            if (j * 2.0 >= 400.0 && std::abs(i * 2.0 - 400.0) <= 3.0)
                g.depth_m[std::size_t(j) * 400 + std::size_t(i)] = -2.0f;
    return g;
}

TEST(CoastField, ALeeWhereNoWaveBreaksHasNoSurf)
{
    // A wave 40 m long and 0.2 m high at normal incidence (towards +x): at
    // most a hundredth of the breaker index times the depth anywhere.
    swell::WaveSet set;
    set.depth_m = 20.0;
    set.waves.push_back(swell::Wave{{1.0, 0.0}, 40.0, 0.1, 0.0, 0.0});
    const swell::CoastField field(set, leeSurfHarbour());
    const glm::dvec2 tip{400.0, 400.0}, along{0.0, 1.0}, lee{1.0, 0.0};
    for (double r : {2.0, 4.0, 6.0})
        for (double into : {0.0, 30.0, 60.0}) {
            // theta from the breakwater's line; the shadow line at 90 degrees.
            const double theta = (90.0 - into) * kDeg;
            const glm::dvec2 p = tip + r * 40.0 * (std::cos(theta) * along + std::sin(theta) * lee);
            const swell::CoastCommonSample common = field.commonAt(p);
            EXPECT_LT(common.breaking, 0.01) << into << " deg into the shadow, r/L " << r << ": gain "
                                             << field.waveAt(0, p, swell::wavenumberVector(set.waves[0])).gain;
        }
    // In the open sea beside it, none either.
    EXPECT_EQ(field.commonAt(tip + glm::dvec2(200.0, -200.0)).breaking, 0.0);
}

} // namespace
