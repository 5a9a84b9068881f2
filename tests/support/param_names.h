// Readable, stable names for the values parameterised tests run with: one
// spelling each, used by the tests' name generators (the CTest name) and by
// gtest's PrintTo (the "GetParam() = ..." that CTest shows beside it).
// Without a PrintTo gtest prints a value's bytes, padding included, so a
// struct's test name changed from build to build.
#pragma once

#include "swell/scene/scene.h"
#include "swell/scene/waves.h"

#include <ostream>
#include <string>

namespace swell {

inline std::string paramName(GridLayout layout) { return layout == GridLayout::Paper ? "Paper" : "Geometric"; }

inline std::string paramName(ReflectionMode mode)
{
    return mode == ReflectionMode::FixedDistance ? "Fixed" : "RayMarch";
}

inline std::string paramName(WaveSampler::Simd simd)
{
    switch (simd) {
    case WaveSampler::Simd::Auto: return "Auto";
    case WaveSampler::Simd::Baseline: return "Baseline";
    case WaveSampler::Simd::Avx2: return "Avx2";
    }
    return "Unknown";
}

// Found by gtest through argument-dependent lookup, so in swell's namespace.
inline void PrintTo(GridLayout layout, std::ostream* os) { *os << paramName(layout); }
inline void PrintTo(ReflectionMode mode, std::ostream* os) { *os << paramName(mode); }
inline void PrintTo(WaveSampler::Simd simd, std::ostream* os) { *os << paramName(simd); }

} // namespace swell
