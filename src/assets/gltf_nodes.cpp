// glTF step 4b: the node graph, checked to be a forest, and each node's
// local transform (TRS or matrix).
#include "assets/gltf_loader.h"

#include "swell/error.h"

#include <fmt/format.h>

#include <cmath>
#include <limits>

namespace swell::detail::gltf {

glm::dmat4 GltfLoader::localTransform(std::size_t n) const
{
    const tinygltf::Node& node = model_.nodes[n];
    const auto numbers = [&](const std::vector<double>& v, std::size_t size, const char* what) {
        if (v.size() != size)
            fail(fmt::format("node {} has a {} of {} numbers (needs {})", n, what, v.size(), size));
        for (double x : v)
            if (!std::isfinite(x))
                fail(fmt::format("node {} has a non-finite {}", n, what));
    };
    if (!node.matrix.empty()) {
        numbers(node.matrix, 16, "matrix");
        glm::dmat4 m(1.0);
        for (int c = 0; c < 4; ++c)
            for (int r = 0; r < 4; ++r)
                m[c][r] = node.matrix[std::size_t(c * 4 + r)];
        return m;
    }
    glm::dmat4 t(1.0), r(1.0), s(1.0);
    if (!node.translation.empty()) {
        numbers(node.translation, 3, "translation");
        t[3] = glm::dvec4(node.translation[0], node.translation[1], node.translation[2], 1.0);
    }
    if (!node.rotation.empty()) {
        numbers(node.rotation, 4, "rotation");
        double x = node.rotation[0], y = node.rotation[1], z = node.rotation[2], w = node.rotation[3];
        const double length = std::sqrt(x * x + y * y + z * z + w * w);
        if (!(length > 1e-12) || !std::isfinite(length))
            fail(fmt::format("node {} has a rotation quaternion of length {}", n, length));
        x /= length, y /= length, z /= length, w /= length;
        r[0] = glm::dvec4(1 - 2 * (y * y + z * z), 2 * (x * y + z * w), 2 * (x * z - y * w), 0);
        r[1] = glm::dvec4(2 * (x * y - z * w), 1 - 2 * (x * x + z * z), 2 * (y * z + x * w), 0);
        r[2] = glm::dvec4(2 * (x * z + y * w), 2 * (y * z - x * w), 1 - 2 * (x * x + y * y), 0);
    }
    if (!node.scale.empty()) {
        numbers(node.scale, 3, "scale");
        s[0][0] = node.scale[0];
        s[1][1] = node.scale[1];
        s[2][2] = node.scale[2];
    }
    return t * r * s;
}

// The root nodes to draw, after checking that the nodes form a forest:
// indices in range, at most one parent each, no cycles.
std::vector<std::size_t> GltfLoader::roots() const
{
    const std::size_t count = model_.nodes.size();
    constexpr std::size_t kNone = std::numeric_limits<std::size_t>::max();
    std::vector<std::size_t> parent(count, kNone);
    for (std::size_t n = 0; n < count; ++n) {
        const tinygltf::Node& node = model_.nodes[n];
        if (node.mesh < -1 || node.mesh >= int(std::min<std::size_t>(model_.meshes.size(), INT32_MAX)))
            fail(fmt::format("node {} refers to mesh {}, which does not exist", n, node.mesh));
        for (int child : node.children) {
            if (child < 0 || std::size_t(child) >= count)
                fail(fmt::format("node {} has child {}, which does not exist", n, child));
            if (std::size_t(child) == n)
                fail(fmt::format("node graph has a cycle: node {} is its own child", n));
            if (parent[std::size_t(child)] != kNone)
                fail(fmt::format("node {} has more than one parent (nodes {} and {})", child,
                                 parent[std::size_t(child)], n));
            parent[std::size_t(child)] = n;
        }
    }
    // With one parent each, a cycle is a loop of parent links.
    std::vector<char> state(count, 0); // 0 unseen, 1 on the current walk, 2 done
    for (std::size_t n = 0; n < count; ++n) {
        std::size_t at = n;
        while (at != kNone && state[at] == 0) {
            state[at] = 1;
            at = parent[at];
        }
        if (at != kNone && state[at] == 1)
            fail(fmt::format("node graph has a cycle through node {}", at));
        for (at = n; at != kNone && state[at] == 1; at = parent[at])
            state[at] = 2;
    }

    std::vector<std::size_t> out;
    if (model_.scenes.empty()) {
        if (model_.defaultScene >= 0)
            fail(fmt::format("scene {} does not exist (the file has no scenes)", model_.defaultScene));
        for (std::size_t n = 0; n < count; ++n)
            if (parent[n] == kNone)
                out.push_back(n);
        return out;
    }
    const int sceneIndex = model_.defaultScene >= 0 ? model_.defaultScene : 0;
    if (std::size_t(sceneIndex) >= model_.scenes.size())
        fail(fmt::format("scene {} does not exist (the file has {})", sceneIndex, model_.scenes.size()));
    std::vector<char> listed(count, 0);
    for (int n : model_.scenes[std::size_t(sceneIndex)].nodes) {
        if (n < 0 || std::size_t(n) >= count)
            fail(fmt::format("scene {} lists node {}, which does not exist", sceneIndex, n));
        if (parent[std::size_t(n)] != kNone)
            fail(fmt::format("scene {} lists node {}, which is a child of node {}", sceneIndex, n,
                             parent[std::size_t(n)]));
        if (listed[std::size_t(n)])
            fail(fmt::format("scene {} lists node {} twice", sceneIndex, n));
        listed[std::size_t(n)] = 1;
        out.push_back(std::size_t(n));
    }
    return out;
}

} // namespace swell::detail::gltf
