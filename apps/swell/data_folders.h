// Where the swell executable finds its data: the preset scenes, the example
// models, and the shader sources the viewer hot-reloads.
//
//   installed:   PREFIX/bin/swell finds PREFIX/share/swell/{scenes,models,shaders,include}
//                (what `cmake --install` writes), wherever PREFIX is moved;
//   build tree:  build/apps/swell/swell uses the source tree it was built from.
//
// The installed layout wins when it is there, so an installed swell never
// depends on the source tree still existing.
#pragma once

#include <filesystem>

namespace swell::app {

struct DataFolders {
    std::filesystem::path scenes;  // preset scene files (*.toml)
    std::filesystem::path models;  // example glTF models
    std::filesystem::path shaders; // GLSL sources laid out like shaders/
    std::filesystem::path include; // holds swell/gpu/*.h for the shaders
    bool installed = false;        // found beside the executable, not the source tree
};

DataFolders dataFolders();

// The executable keeps what scenes derive at a cost (the coast field's
// solve, the breaking ramps) on disk, in $XDG_CACHE_HOME/swell or
// ~/.cache/swell (docs/LIBRARY.md, "The cache of derived data"): sets the
// library's SWELL_CACHE_DIR to it unless the environment already sets it
// (an empty value turns the cache off).
void nameTheDerivedDataCache();

} // namespace swell::app
