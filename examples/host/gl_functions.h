// The example host's own OpenGL loading, as an engine that owns its renderer
// does it: the GL 4.5 core declarations of the system's Khronos header
// (<GL/glcorearb.h>, types and function-pointer typedefs only), and one
// pointer per function the host calls, filled from the context's
// GetProcAddress (GLFW's in a window, EGL's headless). Swell loads its own
// functions through libepoxy inside the library; the two never meet, which
// is the point: a host keeps whatever loader it has (glad, GLEW, this).
// The pointers live in namespace host, so `glDrawArrays(...)` in the host's
// code calls the host's pointer, and nothing clashes with the system
// libGL's exported symbols.
#pragma once

#include <GL/glcorearb.h>

namespace host {

// Every GL function the host calls, once: X(typedef, name).
#define HOST_GL_FUNCTIONS(X)                                                                                          \
    X(PFNGLGETERRORPROC, glGetError)                                                                                  \
    X(PFNGLGETSTRINGPROC, glGetString)                                                                                \
    X(PFNGLFINISHPROC, glFinish)                                                                                      \
    X(PFNGLENABLEPROC, glEnable)                                                                                      \
    X(PFNGLDISABLEPROC, glDisable)                                                                                    \
    X(PFNGLVIEWPORTPROC, glViewport)                                                                                  \
    X(PFNGLCLIPCONTROLPROC, glClipControl)                                                                            \
    X(PFNGLDEPTHFUNCPROC, glDepthFunc)                                                                                \
    X(PFNGLDEPTHMASKPROC, glDepthMask)                                                                                \
    X(PFNGLPIXELSTOREIPROC, glPixelStorei)                                                                            \
    X(PFNGLCREATESHADERPROC, glCreateShader)                                                                          \
    X(PFNGLSHADERSOURCEPROC, glShaderSource)                                                                          \
    X(PFNGLCOMPILESHADERPROC, glCompileShader)                                                                        \
    X(PFNGLGETSHADERIVPROC, glGetShaderiv)                                                                            \
    X(PFNGLGETSHADERINFOLOGPROC, glGetShaderInfoLog)                                                                  \
    X(PFNGLDELETESHADERPROC, glDeleteShader)                                                                          \
    X(PFNGLCREATEPROGRAMPROC, glCreateProgram)                                                                        \
    X(PFNGLATTACHSHADERPROC, glAttachShader)                                                                          \
    X(PFNGLLINKPROGRAMPROC, glLinkProgram)                                                                            \
    X(PFNGLGETPROGRAMIVPROC, glGetProgramiv)                                                                          \
    X(PFNGLGETPROGRAMINFOLOGPROC, glGetProgramInfoLog)                                                                \
    X(PFNGLDELETEPROGRAMPROC, glDeleteProgram)                                                                        \
    X(PFNGLUSEPROGRAMPROC, glUseProgram)                                                                              \
    X(PFNGLGETUNIFORMLOCATIONPROC, glGetUniformLocation)                                                              \
    X(PFNGLUNIFORM1FPROC, glUniform1f)                                                                                \
    X(PFNGLUNIFORM3FVPROC, glUniform3fv)                                                                              \
    X(PFNGLUNIFORM4FVPROC, glUniform4fv)                                                                              \
    X(PFNGLUNIFORMMATRIX3FVPROC, glUniformMatrix3fv)                                                                  \
    X(PFNGLUNIFORMMATRIX4FVPROC, glUniformMatrix4fv)                                                                  \
    X(PFNGLCREATEBUFFERSPROC, glCreateBuffers)                                                                        \
    X(PFNGLNAMEDBUFFERSTORAGEPROC, glNamedBufferStorage)                                                              \
    X(PFNGLDELETEBUFFERSPROC, glDeleteBuffers)                                                                        \
    X(PFNGLCREATEVERTEXARRAYSPROC, glCreateVertexArrays)                                                              \
    X(PFNGLDELETEVERTEXARRAYSPROC, glDeleteVertexArrays)                                                              \
    X(PFNGLVERTEXARRAYVERTEXBUFFERPROC, glVertexArrayVertexBuffer)                                                    \
    X(PFNGLENABLEVERTEXARRAYATTRIBPROC, glEnableVertexArrayAttrib)                                                    \
    X(PFNGLVERTEXARRAYATTRIBFORMATPROC, glVertexArrayAttribFormat)                                                    \
    X(PFNGLVERTEXARRAYATTRIBBINDINGPROC, glVertexArrayAttribBinding)                                                  \
    X(PFNGLBINDVERTEXARRAYPROC, glBindVertexArray)                                                                    \
    X(PFNGLDRAWARRAYSPROC, glDrawArrays)                                                                              \
    X(PFNGLCREATETEXTURESPROC, glCreateTextures)                                                                      \
    X(PFNGLTEXTURESTORAGE2DPROC, glTextureStorage2D)                                                                  \
    X(PFNGLTEXTUREPARAMETERIPROC, glTextureParameteri)                                                                \
    X(PFNGLDELETETEXTURESPROC, glDeleteTextures)                                                                      \
    X(PFNGLBINDTEXTUREUNITPROC, glBindTextureUnit)                                                                    \
    X(PFNGLGETTEXTUREIMAGEPROC, glGetTextureImage)                                                                    \
    X(PFNGLCREATEFRAMEBUFFERSPROC, glCreateFramebuffers)                                                              \
    X(PFNGLDELETEFRAMEBUFFERSPROC, glDeleteFramebuffers)                                                              \
    X(PFNGLNAMEDFRAMEBUFFERTEXTUREPROC, glNamedFramebufferTexture)                                                    \
    X(PFNGLCHECKNAMEDFRAMEBUFFERSTATUSPROC, glCheckNamedFramebufferStatus)                                            \
    X(PFNGLBINDFRAMEBUFFERPROC, glBindFramebuffer)                                                                    \
    X(PFNGLCLEARNAMEDFRAMEBUFFERFVPROC, glClearNamedFramebufferfv)

#define HOST_GL_DECLARE(type, name) inline type name = nullptr;
HOST_GL_FUNCTIONS(HOST_GL_DECLARE)
#undef HOST_GL_DECLARE

// A context's function lookup: glfwGetProcAddress or eglGetProcAddress.
using GetProcAddress = void (*(*)(const char*))();

// Fills every pointer from `getProcAddress` for the current context.
// Returns the name of the first function it cannot find, or nullptr.
const char* loadGl(GetProcAddress getProcAddress);

} // namespace host
