// The [camera], [[camera.path]] and [[camera.rig]] rows of the scene
// parameter table (core/parameter_table.cpp): where the camera stands and
// looks, its lens and sensor, its path and the cameras of its rig. Internal
// to the table.
#pragma once

#include "swell/scene/parameters.h"

#include <vector>

namespace swell::detail {

std::vector<Parameter> cameraParameters();

} // namespace swell::detail
