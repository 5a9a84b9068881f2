// One surface function per model: the vertex shader's oceanSurface() and the
// model's CPU query (swell::WaveModel::surfaceAt, with the grid's filter)
// agree over the whole grid, near the origin and 10^6 m from it, at small
// times and at t = 10^6 s: the Gerstner sum, and the spectral ocean's FFT
// cascades against its kissfft twin.
#include "support/gl_test.h"
#include "swell/coast_field.h"
#include "swell/gerstner_model.h"
#include "swell/renderer.h"
#include "wave_capture.h"

#include <glm/geometric.hpp>

#include <cmath>

namespace {

class WaveAgreement : public swell::test::GlTest {};

swell::Scene agreementScene()
{
    swell::Scene scene = swell::defaultScene();
    scene.objects.clear();
    scene.showTerrain = false;
    scene.grid.resolution = 129; // 128 cells: 16641 vertices, enough to cover every LOD level
    return scene;
}

// Float positions carry ~1e-7 of up to ~100 lattice steps: far below this.
constexpr double kWaveAgreementTieMargin = 1e-4;

// Which normals must agree: the Gerstner model's vertex normals are its
// analytic ones on both sides; the spectral model's GPU normals come from
// mipmapped slopes (for shading), its CPU normals from level 0.
enum class Normals { Compared, NotCompared };

void expectAgreement(swell::Renderer& renderer, const swell::Scene& scene, glm::dvec3 cameraPosition, double time_s,
                     Normals normals = Normals::Compared)
{
    swell::Camera camera = swell::cameraAt(scene.camera, 0.0);
    camera.position_m = cameraPosition;
    const auto gpu = swell::test::captureGpu(renderer, camera, time_s);
    const auto cpu = swell::test::computeCpu(renderer, camera, time_s);
    ASSERT_EQ(gpu.size(), cpu.size());
    const int last = int(std::lround(std::sqrt(double(gpu.size())))) - 1;
    double worstPosition = 0.0, worstRest = 0.0, worstNormal = 0.0;
    int compared = 0, ties = 0;
    for (size_t k = 0; k < gpu.size(); ++k) {
        // The outermost lines are the skirt, 18 km out, where waves are faded to
        // zero; float spacing there is ~1 mm, so they are checked loosely below.
        const bool skirt = gpu[k].i == 0 || gpu[k].j == 0 || gpu[k].i == last || gpu[k].j == last;
        const double rest = glm::length(gpu[k].rest_m - cpu[k].rest_m);
        const double position = glm::length(gpu[k].position_m - cpu[k].position_m);
        if (skirt) {
            EXPECT_LT(position, 0.01) << "skirt vertex " << k;
            continue;
        }
        // A nominal position within float rounding of a tie between two
        // lattice points may snap to either on the GPU; the CPU twin flags
        // those. They must be rare, and on a neighbouring lattice point.
        if (cpu[k].snapMargin < kWaveAgreementTieMargin) {
            ++ties;
            EXPECT_LT(rest, cpu[k].latticeStep_m * 1.5) << "vertex " << k << " is off both lattice points of its tie";
            continue;
        }
        worstRest = std::max(worstRest, rest);
        worstPosition = std::max(worstPosition, position);
        worstNormal = std::max(worstNormal, glm::length(gpu[k].normal - cpu[k].normal));
        ++compared;
    }
    EXPECT_GT(compared, 10000);
    // Exact ties happen on the centre lines, whose nominal offset is 0 when
    // the centre is half way between two points of a level's lattice; near
    // ties elsewhere are float coincidences.
    EXPECT_LE(ties, 2 * (last + 1) + compared / 1000) << "too many vertices near a snapping tie";
    // 1 mm: the bound. Float positions relative to the camera within the
    // 2 km grid carry ~0.1 mm; phases are wrapped in double on the CPU.
    EXPECT_LT(worstRest, 1e-3) << "grid rest points differ";
    EXPECT_LT(worstPosition, 1e-3) << "displaced positions differ at t=" << time_s;
    // Normals: float sin/cos of phases up to ~10^4 rad carry ~10^-3 rad.
    if (normals == Normals::Compared) {
        EXPECT_LT(worstNormal, 2e-3) << "normals differ at t=" << time_s;
    }
}

void expectAgreement(const swell::Scene& scene, glm::dvec3 cameraPosition, double time_s,
                     Normals normals = Normals::Compared)
{
    swell::Renderer renderer(scene);
    expectAgreement(renderer, scene, cameraPosition, time_s, normals);
}

TEST_F(WaveAgreement, NearTheOriginAtSeveralTimes)
{
    const swell::Scene scene = agreementScene();
    for (double t : {0.0, 37.25, 1000.0})
        expectAgreement(scene, {3.7, 6.0, -12.2}, t);
}

TEST_F(WaveAgreement, AfterAMillionSeconds)
{
    expectAgreement(agreementScene(), {3.7, 6.0, -12.2}, 1.0e6);
}

TEST_F(WaveAgreement, AMillionMetresFromTheOrigin)
{
    expectAgreement(agreementScene(), {1.0e6 + 0.37, 6.0, -1.0e6 - 0.81}, 1.0e6);
}

TEST_F(WaveAgreement, FiniteDepthAndHandListedWaves)
{
    swell::Scene scene = agreementScene();
    scene.sea.wind.reset();
    scene.sea.depth_m = 12.0;
    scene.waves.listed = {{{1.0, 0.3}, 60.0, 0.8, 0.7, 0.2}, {{-0.4, 1.0}, 23.0, 0.3, 0.9, 1.9},
                                {{0.2, -1.0}, 7.5, 0.08, 0.5, -2.0}, {{0.9, 0.9}, 1.2, 0.02, 0.3, 0.0}};
    expectAgreement(scene, {-250.0, 3.0, 90.0}, 512.5);
}

// Over a coast field (swell/coast_field.h): a beach whose contours run at
// an angle to the waves, dry land beyond it, under the grid's finest rings;
// the field's 16 longest waves read their layers, the rest its common gain.
TEST_F(WaveAgreement, OverACoastField)
{
    swell::Scene scene = agreementScene();
    scene.sea.wind->windSpeed_mps = 9.0;
    swell::WaveSet set = swell::resolveWaves(scene);
    swell::limitSteepness(set);
    ASSERT_GT(set.waves.size(), swell::kMaxCoastWaves);
    swell::DepthGrid grid;
    grid.origin_m = {-700.0, -500.0};
    grid.cell_m = 4.0;
    grid.size = {300, 260};
    grid.depth_m.resize(std::size_t(grid.size.x) * std::size_t(grid.size.y));
    for (int j = 0; j < grid.size.y; ++j)
        for (int i = 0; i < grid.size.x; ++i) {
            const double across = 0.8 * i + 0.6 * j; // contours at an angle to the grid
            grid.depth_m[std::size_t(j) * std::size_t(grid.size.x) + std::size_t(i)] = float(40.0 - across * 4.0 / 25.0);
        }
    set.coast = std::make_shared<const swell::CoastField>(set, grid);
    swell::Renderer renderer(scene);
    renderer.setWaveModel(std::make_shared<swell::GerstnerModel>(set));
    // The camera over the surf: its finest rings cross the beach and the shore.
    for (double t : {0.0, 41.5})
        expectAgreement(renderer, scene, {-80.0, 5.0, 60.0}, t);
}

swell::Scene spectralScene()
{
    swell::Scene scene = agreementScene();
    scene.waves.model = swell::WaveModelKind::Spectral;
    scene.sea.wind->windSpeed_mps = 14.0;
    return scene;
}

TEST_F(WaveAgreement, SpectralCascadesEqualTheirCpuTwin)
{
    // The displacement: float FFTs on both sides of fields of a few metres
    // carry ~1e-5 m; the phase w*t is reduced in double on both sides.
    for (double t : {0.0, 1000.0, 1.0e6})
        expectAgreement(spectralScene(), {3.7, 6.0, -12.2}, t, Normals::NotCompared);
}

TEST_F(WaveAgreement, SpectralCascadesFarFromTheOrigin)
{
    expectAgreement(spectralScene(), {1.0e6 + 0.37, 6.0, -1.0e6 - 0.81}, 1.0e3, Normals::NotCompared);
}

// The spectral ocean over a sea floor (src/ocean/spectral/spectral_coast.h):
// a 1:40 beach under the grid's finest rings, where the cascades are
// weighed by the coast field, the longest band is handed to the trains
// (wholly near the shore, in part farther out) and the dry sand holds none.
TEST_F(WaveAgreement, SpectralOverASeaFloor)
{
    swell::Scene scene = spectralScene();
    scene.sea.wind->windSpeed_mps = 12.0;
    scene.seabed.toeDepth_m = 60.0;
    swell::SeabedBeach beach;
    beach.shorePoint_m = {0.0, 300.0};
    beach.slope = 1.0 / 40.0;
    beach.length_m = 4000.0;
    scene.seabed.beaches.push_back(beach);
    swell::Renderer renderer(scene);
    for (double t : {0.0, 41.5})
        expectAgreement(renderer, scene, {-30.0, 5.0, 180.0}, t, Normals::NotCompared);
}

} // namespace
