// swell_host_example: a small program that owns its window, its GL loader,
// its shaders and its world (a ship, a pier, crates), and draws Swell's
// water into its own frame (docs/LIBRARY.md walks through it).
//
//   swell_host_example                      a window (GLFW, GL 4.5 core); Esc quits
//   swell_host_example --headless out.png   one frame to a PNG, no display needed
//   swell_host_example --check              the compositing checks; exit 3 when one fails
// Options: --size WxH (default 960x540), --time SECONDS (headless; default 20),
// --frames N (window: quit after N frames).
#include "check.h"
#include "example.h"
#include "gl_functions.h"

#include <swell/error.h>
#include <swell/gl/context.h>
#include <swell/image.h>

#include <EGL/egl.h>
#define GLFW_INCLUDE_NONE // the host's GL declarations are its own (gl_functions.h)
#include <GLFW/glfw3.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <stdexcept>
#include <string>
#include <vector>

namespace {

constexpr int kExitOk = 0, kExitError = 1, kExitUsage = 2;

struct Options {
    enum class Mode { Window, Headless, Check } mode = Mode::Window;
    std::string output;
    glm::ivec2 size{960, 540};
    double time_s = 20.0;
    long frames = -1;
};

[[noreturn]] void usage(const std::string& problem)
{
    std::fprintf(stderr,
                 "swell_host_example: %s\n"
                 "usage: swell_host_example [--headless OUT.png | --check] [--size WxH] [--time S] [--frames N]\n",
                 problem.c_str());
    std::exit(kExitUsage);
}

Options parse(int argc, char** argv)
{
    Options o;
    for (int i = 1; i < argc; ++i) {
        const std::string a = argv[i];
        auto value = [&]() -> std::string {
            if (i + 1 >= argc)
                usage(a + " needs a value");
            return argv[++i];
        };
        try {
            if (a == "--headless") {
                o.mode = Options::Mode::Headless;
                o.output = value();
            } else if (a == "--check") {
                o.mode = Options::Mode::Check;
            } else if (a == "--size") {
                const std::string v = value();
                std::size_t x = v.find('x'), end = 0;
                if (x == std::string::npos)
                    usage("--size " + v + ": expected WxH");
                o.size = {std::stoi(v.substr(0, x), &end), std::stoi(v.substr(x + 1))};
                if (o.size.x < 16 || o.size.y < 16 || o.size.x > 8192 || o.size.y > 8192)
                    usage("--size " + v + ": each side must be 16..8192");
            } else if (a == "--time") {
                o.time_s = std::stod(value());
            } else if (a == "--frames") {
                o.frames = std::stol(value());
            } else {
                usage("unknown argument " + a);
            }
        } catch (const std::logic_error&) { // std::stoi/stod: not a number
            usage(a + " " + argv[i] + ": not a number");
        }
    }
    return o;
}

// Headless: Swell's EGL context (surfaceless, no display), the host's
// functions loaded through EGL, one frame read back to a PNG.
int headless(const Options& o)
{
    swell::gl::HeadlessContext context;
    if (const char* missing = host::loadGl(eglGetProcAddress))
        throw swell::Error(std::string("no GL function ") + missing + " in this context");
    host::Example example(host::harbourScene());
    host::Target display(o.size, GL_RGBA8);
    example.frame(o.time_s, display.framebuffer(), o.size);
    const std::vector<std::uint8_t> rgba = display.pixels();
    swell::Image image;
    image.width = o.size.x;
    image.height = o.size.y;
    image.rgba.resize(rgba.size());
    const std::size_t row = std::size_t(o.size.x) * 4;
    for (int y = 0; y < o.size.y; ++y) // GL's rows run bottom up, a PNG's top down
        std::copy_n(&rgba[std::size_t(o.size.y - 1 - y) * row], row, &image.rgba[std::size_t(y) * row]);
    swell::writePng(image, o.output);
    std::printf("%s: %dx%d at %.2f s, the ship rolled %.1f degrees\n", o.output.c_str(), o.size.x, o.size.y,
                o.time_s, example.harbour().shipRoll_deg());
    return kExitOk;
}

int check()
{
    // Any GL error or high-severity message, Swell's or the host's, fails the
    // check. (The handler first: it must outlive the context.)
    int glErrors = 0;
    swell::gl::DebugHandler handler = [&](const swell::gl::DebugMessage& m) {
        if (m.isError()) {
            std::fprintf(stderr, "GL: %s\n", m.str().c_str());
            ++glErrors;
        }
    };
    swell::gl::HeadlessContext context; // a debug context
    if (const char* missing = host::loadGl(eglGetProcAddress))
        throw swell::Error(std::string("no GL function ") + missing + " in this context");
    if (!swell::gl::installDebugHandler(&handler))
        throw swell::Error("the headless context has no debug output");
    const int result = host::runChecks();
    if (glErrors > 0)
        std::fprintf(stderr, "check: FAILED: %d GL errors\n", glErrors);
    return glErrors > 0 ? 3 : result;
}

int window(const Options& o)
{
    if (!glfwInit())
        throw swell::Error("GLFW cannot start (no display?)");
    glfwWindowHint(GLFW_CONTEXT_VERSION_MAJOR, 4);
    glfwWindowHint(GLFW_CONTEXT_VERSION_MINOR, 5);
    glfwWindowHint(GLFW_OPENGL_PROFILE, GLFW_OPENGL_CORE_PROFILE);
    glfwWindowHint(GLFW_OPENGL_FORWARD_COMPAT, GLFW_TRUE);
    GLFWwindow* w = glfwCreateWindow(o.size.x, o.size.y, "Swell in a host's frame", nullptr, nullptr);
    if (!w) {
        glfwTerminate();
        throw swell::Error("GLFW cannot open a GL 4.5 core window");
    }
    glfwMakeContextCurrent(w);
    glfwSwapInterval(1);
    try {
        if (const char* missing = host::loadGl(glfwGetProcAddress))
            throw swell::Error(std::string("no GL function ") + missing + " in this context");
        host::Example example(host::harbourScene());
        for (long n = 0; !glfwWindowShouldClose(w) && n != o.frames; ++n) {
            glfwPollEvents();
            if (glfwGetKey(w, GLFW_KEY_ESCAPE) == GLFW_PRESS)
                break;
            glm::ivec2 size;
            glfwGetFramebufferSize(w, &size.x, &size.y);
            if (size.x > 0 && size.y > 0) // minimised: nothing to draw
                example.frame(glfwGetTime(), 0, size);
            glfwSwapBuffers(w);
        }
    } catch (...) {
        glfwDestroyWindow(w);
        glfwTerminate();
        throw;
    }
    glfwDestroyWindow(w);
    glfwTerminate();
    return kExitOk;
}

} // namespace

int main(int argc, char** argv)
{
    const Options o = parse(argc, argv);
    try {
        switch (o.mode) {
        case Options::Mode::Headless: return headless(o);
        case Options::Mode::Check: return check();
        case Options::Mode::Window: return window(o);
        }
    } catch (const std::exception& e) {
        std::fprintf(stderr, "swell_host_example: %s\n", e.what());
    }
    return kExitError;
}
