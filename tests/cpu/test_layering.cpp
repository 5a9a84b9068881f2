// Which part of Swell may include which: every #include "..." in src/,
// apps/, python/src/ and include/swell/ read, resolved to the file it names,
// and held to the layers, lowest first:
//
//   include/swell   the public API: below everything, includes only itself
//   core            CPU: grid math, untrusted files
//   gl              GL objects, contexts, programs
//   scene           scene files
//   assets          models, images, a scene's assets and body shapes
//   ocean  objects  the waves and surface queries | the floating bodies;
//                   one level, but only objects may include ocean (the
//                   bodies float on the waves; the waves know no bodies)
//   render          the renderer and its passes
//   apps            the swell executable, and the Python package (which
//                   includes the public API alone)
//
// A file includes its own layer and the ones below it, never one above. A
// public header whose functions one layer defines (the one source file named
// like it: swell/scene/scene_file.h and src/scene/scene_file.cpp) counts as that
// layer's for the files of src/ that include it; the others only declare
// types and interfaces. Two rules more: the CPU half (core, scene, assets, objects, and ocean outside
// its gpu/ folders: swell_core) includes none of the GL code (gl/, render/,
// any gpu/ folder, libepoxy), and no file outside src/ocean/spectral/
// includes that folder's headers (the spectral model's internals stay
// behind swell::SpectralModel). src/CMakeLists.txt draws the same picture.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <optional>
#include <regex>
#include <string>
#include <vector>

