// Counter-based random numbers: a value that depends on its key alone, so
// that a sample, a pixel or a key draws the same wherever and in whatever
// order it is computed. Library-internal.
#pragma once

#include <cstdint>

namespace swell::detail {

// SplitMix64's finaliser (Steele, Lea & Flood 2014): a 64-bit mix in which
// every input bit changes about half the output bits.
inline std::uint64_t splitMix64(std::uint64_t x)
{
    x += 0x9e3779b97f4a7c15ull;
    x = (x ^ (x >> 30)) * 0xbf58476d1ce4e5b9ull;
    x = (x ^ (x >> 27)) * 0x94d049bb133111ebull;
    return x ^ (x >> 31);
}

// The top 53 bits of a mixed key as a double in [0, 1).
inline double unitFromBits(std::uint64_t mixed) { return double(mixed >> 11) * 0x1.0p-53; }

} // namespace swell::detail
