// SWELL_API marks what libswell exports: the public API declared in these
// headers. The library is compiled with hidden visibility, so everything
// else it contains (its internals, and the code it compiles in from stb,
// tinygltf, toml++ and fmt) stays private to it and cannot clash with a
// user's own copy of those libraries. On ELF the same attribute serves for
// building and for using the library, shared or static.
#pragma once

#if defined(__GNUC__) || defined(__clang__)
#define SWELL_API __attribute__((visibility("default")))
#else
#define SWELL_API
#endif

// Swell's API passes GLM types by value. GLM_FORCE_CTOR_INIT (and GLM's
// other options that make its constructors user-provided) turns them from
// trivially copyable into not, which changes how they are passed between
// functions: code built with it cannot call a libswell built without it,
// and would crash rather than fail to link. Say so at compile time instead.
#include <glm/vec2.hpp>

#include <type_traits>

static_assert(std::is_trivially_copyable_v<glm::dvec2>,
              "Swell: GLM's types are not trivially copyable here (is GLM_FORCE_CTOR_INIT defined?); libswell "
              "is built with GLM's defaults, and code that calls it must be too (see docs/LIBRARY.md)");
