// Swell's own world (the scene's island and objects, and the closed volumes
// of open hulls) as one client of the pass geometry API (swell/view.h): the
// renderer draws it through the same callback as a host's geometry. It
// draws relative to the render origin with the Frame uniforms the renderer
// bound for the pass, so its precision does not depend on where it is.
#pragma once

#include "render/programs.h"
#include "render/world.h"
#include "swell/debug.h"
#include "swell/view.h"

#include <glm/mat4x4.hpp>

#include <cstddef>
#include <optional>
#include <vector>

namespace swell::detail {

class SceneWorld final : public PassGeometry {
public:
    // poses: each scene object's transform relative to the render origin;
    // island, seabed: the island's and the seabed mesh's. meshInAir / mesh: the programs for passes whose
    // pixels all look out from the air, and for any pass.
    SceneWorld(const World& world, const MeshProgram& meshInAir, const MeshProgram& mesh,
               const std::vector<glm::mat4>& poses, const glm::mat4& island, const glm::mat4& seabed,
               FrameCounters& counters);

    // Whether the next Main pass may have pixels that look out from below
    // the water (the main pass's waterline mask decides per pixel then).
    void setMainPassInAir(bool inAir) { mainInAir_ = inAir; }
    // The island's largest error a pass may show, in its pixels; 0 draws
    // its full grid in every pass (default kIslandLodTolerance_px).
    void setIslandTolerance(double tolerance_px) { islandTolerance_px_ = tolerance_px; }

    void drawPass(const PassView& pass) override;

    // For the label pass's silhouettes: draw object `index` alone (its mesh
    // and its hull's volume; no island, sea floor or other object); empty:
    // the whole world (the default).
    void setAlone(std::optional<std::size_t> index) { alone_ = index; }

    // For the label pass (its mesh program): the island's class and
    // instance (the seabed's too: both are terrain), and each object's, set
    // before each draw.
    void setLabels(glm::uvec2 island, std::vector<glm::uvec2> objects)
    {
        islandLabel_ = island;
        objectLabels_ = std::move(objects);
    }

    // For the host's motion vectors (the motion program): each object's
    // transform at the view's previous draw, relative to this draw's render
    // origin, set before each draw (the island and seabed stay put); not
    // owned. Null: none set (the other programs).
    void setPreviousPoses(const std::vector<glm::mat4>* poses) { previousPoses_ = poses; }

private:
    void drawObjects(const MeshProgram& program, const PassView& pass);
    void drawIsland(const MeshProgram& program, const PassView& pass);
    void drawHullVolumes(const MeshProgram& program);
    // Whether object `index` may reach the contact pass's window (render/contact_map.h).
    bool inContactWindow(const PassView& pass, std::size_t index) const;
    // The counter a pass's triangles go to: the contact pass's own, the
    // others' worldTriangles.
    long long& trianglesOf(const PassView& pass)
    {
        return pass.pass == PassKind::Contact ? counters_.contactTriangles : counters_.worldTriangles;
    }

    const World& world_;
    const MeshProgram &meshInAir_, &mesh_;
    const std::vector<glm::mat4>& poses_;
    glm::mat4 island_;
    glm::mat4 seabed_;
    FrameCounters& counters_;
    bool mainInAir_ = true;
    double islandTolerance_px_ = kIslandLodTolerance_px;
    // The island's tiles' levels (-1: out of the pass) and the index ranges
    // drawn, kept between passes to reuse their storage.
    std::vector<int> tileLevels_;
    std::vector<GLsizei> tileCounts_;
    std::vector<const void*> tileOffsets_;
    glm::uvec2 islandLabel_{0};
    std::vector<glm::uvec2> objectLabels_;
    std::optional<std::size_t> alone_;
    const std::vector<glm::mat4>* previousPoses_ = nullptr;
    const glm::mat4& previousPose(std::size_t i) const
    {
        return previousPoses_ && i < previousPoses_->size() ? (*previousPoses_)[i] : poses_[i];
    }

    bool draws(std::size_t object) const { return !alone_ || *alone_ == object; }
};

} // namespace swell::detail
