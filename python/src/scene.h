// The scene as Python holds it: a swell::Scene and the file it came from,
// so that the checks made before rendering name that file.
#pragma once

#include "constructed.h"

#include "swell/scene/scene.h"

#include <filesystem>
#include <string>

namespace swell::python {

struct PyScene {
    Scene scene;
    std::string file; // the scene file it was loaded from; empty when built in Python

    // What validateScene() names in its errors and resolves relative paths
    // against: the file, or a stand-in in the scene's asset folder.
    std::filesystem::path placeForErrors() const
    {
        if (!file.empty())
            return file;
        return std::filesystem::path(scene.assetFolder) / "<scene built in Python>";
    }
};

} // namespace swell::python

SWELL_PYTHON_CONSTRUCTED_ONLY(swell::python::PyScene)
