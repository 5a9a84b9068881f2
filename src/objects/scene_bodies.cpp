// A scene's floating bodies (scene_bodies.h).
#include "objects/scene_bodies.h"

#include "swell/error.h"
#include "swell/grid.h"

#include <fmt/format.h>
#include <algorithm>
#include <glm/gtc/matrix_transform.hpp>

namespace swell::detail {

SurfaceFilter bodySurfaceFilter(const Scene& scene)
{
    const GridShape shape = gridShapeFor(scene.grid, scene.camera);
    const GridPlacement atScaleOne = placeGrid(shape, glm::dvec3(0.0));
    const int centre = shape.cells / 2;
    return {gridPoint(shape, atScaleOne, centre, centre).cellSize_m, 1.0};
}

bool sameBodies(const Scene& a, const Scene& b)
{
    if (a.objects.size() != b.objects.size() || a.grid.resolution != b.grid.resolution ||
        a.grid.radius_m != b.grid.radius_m || a.grid.layout != b.grid.layout || a.camera.far_m != b.camera.far_m)
        return false;
    for (std::size_t i = 0; i < a.objects.size(); ++i) {
        const SceneObject &x = a.objects[i], &y = b.objects[i];
        if (x.isRigidBody() != y.isRigidBody())
            return false;
        if (x.isRigidBody() &&
            (x.position_m != y.position_m || x.yaw_deg != y.yaw_deg || x.scale != y.scale || x.mass_kg != y.mass_kg ||
             x.density_kg_per_m3 != y.density_kg_per_m3 || x.centerOfMassOffset_m != y.centerOfMassOffset_m ||
             x.inertia_kg_m2 != y.inertia_kg_m2 || x.velocity_m_per_s != y.velocity_m_per_s ||
             x.dampingRatio != y.dampingRatio))
            return false;
    }
    return true;
}

SceneBodies::SceneBodies(const Scene& scene, const std::vector<const MeshData*>& shapes, const WaveModel& surface)
{
    const SurfaceFilter filter = bodySurfaceFilter(scene);
    for (std::size_t i = 0; i < scene.objects.size(); ++i) {
        const SceneObject& o = scene.objects[i];
        scale_.push_back(o.scale);
        if (!o.isRigidBody() || i >= shapes.size() || shapes[i] == nullptr) {
            bodies_.emplace_back();
            continue;
        }
        try {
            BodyShape shape;
            for (const MeshVertex& v : shapes[i]->vertices)
                shape.positions_m.push_back(glm::dvec3(v.position) * o.scale);
            shape.indices = shapes[i]->indices;
            BodySettings settings;
            settings.mass_kg = o.mass_kg > 0.0 ? o.mass_kg : o.density_kg_per_m3 * massPropertiesOf(shape).volume_m3;
            settings.centerOfMassOffset_m = o.centerOfMassOffset_m * o.scale;
            settings.principalInertia_kg_m2 = o.inertia_kg_m2;
            settings.dampingRatio = o.dampingRatio;
            const BodyStart start{o.position_m, o.yaw_deg, o.velocity_m_per_s};
            bodies_.push_back(std::make_unique<FloatingBody>(shape, settings, start, surface, filter));
            ++count_;
        } catch (const InputError& e) {
            const std::string key = fmt::format("objects[{}].path", i);
            for (const AssetReference& r : scene.assetReferences)
                if (r.key == key)
                    throw InputError(r.place, fmt::format("objects[{}] ({}): {}", i, o.path, e.message()));
            throw InputError({o.path}, fmt::format("objects[{}]: {}", i, e.message()));
        }
    }
}

void SceneBodies::advanceTo(double time_s)
{
    // In lockstep, step by step: every body asks for the water at the same
    // sample times one after another (see FloatingBody::advanceToStep).
    const std::int64_t last = FloatingBody::lastStepFor(time_s);
    std::int64_t from = last;
    for (const auto& b : bodies_)
        if (b) {
            if (b->state().step > last)
                b->advanceToStep(0); // time went back: start again from t = 0
            from = std::min(from, b->state().step);
        }
    for (std::int64_t n = from + 1; n <= last; ++n)
        for (const auto& b : bodies_)
            if (b && b->state().step < n)
                b->advanceToStep(n);
}

std::optional<glm::dmat4> SceneBodies::poseAt(std::size_t i, double time_s)
{
    if (i >= bodies_.size() || !bodies_[i])
        return std::nullopt;
    return bodies_[i]->poseAt(time_s) * glm::scale(glm::dmat4(1.0), glm::dvec3(scale_[i]));
}

std::int64_t SceneBodies::stepsTaken() const
{
    std::int64_t steps = 0;
    for (const auto& b : bodies_)
        if (b)
            steps += b->stepsTaken();
    return steps;
}

} // namespace swell::detail
