// A ray cast against a mesh on the CPU, for tests that hold a label's range
// to the geometry it was drawn from.
#pragma once

#include "assets/mesh_data.h"

#include <glm/geometric.hpp>
#include <glm/mat4x4.hpp>
#include <glm/vec3.hpp>

#include <algorithm>
#include <cmath>
#include <optional>

namespace swell::test {

// Where the ray from eye along the unit direction d first meets the mesh
// placed at `pose` (Moller and Trumbore 1997, "Fast, minimum storage
// ray-triangle intersection"): the point in the model's own axes (its triangle's
// vertices weighted by the hit's barycentric weights) and the distance;
// empty where it misses.
struct MeshHit {
    glm::dvec3 model_m{0.0};
    double distance_m = INFINITY;
};
inline std::optional<MeshHit> rayHitOnMesh(const detail::MeshData& mesh, const glm::dmat4& pose, glm::dvec3 eye,
                                           glm::dvec3 d)
{
    std::optional<MeshHit> nearest;
    for (std::size_t t = 0; t + 2 < mesh.indices.size(); t += 3) {
        glm::dvec3 m[3], v[3];
        for (int k = 0; k < 3; ++k) {
            m[k] = glm::dvec3(mesh.vertices[mesh.indices[t + std::size_t(k)]].position);
            v[k] = glm::dvec3(pose * glm::dvec4(m[k], 1.0));
        }
        const glm::dvec3 e1 = v[1] - v[0], e2 = v[2] - v[0], p = glm::cross(d, e2);
        const double det = glm::dot(e1, p);
        if (std::abs(det) < 1e-15)
            continue;
        const glm::dvec3 s0 = eye - v[0];
        const double u = glm::dot(s0, p) / det;
        const glm::dvec3 q = glm::cross(s0, e1);
        const double w = glm::dot(d, q) / det, t0 = glm::dot(e2, q) / det;
        if (u >= 0.0 && w >= 0.0 && u + w <= 1.0 && t0 > 0.0 && (!nearest || t0 < nearest->distance_m))
            nearest = MeshHit{(1.0 - u - w) * m[0] + u * m[1] + w * m[2], t0};
    }
    return nearest;
}

// The distance along the unit direction d from eye to the first of the
// mesh's triangles placed at `pose` (Moller and Trumbore 1997, "Fast,
// minimum storage ray-triangle intersection"); infinity where it misses.
inline double rayCastMesh(const detail::MeshData& mesh, const glm::dmat4& pose, glm::dvec3 eye, glm::dvec3 d)
{
    const std::optional<MeshHit> hit = rayHitOnMesh(mesh, pose, eye, d);
    return hit ? hit->distance_m : INFINITY;
}

} // namespace swell::test
