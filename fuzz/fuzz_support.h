// What the libFuzzer targets share: a private temporary folder for the
// files an input is written to (removed at exit), writing one, and
// reporting a bug the sanitizers cannot see (an abort, which libFuzzer
// keeps as a crash).
#pragma once

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>

#include <stdlib.h> // mkdtemp

namespace swell::fuzz {

// Made once, by LLVMFuzzerInitialize: /tmp/swell-fuzz-NAME-XXXXXX.
inline const std::filesystem::path& privateFolder(const char* name = nullptr)
{
    static const std::filesystem::path folder = [name] {
        std::string f = (std::filesystem::temp_directory_path() / (std::string("swell-fuzz-") + name + "-XXXXXX")).string();
        if (!mkdtemp(f.data())) {
            std::perror("mkdtemp");
            std::abort();
        }
        std::atexit([] {
            std::error_code ec;
            std::filesystem::remove_all(privateFolder(), ec);
        });
        return std::filesystem::path(f);
    }();
    return folder;
}

inline void writeFile(const std::filesystem::path& path, const void* data, std::size_t size)
{
    std::ofstream out(path, std::ios::binary | std::ios::trunc);
    out.write(static_cast<const char*>(data), std::streamsize(size));
}

[[noreturn]] inline void bug(const char* target, const char* what, const std::string& detail)
{
    std::fprintf(stderr, "%s: %s\n%s\n", target, what, detail.c_str());
    std::abort();
}

} // namespace swell::fuzz
