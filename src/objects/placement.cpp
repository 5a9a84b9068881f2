// Where a scene's objects stand (placement.h).
#include "objects/placement.h"

#include <glm/common.hpp>
#include <glm/geometric.hpp>
#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <cmath>
#include <utility>

namespace swell::detail {

namespace {

glm::dmat4 objectPose(const SceneObject& o, const ProbedPoint* water)
{
    glm::dvec3 position = o.position_m;
    glm::dmat4 tilt(1.0);
    if (water) {
        // On the water the user sees: the grid's triangles, which leave out
        // the waves their cells cannot carry (the exact surface only where
        // no triangle is found).
        position.y += water->drawn ? water->drawn->position_m.y : water->displacement_m.y;
        // A body larger than the short waves does not follow every ripple:
        // tilt half way towards the surface normal.
        const glm::dvec3 up = glm::normalize(glm::mix(glm::dvec3(0, 1, 0), water->normal, 0.5));
        const glm::dvec3 axis = glm::cross(glm::dvec3(0, 1, 0), up);
        const double s = glm::length(axis);
        if (s > 1e-9)
            tilt = glm::rotate(glm::dmat4(1.0), std::asin(std::min(s, 1.0)), axis / s);
    }
    return placedObjectPose(o, position, tilt);
}

} // namespace

glm::dmat4 placedObjectPose(const SceneObject& o, glm::dvec3 position_m, const glm::dmat4& tilt)
{
    return glm::translate(glm::dmat4(1.0), position_m) * tilt *
           glm::rotate(glm::dmat4(1.0), glm::radians(o.yaw_deg), glm::dvec3(0, 1, 0)) *
           glm::scale(glm::dmat4(1.0), glm::dvec3(o.scale));
}

SceneBodies buildBodies(const SceneShapes& shapes, const Scene& scene, std::shared_ptr<const SurfaceQuery> surface,
                        std::shared_ptr<const Seabed> seabed)
{
    return SceneBodies(scene, shapes.list(), std::move(surface), std::move(seabed));
}

std::vector<glm::dvec2> floatingObjectPoints(const Scene& scene)
{
    std::vector<glm::dvec2> points;
    for (const SceneObject& o : scene.objects)
        if (o.floats && !o.isRigidBody())
            points.emplace_back(o.position_m.x, o.position_m.z);
    return points;
}

std::vector<glm::dmat4> objectPoses(const Scene& scene, const std::vector<ProbedPoint>& water, SceneBodies& bodies,
                                    double time_s)
{
    std::vector<glm::dmat4> poses;
    poses.reserve(scene.objects.size());
    bodies.advanceTo(time_s);
    std::size_t floating = 0;
    for (std::size_t i = 0; i < scene.objects.size(); ++i) {
        const SceneObject& o = scene.objects[i];
        if (const std::optional<glm::dmat4> body = bodies.poseAt(i, time_s))
            poses.push_back(*body);
        else
            poses.push_back(objectPose(o, o.floats && !o.isRigidBody() ? &water.at(floating++) : nullptr));
    }
    return poses;
}

std::vector<std::optional<FloatingBody::Velocity>> objectVelocities(const Scene& scene, const SceneBodies& bodies,
                                                                    double time_s)
{
    std::vector<std::optional<FloatingBody::Velocity>> velocities;
    velocities.reserve(scene.objects.size());
    for (std::size_t i = 0; i < scene.objects.size(); ++i) {
        const SceneObject& o = scene.objects[i];
        if (std::optional<FloatingBody::Velocity> body = bodies.velocityAt(i, time_s))
            velocities.push_back(*body);
        else if (o.floats)
            velocities.emplace_back(); // on the drawn water: no state of its own
        else
            velocities.push_back(FloatingBody::Velocity{}); // fixed
    }
    return velocities;
}

} // namespace swell::detail
