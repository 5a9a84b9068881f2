// The spectral ocean over a sea floor (src/ocean/spectral/spectral_coast.h):
// the trains carry the longest cascade's height variance; offshore the
// surface is the open sea's, bit for bit; near the shore the longest band
// is exactly the trains summed over their coast field (so the coast field's
// own tests, tests/cpu/test_coast_field.cpp, hold the spectral model's
// shallow water to the laws of dispersion, shoaling, refraction and
// breaking), and no water moves on dry land.
#include "ocean/coast/coast_grid.h"
#include "ocean/spectral/spectral_coast.h"

#include "swell/coast_field.h"
#include "swell/gpu/ocean.h"
#include "swell/scene/scene.h"
#include "swell/scene/seabed.h"
#include "swell/scene/waves.h"
#include "swell/spectral_model.h"

#include <glm/geometric.hpp>
#include <gtest/gtest.h>

#include <cmath>
#include <complex>
#include <memory>

namespace {

swell::SpectralSettings seaSettings()
{
    swell::SpectralSettings s;
    s.wind.windSpeed_mps = 12.0;
    s.wind.windDirection_deg = 90.0; // towards +z: onto the beach
    s.wind.fetch_km = 300.0;
    s.foamLifetime_s = 0.0;          // no whitecaps: not what is tested, and their replay is slow
    s.seed = 11;
    return s;
}

// A 1:40 beach whose waterline runs along x at z = 300 m, the sea towards
// -z, the slope ending 60 m deep.
swell::Scene beachScene()
{
    swell::Scene scene = swell::defaultScene();
    scene.showTerrain = false;
    scene.seabed.toeDepth_m = 60.0;
    swell::SeabedBeach beach;
    beach.shorePoint_m = {0.0, 300.0};
    beach.seawardAzimuth_deg = 0.0;
    beach.slope = 1.0 / 40.0;
    beach.length_m = 4000.0;
    beach.top_m = 3.0;
    beach.landWidth_m = 200.0;
    scene.seabed.beaches.push_back(beach);
    return scene;
}

// The floor's depth at world point (x, z), m.
double depthAt(const swell::Seabed& seabed, glm::dvec2 p) { return -seabed.elevation_m(p); }

TEST(SpectralCoast, TheTrainsCarryTheLongestCascadesHeightVariance)
{
    // A field of the model's settings, as the model makes it.
    const swell::spectral::SpectralField field = swell::spectral::makeSpectralField(
        swell::SeaSpectrum(seaSettings().wind), seaSettings().choppiness, seaSettings().seed);
    const swell::WaveSet trains = swell::spectral::coastTrainsOf(field, seaSettings().wind.depth_m);
    ASSERT_EQ(trains.waves.size(), swell::kMaxCoastWaves);
    double band = 0.0, carried = 0.0;
    for (const std::complex<float>& h : field.h0[0])
        band += 2.0 * std::norm(std::complex<double>(h));
    for (const swell::Wave& w : trains.waves) {
        carried += 0.5 * w.amplitude_m * w.amplitude_m;
        // In the band: no longer than the patch, no shorter than its shortest.
        EXPECT_LE(w.wavelength_m, field.cascades[0].patch_m * (1.0 + 1e-12));
        EXPECT_GE(w.wavelength_m, field.cascades[0].shortestWavelength_m() * (1.0 - 1e-12));
    }
    EXPECT_NEAR(carried, band, 1e-9 * band);
    for (std::size_t i = 1; i < trains.waves.size(); ++i)
        EXPECT_GE(trains.waves[i - 1].wavelength_m, trains.waves[i].wavelength_m) << "longest first";
    // They hand over where the peak's waves begin to feel the bottom.
    const swell::CoastTrainDepths depths = swell::spectral::coastTrainDepthsOf(trains);
    EXPECT_GT(depths.noneDepth_m, depths.fullDepth_m);
    EXPECT_GT(depths.fullDepth_m, 5.0);
}

TEST(SpectralCoast, OffshoreTheSurfaceIsTheOpenSeas)
{
    const swell::SpectralSurface open(seaSettings());
    const swell::SpectralSurface model(seaSettings(), swell::Seabed(beachScene()));
    // Deep water over the floor's toe (60 m: the trains hand nothing over
    // there) and far beyond the floor.
    for (const glm::dvec2 p : {glm::dvec2(10.0, -2500.0), glm::dvec2(0.0, -20000.0), glm::dvec2(9000.0, 300.0)})
        for (const double t : {0.0, 17.25}) {
            const swell::SurfacePoint a = open.surfaceAt(p, t), b = model.surfaceAt(p, t);
            EXPECT_EQ(a.displacement_m, b.displacement_m) << p.x << ", " << p.y;
            EXPECT_EQ(a.normal, b.normal) << p.x << ", " << p.y;
        }
}

// Near the shore the trains carry the longest band wholly: with a filter
// that weighs the longest cascade and the trains fully and every shorter
// cascade not at all, the surface is the trains' Gerstner sum over their
// coast field, to the float texels' precision. Where the floor stands above
// the sea, nothing moves.
TEST(SpectralCoast, NearTheShoreTheLongestBandIsTheTrainsOverTheFloor)
{
    const swell::Scene scene = beachScene();
    const swell::Seabed seabed(scene);
    const swell::SpectralSurface model(seaSettings(), seabed);
    const swell::spectral::SpectralField field = swell::spectral::makeSpectralField(
        swell::SeaSpectrum(seaSettings().wind), seaSettings().choppiness, seaSettings().seed);
    // The trains over the same floor: the field the model solved (kept, so
    // asked again for the same trains and grid it is the same one).
    swell::WaveSet trains = swell::spectral::coastTrainsOf(field, seaSettings().wind.depth_m);
    trains.coast = swell::coast::coastFieldOf(seabed, trains);
    ASSERT_TRUE(trains.coast);
    // The second cascade's shortest wave weighs 0 at twice this footprint
    // or less; the first's and the trains' weigh 1.
    swell::SurfaceFilter filter;
    filter.footprint_m = 0.5 * field.cascades[0].shortestWavelength_m() / SWELL_FULL_CELLS_PER_WAVELENGTH;
    ASSERT_GE(2.0 * filter.footprint_m, field.cascades[1].shortestWavelength_m());
    const swell::CoastTrainDepths depths = swell::spectral::coastTrainDepthsOf(trains);
    int compared = 0;
    for (double z = 0.0; z <= 290.0; z += 10.0) {
        const glm::dvec2 p(37.0, z);
        // Well inside the trains' whole share (the field's bilinear depth
        // is the floor's within centimetres here).
        if (depthAt(seabed, p) > 0.9 * depths.fullDepth_m || depthAt(seabed, p) < 0.0)
            continue;
        const glm::dvec3 seen = model.surfaceAt(p, 23.5, filter).displacement_m;
        const glm::dvec3 expected = swell::displacementAt(trains, p, 23.5);
        EXPECT_LT(glm::length(seen - expected), 1e-9) << "at z = " << z;
        ++compared;
    }
    EXPECT_GE(compared, 5);
    // Dry sand: no wave, no displacement at all.
    for (const double t : {0.0, 23.5})
        EXPECT_EQ(model.surfaceAt({37.0, 330.0}, t).displacement_m, glm::dvec3(0.0));
}

} // namespace
