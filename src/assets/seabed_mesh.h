// The scene's seabed as world geometry (docs/RENDERING.md "The seabed"):
// its beaches and shelves in sand, its breakwaters in grey rock and its
// heightmap, each a sheet whose vertices take their heights from the same
// functions Seabed::elevation_m() takes the highest of, with walls down to
// the toe along the edges where a shape stops. The island and a host's
// heights are not drawn here (the island has its own mesh; the host draws
// its own terrain).
#pragma once

#include "assets/mesh_data.h"
#include "swell/scene/seabed.h"

#include <glm/vec2.hpp>

namespace swell::detail {

// Most vertices along each side of a heightmap's sheet: a larger image is
// drawn at every n-th pixel (the physics still samples every pixel).
inline constexpr int kMaxSeabedSheetSide = 512;

struct SeabedMesh {
    MeshData mesh;          // in the sea frame (y = 0 at the sea's mean level), relative to origin_m
    glm::dvec2 origin_m{0.0}; // world [x, z] of the mesh's origin: the middle of what it covers, m
};

// The mesh of `seabed`'s scene shapes and heightmap; empty when it has none.
SeabedMesh makeSeabedMesh(const Seabed& seabed);

} // namespace swell::detail
