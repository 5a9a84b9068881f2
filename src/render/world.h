// What the world draws besides the water: the island, one mesh per scene
// object (and the closed volume of each open hull), and the sky cubemap;
// and the boxes that bound them all for the reflection march. Where each
// object stands is objects/placement.h's.
#pragma once

#include "assets/island_levels.h"
#include "assets/island_terrain.h"
#include "assets/seabed_mesh.h"
#include "assets/scene_assets.h"
#include "render/gpu/blocks.h"
#include "render/mesh.h"
#include "swell/scene/scene.h"
#include "swell/surface_query.h"

#include <glm/mat4x4.hpp>

#include <memory>
#include <vector>

namespace swell::detail {

// The built-in island's grid (its size, peak and place: assets/island_terrain.h).
inline constexpr int kIslandResolution = 192;
// Its levels of detail (assets/island_levels.h): tiles of 24 of the full
// grid's cells a side (8 x 8 tiles; levels of step 1, 2, 4 and 8), and the
// largest error a tile may show, in the pass's own pixels (docs/RENDERING.md
// "The island's levels of detail").
inline constexpr int kIslandTileCells = 16;
inline constexpr double kIslandLodTolerance_px = 0.5;

struct World {
    // The island's vertices and every level's triangles and skirts
    // (islandLevels' mesh, emptied once uploaded): drawn a tile at a time,
    // each at its own level, never whole.
    GpuMesh island;
    IslandLevels islandLevels;
    std::vector<std::unique_ptr<GpuMesh>> meshes;
    // Per scene object, the farthest any vertex lies from the model's origin, m (unscaled).
    std::vector<double> meshReach_m;
    // Per scene object, its mesh's bounding box in model space (lowest and
    // highest corner, unscaled, m): its 3D box in labelled frames.
    std::vector<std::pair<glm::dvec3, glm::dvec3>> meshBounds_m;
    // Per scene object, the closed volume of its open hull, or null (see Renderer's drawHullVolumes).
    std::vector<std::unique_ptr<GpuMesh>> hullVolumes;
    gl::Texture skyCube;
    // The scene's seabed shapes and heightmap (assets/seabed_mesh.h), built
    // again apart from the rest when only the seabed changed; empty: none.
    GpuMesh seabed;
    glm::dvec2 seabedOrigin_m{0.0}; // world [x, z] its vertices are relative to (sea frame y)
    glm::dvec3 seabedLo_m{0.0}, seabedHi_m{0.0}; // its box, sea frame, relative to seabedOrigin_m
};

// Uploads the seabed's mesh into `world`, replacing any it had.
void setSeabedMesh(World& world, const SeabedMesh& mesh);

// Uploads the meshes and sky of `scene`, read into `assets`
// (loadSceneAssets), without touching any current world, so a bad asset
// leaves the renderer as it was.
World buildWorld(const Scene& scene, const SceneAssets& assets);

// Fills boxes holding all world geometry, relative to the render origin: a
// reflected ray that misses them all can only meet the sky. Returns the
// count, or -1 when there are more than SWELL_MAX_WORLD_BOXES (every ray is
// then marched).
// `poses` are this frame's objectPoses(): rigid bodies are boxed where they are.
int worldBoxes(const World& world, const Scene& scene, const WaveReach& reach, glm::dvec3 origin,
               const std::vector<glm::dmat4>& poses, WorldBoxUniform* boxes);
// Which of worldBoxes()' boxes, in its order, bound an object that rides
// the water (the island's and the sea floor's stay put).
std::vector<bool> worldBoxesThatFloat(const World& world, const Scene& scene);

} // namespace swell::detail
