#include "gl_functions.h"

namespace host {

const char* loadGl(GetProcAddress getProcAddress)
{
#define HOST_GL_LOAD(type, name)                                                                                      \
    name = reinterpret_cast<type>(getProcAddress(#name));                                                             \
    if (!name)                                                                                                        \
        return #name;
    HOST_GL_FUNCTIONS(HOST_GL_LOAD)
#undef HOST_GL_LOAD
    return nullptr;
}

} // namespace host
