// The water's edge in a frame's labels (swell::measureShoreline): the sides
// between water and land pixels chained corner to corner, each corner's
// water point along a water pixel's ray at its range.
#include "swell/dataset/labels.h"
#include "swell/gpu/label_classes.h"

#include <glm/geometric.hpp>
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <string>
#include <vector>

namespace {

// A w x h frame from rows of characters: '~' water, '#' land, '.' sky,
// 'f' whitecap foam; every range 10 m; a pinhole camera at the origin
// looking along +z (world = camera axes).
swell::FrameLabels frameOf(const std::vector<std::string>& rows)
{
    swell::FrameLabels labels;
    labels.size = {int(rows.front().size()), int(rows.size())};
    for (const std::string& row : rows)
        for (const char c : row) {
            labels.semantic.push_back(c == '~'   ? SWELL_LABEL_WATER
                                      : c == 'f' ? SWELL_LABEL_WHITECAP_FOAM
                                      : c == '#' ? SWELL_LABEL_TERRAIN
                                                 : SWELL_LABEL_SKY);
            labels.range_m.push_back(10.0f);
        }
    labels.camera.size = labels.size;
    labels.camera.fx_px = labels.camera.fy_px = 100.0;
    labels.camera.cx_px = 0.5 * labels.size.x;
    labels.camera.cy_px = 0.5 * labels.size.y;
    return labels;
}

TEST(Shoreline, AStraightEdgeIsOneChainAlongThePixelSides)
{
    swell::FrameLabels labels = frameOf({"...###", "~~~###", "~~f###", "~~~###"});
    swell::measureShoreline(labels);
    ASSERT_EQ(labels.shoreline.size(), 1u);
    const swell::ShoreLine& line = labels.shoreline.front();
    // From the corner (3, 1), down the side x = 3 to (3, 4): the foam is water too.
    ASSERT_EQ(line.points_px.size(), 4u);
    EXPECT_EQ(line.points_px.front(), glm::dvec2(3.0, 1.0));
    EXPECT_EQ(line.points_px.back(), glm::dvec2(3.0, 4.0));
    for (const glm::dvec2& p : line.points_px)
        EXPECT_EQ(p.x, 3.0);
    // Each corner's water point: 10 m along the ray of a water pixel touching it.
    ASSERT_EQ(line.points_m.size(), line.points_px.size());
    for (std::size_t k = 0; k < line.points_m.size(); ++k) {
        EXPECT_NEAR(glm::length(line.points_m[k]), 10.0, 1e-9);
        // The pixel left of the corner's side: its centre 2.5 px along x.
        const double x = (2.5 - 3.0) / 100.0;
        EXPECT_NEAR(line.points_m[k].x / line.points_m[k].z, x, 1e-12) << k;
    }
}

TEST(Shoreline, AnIslandIsAClosedLoopAndTheSkyNoShore)
{
    swell::FrameLabels labels = frameOf({"......", "~~~~~~", "~~##~~", "~~##~~", "~~~~~~"});
    swell::measureShoreline(labels);
    ASSERT_EQ(labels.shoreline.size(), 1u);
    const swell::ShoreLine& loop = labels.shoreline.front();
    // Round the 2 x 2 island's 8 sides, back to the first corner.
    ASSERT_EQ(loop.points_px.size(), 9u);
    EXPECT_EQ(loop.points_px.front(), loop.points_px.back());
    for (const glm::dvec2& p : loop.points_px) {
        EXPECT_GE(p.x, 2.0);
        EXPECT_LE(p.x, 4.0);
        EXPECT_GE(p.y, 2.0);
        EXPECT_LE(p.y, 4.0);
    }
    // Water against sky only: no shore.
    swell::FrameLabels open = frameOf({"......", "~~~~~~"});
    swell::measureShoreline(open);
    EXPECT_TRUE(open.shoreline.empty());
}

TEST(Shoreline, TheDepthsSeenFromBelowHaveNoWaterPoint)
{
    swell::FrameLabels labels = frameOf({"~~##", "~~##"});
    for (float& r : labels.range_m)
        r = std::numeric_limits<float>::infinity();
    swell::measureShoreline(labels);
    ASSERT_EQ(labels.shoreline.size(), 1u);
    for (const glm::dvec3& p : labels.shoreline.front().points_m)
        EXPECT_TRUE(std::isnan(p.x));
}

} // namespace
