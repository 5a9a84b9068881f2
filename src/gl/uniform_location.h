// Looking up a program's uniforms, once, when it is built: every lookup
// says whether the uniform must be there. Library-internal.
#pragma once

#include "swell/gl/handle.h"

namespace swell::gl {

// A uniform the program must have. A missing one is a shader bug (a renamed
// uniform, or one the compiler dropped as unused), reported like a compile
// error, naming the shader file that declares it, rather than left at
// location -1, which GL's setters silently ignore. Throws swell::InputError.
GLint requiredUniform(const Program& program, const char* name, const char* file);

// A uniform only some builds of the program have (the label pass's, one
// path's of two): -1 where it is absent, which GL's setters ignore.
GLint optionalUniform(const Program& program, const char* name);

} // namespace swell::gl
