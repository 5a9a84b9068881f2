// glTF step 4c: mesh primitives as triangles in one MeshData, with node
// transforms applied and the totals capped before anything is read.
#include "assets/gltf_loader.h"

#include "swell/error.h"

#include <fmt/format.h>

#include <glm/geometric.hpp>
#include <glm/mat3x3.hpp>
#include <glm/matrix.hpp>

#include <algorithm>
#include <cmath>
#include <limits>

namespace swell::detail::gltf {

GltfLoader::Shape GltfLoader::shape(std::size_t m, std::size_t p) const
{
    const tinygltf::Primitive& prim = model_.meshes[m].primitives[p];
    const std::string where = fmt::format("mesh {} primitive {}", m, p);
    Shape s;
    if (prim.mode >= TINYGLTF_MODE_POINTS && prim.mode <= TINYGLTF_MODE_LINE_STRIP)
        return s; // points and lines have no surface
    if (prim.mode < TINYGLTF_MODE_TRIANGLES || prim.mode > TINYGLTF_MODE_TRIANGLE_FAN)
        fail(fmt::format("{} has unknown mode {}", where, prim.mode));
    s.drawn = true;
    const auto attribute = [&](const char* name) {
        const auto it = prim.attributes.find(name);
        return it == prim.attributes.end() ? -1 : it->second;
    };
    s.position = attribute("POSITION");
    if (s.position < 0)
        fail(where + " has no POSITION attribute");
    s.vertices = accessorAt(s.position, where + " POSITION").count;
    s.normal = attribute("NORMAL");
    s.color = attribute("COLOR_0");
    for (const auto& [index, name] : {std::pair{s.normal, "NORMAL"}, std::pair{s.color, "COLOR_0"}})
        if (index >= 0 && accessorAt(index, where + " " + name).count != s.vertices)
            fail(fmt::format("{} has {} {} values but {} positions", where,
                             accessorAt(index, where).count, name, s.vertices));
    // Counts are at most 2^53 (checked in the JSON), so these cannot overflow.
    const std::size_t n = prim.indices >= 0 ? accessorAt(prim.indices, where + " indices").count : s.vertices;
    if (prim.mode == TINYGLTF_MODE_TRIANGLES) {
        if (n % 3 != 0)
            fail(fmt::format("{} has {} {}, not a multiple of 3", where, n,
                             prim.indices >= 0 ? "indices" : "vertices"));
        s.indices = n;
    } else
        s.indices = n >= 3 ? 3 * (n - 2) : 0;
    return s;
}

// Appends primitive p of mesh m, placed by `world`.
void GltfLoader::addPrimitive(MeshData& out, std::size_t m, std::size_t p, const glm::dmat4& world, std::size_t node) const
{
    const tinygltf::Primitive& prim = model_.meshes[m].primitives[p];
    const std::string where = fmt::format("mesh {} primitive {}", m, p);
    const Shape s = shape(m, p);
    if (!s.drawn)
        return;
    if (out.vertices.size() + s.vertices > kMaxVertices || out.indices.size() + s.indices > kMaxIndices)
        fail(fmt::format("model has more than {} vertices or {} indices", kMaxVertices, kMaxIndices));

    const Values<float> positions =
        readFloats(s.position, where + " POSITION", false, {TINYGLTF_TYPE_VEC3}, "float VEC3");
    const std::size_t vertexCount = positions.count();
    std::optional<Values<float>> normals, colors;
    if (s.normal >= 0)
        normals = readFloats(s.normal, where + " NORMAL", false, {TINYGLTF_TYPE_VEC3}, "float VEC3");
    if (s.color >= 0)
        colors = readFloats(s.color, where + " COLOR_0", true, {TINYGLTF_TYPE_VEC3, TINYGLTF_TYPE_VEC4},
                            "VEC3 or VEC4 of float or normalised unsigned byte or short");

    // Vertex indices of the primitive, then triangles from them.
    std::vector<std::uint32_t> order;
    if (prim.indices >= 0) {
        const Values<std::uint32_t> indices = readIndices(prim.indices, where + " indices");
        for (std::size_t i = 0; i < indices.data.size(); ++i)
            if (indices.data[i] >= vertexCount)
                fail(fmt::format("{} index {} is {}, but there are only {} vertices", where, i, indices.data[i],
                                 vertexCount));
        order = indices.data;
    } else {
        order.resize(vertexCount);
        for (std::size_t i = 0; i < vertexCount; ++i)
            order[i] = std::uint32_t(i);
    }
    const std::size_t triangleCount = s.indices / 3;

    const double det = glm::determinant(glm::dmat3(world));
    const bool mirrored = det < 0.0;
    std::vector<std::uint32_t> triangles;
    triangles.reserve(triangleCount * 3);
    for (std::size_t t = 0; t < triangleCount; ++t) {
        std::uint32_t a = 0, b = 0, c = 0;
        if (prim.mode == TINYGLTF_MODE_TRIANGLES)
            a = order[3 * t], b = order[3 * t + 1], c = order[3 * t + 2];
        else if (prim.mode == TINYGLTF_MODE_TRIANGLE_STRIP)
            a = order[t + (t % 2)], b = order[t + 1 - (t % 2)], c = order[t + 2];
        else
            a = order[0], b = order[t + 1], c = order[t + 2];
        if (mirrored)
            std::swap(b, c);
        triangles.insert(triangles.end(), {a, b, c});
    }

    glm::vec3 factor = kDefaultColor;
    if (prim.material >= 0) {
        if (std::size_t(prim.material) >= model_.materials.size())
            fail(fmt::format("{} refers to material {}, which does not exist", where, prim.material));
        const std::vector<double>& f = model_.materials[std::size_t(prim.material)].pbrMetallicRoughness.baseColorFactor;
        if (f.size() < 3)
            fail(fmt::format("material {} has a baseColorFactor of {} numbers", prim.material, f.size()));
        for (int c = 0; c < 3; ++c)
            factor[c] = float(std::clamp(f[std::size_t(c)], 0.0, 1.0));
    } else if (colors)
        factor = glm::vec3(1.0f);

    // Normals transform with the cofactor matrix (the inverse transpose
    // scaled by the determinant), which also works for flattening scales.
    const glm::dmat3 linear(world);
    glm::dmat3 cofactor;
    cofactor[0] = glm::cross(linear[1], linear[2]);
    cofactor[1] = glm::cross(linear[2], linear[0]);
    cofactor[2] = glm::cross(linear[0], linear[1]);
    if (mirrored)
        cofactor = -cofactor;

    const auto base = std::uint32_t(out.vertices.size());
    for (std::size_t i = 0; i < vertexCount; ++i) {
        const float* q = &positions.data[3 * i];
        const glm::dvec3 position = glm::dvec3(world * glm::dvec4(q[0], q[1], q[2], 1.0));
        constexpr double kFloatMax = std::numeric_limits<float>::max();
        if (!(std::abs(position.x) <= kFloatMax && std::abs(position.y) <= kFloatMax &&
              std::abs(position.z) <= kFloatMax))
            fail(fmt::format("node {}'s transform moves {} vertex {} to a non-finite position", node, where, i));
        MeshVertex v;
        v.position = glm::vec3(position);
        if (normals) {
            const float* nn = &normals->data[3 * i];
            const glm::dvec3 n = cofactor * glm::dvec3(nn[0], nn[1], nn[2]);
            const double length = glm::length(n);
            v.normal = length > 1e-30 && std::isfinite(length) ? glm::vec3(n / length) : glm::vec3(0, 1, 0);
        }
        v.color = factor;
        if (colors) {
            const float* c = &colors->data[std::size_t(colors->components) * i];
            v.color *= glm::clamp(glm::vec3(c[0], c[1], c[2]), glm::vec3(0.0f), glm::vec3(1.0f));
        }
        out.vertices.push_back(v);
    }
    if (!normals) {
        // Smooth normals: area-weighted sums of the faces around each vertex.
        for (std::size_t t = 0; t < triangles.size(); t += 3) {
            MeshVertex& a = out.vertices[base + triangles[t]];
            MeshVertex& b = out.vertices[base + triangles[t + 1]];
            MeshVertex& c = out.vertices[base + triangles[t + 2]];
            const glm::vec3 n = glm::cross(b.position - a.position, c.position - a.position);
            if (std::isfinite(n.x) && std::isfinite(n.y) && std::isfinite(n.z)) {
                a.normal += n;
                b.normal += n;
                c.normal += n;
            }
        }
        for (std::size_t i = base; i < out.vertices.size(); ++i) {
            const float length = glm::length(out.vertices[i].normal);
            out.vertices[i].normal = length > 0.0f && std::isfinite(length) ? out.vertices[i].normal / length
                                                                             : glm::vec3(0, 1, 0);
        }
    }
    for (std::uint32_t i : triangles)
        out.indices.push_back(base + i);
}

MeshData GltfLoader::assemble(std::string_view hullNode, MeshData* hull) const
{
    // Pass 1: every primitive drawn, with its node's world transform.
    struct Instance {
        std::size_t node, mesh, primitive;
        glm::dmat4 world;
        bool hull; // under the node named hullNode: the hull volume, not drawn
    };
    std::vector<Instance> instances;
    struct Item {
        std::size_t node;
        glm::dmat4 parent;
        bool hull;
    };
    bool hullFound = false;
    // Depth first in file order: roots and children go on in reverse.
    const std::vector<std::size_t> rootNodes = roots();
    std::vector<Item> stack;
    for (auto r = rootNodes.rbegin(); r != rootNodes.rend(); ++r)
        stack.push_back({*r, glm::dmat4(1.0), false});
    while (!stack.empty()) {
        const Item item = stack.back();
        stack.pop_back();
        const tinygltf::Node& node = model_.nodes[item.node];
        const glm::dmat4 world = item.parent * localTransform(item.node);
        const bool inHull = item.hull || (!hullNode.empty() && node.name == hullNode);
        hullFound = hullFound || inHull;
        if (node.mesh >= 0)
            for (std::size_t p = 0; p < model_.meshes[std::size_t(node.mesh)].primitives.size(); ++p) {
                if (instances.size() == kMaxPrimitiveInstances)
                    fail(fmt::format("model draws more than {} mesh primitives", kMaxPrimitiveInstances));
                instances.push_back({item.node, std::size_t(node.mesh), p, world, inHull});
            }
        for (auto c = node.children.rbegin(); c != node.children.rend(); ++c)
            stack.push_back({std::size_t(*c), world, inHull});
    }

    if (!hullNode.empty() && !hullFound) {
        std::string names;
        for (const tinygltf::Node& n : model_.nodes)
            if (!n.name.empty() && names.size() < 200)
                names += (names.empty() ? "'" : ", '") + printable(n.name) + "'";
        fail(fmt::format("hull_node: no node named '{}' in the scene drawn; its named nodes: {}", printable(hullNode),
                         names.empty() ? "none" : names));
    }

    // The totals, checked against the limits before anything is read.
    std::optional<std::uint64_t> vertices = 0, indices = 0;
    for (const Instance& i : instances) {
        const Shape s = shape(i.mesh, i.primitive);
        vertices = vertices ? add(*vertices, s.vertices) : vertices;
        indices = indices ? add(*indices, s.indices) : indices;
    }
    if (!vertices || *vertices > kMaxVertices)
        fail(fmt::format("model has {} vertices, more than the limit of {}", needs(vertices), kMaxVertices));
    if (!indices || *indices > kMaxIndices)
        fail(fmt::format("model has {} indices, more than the limit of {}", needs(indices), kMaxIndices));

    // Pass 2: the data.
    // Reserved at the totals: growing by doubling would hold the old and the
    // new copy at once, half again the peak at the caps.
    MeshData out;
    out.vertices.reserve(std::size_t(*vertices));
    out.indices.reserve(std::size_t(*indices));
    for (const Instance& i : instances)
        addPrimitive(i.hull && hull ? *hull : out, i.mesh, i.primitive, i.world, i.node);
    if (out.indices.empty())
        fail(hullNode.empty() ? "model has no triangles to draw" : "model has no triangles to draw besides its hull");
    if (hull && !hullNode.empty() && hull->indices.empty())
        fail(fmt::format("hull_node: node '{}' and its children have no triangles", printable(hullNode)));
    return out;
}

} // namespace swell::detail::gltf
