// The world's GPU assets and reflection bounds.
#include "render/world.h"

#include "swell/error.h"
#include "swell/gpu/limits.h"
#include "swell/image.h"

#include <glm/common.hpp>
#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <utility>

namespace swell::detail {

World buildWorld(const Scene& from, const SceneAssets& assets)
{
    // Every file was read and checked on the CPU first (assets/scene_assets.h); only uploads here.
    World world;
    if (from.showTerrain) {
        world.islandLevels =
            makeIslandLevels(makeIsland(kIslandSize_m, kIslandPeak_m, kIslandResolution), kIslandResolution, kIslandTileCells);
        world.island = GpuMesh(world.islandLevels.mesh);
        // The GPU holds them now; the tiles' ranges and boxes are all the frame needs.
        world.islandLevels.mesh = {};
    }
    for (const ObjectAssets& o : assets.objects) {
        world.meshes.push_back(std::make_unique<GpuMesh>(*o.mesh));
        world.meshReach_m.push_back(o.reach_m);
        glm::dvec3 lo(0.0), hi(0.0);
        for (std::size_t v = 0; v < o.mesh->vertices.size(); ++v) {
            const glm::dvec3 p(o.mesh->vertices[v].position);
            lo = v == 0 ? p : glm::min(lo, p);
            hi = v == 0 ? p : glm::max(hi, p);
        }
        world.meshBounds_m.emplace_back(lo, hi);
        world.hullVolumes.push_back(o.hullVolume->indices.empty() ? nullptr : std::make_unique<GpuMesh>(*o.hullVolume));
    }
    if (!assets.skyFaces.empty()) {
        const std::vector<Image>& faces = assets.skyFaces;
        world.skyCube = gl::Texture::create(GLenum(GL_TEXTURE_CUBE_MAP));
        const int n = faces.front().width;
        // A full mip chain: user photos may be far more detailed than the
        // pixels the sky pass samples them with.
        const int levels = 1 + int(std::floor(std::log2(double(n))));
        glTextureStorage2D(world.skyCube.id(), levels, GL_SRGB8_ALPHA8, n, n);
        for (int face = 0; face < 6; ++face)
            glTextureSubImage3D(world.skyCube.id(), 0, 0, 0, face, n, n, 1, GL_RGBA, GL_UNSIGNED_BYTE,
                                faces[size_t(face)].rgba.data());
        glGenerateTextureMipmap(world.skyCube.id());
        glTextureParameteri(world.skyCube.id(), GL_TEXTURE_MIN_FILTER, GL_LINEAR_MIPMAP_LINEAR);
        glTextureParameteri(world.skyCube.id(), GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    }
    return world;
}

void setSeabedMesh(World& world, const SeabedMesh& seabed)
{
    world.seabed = seabed.mesh.indices.empty() ? GpuMesh() : GpuMesh(seabed.mesh);
    world.seabedOrigin_m = seabed.origin_m;
    world.seabedLo_m = world.seabedHi_m = glm::dvec3(0.0);
    for (std::size_t v = 0; v < seabed.mesh.vertices.size(); ++v) {
        const glm::dvec3 p(seabed.mesh.vertices[v].position);
        world.seabedLo_m = v == 0 ? p : glm::min(world.seabedLo_m, p);
        world.seabedHi_m = v == 0 ? p : glm::max(world.seabedHi_m, p);
    }
}

int worldBoxes(const World& world, const Scene& scene, const WaveReach& reach, glm::dvec3 origin,
               const std::vector<glm::dmat4>& poses, WorldBoxUniform* boxes)
{
    int count = 0;
    auto add = [&](glm::dvec3 lo, glm::dvec3 hi) {
        if (count < SWELL_MAX_WORLD_BOXES)
            boxes[count] = {glm::vec3(lo - origin), 0.0f, glm::vec3(hi - origin), 0.0f};
        ++count;
    };
    if (world.island.indexCount() > 0) {
        const glm::dvec3 half(0.5 * kIslandSize_m, 0.0, 0.5 * kIslandSize_m);
        add(kIslandPosition_m - half - glm::dvec3(0.0, 1.0, 0.0),
            kIslandPosition_m + half + glm::dvec3(0.0, kIslandPeak_m + 1.0, 0.0));
    }
    if (world.seabed.indexCount() > 0) {
        const glm::dvec3 at(world.seabedOrigin_m.x, 0.0, world.seabedOrigin_m.y);
        add(at + world.seabedLo_m, at + world.seabedHi_m);
    }
    // Objects may turn and tilt, so each is boxed as a sphere round its
    // origin; floating ones also rise and fall with the surface.
    for (size_t i = 0; i < world.meshes.size() && i < scene.objects.size(); ++i) {
        const SceneObject& o = scene.objects[i];
        const double r = world.meshReach_m[i] * o.scale;
        if (o.isRigidBody() && i < poses.size()) {
            // Where it is this frame (a body under way leaves its start behind).
            const glm::dvec3 at(poses[i][3]);
            add(at - glm::dvec3(r), at + glm::dvec3(r));
            continue;
        }
        const glm::dvec3 pad(r, r + (o.floats ? reach.vertical_m : 0.0), r);
        add(o.position_m - pad, o.position_m + pad);
    }
    return count <= SWELL_MAX_WORLD_BOXES ? count : -1;
}

std::vector<bool> worldBoxesThatFloat(const World& world, const Scene& scene)
{
    // worldBoxes()' order: the island, the sea floor, then each object.
    std::vector<bool> floating;
    if (world.island.indexCount() > 0)
        floating.push_back(false);
    if (world.seabed.indexCount() > 0)
        floating.push_back(false);
    for (size_t i = 0; i < world.meshes.size() && i < scene.objects.size(); ++i)
        floating.push_back(scene.objects[i].floats);
    return floating;
}

} // namespace swell::detail
