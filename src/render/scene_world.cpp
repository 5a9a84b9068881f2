#include "render/scene_world.h"

#include "core/grid_tiles.h"

#include <glm/common.hpp>
#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <cstddef>

namespace swell::detail {

SceneWorld::SceneWorld(const World& world, const MeshProgram& meshInAir, const MeshProgram& mesh,
                       const std::vector<glm::mat4>& poses, const glm::mat4& island, const glm::mat4& seabed,
                       FrameCounters& counters)
    : world_(world), meshInAir_(meshInAir), mesh_(mesh), poses_(poses), island_(island), seabed_(seabed),
      counters_(counters)
{
}

void SceneWorld::drawPass(const PassView& pass)
{
    // The reflection and refraction passes see nothing from below the water.
    const bool inAir = pass.pass != PassKind::Main && pass.pass != PassKind::WaterMask ? true : mainInAir_;
    const MeshProgram& program = inAir ? meshInAir_ : mesh_;
    if (pass.pass == PassKind::WaterMask)
        drawHullVolumes(program);
    else
        drawObjects(program, pass);
}

namespace {

// The planes a tile of the island must not lie wholly behind: the four
// sides of the pass's frustum, its clip plane and the eye's own plane
// (clip w >= 0), absolute world. Near and far are left out (a reversed or
// infinite depth range needs no special case here).
Frustum passPlanes(const PassView& pass, const glm::dmat4& viewProj)
{
    Frustum planes = frustumPlanes(viewProj);
    planes[4] = pass.clipPlane_m;
    planes[5] = 0.5 * (planes[0] + planes[1]); // row 3 of viewProj: clip w
    return planes;
}

// Distance from p to the box, m (0 inside).
double distanceToBox(glm::dvec3 p, glm::dvec3 lo, glm::dvec3 hi)
{
    return glm::length(glm::max(glm::max(lo - p, p - hi), glm::dvec3(0.0)));
}

} // namespace

// Each tile of the island in view at the coarsest level whose error
// projects to the tolerance or less from the nearest point of its box, in
// this pass's own pixels (the reduced reflection and refraction passes take
// coarser levels than the main pass), with its skirt along each side whose
// neighbour took another level. One draw call.
void SceneWorld::drawIsland(const MeshProgram& program, const PassView& pass)
{
    const IslandLevels& levels = world_.islandLevels;
    if (levels.levels.empty())
        return;
    // The contact pass looks straight down through an orthographic
    // projection: its texels are the same size at every distance, so a
    // tile's error is measured in them at unit distance (texels per metre).
    const bool orthographic = pass.pass == PassKind::Contact;
    const double focal_px = orthographic ? 0.5 * double(pass.viewport.z) * pass.projection[0][0]
                                         : 0.5 * double(pass.viewport.w) * pass.projection[1][1];
    const FrustumTest inPass(passPlanes(pass, pass.projection * pass.view), glm::dvec3(0.0));
    const std::size_t tiles = levels.boxLo.size();
    tileLevels_.assign(tiles, -1);
    for (std::size_t t = 0; t < tiles; ++t) {
        const glm::dvec3 lo = kIslandPosition_m + glm::dvec3(levels.boxLo[t]);
        const glm::dvec3 hi = kIslandPosition_m + glm::dvec3(levels.boxHi[t]);
        if (inPass(centred(Bounds{lo, hi})) != Containment::Outside)
            tileLevels_[t] = int(islandTileLevel(levels, t, orthographic ? 1.0 : distanceToBox(pass.eye_m, lo, hi),
                                                 focal_px, islandTolerance_px_));
    }
    tileCounts_.clear();
    tileOffsets_.clear();
    long long triangles = 0;
    auto add = [&](const IndexRange& range) {
        tileCounts_.push_back(GLsizei(range.count));
        tileOffsets_.push_back(reinterpret_cast<const void*>(std::size_t(range.first) * sizeof(std::uint32_t)));
        triangles += range.count / 3;
    };
    for (std::size_t t = 0; t < tiles; ++t) {
        if (tileLevels_[t] < 0)
            continue;
        const IslandTile& tile = levels.levels[std::size_t(tileLevels_[t])].tiles[t];
        add(tile.cells);
        // A neighbour out of the pass hides nothing: the gap lies inside its box.
        for (int side = 0; side < kTileSides; ++side) {
            const int across = levels.neighbours[t][std::size_t(side)];
            if (across >= 0 && tileLevels_[std::size_t(across)] >= 0 && tileLevels_[std::size_t(across)] != tileLevels_[t])
                add(tile.skirts[std::size_t(side)]);
        }
    }
    if (tileCounts_.empty())
        return;
    program.setModel(island_);
    program.setPreviousModel(island_);
    program.setLabel(islandLabel_);
    program.setSwashWets(true);
    world_.island.drawRanges(tileCounts_, tileOffsets_);
    trianglesOf(pass) += triangles;
    ++counters_.drawCalls;
}

// Whether object i's sphere (its mesh's reach round its origin, scaled)
// reaches the contact pass's window and band: its projection maps points
// relative to the render origin (the poses' frame) to clip space, x and z
// over the window and y over the band, without a perspective divide.
bool SceneWorld::inContactWindow(const PassView& pass, std::size_t i) const
{
    const glm::dvec4 centre = pass.projection * glm::dvec4(glm::dvec3(poses_[i][3]), 1.0);
    const double scale = glm::length(glm::dvec3(poses_[i][0]));
    const double reach_m = (i < world_.meshReach_m.size() ? world_.meshReach_m[i] : 0.0) * scale;
    const double across = std::abs(pass.projection[0][0]) * reach_m + 0.05;
    const double up = std::abs(pass.projection[1][2]) * reach_m + 0.05;
    return std::abs(centre.x) <= 1.0 + across && std::abs(centre.y) <= 1.0 + across && std::abs(centre.z) <= 1.0 + up;
}

void SceneWorld::drawObjects(const MeshProgram& program, const PassView& pass)
{
    program.use();
    if (!alone_)
        drawIsland(program, pass);
    if (!alone_ && world_.seabed.indexCount() > 0) {
        program.setModel(seabed_);
        program.setPreviousModel(seabed_);
        program.setLabel(islandLabel_);
        program.setSwashWets(true);
        world_.seabed.draw();
        trianglesOf(pass) += world_.seabed.indexCount() / 3;
        ++counters_.drawCalls;
    }
    program.setSwashWets(false);
    for (std::size_t i = 0; i < world_.meshes.size() && i < poses_.size(); ++i) {
        if (!draws(i) || (pass.pass == PassKind::Contact && !inContactWindow(pass, i)))
            continue;
        program.setModel(poses_[i]);
        program.setPreviousModel(previousPose(i));
        if (i < objectLabels_.size())
            program.setLabel(objectLabels_[i]);
        world_.meshes[i]->draw();
        trianglesOf(pass) += world_.meshes[i]->indexCount() / 3;
        ++counters_.drawCalls;
    }
}

// Clean intersections: each open hull's closed volume is drawn into depth
// only, after the world and before the water. Its outer surface coincides
// with the hull's, so only its lid at the gunwale changes the depth buffer:
// a ray into the open hull meets the lid before the water inside, and that
// water fails the depth test. (The reflection and refraction passes draw no
// water, so they need no mask.) The renderer has turned colour writes off.
void SceneWorld::drawHullVolumes(const MeshProgram& program)
{
    program.use();
    for (std::size_t i = 0; i < world_.hullVolumes.size() && i < poses_.size(); ++i)
        if (world_.hullVolumes[i] && draws(i)) {
            program.setModel(poses_[i]);
            program.setPreviousModel(previousPose(i));
            world_.hullVolumes[i]->draw();
            ++counters_.drawCalls;
        }
}

} // namespace swell::detail
