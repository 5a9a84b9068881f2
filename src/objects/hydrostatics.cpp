// Hydrostatic pressure over a body's submerged surface (hydrostatics.h).
#include "objects/hydrostatics.h"

#include "swell/constants.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>

namespace swell::detail {

double WaterPatch::heightAt(glm::dvec2 world_m) const
{
    const glm::dvec2 u = glm::clamp((world_m - corner_m) / spacing_m, 0.0, double(kPatchSamples - 1));
    const int i = std::min(int(u.x), kPatchSamples - 2), j = std::min(int(u.y), kPatchSamples - 2);
    const double fx = u.x - i, fz = u.y - j;
    auto h = [&](int a, int b) { return height_m[std::size_t(b * kPatchSamples + a)]; };
    return (1.0 - fz) * ((1.0 - fx) * h(i, j) + fx * h(i + 1, j)) + fz * ((1.0 - fx) * h(i, j + 1) + fx * h(i + 1, j + 1));
}

WaterPatch blend(const WaterPatch& from, const WaterPatch& to, double f)
{
    WaterPatch patch = from;
    for (std::size_t i = 0; i < patch.height_m.size(); ++i)
        patch.height_m[i] = from.height_m[i] + f * (to.height_m[i] - from.height_m[i]);
    return patch;
}

WaterPatch sampleWater(const SurfaceQuery& surface, glm::dvec2 centre_m, double halfSize_m, double time_s,
                       const SurfaceFilter& filter)
{
    WaterPatch patch;
    patch.centre_m = centre_m;
    patch.halfSize_m = halfSize_m;
    patch.spacing_m = 2.0 * halfSize_m / (kPatchSamples - 1);
    patch.corner_m = centre_m - glm::dvec2(halfSize_m);
    // The lattice's spacing is its footprint: waves it cannot resolve are
    // faded out before they are sampled, not aliased. Sampled at points
    // 1.9 m apart under a 7 m boat, waves of 2 to 4 m read as longer ones
    // under the whole hull: it heaved 3.5 times the height of a wave a
    // third of its length, and under way in the gale's sea
    // (scenes/gale-under-way.toml) it stood on its stern. A rigid body does
    // not follow waves much shorter than itself (its heave and pitch
    // responses fall towards 0 there: Jensen, Mansour & Olsen 2004, Ocean
    // Engineering 31, 61-85; tests/cpu/test_seakeeping.cpp).
    SurfaceFilter lattice = filter;
    lattice.footprint_m = std::max(filter.footprint_m, patch.spacing_m);
    for (int j = 0; j < kPatchSamples; ++j)
        for (int i = 0; i < kPatchSamples; ++i)
            patch.height_m[std::size_t(j * kPatchSamples + i)] =
                surface.heightAt(patch.corner_m + patch.spacing_m * glm::dvec2(i, j), time_s, lattice);
    return patch;
}

namespace {

struct Accumulator {
    glm::dvec3 reference{0.0};
    glm::dvec3 force{0.0}, torque{0.0};

    // One submerged triangle with depths d (>= 0, linear across it). With
    // S = n A its area vector (outward), the pressure rho g d pushes with
    // -rho g S mean(d); for linear f, g over a triangle,
    // int f g dA = A/12 (sum f_i g_i + sum f_i sum g_i), which gives the
    // first moment int d (x - ref) dA for the torque.
    void add(const glm::dvec3 (&p)[3], const double (&d)[3], double rhoG)
    {
        const glm::dvec3 areaVector = 0.5 * glm::cross(p[1] - p[0], p[2] - p[0]);
        const double sumD = d[0] + d[1] + d[2];
        const glm::dvec3 f = -rhoG * (sumD / 3.0) * areaVector;
        force += f;
        const glm::dvec3 r[3] = {p[0] - reference, p[1] - reference, p[2] - reference};
        const glm::dvec3 weighted = (d[0] * r[0] + d[1] * r[1] + d[2] * r[2] + sumD * (r[0] + r[1] + r[2])) / 12.0;
        // int r x (-rho g d n) dA = (int d r dA / A) x (-rho g S); `weighted` already is that first factor.
        torque += glm::cross(weighted, -rhoG * areaVector);
    }
};

glm::dvec3 cut(glm::dvec3 a, double da, glm::dvec3 b, double db) { return a + (da / (da - db)) * (b - a); }

} // namespace

HydrostaticLoad hydrostaticLoad(const std::vector<glm::dvec3>& world_m, const std::vector<std::uint32_t>& indices,
                                glm::dvec3 reference_m, const WaterPatch& water, double density_kg_per_m3)
{
    const double rhoG = density_kg_per_m3 * kGravity;
    std::vector<double> depth(world_m.size());
    for (std::size_t i = 0; i < world_m.size(); ++i)
        depth[i] = water.heightAt({world_m[i].x, world_m[i].z}) - world_m[i].y;

    Accumulator acc;
    acc.reference = reference_m;
    for (std::size_t t = 0; t + 2 < indices.size(); t += 3) {
        const glm::dvec3 p[3] = {world_m[indices[t]], world_m[indices[t + 1]], world_m[indices[t + 2]]};
        const double d[3] = {depth[indices[t]], depth[indices[t + 1]], depth[indices[t + 2]]};
        const int wet = int(d[0] > 0.0) + int(d[1] > 0.0) + int(d[2] > 0.0);
        if (wet == 0)
            continue;
        if (wet == 3) {
            acc.add(p, d, rhoG);
            continue;
        }
        // Rotate so that vertex 0 is the odd one out (the only wet or the only dry), keeping the winding.
        int k = 0;
        for (int i = 0; i < 3; ++i)
            if ((d[i] > 0.0) == (wet == 1))
                k = i;
        const glm::dvec3 a = p[k], b = p[(k + 1) % 3], c = p[(k + 2) % 3];
        const double da = d[k], db = d[(k + 1) % 3], dc = d[(k + 2) % 3];
        const glm::dvec3 ab = cut(a, da, b, db), ac = cut(a, da, c, dc);
        if (wet == 1) {
            acc.add({a, ab, ac}, {da, 0.0, 0.0}, rhoG);
        } else { // a is dry: the wet part is the quad ab, b, c, ac
            acc.add({ab, b, c}, {0.0, db, dc}, rhoG);
            acc.add({ab, c, ac}, {0.0, dc, 0.0}, rhoG);
        }
    }
    HydrostaticLoad load;
    load.force_N = acc.force;
    load.torque_N_m = acc.torque;
    load.submergedVolume_m3 = std::max(0.0, acc.force.y / rhoG);
    return load;
}

} // namespace swell::detail
