// A mesh placed by a pose and projected with a calibration, rasterised on
// the CPU: the pixels whose centres its triangles cover. For tests that hold
// a label's mask to the geometry it was drawn from.
#pragma once

#include "assets/mesh_data.h"
#include "swell/dataset/labels.h"

#include <glm/common.hpp>
#include <glm/mat4x4.hpp>

#include <algorithm>
#include <cmath>
#include <optional>
#include <vector>

namespace swell::test {

// Twice the signed area of the triangle (a, b, p).
inline double signedArea2(glm::dvec2 a, glm::dvec2 b, glm::dvec2 p)
{
    return (b.x - a.x) * (p.y - a.y) - (b.y - a.y) * (p.x - a.x);
}

// The pixels (rows top first, c.size) whose centres the mesh's triangles,
// placed by worldFromObject and projected with the calibration, cover.
inline std::vector<bool> projectedMask(const detail::MeshData& mesh, const glm::dmat4& worldFromObject,
                                       const CameraCalibration& c)
{
    std::vector<bool> mask(std::size_t(c.size.x) * std::size_t(c.size.y), false);
    for (std::size_t t = 0; t + 2 < mesh.indices.size(); t += 3) {
        glm::dvec2 p[3];
        bool seen = true;
        for (int k = 0; k < 3; ++k) {
            const glm::dvec3 model(mesh.vertices[mesh.indices[t + std::size_t(k)]].position);
            const std::optional<glm::dvec2> at = projectToImage(c, glm::dvec3(worldFromObject * glm::dvec4(model, 1.0)));
            seen = seen && at.has_value();
            p[k] = at.value_or(glm::dvec2(0.0));
        }
        if (!seen)
            continue;
        const double area = signedArea2(p[0], p[1], p[2]);
        if (area == 0.0)
            continue;
        const glm::dvec2 lo = glm::min(p[0], glm::min(p[1], p[2])), hi = glm::max(p[0], glm::max(p[1], p[2]));
        for (int y = std::max(0, int(std::floor(lo.y))); y <= std::min(c.size.y - 1, int(std::ceil(hi.y))); ++y)
            for (int x = std::max(0, int(std::floor(lo.x))); x <= std::min(c.size.x - 1, int(std::ceil(hi.x))); ++x) {
                const glm::dvec2 centre(x + 0.5, y + 0.5);
                const double w0 = signedArea2(p[1], p[2], centre) / area, w1 = signedArea2(p[2], p[0], centre) / area,
                             w2 = signedArea2(p[0], p[1], centre) / area;
                if (w0 >= 0.0 && w1 >= 0.0 && w2 >= 0.0)
                    mask[std::size_t(y) * std::size_t(c.size.x) + std::size_t(x)] = true;
            }
    }
    return mask;
}

} // namespace swell::test
