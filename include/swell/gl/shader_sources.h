// Where GLSL sources come from: the copies embedded in the library at build
// time, a folder on disk (the viewer's hot reload), or memory (tests). No GL
// here: swell/renderer.h includes this, and a program that loads GL through
// another loader than libepoxy can include it (swell/gl/handle.h and
// swell/gl/shader.h, which call GL, use libepoxy's declarations).
#pragma once

#include "swell/export.h"

#include <filesystem>
#include <map>
#include <string>
#include <vector>

namespace swell::gl {

class SWELL_API ShaderSources {
public:
    // The sources embedded in the library at build time.
    static ShaderSources embedded();
    // Sources read from a folder laid out like shaders/ (plus the headers under swell/gpu/
    // looked up in includeDir). Files are read when first needed; the files
    // generated from the library's C++ (gpu/*.glsl) are its embedded copies.
    static ShaderSources fromDirectory(std::filesystem::path shaderDir, std::filesystem::path includeDir);
    // In-memory sources, for tests.
    static ShaderSources fromMap(std::map<std::string, std::string> files);

    // Adds a file held in memory, or replaces one, over any folder's (the
    // renderer's code written from its surface sources, swell/surface_source.h).
    void set(const std::string& name, std::string text) { loaded_[name] = std::move(text); }

    // Files read from disk are kept after their first read; this forgets them
    // so the next build reads them again (hot reload).
    void forgetCachedFiles() { cache_.clear(); }

    // The names of the files held in memory (embedded, given or set), sorted;
    // for sources read from a folder, only those set and the generated ones.
    std::vector<std::string> fileNames() const;

    // The text of one file. Throws swell::InputError when it does not exist.
    const std::string& file(const std::string& name) const;

    // The preprocessed source of `name`: "#version 450 core", then `defines`,
    // then the file with its includes expanded. fileNames receives the file
    // behind each #line source number.
    std::string expand(const std::string& name, const std::vector<std::string>& defines,
                       std::vector<std::string>& fileNames) const;

private:
    std::map<std::string, std::string> loaded_;
    std::filesystem::path shaderDir_, includeDir_;
    bool fromDisk_ = false;
    mutable std::map<std::string, std::string> cache_;
};

} // namespace swell::gl
