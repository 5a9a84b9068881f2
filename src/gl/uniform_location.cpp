#include "gl/uniform_location.h"

#include "swell/error.h"

#include <fmt/format.h>

namespace swell::gl {

GLint requiredUniform(const Program& program, const char* name, const char* file)
{
    const GLint location = glGetUniformLocation(program.id(), name);
    if (location < 0)
        throw InputError({file}, fmt::format("program has no uniform '{}'", name));
    return location;
}

GLint optionalUniform(const Program& program, const char* name) { return glGetUniformLocation(program.id(), name); }

} // namespace swell::gl
