// The fleet's design loading (design_loading.h).
#include "objects/design_loading.h"

#include "swell/error.h"

#include <glm/geometric.hpp>

#include <vector>

namespace swell::detail {

VolumeBelow volumeBelow(const BodyShape& shape, double level_m)
{
    const glm::dvec3 apex(0.0, level_m, 0.0);
    double volume = 0.0;
    glm::dvec3 moment(0.0);
    std::vector<glm::dvec3> below;
    for (std::size_t t = 0; t + 2 < shape.indices.size(); t += 3) {
        below.clear();
        for (int k = 0; k < 3; ++k) {
            const glm::dvec3 p = shape.positions_m[shape.indices[t + std::size_t(k)]] - apex;
            const glm::dvec3 q = shape.positions_m[shape.indices[t + std::size_t((k + 1) % 3)]] - apex;
            if (p.y <= 0.0)
                below.push_back(p);
            if ((p.y < 0.0) != (q.y < 0.0) && p.y != q.y)
                below.push_back(p + (q - p) * (-p.y / (q.y - p.y)));
        }
        for (std::size_t k = 1; k + 1 < below.size(); ++k) {
            const double v = glm::dot(below[0], glm::cross(below[k], below[k + 1])) / 6.0;
            volume += v;
            moment += v * (below[0] + below[k] + below[k + 1]) / 4.0;
        }
    }
    return {volume, volume > 0.0 ? moment / volume + apex : apex};
}

DesignLoading designLoadingOf(const BodyShape& shape, double centerOfMassHeight_m, double waterDensity_kg_per_m3)
{
    const VolumeBelow displaced = volumeBelow(shape, 0.0);
    if (!(displaced.volume_m3 > 0.0))
        throw InputError({}, "its hull reaches no lower than its design waterline: nothing to float it");
    const glm::dvec3 centerOfMass(displaced.centroid_m.x, centerOfMassHeight_m, displaced.centroid_m.z);
    return {waterDensity_kg_per_m3 * displaced.volume_m3, centerOfMass - massPropertiesOf(shape).centroid_m};
}

} // namespace swell::detail
