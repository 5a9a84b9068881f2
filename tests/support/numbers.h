// Numbers many tests write with: one definition, so that the test
// executables' batched compiles (CMakeLists.txt, SWELL_UNITY_BUILD) see
// each once. A test file brings them in with using-declarations, which may
// repeat.
#pragma once

#include "swell/constants.h"

#include <limits>

namespace swell::test {

inline constexpr double kInf = std::numeric_limits<double>::infinity();
inline constexpr double kDeg = kPi / 180.0; // radians in a degree

} // namespace swell::test
