// The std140 rules (OpenGL 4.5 core, section 7.6.2.2) for the types the
// blocks use, and the GLSL text of a described block.
#include "gl/block_layout.h"

#include <fmt/format.h>

#include <algorithm>
#include <set>

namespace swell::gl {

namespace {

constexpr std::size_t kVec4Bytes = 16;

std::size_t roundUp(std::size_t n, std::size_t to) { return (n + to - 1) / to * to; }

struct Std140 {
    std::size_t size = 0;  // of one element
    std::size_t align = 0; // base alignment of one element
};

// Rules 1-4 and 5 (a column-major matrix is an array of its columns).
Std140 basicType(std::string_view type)
{
    if (type == "float" || type == "int" || type == "uint")
        return {4, 4};
    if (type == "vec2" || type == "ivec2")
        return {8, 8};
    if (type == "vec3")
        return {12, 16};
    if (type == "vec4" || type == "ivec4")
        return {16, 16};
    if (type == "mat4")
        return {64, 16};
    return {0, 0};
}

Std140 memberType(const BlockMember& m)
{
    // Rule 9: a struct is aligned to its largest member's alignment rounded
    // up to a vec4's, and padded to a multiple of that.
    if (m.structure)
        return {std140Size(*m.structure), kVec4Bytes};
    return basicType(m.type);
}

// Where each member lies, and the struct's end (before its final padding).
std::vector<std::size_t> layOut(const BlockStruct& s, std::size_t* end)
{
    std::vector<std::size_t> offsets;
    std::size_t at = 0;
    for (const BlockMember& m : s.members) {
        if (m.padding)
            continue;
        Std140 t = memberType(m);
        if (m.count > 0) {
            // Rule 4 (and 10): an array's elements are aligned, and strided,
            // to a vec4's multiple.
            t.align = roundUp(t.align, kVec4Bytes);
            t.size = roundUp(t.size, kVec4Bytes) * m.count;
        }
        at = roundUp(at, std::max<std::size_t>(t.align, 1));
        offsets.push_back(at);
        at += t.size;
    }
    *end = at;
    return offsets;
}

std::string memberDeclaration(const BlockMember& m)
{
    const std::string_view type = m.structure ? m.structure->name : m.type;
    if (m.count > 0)
        return fmt::format("{} {}[{}];", type, m.name, m.count);
    return fmt::format("{} {};", type, m.name);
}

// The members that GLSL declares.
std::vector<const BlockMember*> glslMembers(const BlockStruct& s)
{
    std::vector<const BlockMember*> members;
    for (const BlockMember& m : s.members)
        if (!m.padding)
            members.push_back(&m);
    return members;
}

std::string memberLines(const BlockStruct& s)
{
    std::string text;
    const std::vector<const BlockMember*> members = glslMembers(s);
    const std::vector<std::size_t> offsets = std140Offsets(s);
    for (std::size_t i = 0; i < members.size(); ++i)
        text += fmt::format("    {:<40} // at byte {}\n", memberDeclaration(*members[i]), offsets[i]);
    return text;
}

// A C++ byte that no member covers and no C++ alignment explains: a member
// forgotten in the description (or padding not described as such).
std::string coverageProblems(const BlockStruct& s)
{
    std::vector<const BlockMember*> byOffset;
    for (const BlockMember& m : s.members)
        byOffset.push_back(&m);
    std::sort(byOffset.begin(), byOffset.end(),
              [](const BlockMember* a, const BlockMember* b) { return a->offset < b->offset; });
    std::string problems;
    std::size_t covered = 0;
    for (const BlockMember* m : byOffset) {
        if (m->offset > roundUp(covered, m->cppAlign))
            problems += fmt::format("{}: bytes {}..{} are no described member's (described as padding?)\n",
                                    s.cppName, covered, m->offset - 1);
        covered = std::max(covered, m->offset + m->cppSize);
    }
    // The rest up to a multiple of 16 is the struct's own padding (alignas(16)).
    if (roundUp(covered, kVec4Bytes) < s.size)
        problems += fmt::format("{}: bytes {}..{} are no described member's\n", s.cppName, covered, s.size - 1);
    return problems;
}

std::string guardOf(std::string_view file)
{
    std::string guard = "SWELL_";
    for (const char c : file)
        guard += (c >= 'a' && c <= 'z') ? char(c - 'a' + 'A') : (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') ? c : '_';
    return guard;
}

// The structs a struct's members use, innermost first, each once.
void collectStructs(const BlockStruct& s, std::vector<const BlockStruct*>& out)
{
    for (const BlockMember& m : s.members)
        if (m.structure && std::find(out.begin(), out.end(), m.structure) == out.end()) {
            collectStructs(*m.structure, out);
            out.push_back(m.structure);
        }
}

std::string header(std::string_view cppName, std::string_view file, std::string_view describedIn)
{
    return fmt::format("// Generated at build time by src/render/gpu/generate_glsl.cpp from\n"
                       "// {}, described in {}\n"
                       "// (which says what each member holds): do not edit.\n"
                       "#ifndef {}\n#define {}\n",
                       cppName, describedIn, guardOf(file), guardOf(file));
}

// The declarations of the structs `s` uses: an include for each shared one,
// the others in full.
std::string usedStructs(const BlockStruct& s)
{
    std::vector<const BlockStruct*> structs;
    collectStructs(s, structs);
    std::string includes, declarations;
    for (const BlockStruct* used : structs) {
        if (!used->file.empty())
            includes += fmt::format("#include \"{}\"\n", used->file);
        else
            declarations += fmt::format("\nstruct {} {{\n{}}};\n", used->name, memberLines(*used));
    }
    return includes + declarations;
}

} // namespace

std::vector<std::size_t> std140Offsets(const BlockStruct& s)
{
    std::size_t end = 0;
    return layOut(s, &end);
}

std::size_t std140Size(const BlockStruct& s)
{
    std::size_t end = 0;
    layOut(s, &end);
    return roundUp(end, kVec4Bytes);
}

std::string std140Problems(const BlockStruct& s)
{
    std::string problems = coverageProblems(s);
    const std::vector<const BlockMember*> members = glslMembers(s);
    const std::vector<std::size_t> offsets = std140Offsets(s);
    std::set<std::string_view> names;
    for (std::size_t i = 0; i < members.size(); ++i) {
        const BlockMember& m = *members[i];
        if (!names.insert(m.name).second)
            problems += fmt::format("{}: two members named {}\n", s.cppName, m.name);
        if (!m.structure && basicType(m.type).size == 0)
            problems += fmt::format("{}::{}: no std140 rule for GLSL type '{}'\n", s.cppName, m.name, m.type);
        if (offsets[i] != m.offset)
            problems += fmt::format("{}::{}: std140 puts it at byte {}, the C++ struct at {}\n", s.cppName, m.name,
                                    offsets[i], m.offset);
        if (m.structure)
            problems += std140Problems(*m.structure);
    }
    if (std140Size(s) != s.size)
        problems += fmt::format("{}: std140 makes it {} bytes, the C++ struct {}\n", s.cppName, std140Size(s), s.size);
    return problems;
}

std::string glslFile(const UniformBlock& block)
{
    const BlockStruct& s = *block.layout;
    std::string text = header(s.cppName, block.file, block.describedIn);
    text += "#include \"swell/gpu/bindings.h\"\n";
    text += usedStructs(s);
    text += fmt::format("\nlayout(std140, binding = {}) uniform {} {{\n{}}};\n#endif\n", block.bindingMacro, s.name,
                        memberLines(s));
    return text;
}

std::string glslFile(const BlockStruct& shared)
{
    std::string text = header(shared.cppName, shared.file, shared.describedIn);
    text += usedStructs(shared);
    text += fmt::format("\nstruct {} {{\n{}}};\n#endif\n", shared.name, memberLines(shared));
    return text;
}

} // namespace swell::gl
