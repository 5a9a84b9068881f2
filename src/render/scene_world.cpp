#include "render/scene_world.h"

namespace swell::detail {

SceneWorld::SceneWorld(const World& world, const MeshProgram& meshInAir, const MeshProgram& mesh,
                       const std::vector<glm::mat4>& poses, const glm::mat4& island, FrameCounters& counters)
    : world_(world), meshInAir_(meshInAir), mesh_(mesh), poses_(poses), island_(island), counters_(counters)
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
        drawObjects(program);
}

void SceneWorld::drawObjects(const MeshProgram& program)
{
    program.use();
    if (world_.island.indexCount() > 0) {
        program.setModel(island_);
        program.setLabel(islandLabel_);
        world_.island.draw();
        counters_.worldTriangles += world_.island.indexCount() / 3;
        ++counters_.drawCalls;
    }
    for (std::size_t i = 0; i < world_.meshes.size() && i < poses_.size(); ++i) {
        program.setModel(poses_[i]);
        if (i < objectLabels_.size())
            program.setLabel(objectLabels_[i]);
        world_.meshes[i]->draw();
        counters_.worldTriangles += world_.meshes[i]->indexCount() / 3;
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
        if (world_.hullVolumes[i]) {
            program.setModel(poses_[i]);
            world_.hullVolumes[i]->draw();
            ++counters_.drawCalls;
        }
}

} // namespace swell::detail
