// One description of each std140 uniform block C++ and GLSL share, kept
// next to its C++ struct (Filament's UibStructs): its members' GLSL names
// and the C++ offsets they are written at. The GLSL declaration is
// generated from it at build time (src/render/gpu/generate_glsl.cpp writes
// every file src/render/gpu/glsl_files.h lists), after checking that the
// std140 rules put every member where the C++ struct has it; the shaders
// include the generated files and declare no block by hand, and
// tests/gl/test_uniform_layout.cpp asks the driver for every member's
// offset too. No GL here: the generator builds without a context.
//
// A struct is described by a function found by argument-dependent lookup,
//
//     inline const gl::BlockStruct& blockStructOf(const MyStruct*)
//     {
//         static const gl::BlockStruct s{"MyStruct", "swell::detail::MyStruct", sizeof(MyStruct), {
//             SWELL_BLOCK_MEMBER(MyStruct, position_m),
//             SWELL_BLOCK_MEMBER_AS(MyStruct, count, "myCount"),
//         }};
//         return s;
//     }
//
// listing its members in order, C++ padding with SWELL_BLOCK_PADDING; a
// member whose type is a described struct, or an array of one, is that
// struct in GLSL.
#pragma once

#include <glm/mat4x4.hpp>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include <cstddef>
#include <string>
#include <string_view>
#include <type_traits>
#include <vector>

namespace swell::gl {

struct BlockStruct;

struct BlockMember {
    std::string_view name;    // in GLSL
    std::string_view type;    // GLSL's scalar, vector or matrix type; empty for a struct
    std::size_t offset = 0;   // where the C++ struct holds it, bytes
    std::size_t count = 0;    // array elements; 0: not an array
    const BlockStruct* structure = nullptr; // the struct's description, for a struct member
    std::size_t cppSize = 0;  // sizeof the C++ member
    std::size_t cppAlign = 1; // alignof the C++ member
    // C++ padding where std140 leaves a gap (after a vec3, say): not in
    // GLSL, but described so that every byte of the C++ struct is accounted for.
    bool padding = false;
};

struct BlockStruct {
    std::string_view name;    // the GLSL struct's or block's name
    std::string_view cppName; // the C++ struct's, for messages and the generated file's header
    std::size_t size = 0;     // sizeof the C++ struct
    std::vector<BlockMember> members;
    // The generated file that declares the struct alone, for a struct that
    // several blocks and GLSL files share (its users include it), and the
    // header describing it; empty: declared in each block file that uses it.
    std::string_view file{};
    std::string_view describedIn{};
};

// A uniform block: its members as a struct's, at a binding point of
// swell/gpu/bindings.h, declared in a generated file of its own.
struct UniformBlock {
    const BlockStruct* layout = nullptr; // name: the GLSL block's
    std::string_view bindingMacro;       // e.g. "SWELL_BINDING_FRAME"
    int binding = 0;                     // its value
    std::string_view file;               // the generated file, e.g. "gpu/frame_block.glsl"
    std::string_view describedIn;        // the header holding the C++ struct and its description
};

// GLSL's name for a C++ member type (the types the blocks use).
template <class T>
constexpr std::string_view glslTypeName()
{
    if constexpr (std::is_same_v<T, float>)
        return "float";
    else if constexpr (std::is_same_v<T, int>)
        return "int";
    else if constexpr (std::is_same_v<T, unsigned>)
        return "uint";
    else if constexpr (std::is_same_v<T, glm::vec2>)
        return "vec2";
    else if constexpr (std::is_same_v<T, glm::vec3>)
        return "vec3";
    else if constexpr (std::is_same_v<T, glm::vec4>)
        return "vec4";
    else if constexpr (std::is_same_v<T, glm::ivec2>)
        return "ivec2";
    else if constexpr (std::is_same_v<T, glm::ivec4>)
        return "ivec4";
    else if constexpr (std::is_same_v<T, glm::mat4>)
        return "mat4";
    else
        static_assert(sizeof(T) == 0, "no GLSL type for this member: add it to glslTypeName and std140 rules");
}

// A member of C++ type `Member` (a type, or a one-dimensional array of one)
// at `offset`, GLSL name `name`.
template <class Member>
BlockMember blockMember(std::string_view name, std::size_t offset)
{
    static_assert(std::rank_v<Member> <= 1, "std140 blocks here hold one-dimensional arrays only");
    using Element = std::remove_extent_t<Member>;
    BlockMember m{name, {}, offset, std::extent_v<Member>, nullptr, sizeof(Member), alignof(Member)};
    if constexpr (requires { blockStructOf(static_cast<const Element*>(nullptr)); })
        m.structure = &blockStructOf(static_cast<const Element*>(nullptr));
    else
        m.type = glslTypeName<Element>();
    return m;
}

inline BlockMember blockPadding(std::size_t offset, std::size_t cppSize)
{
    return {"", "", offset, 0, nullptr, cppSize, 1, true};
}

// Any disagreement between the std140 layout of a struct's members and
// the C++ struct's (its offsets and size, and a C++ byte that no member or
// padding covers): one line per problem, empty when they agree.
std::string std140Problems(const BlockStruct& s);

// The std140 size of a struct (rounded up to its 16-byte alignment).
std::size_t std140Size(const BlockStruct& s);

// The std140 offset of each GLSL member, in order (padding left out; what
// std140Problems compares).
std::vector<std::size_t> std140Offsets(const BlockStruct& s);

// The GLSL text of a generated file: a uniform block's declaration (with
// the structs it uses), or a shared struct's alone.
std::string glslFile(const UniformBlock& block);
std::string glslFile(const BlockStruct& shared);

} // namespace swell::gl

// A member whose GLSL name is its C++ name, one named otherwise, and C++
// padding.
#define SWELL_BLOCK_MEMBER(Struct, member) \
    ::swell::gl::blockMember<decltype(Struct::member)>(#member, offsetof(Struct, member))
#define SWELL_BLOCK_MEMBER_AS(Struct, member, glslName) \
    ::swell::gl::blockMember<decltype(Struct::member)>(glslName, offsetof(Struct, member))
#define SWELL_BLOCK_PADDING(Struct, member) ::swell::gl::blockPadding(offsetof(Struct, member), sizeof(Struct::member))
