// Move-only owners of OpenGL object names. The destructor deletes the name;
// a default-constructed handle is empty (usable before a context exists);
// release() hands ownership out. One template, one traits struct per kind.
#pragma once

#include <epoxy/gl.h>

#include <utility>

namespace swell::gl {

template <class Traits>
class Handle {
public:
    Handle() = default;
    // Takes ownership of an existing name.
    explicit Handle(GLuint name) : name_(name) {}
    // Creates a fresh object (glCreate* with the kind's arguments).
    template <class... Args>
    static Handle create(Args... args) { return Handle(Traits::create(args...)); }

    Handle(const Handle&) = delete;
    Handle& operator=(const Handle&) = delete;
    Handle(Handle&& other) noexcept : name_(std::exchange(other.name_, 0)) {}
    Handle& operator=(Handle&& other) noexcept
    {
        if (this != &other) {
            reset();
            name_ = std::exchange(other.name_, 0);
        }
        return *this;
    }
    ~Handle() { reset(); }

    GLuint id() const { return name_; }
    explicit operator bool() const { return name_ != 0; }
    GLuint release() { return std::exchange(name_, 0); }
    void reset()
    {
        if (name_ != 0)
            Traits::destroy(name_);
        name_ = 0;
    }

private:
    GLuint name_ = 0;
};

struct BufferTraits {
    static GLuint create() { GLuint n = 0; glCreateBuffers(1, &n); return n; }
    static void destroy(GLuint n) { glDeleteBuffers(1, &n); }
};
struct TextureTraits {
    static GLuint create(GLenum target) { GLuint n = 0; glCreateTextures(target, 1, &n); return n; }
    static void destroy(GLuint n) { glDeleteTextures(1, &n); }
};
struct FramebufferTraits {
    static GLuint create() { GLuint n = 0; glCreateFramebuffers(1, &n); return n; }
    static void destroy(GLuint n) { glDeleteFramebuffers(1, &n); }
};
struct VertexArrayTraits {
    static GLuint create() { GLuint n = 0; glCreateVertexArrays(1, &n); return n; }
    static void destroy(GLuint n) { glDeleteVertexArrays(1, &n); }
};
struct ProgramTraits {
    static GLuint create() { return glCreateProgram(); }
    static void destroy(GLuint n) { glDeleteProgram(n); }
};
struct ShaderTraits {
    static GLuint create(GLenum stage) { return glCreateShader(stage); }
    static void destroy(GLuint n) { glDeleteShader(n); }
};
struct QueryTraits {
    static GLuint create(GLenum target) { GLuint n = 0; glCreateQueries(target, 1, &n); return n; }
    static void destroy(GLuint n) { glDeleteQueries(1, &n); }
};

using Buffer = Handle<BufferTraits>;
using Texture = Handle<TextureTraits>;
using Framebuffer = Handle<FramebufferTraits>;
using VertexArray = Handle<VertexArrayTraits>;
using Program = Handle<ProgramTraits>;
using Shader = Handle<ShaderTraits>;
using Query = Handle<QueryTraits>;

} // namespace swell::gl