namespace {

namespace fs = std::filesystem;

const fs::path kRoot = SWELL_SOURCE_DIR;

enum class Layer { Api, Core, Gl, Scene, Assets, Ocean, Objects, Render, Apps };

const char* nameOf(Layer layer)
{
    switch (layer) {
    case Layer::Api: return "include/swell";
    case Layer::Core: return "core";
    case Layer::Gl: return "gl";
    case Layer::Scene: return "scene";
    case Layer::Assets: return "assets";
    case Layer::Ocean: return "ocean";
    case Layer::Objects: return "objects";
    case Layer::Render: return "render";
    case Layer::Apps: return "apps";
    }
    return "?";
}

// Lowest first; ocean and objects share a level.
int levelOf(Layer layer)
{
    switch (layer) {
    case Layer::Api: return 0;
    case Layer::Core: return 1;
    case Layer::Gl: return 2;
    case Layer::Scene: return 3;
    case Layer::Assets: return 4;
    case Layer::Ocean: return 5;
    case Layer::Objects: return 5;
    case Layer::Render: return 6;
    case Layer::Apps: return 7;
    }
    return 0;
}

// The layer of a file, from its path relative to the root; nothing for a
// file outside the layers (a test's, a benchmark's).
std::optional<Layer> layerOf(const fs::path& relative)
{
    const std::vector<std::string> parts(relative.begin(), relative.end());
    if (parts.size() >= 2 && parts[0] == "include" && parts[1] == "swell")
        return Layer::Api;
    if (!parts.empty() && (parts[0] == "apps" || parts[0] == "python"))
        return Layer::Apps;
    if (parts.size() == 2 && parts[0] == "src")
        return Layer::Core; // src/embedded_files.h: the declarations of the embedded files
    if (parts.size() < 3 || parts[0] != "src")
        return std::nullopt;
    const std::string& folder = parts[1];
    if (folder == "core") return Layer::Core;
    if (folder == "gl") return Layer::Gl;
    if (folder == "scene") return Layer::Scene;
    if (folder == "assets") return Layer::Assets;
    if (folder == "ocean") return Layer::Ocean;
    if (folder == "objects") return Layer::Objects;
    if (folder == "render") return Layer::Render;
    return std::nullopt;
}

bool mayInclude(Layer from, Layer to)
{
    if (to == Layer::Api)
        return true;
    if (from == Layer::Api)
        return false;
    if (from == to || (from == Layer::Objects && to == Layer::Ocean))
        return true;
    return levelOf(to) < levelOf(from);
}

// A GL half's folder under src/ (ocean/<model>/gpu/, render/gpu/); not the
// public swell/gpu/ headers, which hold the constants C++ and GLSL share.
bool inGpuFolder(const fs::path& relative)
{
    return *relative.begin() == "src" && std::find(relative.begin(), relative.end(), fs::path("gpu")) != relative.end();
}

// Built into swell_core, which links no GL code.
bool inCpuHalf(const fs::path& relative)
{
    const std::optional<Layer> layer = layerOf(relative);
    return layer && *layer != Layer::Api && *layer != Layer::Gl && *layer != Layer::Render && *layer != Layer::Apps &&
           !inGpuFolder(relative);
}

bool startsWith(const fs::path& relative, const fs::path& folder)
{
    auto f = folder.begin();
    for (auto p = relative.begin(); f != folder.end(); ++p, ++f)
        if (p == relative.end() || *p != *f)
            return false;
    return true;
}

struct Include {
    fs::path file; // relative to the root
    int line = 0;
    std::string named; // as written between the quotes or brackets
    bool quoted = true;
};

// The includes of one file, leaving out the lines of C++ raw strings (GLSL
// the renderer writes, which includes shader files of its own).
std::vector<Include> includesOf(const fs::path& relative)
{
    static const std::regex include(R"(^\s*#\s*include\s*(["<])([^">]+)[">])");
    static const std::regex rawOpen(R"(R"([^(\s]*)\()");
    std::vector<Include> out;
    std::ifstream in(kRoot / relative);
    std::string text, rawClose;
    for (int line = 1; std::getline(in, text); ++line) {
        if (!rawClose.empty()) {
            if (const std::size_t end = text.find(rawClose); end != std::string::npos)
                rawClose.clear();
            continue;
        }
        std::smatch m;
        if (std::regex_search(text, m, include))
            out.push_back({relative, line, m[2].str(), m[1].str() == "\""});
        if (std::regex_search(text, m, rawOpen)) {
            std::string close = m[1].str();
            close.insert(close.begin(), ')');
            close.push_back('"');
            if (text.find(close, std::size_t(m.position(0) + m.length(0))) == std::string::npos)
                rawClose = close;
        }
    }
    return out;
}

// The file a quoted include names, relative to the root, searched as the
// build searches: beside the file, then src/, include/ and apps/swell/.
std::optional<fs::path> resolve(const Include& include)
{
    const std::vector<fs::path> folders = {include.file.parent_path(), "src", "include", "apps/swell"};
    for (const fs::path& folder : folders)
        if (fs::is_regular_file(kRoot / folder / include.named))
            return (folder / include.named).lexically_normal();
    return std::nullopt;
}

std::vector<fs::path> sourceFiles();

// The layer that defines what a public header declares: that of the one
// source file under src/ named like it, else none (the API's own).
std::optional<Layer> ownerOf(const fs::path& publicHeader)
{
    static const std::vector<fs::path> sources = [] {
        std::vector<fs::path> cpp;
        for (const fs::path& f : sourceFiles())
            if (startsWith(f, "src") && f.extension() == ".cpp")
                cpp.push_back(f);
        return cpp;
    }();
    std::optional<Layer> owner;
    int named = 0;
    for (const fs::path& f : sources)
        if (f.stem() == publicHeader.stem()) {
            owner = layerOf(f);
            ++named;
        }
    return named == 1 ? owner : std::nullopt;
}

std::vector<fs::path> sourceFiles()
{
    std::vector<fs::path> files;
    for (const char* folder : {"src", "apps", "python/src", "include/swell"})
        for (const fs::directory_entry& e : fs::recursive_directory_iterator(kRoot / folder)) {
            const std::string ext = e.path().extension().string();
            if (e.is_regular_file() && (ext == ".h" || ext == ".cpp"))
                files.push_back(fs::relative(e.path(), kRoot));
        }
    std::sort(files.begin(), files.end());
    return files;
}

std::string where(const Include& i) { return i.file.generic_string() + ":" + std::to_string(i.line) + ": "; }

// Every broken rule, one line each; empty when the layers hold.
std::vector<std::string> brokenRules()
{
    std::vector<std::string> broken;
    for (const fs::path& file : sourceFiles()) {
        const std::optional<Layer> from = layerOf(file);
        if (!from)
            continue;
        for (const Include& i : includesOf(file)) {
            if (!i.quoted) {
                if (inCpuHalf(file) && i.named.rfind("epoxy/", 0) == 0)
                    broken.push_back(where(i) + "the CPU half includes <" + i.named + ">");
                continue;
            }
            const std::optional<fs::path> target = resolve(i);
            if (!target) {
                broken.push_back(where(i) + "\"" + i.named + "\" is no file of the source tree");
                continue;
            }
            const std::optional<Layer> to = layerOf(*target);
            if (to && !mayInclude(*from, *to))
                broken.push_back(where(i) + nameOf(*from) + " includes \"" + i.named + "\", of " + nameOf(*to) +
                                 " above it");
            const std::optional<Layer> owner =
                to == Layer::Api && startsWith(file, "src") ? ownerOf(*target) : std::nullopt;
            if (owner && !mayInclude(*from, *owner))
                broken.push_back(where(i) + nameOf(*from) + " includes \"" + i.named + "\", which " +
                                 nameOf(*owner) + " above it defines");
            if (*from == Layer::Apps && startsWith(file, "python") && to && *to != Layer::Api && *to != Layer::Apps)
                broken.push_back(where(i) + "the Python package includes \"" + i.named + "\", not the public API");
            if (inCpuHalf(file) && to && (*to == Layer::Gl || *to == Layer::Render || inGpuFolder(*target)))
                broken.push_back(where(i) + "the CPU half includes \"" + i.named + "\", GL code");
            if (startsWith(*target, "src/ocean/spectral") && !startsWith(file, "src/ocean/spectral"))
                broken.push_back(where(i) + "\"" + i.named + "\" is the spectral model's own, outside src/ocean/spectral/");
        }
    }
    return broken;
}

TEST(Layering, NoIncludeRunsFromALowerLayerToAHigherOne)
{
    const std::vector<std::string> broken = brokenRules();
    std::string all;
    for (const std::string& b : broken)
        all += b + "\n";
    EXPECT_TRUE(broken.empty()) << all;
}

// The test reads what it is meant to: the tree's files, and includes of
// every layer among them.
TEST(Layering, ReadsTheWholeTree)
{
    std::vector<int> perLayer(9, 0);
    int includes = 0;
    for (const fs::path& file : sourceFiles())
        if (const std::optional<Layer> layer = layerOf(file)) {
            ++perLayer[std::size_t(*layer)];
            includes += int(includesOf(file).size());
        }
    for (std::size_t layer = 0; layer < perLayer.size(); ++layer)
        EXPECT_GT(perLayer[layer], 2) << nameOf(Layer(layer));
    EXPECT_GT(includes, 1000);
}

} // namespace
