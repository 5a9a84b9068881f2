// The wave models' CPU queries on their own (GerstnerSurface,
// SpectralSurface: no GL code linked), and ComposedSurface, the one
// composition of a surface and surface sources that the floating bodies and
// DrawnSurface query.
#include "swell/composed_surface.h"
#include "swell/gerstner_model.h"
#include "swell/spectral_model.h"
#include "swell/error.h"

#include <gtest/gtest.h>

#include <glm/geometric.hpp>

#include <cmath>
#include <memory>
#include <vector>

namespace {

swell::WaveSet twoWaves()
{
    swell::WaveSet set;
    set.waves = {{{1.0, 0.0}, 30.0, 0.6, 0.7, 0.0}, {{0.6, 0.8}, 11.0, 0.25, 0.5, 1.3}};
    return set;
}

// A source a host might add: a mound whose height and slopes come from one formula.
class Mound final : public swell::SurfaceSource {
public:
    Mound(glm::dvec2 centre_m, double height_m) : centre_m_(centre_m), height_m_(height_m) {}
    glm::dvec3 heightAt(glm::dvec2 p, double time_s) const override
    {
        const glm::dvec2 d = p - centre_m_;
        const double h = height_m_ * std::exp(-glm::dot(d, d) / 50.0) * std::cos(0.5 * time_s);
        return {h, -h * 2.0 * d.x / 50.0, -h * 2.0 * d.y / 50.0};
    }
    double reach_m(double) const override { return std::abs(height_m_); }
    std::string glsl() const override { return {}; }
    swell::SurfaceSourceParameters gpuParameters(double, glm::dvec3) const override { return {}; }

private:
    glm::dvec2 centre_m_;
    double height_m_;
};

TEST(SurfaceQuery, GerstnerSurfaceAnswersWithTheWaveFunctions)
{
    const swell::WaveSet set = twoWaves();
    const swell::GerstnerSurface surface(set);
    const swell::SurfaceFilter filter{2.0, 0.8};
    for (const glm::dvec2 p : {glm::dvec2(0.0), glm::dvec2(13.5, -7.25), glm::dvec2(-4.0e4, 2.5e4)})
        for (double t : {0.0, 3.7, 1.0e5}) {
            EXPECT_EQ(surface.surfaceAt(p, t, filter).displacement_m, swell::surfaceAt(set, p, t, filter).displacement_m);
            EXPECT_EQ(surface.restPointUnder(p, t), swell::restPointUnder(set, p, t));
            EXPECT_NEAR(surface.heightAt(p, t), swell::heightAt(set, p, t), 1e-12);
        }
    EXPECT_DOUBLE_EQ(surface.reach().vertical_m, 0.85);
    swell::WaveSet noDirection = set;
    noDirection.waves[1].direction = glm::dvec2(0.0);
    EXPECT_THROW(swell::GerstnerSurface{noDirection}, swell::InputError);
}

TEST(SurfaceQuery, SpectralSurfaceFindsTheRestPointUnderAPoint)
{
    swell::SpectralSettings settings;
    settings.wind.windSpeed_mps = 11.0;
    const swell::SpectralSurface surface(settings);
    EXPECT_GT(surface.heightDeviation_m(), 0.1);
    EXPECT_GT(surface.reach().vertical_m, 3.0 * surface.heightDeviation_m());
    for (const glm::dvec2 p : {glm::dvec2(0.0), glm::dvec2(31.0, -12.0), glm::dvec2(-800.0, 450.0)}) {
        const double t = 8.0;
        const glm::dvec2 rest = surface.restPointUnder(p, t);
        const glm::dvec3 d = surface.displacementAt(rest, t);
        EXPECT_LT(glm::length(rest + glm::dvec2(d.x, d.z) - p), 1e-6);
        EXPECT_EQ(surface.heightAt(p, t), d.y);
        // The normal's query moves the point where the displacement's does.
        EXPECT_NEAR(surface.surfaceAt(rest, t).displacement_m.y, d.y, 1e-6);
    }
}

TEST(ComposedSurface, WithoutSourcesItIsTheSurfaceItself)
{
    const auto waves = std::make_shared<const swell::GerstnerSurface>(twoWaves());
    const swell::ComposedSurface composed(waves, {});
    const swell::SurfaceFilter filter{1.0, 0.9};
    for (const glm::dvec2 p : {glm::dvec2(0.3, 0.0), glm::dvec2(-12.0, 40.0)}) {
        const swell::SurfacePoint a = composed.surfaceAt(p, 2.5, filter), b = waves->surfaceAt(p, 2.5, filter);
        EXPECT_EQ(a.displacement_m, b.displacement_m);
        EXPECT_EQ(a.normal, b.normal);
        EXPECT_EQ(composed.restPointUnder(p, 2.5, filter), waves->restPointUnder(p, 2.5, filter));
        EXPECT_EQ(composed.heightAt(p, 2.5), waves->heightAt(p, 2.5));
    }
    EXPECT_EQ(composed.reach().vertical_m, waves->reach().vertical_m);
    EXPECT_EQ(composed.heightDeviation_m(), waves->heightDeviation_m());
}

TEST(ComposedSurface, SourcesAddHeightsAndSlopesAtTheRestPoint)
{
    const auto waves = std::make_shared<const swell::GerstnerSurface>(twoWaves());
    const auto a = std::make_shared<const Mound>(glm::dvec2(3.0, -2.0), 0.4);
    const auto b = std::make_shared<const Mound>(glm::dvec2(-5.0, 1.0), -0.3);
    const swell::ComposedSurface composed(waves, {a, b});
    for (const glm::dvec2 rest : {glm::dvec2(0.0), glm::dvec2(4.0, -1.0), glm::dvec2(-6.0, 2.5)}) {
        const double t = 1.1;
        const glm::dvec3 ha = a->heightAt(rest, t), hb = b->heightAt(rest, t);
        const swell::SurfacePoint w = waves->surfaceAt(rest, t);
        const swell::SurfacePoint c = composed.surfaceAt(rest, t);
        EXPECT_DOUBLE_EQ(c.displacement_m.y, w.displacement_m.y + ha.x + hb.x);
        EXPECT_EQ(c.displacement_m.x, w.displacement_m.x);
        EXPECT_EQ(composed.displacementAt(rest, t), c.displacement_m);
        // The normal of the summed height field: the slopes add.
        const glm::dvec3 n = w.normal / w.normal.y - glm::dvec3(ha.y + hb.y, 0.0, ha.z + hb.z);
        EXPECT_LT(glm::length(c.normal - glm::normalize(n)), 1e-12);
        // The rest point under a world point is the waves' own.
        EXPECT_EQ(composed.restPointUnder(rest, t), waves->restPointUnder(rest, t));
    }
    EXPECT_THROW(swell::ComposedSurface(nullptr, {}), swell::Error);
    EXPECT_THROW(swell::ComposedSurface(waves, {nullptr}), swell::Error);
}

// The floating bodies' clock: the surface runs at t + offset, the sources at t.
TEST(ComposedSurface, TheSurfaceRunsOnItsOwnClock)
{
    const auto waves = std::make_shared<const swell::GerstnerSurface>(twoWaves());
    const auto mound = std::make_shared<const Mound>(glm::dvec2(1.0, 1.0), 0.5);
    const double offset_s = -60.0;
    const swell::ComposedSurface composed(waves, {mound}, offset_s);
    for (double t : {0.0, 2.0, 17.25}) {
        const glm::dvec2 p(2.0, -3.0);
        const glm::dvec2 rest = waves->restPointUnder(p, t + offset_s);
        EXPECT_EQ(composed.restPointUnder(p, t), rest);
        EXPECT_EQ(composed.heightAt(p, t), waves->displacementAt(rest, t + offset_s).y + mound->heightAt(rest, t).x);
    }
}

} // namespace
