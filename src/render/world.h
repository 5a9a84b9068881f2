// What the world draws besides the water: the island, one mesh per scene
// object (and the closed volume of each open hull), and the sky cubemap;
// where each object stands this frame; and the boxes that bound them all for
// the reflection march.
#pragma once

#include "assets/island_levels.h"
#include "assets/mesh_data.h"
#include "objects/scene_bodies.h"
#include "render/gpu/blocks.h"
#include "render/mesh.h"
#include "render/surface_probe.h"
#include "swell/drawn_surface.h"
#include "swell/scene.h"
#include "swell/wave_model.h"

#include <glm/mat4x4.hpp>

#include <memory>
#include <vector>

namespace swell::detail {

// The built-in island: size, peak and where it stands (ahead-left of the default camera).
inline constexpr double kIslandSize_m = 1400.0;
inline constexpr double kIslandPeak_m = 70.0;
inline constexpr int kIslandResolution = 192;
inline constexpr glm::dvec3 kIslandPosition_m{-700.0, 0.0, -1700.0};
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
    // Per scene object, the closed shape a floating rigid body is built from:
    // its hull volume when it has one, else its mesh (CPU data, model space).
    std::vector<std::shared_ptr<const MeshData>> bodyShapes;
    gl::Texture skyCube;
};

// The floating bodies of `scene` on `surface`, from the world's shapes.
SceneBodies buildBodies(const World& world, const Scene& scene, const WaveModel& surface);

// Builds the meshes and sky of `scene` without touching any current world,
// so a bad asset leaves the renderer as it was. Throws swell::InputError.
World buildWorld(const Scene& scene);

// Where the frame asks for the water under its floating objects (those that
// ride the waves without being rigid bodies), x, z in the sea frame, m, in
// the scene's object order.
std::vector<glm::dvec2> floatingObjectPoints(const Scene& scene);

// Each object's transform (object to absolute world, m) at time_s:
// rigid bodies where `bodies` has stepped them to time_s (on the surface
// their own filter gives, from the scene alone: swell/floating_body.h);
// other floating objects sit on the water as drawn (the grid's triangles)
// at their position, and tilt with the exact surface's normal: `water`
// holds the frame's answers for floatingObjectPoints(), in its order.
// Computed once per simulated time; every view and pass draws with them.
std::vector<glm::dmat4> objectPoses(const Scene& scene, const std::vector<ProbedPoint>& water, SceneBodies& bodies,
                                    double time_s);

// An object's transform standing at position_m (sea frame), tilted by
// `tilt`, turned by its yaw and scaled: a fixed object's at its own position.
glm::dmat4 placedObjectPose(const SceneObject& o, glm::dvec3 position_m, const glm::dmat4& tilt = glm::dmat4(1.0));

// Fills boxes holding all world geometry, relative to the render origin: a
// reflected ray that misses them all can only meet the sky. Returns the
// count, or -1 when there are more than SWELL_MAX_WORLD_BOXES (every ray is
// then marched).
// `poses` are this frame's objectPoses(): rigid bodies are boxed where they are.
int worldBoxes(const World& world, const Scene& scene, const WaveReach& reach, glm::dvec3 origin,
               const std::vector<glm::dmat4>& poses, WorldBoxUniform* boxes);

} // namespace swell::detail
