// glTF step 4a: accessors and buffer views, every offset, stride and count
// checked against the bytes that are really there before anything is read.
#include "assets/gltf_loader.h"

#include "swell/error.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <cstring>

namespace swell::detail::gltf {

// Checks that `count` elements of `elementSize` bytes, starting `offset`
// bytes into bufferView `view`, lie inside that view and the view inside
// its buffer. Elements are the view's byteStride apart when allowStride,
// else packed. `user` names the reader in messages.
GltfLoader::Run GltfLoader::locate(const std::string& user, int view, std::uint64_t offset, std::uint64_t count, std::size_t elementSize,
           bool allowStride) const
{
    if (view < 0 || std::size_t(view) >= model_.bufferViews.size())
        fail(fmt::format("{} refers to bufferView {}, which does not exist", user, view));
    const tinygltf::BufferView& v = model_.bufferViews[std::size_t(view)];
    if (v.buffer < 0 || std::size_t(v.buffer) >= model_.buffers.size())
        fail(fmt::format("bufferView {} refers to buffer {}, which does not exist", view, v.buffer));
    const std::vector<unsigned char>& buffer = model_.buffers[std::size_t(v.buffer)].data;
    const std::optional<std::uint64_t> viewEnd = add(v.byteOffset, v.byteLength);
    if (!viewEnd || *viewEnd > buffer.size())
        fail(fmt::format("bufferView {} reads past the end of buffer {} (needs {} bytes, has {})", view, v.buffer,
                         needs(viewEnd), buffer.size()));
    if (count == 0)
        return {};
    std::size_t stride = elementSize;
    if (allowStride && v.byteStride != 0) {
        if (v.byteStride < elementSize || v.byteStride > 252 || v.byteStride % 4 != 0)
            fail(fmt::format("bufferView {} has byteStride {}, which does not fit the {}-byte elements of {}",
                             view, v.byteStride, elementSize, user));
        stride = v.byteStride;
    }
    std::optional<std::uint64_t> end = mul(count - 1, stride);
    if (end)
        end = add(*end, elementSize);
    if (end)
        end = add(*end, offset);
    if (!end || *end > v.byteLength)
        fail(fmt::format("{} reads past the end of bufferView {} (needs {} bytes, has {})", user, view, needs(end),
                         v.byteLength));
    return {buffer.data() + v.byteOffset + std::size_t(offset), stride};
}

std::size_t GltfLoader::componentSize(int type)
{
    switch (type) {
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE:
        return 1;
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT:
        return 2;
    default:
        return 4; // UNSIGNED_INT, FLOAT
    }
}

// Reads element components as floats; unsigned integers are normalised to 0..1.
float GltfLoader::readFloat(const unsigned char* p, int type)
{
    switch (type) {
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE:
        return float(*p) / 255.0f;
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT: {
        std::uint16_t v = 0;
        std::memcpy(&v, p, 2);
        return float(v) / 65535.0f;
    }
    default: {
        float v = 0;
        std::memcpy(&v, p, 4);
        return v;
    }
    }
}

std::uint32_t GltfLoader::readIndex(const unsigned char* p, int type)
{
    switch (type) {
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE:
        return *p;
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT: {
        std::uint16_t v = 0;
        std::memcpy(&v, p, 2);
        return v;
    }
    default: {
        std::uint32_t v = 0;
        std::memcpy(&v, p, 4);
        return v;
    }
    }
}

const tinygltf::Accessor& GltfLoader::accessorAt(int index, const std::string& semantic) const
{
    if (index < 0 || std::size_t(index) >= model_.accessors.size())
        fail(fmt::format("{} refers to accessor {}, which does not exist", semantic, index));
    return model_.accessors[std::size_t(index)];
}

// Reads accessor `index`, used as `semantic`, whose component type must be
// in `componentTypes` and element type in `types`, with at most
// `maxElements` elements (kMaxVertices for attributes, kMaxIndices for
// indices). Read converts one component. Sparse substitutions are applied.
template <class T, class Read>
GltfLoader::Values<T> GltfLoader::readAccessor(int index, const std::string& semantic, std::size_t maxElements,
                                               std::initializer_list<int> componentTypes,
                                               std::initializer_list<int> types, const char* expected, Read read) const
{
    const tinygltf::Accessor& a = accessorAt(index, semantic);
    const std::string user = fmt::format("accessor {} ({})", index, semantic);
    if (std::find(componentTypes.begin(), componentTypes.end(), a.componentType) == componentTypes.end() ||
        std::find(types.begin(), types.end(), a.type) == types.end())
        fail(fmt::format("{} must be {}", user, expected));
    if (a.count > maxElements)
        fail(fmt::format("{} has {} elements, more than the limit of {}", user, a.count, maxElements));
    const int components = a.type == TINYGLTF_TYPE_SCALAR ? 1 : a.type; // VEC2..VEC4 are 2..4
    const std::size_t size = componentSize(a.componentType);
    const std::size_t elementSize = size * std::size_t(components);

    const Run run = a.bufferView >= 0 ? locate(user, a.bufferView, a.byteOffset, a.count, elementSize, true) : Run{};
    Values<T> out;
    out.components = components;
    out.data.assign(a.count * std::size_t(components), T{});
    if (run.data) {
        for (std::size_t i = 0; i < a.count; ++i)
            for (int c = 0; c < components; ++c)
                out.data[i * std::size_t(components) + std::size_t(c)] =
                    read(run.data + i * run.stride + std::size_t(c) * size, a.componentType);
    }
    if (a.sparse.isSparse) {
        const auto& s = a.sparse;
        const std::string sparseUser = user + " sparse";
        if (s.count < 1 || std::size_t(s.count) > a.count)
            fail(fmt::format("{} has {} substitutions for {} elements", sparseUser, s.count, a.count));
        if (s.indices.byteOffset < 0 || s.values.byteOffset < 0)
            fail(fmt::format("{} has a negative byteOffset", sparseUser));
        const int indexType = s.indices.componentType;
        if (indexType != TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE &&
            indexType != TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT && indexType != TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT)
            fail(fmt::format("{} indices must be unsigned byte, short or int", sparseUser));
        const Run indices = locate(sparseUser + " indices", s.indices.bufferView, std::uint64_t(s.indices.byteOffset),
                                   std::uint64_t(s.count), componentSize(indexType), false);
        const Run values = locate(sparseUser + " values", s.values.bufferView, std::uint64_t(s.values.byteOffset),
                                  std::uint64_t(s.count), elementSize, false);
        for (std::size_t i = 0; i < std::size_t(s.count); ++i) {
            const std::uint32_t target = readIndex(indices.data + i * indices.stride, indexType);
            if (target >= a.count)
                fail(fmt::format("{} index {} is out of range (the accessor has {} elements)", sparseUser, target,
                                 a.count));
            for (int c = 0; c < components; ++c)
                out.data[target * std::size_t(components) + std::size_t(c)] =
                    read(values.data + i * values.stride + std::size_t(c) * size, a.componentType);
        }
    }
    return out;
}

GltfLoader::Values<float> GltfLoader::readFloats(int index, const std::string& semantic, bool allowNormalized,
                         std::initializer_list<int> types, const char* expected) const
{
    Values<float> v = allowNormalized
                          ? readAccessor<float>(index, semantic, kMaxVertices,
                                                {TINYGLTF_COMPONENT_TYPE_FLOAT, TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE,
                                                 TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT},
                                                types, expected, readFloat)
                          : readAccessor<float>(index, semantic, kMaxVertices, {TINYGLTF_COMPONENT_TYPE_FLOAT}, types, expected,
                                                readFloat);
    for (std::size_t i = 0; i < v.data.size(); ++i)
        if (!std::isfinite(v.data[i]))
            fail(fmt::format("accessor {} ({}) has a non-finite value in element {}", index, semantic,
                             i / std::size_t(v.components)));
    return v;
}

GltfLoader::Values<std::uint32_t> GltfLoader::readIndices(int index, const std::string& semantic) const
{
    return readAccessor<std::uint32_t>(index, semantic, kMaxIndices,
                                       {TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE, TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT,
                                        TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT},
                                       {TINYGLTF_TYPE_SCALAR}, "SCALAR unsigned byte, short or int", readIndex);
}

} // namespace swell::detail::gltf
