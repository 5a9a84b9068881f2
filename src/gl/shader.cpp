#include "swell/gl/shader.h"

#include "core/input_file.h"
#include "embedded_files.h"
#include "gl/program_count.h"
#include "swell/error.h"

#include <fmt/format.h>

#include <atomic>
#include <fstream>
#include <regex>
#include <set>
#include <sstream>

namespace swell::gl {

namespace {
// Largest shader source read from disk: ours are a few KiB each.
constexpr std::uintmax_t kMaxShaderFileBytes = std::uintmax_t(1) << 20;
// The programs buildProgram() has built (gl/program_count.h).
std::atomic<std::uint64_t> builtPrograms{0};
} // namespace

std::uint64_t programsBuilt() { return builtPrograms.load(); }

ShaderSources ShaderSources::embedded()
{
    ShaderSources s;
    for (const detail::EmbeddedFile& f : detail::embeddedShaderFiles())
        s.loaded_.emplace(std::string(f.path), std::string(f.text));
    return s;
}

ShaderSources ShaderSources::fromDirectory(std::filesystem::path shaderDir, std::filesystem::path includeDir)
{
    ShaderSources s;
    s.shaderDir_ = std::move(shaderDir);
    s.includeDir_ = std::move(includeDir);
    s.fromDisk_ = true;
    // The files generated from the library's C++ at build time (the uniform
    // blocks' declarations, gpu/*.glsl): no folder has them, and they follow
    // the C++ structs compiled in, not anything a reload could change.
    for (const detail::EmbeddedFile& f : detail::embeddedShaderFiles())
        if (f.path.starts_with("gpu/"))
            s.loaded_.emplace(std::string(f.path), std::string(f.text));
    return s;
}

ShaderSources ShaderSources::fromMap(std::map<std::string, std::string> files)
{
    ShaderSources s;
    s.loaded_ = std::move(files);
    return s;
}

std::vector<std::string> ShaderSources::fileNames() const
{
    std::vector<std::string> names;
    for (const auto& [name, text] : loaded_)
        names.push_back(name);
    return names;
}

const std::string& ShaderSources::file(const std::string& name) const
{
    if (auto it = loaded_.find(name); it != loaded_.end())
        return it->second;
    if (fromDisk_) {
        if (auto it = cache_.find(name); it != cache_.end())
            return it->second;
        // The constants headers shared with C++ live with the C++ headers.
        const std::filesystem::path path = name.starts_with("swell/") ? includeDir_ / name : shaderDir_ / name;
        // Read as any other input: regular files only, never blocking, bounded (core/input_file.h).
        std::error_code ec;
        if (std::filesystem::exists(std::filesystem::symlink_status(path, ec)))
            return cache_.emplace(name, detail::readInputFile(path, kMaxShaderFileBytes, "shader file")).first->second;
    }
    throw InputError({name}, "shader file not found");
}

namespace {

// The value of a define of the form NAME "file" among a program's defines,
// for a computed #include NAME, or "" when there is none.
std::string quotedDefine(const std::vector<std::string>& defines, const std::string& macro)
{
    static const std::regex quoted(R"(^(\w+)\s+"([^"]+)\"\s*$)");
    for (const std::string& d : defines) {
        std::smatch m;
        if (std::regex_match(d, m, quoted) && m[1].str() == macro)
            return m[2].str();
    }
    return {};
}

void expandInto(const ShaderSources& sources, const std::string& name, const std::vector<std::string>& defines,
                std::vector<std::string>& fileNames, std::set<std::string>& included, std::string& out,
                const SourcePlace& from)
{
    if (!included.insert(name).second)
        return; // each file once per program, like #pragma once
    const std::string* text = nullptr;
    try {
        text = &sources.file(name);
    } catch (const InputError&) {
        if (from.path.empty())
            throw;
        throw InputError(from, fmt::format("cannot include \"{}\": shader file not found", name));
    }
    const int index = int(fileNames.size());
    fileNames.push_back(name);
    out += fmt::format("#line 1 {}\n", index);
    std::istringstream lines(*text);
    std::string line;
    int lineNumber = 0;
    static const std::regex includeLine(R"(^\s*#\s*include\s*"([^"]+)\"\s*$)");
    // A computed include names a define that holds the file: #include SWELL_OCEAN_FILE.
    static const std::regex computedIncludeLine(R"(^\s*#\s*include\s+(\w+)\s*$)");
    while (std::getline(lines, line)) {
        ++lineNumber;
        std::smatch m;
        const bool directive = line.find("#") != std::string::npos;
        if (directive && std::regex_match(line, m, includeLine)) {
            expandInto(sources, m[1].str(), defines, fileNames, included, out,
                       SourcePlace{name, lineNumber, int(m.position(1))});
            out += fmt::format("#line {} {}\n", lineNumber + 1, index);
        } else if (directive && std::regex_match(line, m, computedIncludeLine)) {
            const std::string file = quotedDefine(defines, m[1].str());
            if (file.empty())
                throw InputError(SourcePlace{name, lineNumber, int(m.position(1)) + 1},
                                 fmt::format("#include {}: no define gives {} a quoted file name", m[1].str(), m[1].str()));
            expandInto(sources, file, defines, fileNames, included, out,
                       SourcePlace{name, lineNumber, int(m.position(1))});
            out += fmt::format("#line {} {}\n", lineNumber + 1, index);
        } else {
            out += line;
            out += '\n';
        }
    }
}

} // namespace

std::string ShaderSources::expand(const std::string& name, const std::vector<std::string>& defines,
                                  std::vector<std::string>& fileNames) const
{
    std::string out = "#version 450 core\n";
    for (const std::string& d : defines)
        out += "#define " + d + "\n";
    std::set<std::string> included;
    fileNames.clear();
    expandInto(*this, name, defines, fileNames, included, out, {});
    return out;
}

std::string mapInfoLog(const std::string& log, const std::vector<std::string>& fileNames)
{
    // Mesa writes "S:L(C): error: ...", NVIDIA "S(L) : error ...", where S is
    // the #line source number.
    static const std::regex mesa(R"((\d+):(\d+)\((\d+)\))");
    static const std::regex nvidia(R"(^(\d+)\((\d+)\))");
    std::istringstream lines(log);
    std::string line, out;
    auto fileOf = [&](const std::string& s) {
        const size_t i = std::stoul(s);
        return i < fileNames.size() ? fileNames[i] : "<source " + s + ">";
    };
    while (std::getline(lines, line)) {
        std::smatch m;
        if (std::regex_search(line, m, mesa) && m.position(0) == 0)
            line = fmt::format("{}:{}:{}{}", fileOf(m[1]), m[2].str(), m[3].str(), m.suffix().str());
        else if (std::regex_search(line, m, nvidia))
            line = fmt::format("{}:{}{}", fileOf(m[1]), m[2].str(), m.suffix().str());
        out += line + '\n';
    }
    return out;
}

namespace {

std::string infoLog(GLuint object, bool program)
{
    GLint length = 0;
    program ? glGetProgramiv(object, GL_INFO_LOG_LENGTH, &length) : glGetShaderiv(object, GL_INFO_LOG_LENGTH, &length);
    std::string log(size_t(std::max(length, 1)), '\0');
    program ? glGetProgramInfoLog(object, length, nullptr, log.data())
            : glGetShaderInfoLog(object, length, nullptr, log.data());
    log.resize(std::char_traits<char>::length(log.c_str()));
    return log;
}

// The first "file:line:column" in a mapped log, so the error's place is structured too.
SourcePlace firstPlace(const std::string& mappedLog, const std::string& fallback)
{
    static const std::regex place(R"(^([^:\s]+):(\d+)(?::(\d+))?)");
    std::smatch m;
    if (std::regex_search(mappedLog, m, place))
        return {m[1].str(), std::stoi(m[2].str()), m[3].matched ? std::stoi(m[3].str()) : 0};
    return {fallback};
}

} // namespace

Program buildProgram(const ShaderSources& sources, const std::vector<ShaderStage>& stages,
                     const std::vector<std::string>& defines,
                     const std::vector<std::string>& transformFeedbackVaryings)
{
    Program program = Program::create();
    std::vector<Shader> shaders;
    std::string names;
    for (const ShaderStage& s : stages) {
        std::vector<std::string> fileNames;
        const std::string text = sources.expand(s.file, defines, fileNames);
        Shader shader = Shader::create(s.stage);
        const char* ptr = text.c_str();
        glShaderSource(shader.id(), 1, &ptr, nullptr);
        glCompileShader(shader.id());
        GLint ok = 0;
        glGetShaderiv(shader.id(), GL_COMPILE_STATUS, &ok);
        if (!ok) {
            const std::string log = mapInfoLog(infoLog(shader.id(), false), fileNames);
            const SourcePlace place = firstPlace(log, s.file);
            throw InputError(place, fmt::format("shader {} failed to compile:\n{}", s.file, log));
        }
        glAttachShader(program.id(), shader.id());
        names += (names.empty() ? "" : " + ") + s.file;
        shaders.push_back(std::move(shader));
    }
    if (!transformFeedbackVaryings.empty()) {
        std::vector<const char*> v;
        for (const std::string& s : transformFeedbackVaryings)
            v.push_back(s.c_str());
        glTransformFeedbackVaryings(program.id(), GLsizei(v.size()), v.data(), GL_INTERLEAVED_ATTRIBS);
    }
    glLinkProgram(program.id());
    GLint ok = 0;
    glGetProgramiv(program.id(), GL_LINK_STATUS, &ok);
    if (!ok)
        throw InputError({stages.empty() ? std::string() : stages.front().file},
                         fmt::format("program {} failed to link:\n{}", names, infoLog(program.id(), true)));
    for (const Shader& s : shaders)
        glDetachShader(program.id(), s.id());
    ++builtPrograms;
    return program;
}

} // namespace swell::gl
