// The sea's frame: the world's axes with y = 0 at the water's mean level
// (the scene's sea level). The wave models, the floating bodies and every
// query of the water work in it; a host, the labels and the scene file work
// in the world's. This type is the one place that moves between them, so
// no caller adds or subtracts the level by hand.
#pragma once

#include <glm/gtc/matrix_transform.hpp>
#include <glm/mat4x4.hpp>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

namespace swell {

class SeaFrame {
public:
    SeaFrame() = default;
    // level_m: the water's mean level, absolute world y, m.
    explicit SeaFrame(double level_m) : level_m_(level_m) {}

    double level_m() const { return level_m_; }

    // A point or height between the frames, m.
    glm::dvec3 toSea(glm::dvec3 world_m) const { return world_m - up(); }
    glm::dvec3 toWorld(glm::dvec3 sea_m) const { return sea_m + up(); }
    double heightInSea(double worldY_m) const { return worldY_m - level_m_; }
    double heightInWorld(double seaY_m) const { return seaY_m + level_m_; }

    // Sea frame to world (a translation), and back.
    glm::dmat4 worldFromSea() const { return glm::translate(glm::dmat4(1.0), up()); }
    glm::dmat4 seaFromWorld() const { return glm::translate(glm::dmat4(1.0), -up()); }

    // The world mirrored about the sea level (absolute world to absolute
    // world): what the reflection pass sees, and the eye it sees from.
    glm::dmat4 mirror() const
    {
        return worldFromSea() * glm::scale(glm::dmat4(1.0), glm::dvec3(1.0, -1.0, 1.0)) * seaFromWorld();
    }
    glm::dvec3 mirrored(glm::dvec3 world_m) const { return glm::dvec3(world_m.x, 2.0 * level_m_ - world_m.y, world_m.z); }

    // A plane (a, b, c, d: a x + b y + c z + d >= 0 keeps a point) given in
    // the sea frame, as the same plane in the world's.
    glm::dvec4 planeInWorld(glm::dvec4 seaPlane) const
    {
        return glm::dvec4(glm::dvec3(seaPlane), seaPlane.w - seaPlane.y * level_m_);
    }

    bool operator==(const SeaFrame&) const = default;

private:
    glm::dvec3 up() const { return glm::dvec3(0.0, level_m_, 0.0); }

    double level_m_ = 0.0;
};

} // namespace swell
