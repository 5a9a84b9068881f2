// Headless EGL contexts and KHR_debug plumbing.
#include "swell/gl/context.h"

#include "swell/error.h"

#include <epoxy/egl.h>
#include <epoxy/gl.h>
#include <fmt/format.h>

#include <cstdio>
#include <mutex>
#include <set>
#include <vector>

namespace swell::gl {

bool DebugMessage::isError() const
{
    // The shader compiler's reports are not GL errors: buildProgram() turns
    // them into exceptions that name the file and line.
    if (source == GL_DEBUG_SOURCE_SHADER_COMPILER)
        return false;
    return type == GL_DEBUG_TYPE_ERROR || severity == GL_DEBUG_SEVERITY_HIGH;
}

std::string DebugMessage::str() const
{
    const char* kind = type == GL_DEBUG_TYPE_ERROR                ? "error"
                       : type == GL_DEBUG_TYPE_PERFORMANCE        ? "performance"
                       : type == GL_DEBUG_TYPE_DEPRECATED_BEHAVIOR ? "deprecated"
                       : type == GL_DEBUG_TYPE_UNDEFINED_BEHAVIOR  ? "undefined behaviour"
                                                                   : "message";
    return fmt::format("GL {} {}: {}", kind, id, text);
}

namespace {

void GLAPIENTRY forwardDebugMessage(GLenum source, GLenum type, GLuint id, GLenum severity, GLsizei length,
                                   const GLchar* message, const void* user)
{
    auto* handler = static_cast<DebugHandler*>(const_cast<void*>(user));
    DebugMessage m{source, type, id, severity, std::string(message, length < 0 ? std::char_traits<char>::length(message) : size_t(length))};
    (*handler)(m);
}

} // namespace

bool installDebugHandler(DebugHandler* handler)
{
    GLint flags = 0;
    glGetIntegerv(GL_CONTEXT_FLAGS, &flags);
    if (!(flags & GL_CONTEXT_FLAG_DEBUG_BIT))
        return false;
    glEnable(GL_DEBUG_OUTPUT);
    glEnable(GL_DEBUG_OUTPUT_SYNCHRONOUS);
    glDebugMessageCallback(forwardDebugMessage, handler);
    glDebugMessageControl(GL_DONT_CARE, GL_DONT_CARE, GL_DONT_CARE, 0, nullptr, GL_TRUE);
    // Notifications (buffer placement hints and the like) are noise.
    glDebugMessageControl(GL_DONT_CARE, GL_DONT_CARE, GL_DEBUG_SEVERITY_NOTIFICATION, 0, nullptr, GL_FALSE);
    return true;
}

DebugHandler logOnceDebugHandler()
{
    auto seen = std::make_shared<std::set<std::string>>();
    return [seen](const DebugMessage& m) {
        // A shader that does not compile or link is reported by buildProgram
        // as an error naming the file and line; the driver's copy of the same
        // log ("GL error 1: 0:12(5): ...") would only repeat it unmapped.
        if (m.source == GL_DEBUG_SOURCE_SHADER_COMPILER)
            return;
        if (seen->insert(m.text).second)
            std::fprintf(stderr, "swell: OpenGL driver %s: %s\n",
                         m.type == GL_DEBUG_TYPE_ERROR ? "error" : "message", m.text.c_str());
    };
}

struct HeadlessContext::State {
    EGLDisplay display = EGL_NO_DISPLAY;
    EGLContext context = EGL_NO_CONTEXT;
    std::string platform;
};

namespace {

EGLContext createCoreContext(EGLDisplay display, bool debug)
{
    if (!eglBindAPI(EGL_OPENGL_API))
        return EGL_NO_CONTEXT;
    const EGLint attributes[] = {
        EGL_CONTEXT_MAJOR_VERSION, 4, EGL_CONTEXT_MINOR_VERSION, 5,
        EGL_CONTEXT_OPENGL_PROFILE_MASK, EGL_CONTEXT_OPENGL_CORE_PROFILE_BIT,
        EGL_CONTEXT_OPENGL_DEBUG, debug ? EGL_TRUE : EGL_FALSE, EGL_NONE};
    // Configless: we only ever render into framebuffer objects.
    return eglCreateContext(display, EGL_NO_CONFIG_KHR, EGL_NO_CONTEXT, attributes);
}

// Displays to try, best first: Mesa's surfaceless platform, then each EGL device.
std::vector<std::pair<EGLDisplay, std::string>> candidateDisplays()
{
    std::vector<std::pair<EGLDisplay, std::string>> out;
    if (epoxy_has_egl_extension(EGL_NO_DISPLAY, "EGL_MESA_platform_surfaceless")) {
        EGLDisplay d = eglGetPlatformDisplayEXT(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, nullptr);
        if (d != EGL_NO_DISPLAY)
            out.emplace_back(d, "surfaceless");
    }
    if (epoxy_has_egl_extension(EGL_NO_DISPLAY, "EGL_EXT_device_enumeration")) {
        EGLDeviceEXT devices[16];
        EGLint count = 0;
        if (eglQueryDevicesEXT(16, devices, &count))
            for (EGLint i = 0; i < count; ++i) {
                EGLDisplay d = eglGetPlatformDisplayEXT(EGL_PLATFORM_DEVICE_EXT, devices[i], nullptr);
                if (d != EGL_NO_DISPLAY)
                    out.emplace_back(d, "device");
            }
    }
    return out;
}

} // namespace

HeadlessContext::HeadlessContext(bool debug) : state_(std::make_unique<State>())
{
    std::string tried;
    for (auto& [display, name] : candidateDisplays()) {
        EGLint major = 0, minor = 0;
        if (!eglInitialize(display, &major, &minor)) {
            tried += fmt::format(" {}: eglInitialize failed (0x{:x});", name, eglGetError());
            continue;
        }
        EGLContext context = createCoreContext(display, debug);
        if (context == EGL_NO_CONTEXT || !eglMakeCurrent(display, EGL_NO_SURFACE, EGL_NO_SURFACE, context)) {
            tried += fmt::format(" {}: no OpenGL 4.5 core context (0x{:x});", name, eglGetError());
            if (context != EGL_NO_CONTEXT)
                eglDestroyContext(display, context);
            eglTerminate(display);
            continue;
        }
        state_->display = display;
        state_->context = context;
        state_->platform = name;
        return;
    }
    throw Error("swell::gl::HeadlessContext: cannot create an OpenGL 4.5 core context through EGL;" +
                (tried.empty() ? std::string(" no EGL platform found (is Mesa's libegl1 installed?)") : tried));
}

HeadlessContext::~HeadlessContext()
{
    if (state_->context != EGL_NO_CONTEXT) {
        eglMakeCurrent(state_->display, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
        eglDestroyContext(state_->display, state_->context);
        eglTerminate(state_->display);
    }
}

void HeadlessContext::makeCurrent()
{
    eglMakeCurrent(state_->display, EGL_NO_SURFACE, EGL_NO_SURFACE, state_->context);
}

std::string HeadlessContext::description() const
{
    return fmt::format("{}, {}", reinterpret_cast<const char*>(glGetString(GL_RENDERER)),
                       reinterpret_cast<const char*>(glGetString(GL_VERSION)));
}

const std::string& HeadlessContext::platform() const { return state_->platform; }

bool isSoftwareRasterizer()
{
    const auto* renderer = reinterpret_cast<const char*>(glGetString(GL_RENDERER));
    const std::string_view name = renderer ? renderer : "";
    return name.find("llvmpipe") != name.npos || name.find("softpipe") != name.npos;
}

} // namespace swell::gl
