// The [seabed] rows of the scene parameter table (core/parameter_table.cpp):
// the sea floor's toe depth, beaches, shelves, breakwaters and heightmap
// (swell/scene/seabed.h). Internal to the table.
#pragma once

#include "swell/scene/parameters.h"

#include <vector>

namespace swell::detail {

std::vector<Parameter> seabedParameters();

} // namespace swell::detail
