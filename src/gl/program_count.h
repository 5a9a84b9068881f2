// How many programs gl::buildProgram has built (compiled and linked) in
// this process, on any thread: the tests that hold a scene change to
// rebuilding only the programs whose flags changed count with it.
// Library-internal.
#pragma once

#include <cstdint>

namespace swell::gl {

std::uint64_t programsBuilt();

} // namespace swell::gl
