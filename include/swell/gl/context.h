// OpenGL 4.5 core contexts. HeadlessContext renders without any display
// through EGL (Mesa's surfaceless platform first, then an EGL device);
// windows come from GLFW in the viewer. Both load functions through libepoxy.
#pragma once

#include "swell/export.h"

#include <functional>
#include <memory>
#include <string>

namespace swell::gl {

// One message from the driver's KHR_debug output.
struct SWELL_API DebugMessage {
    unsigned source = 0, type = 0, id = 0, severity = 0;
    std::string text;
    // An error, or a high-severity message: tests fail on these.
    bool isError() const;
    std::string str() const;
};

using DebugHandler = std::function<void(const DebugMessage&)>;

// Installs a KHR_debug callback on the current context that forwards every
// message to handler (synchronously, so the GL call is still on the stack).
// The handler must outlive the context's use. Returns false when the context
// has no debug output.
SWELL_API bool installDebugHandler(DebugHandler* handler);

// A handler for the apps: logs each distinct message once to stderr.
SWELL_API DebugHandler logOnceDebugHandler();

// Whether the current context's GL_RENDERER is a software rasteriser
// (Mesa's llvmpipe or softpipe), where some GPU work is cheaper done
// another way (the spectral model's foam replay, its mip chains).
SWELL_API bool isSoftwareRasterizer();

class SWELL_API HeadlessContext {
public:
    // Creates and makes current a 4.5 core context; debug adds KHR_debug output.
    // Throws swell::Error naming what failed when no context can be had.
    explicit HeadlessContext(bool debug = true);
    ~HeadlessContext();
    HeadlessContext(const HeadlessContext&) = delete;
    HeadlessContext& operator=(const HeadlessContext&) = delete;

    void makeCurrent();
    // GL_RENDERER and GL_VERSION, e.g. "llvmpipe (LLVM 15.0.6, 256 bits), 4.5 (Core Profile) Mesa 22.3.6".
    std::string description() const;
    // "surfaceless" or "device": which EGL platform gave the context.
    const std::string& platform() const;

private:
    struct State;
    std::unique_ptr<State> state_;
};

} // namespace swell::gl
