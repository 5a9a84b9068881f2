// The viewer loop. Each frame: input, the clock, the panel (whose edits reach
// the renderer before it draws), the ocean into the default framebuffer, the
// panel over it, then a screenshot when one was asked for, and the swap.
//
// With --exit-after-frames the run is scripted: no input, the scene's own
// camera, and time advancing exactly 1/60 s per frame (or --time-step), so
// the frames (and the --screenshot of the last) do not depend on how fast
// the machine is.
//
// The renderer is interactive (Renderer::setInteractive): a frame, however
// long after the last, never replays the foam's history, so a slow frame
// does not make the next one slower.
#include "viewer/viewer.h"

#include "data_folders.h"
#include "scene_loading.h"
#include "viewer/gui.h"
#include "viewer/panel.h"
#include "viewer/screenshot.h"
#include "viewer/session.h"
#include "viewer/view_quality.h"
#include "viewer/window.h"

#include "core/thread_cpu.h"

#include "swell/error.h"
#include "swell/gl/context.h"

#include <epoxy/gl.h>
#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>
#include <fmt/format.h>
#include <imgui.h>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <set>
#include <vector>

namespace swell::app::viewer {

namespace {

namespace fs = std::filesystem;
using detail::processCpu_ms;

// The fly camera moves for at most this long per frame, s: long enough to
// keep its speed at the few frames per second of software GL, short enough
// that a stall does not throw the camera far away.
constexpr double kMaxFlyStep_s = 1.0;

// Key presses, each seen once. They are collected by a GLFW key callback, so
// a press released before the next frame (a few frames per second on
// software GL) is not lost. Construct before Gui: ImGui's GLFW backend then
// forwards every key event here after handling it.
class KeyPresses {
public:
    explicit KeyPresses(GLFWwindow* window) : window_(window)
    {
        glfwSetWindowUserPointer(window, this);
        glfwSetKeyCallback(window, [](GLFWwindow* w, int key, int, int action, int) {
            if (action == GLFW_PRESS)
                static_cast<KeyPresses*>(glfwGetWindowUserPointer(w))->pressed_.insert(key);
        });
    }
    ~KeyPresses()
    {
        glfwSetKeyCallback(window_, nullptr);
        glfwSetWindowUserPointer(window_, nullptr);
    }
    KeyPresses(const KeyPresses&) = delete;
    KeyPresses& operator=(const KeyPresses&) = delete;

    // Whether the key was pressed since the last call to take() for it.
    bool take(int key) { return pressed_.erase(key) > 0; }
    // Forgets presses nobody took (the keys of a scripted run).
    void clear() { pressed_.clear(); }

private:
    GLFWwindow* window_;
    std::set<int> pressed_;
};

// The rate simulation time really advances at, simulated seconds per real
// second, over about the last second. It differs from the rate asked for
// when frames take longer than kMaxFrameStep_s or time is paused.
class TimeRateMeter {
public:
    void add(double simulated_s, double real_s)
    {
        simulated_s_ += simulated_s;
        real_s_ += real_s;
        if (real_s_ >= kWindow_s) {
            rate_ = simulated_s_ / real_s_;
            simulated_s_ = real_s_ = 0.0;
        }
    }
    double rate() const { return rate_; }

private:
    static constexpr double kWindow_s = 1.0;
    double simulated_s_ = 0.0, real_s_ = 0.0;
    double rate_ = 1.0;
};

// Turns the mouse and keyboard into fly-camera input, leaving to ImGui what
// it is using: keys while a widget is active, the mouse over the panel.
class FlyControls {
public:
    explicit FlyControls(GLFWwindow* window) : window_(window) {}
    FlyInput read(const ImGuiIO& io)
    {
        FlyInput input;
        glm::dvec2 cursor;
        glfwGetCursorPos(window_, &cursor.x, &cursor.y);
        const bool held = glfwGetMouseButton(window_, GLFW_MOUSE_BUTTON_RIGHT) == GLFW_PRESS;
        if (held && !looking_ && !io.WantCaptureMouse)
            looking_ = true;
        else if (!held)
            looking_ = false;
        else
            input.look_px = cursor - lastCursor_;
        lastCursor_ = cursor;
        if (!io.WantCaptureKeyboard) {
            auto axis = [this](int negative, int positive) {
                return double(glfwGetKey(window_, positive) == GLFW_PRESS) - double(glfwGetKey(window_, negative) == GLFW_PRESS);
            };
            input.move = glm::dvec3(axis(GLFW_KEY_A, GLFW_KEY_D), axis(GLFW_KEY_Q, GLFW_KEY_E), axis(GLFW_KEY_S, GLFW_KEY_W));
            input.fast = glfwGetKey(window_, GLFW_KEY_LEFT_SHIFT) == GLFW_PRESS ||
                         glfwGetKey(window_, GLFW_KEY_RIGHT_SHIFT) == GLFW_PRESS;
        }
        if (!io.WantCaptureMouse)
            input.wheel = io.MouseWheel;
        return input;
    }

private:
    GLFWwindow* window_;
    bool looking_ = false;
    glm::dvec2 lastCursor_{0.0};
};

// The camera a frame is drawn with: the scene's (following its path) or the
// fly camera, with the scene's lens either way.
Camera frameCamera(ViewState& view, const Scene& scene)
{
    if (view.followSceneCamera)
        return cameraAt(scene.camera, view.time_s);
    view.fly.setLens(scene.camera.fovY_deg, scene.camera.near_m, scene.camera.far_m);
    return view.fly.camera();
}

// The median of `values` (not empty).
double median(std::vector<double> values)
{
    std::sort(values.begin(), values.end());
    return values[values.size() / 2];
}

fs::path absolutePath(const fs::path& path)
{
    std::error_code ec;
    fs::path absolute = fs::absolute(path, ec);
    return ec ? path : absolute;
}

// Writes the frame just drawn and prints its absolute path on stdout.
fs::path writeScreenshot(glm::ivec2 size, const fs::path& path)
{
    if (size.x <= 0 || size.y <= 0)
        throw Error("the window has no pixels (minimised?)");
    writePng(readDefaultFramebuffer(size), path);
    const fs::path absolute = absolutePath(path);
    std::printf("%s\n", absolute.c_str());
    std::fflush(stdout);
    return absolute;
}

} // namespace

int run(const ViewOptions& options)
{
    const bool scripted = options.exitAfterFrames > 0;
    if (options.scriptedStep_s != 1.0 / 60.0 && !scripted)
        throw InputError({"--time-step"}, "--time-step needs --exit-after-frames N (an interactive run follows the clock)");
    if (!options.screenshotPath.empty() && !scripted)
        throw InputError({"--screenshot"}, "--screenshot needs --exit-after-frames N (press F12 for a screenshot "
                                           "in an interactive session)");
    if (!options.screenshotPath.empty() && fs::path(options.screenshotPath).extension() != ".png")
        throw InputError({"--screenshot"}, fmt::format("'{}': a screenshot is a .png file", options.screenshotPath));
    Scene scene = loadSceneOrDefault(options.scenePath);
    options.outputSettings.applyTo(scene);

    const std::string title =
        options.scenePath.empty() ? std::string("Swell") : "Swell - " + fs::path(options.scenePath).filename().string();
    Window window(title, {options.width, options.height}, !scripted);
    gl::DebugHandler debug = gl::logOnceDebugHandler();
    gl::installDebugHandler(&debug);
    const DataFolders data = dataFolders();
    Session session(std::move(scene), options.scenePath, ShaderFolders{data.shaders, data.include});
    KeyPresses keys(window.handle());
    Gui gui(window.handle(), GuiTesting{.slowFrame_ms = options.slowFrame_ms, .logInput = options.logInput});
    Panel panel(data.scenes);
    panel.sceneLoaded(options.scenePath);

    ViewState view;
    view.quality.temporal = options.temporal;
    view.quality.fixedScale = options.outputSettings.renderScale;
    view.quality.dynamicScale = options.frameTarget_ms > 0.0;
    if (view.quality.dynamicScale)
        view.quality.frameTarget_ms = options.frameTarget_ms;
    ViewQuality quality(options.outputSettings.renderScale);
    view.fly.setPose(cameraAt(session.scene().camera, 0.0));
    FlyControls controls(window.handle());
    FrameStats stats;
    stats.context = window.description();
    TimeRateMeter rate;

    // A scripted run's frame times, from each frame's start to the next's
    // (input, panel, drawing, swap), reported when it ends: wall s, CPU ms.
    std::vector<double> scriptedFrames_s, scriptedFramesCpu_ms, scriptedScales;
    int scriptedTemporal = 0; // of those frames, drawn with the temporal resolve
    double last = glfwGetTime();
    double lastCpu_ms = processCpu_ms();
    for (int frame = 0; !window.shouldClose(); ++frame) {
        if (!scripted && window.framebufferSize() == glm::ivec2(0)) {
            // Minimised: nothing to draw; wait for the window to come back.
            glfwWaitEventsTimeout(0.1);
            last = glfwGetTime();
            continue;
        }
        glfwPollEvents();
        const double now = glfwGetTime();
        const double frame_s = now - last;
        last = now;
        stats.times.add(float(frame_s * 1000.0));
        const double cpu_ms = processCpu_ms();
        // Frame 1 measures frame 0, the first: it replays the sea's history
        // (there is no frame before it), so it is left out like a warm-up.
        if (scripted && frame > 1) {
            scriptedFrames_s.push_back(frame_s);
            scriptedFramesCpu_ms.push_back(cpu_ms - lastCpu_ms);
            scriptedScales.push_back(view.drawn.renderScale);
            scriptedTemporal += view.drawn.temporal ? 1 : 0;
        }
        lastCpu_ms = cpu_ms;

        gui.beginFrame();
        bool reloadShaders = false, screenshot = false;
        if (scripted) {
            keys.clear();
            view.time_s = frame * options.scriptedStep_s;
        } else {
            const ImGuiIO& io = ImGui::GetIO();
            // Esc quits, unless it is ending an edit in the panel (ImGui
            // takes it to leave a text field or an open list).
            if (keys.take(GLFW_KEY_ESCAPE) && !ImGui::IsAnyItemActive() && !ImGui::IsPopupOpen("", ImGuiPopupFlags_AnyPopup))
                window.requestClose();
            if (keys.take(GLFW_KEY_F1))
                view.panel = nextPanelMode(view.panel);
            reloadShaders = keys.take(GLFW_KEY_F5);
            screenshot = keys.take(GLFW_KEY_F12);
            if (keys.take(GLFW_KEY_SPACE) && !io.WantCaptureKeyboard)
                view.paused = !view.paused;
            keys.clear();
            const FlyInput input = controls.read(io);
            if (view.followSceneCamera && FlyCamera::moves(input)) {
                // Taking the controls leaves the scene's camera where it is.
                view.fly.setPose(frameCamera(view, session.scene()));
                view.followSceneCamera = false;
            }
            if (!view.followSceneCamera)
                view.fly.update(input, std::min(frame_s, kMaxFlyStep_s));
            else if (input.wheel != 0.0)
                view.fly.update(FlyInput{.wheel = input.wheel}, 0.0);
            const double step_s = view.paused ? 0.0 : std::min(frame_s, kMaxFrameStep_s) * view.timeRate;
            view.time_s += step_s;
            rate.add(step_s, frame_s);
            view.actualTimeRate = rate.rate();
        }

        if (view.panel != PanelMode::Hidden) {
            const PanelRequests requests = view.panel == PanelMode::Full ? panel.draw(session, view, stats)
                                                                         : panel.drawOverlay(view, stats);
            reloadShaders |= requests.reloadShaders;
            screenshot |= requests.screenshot;
        }
        if (reloadShaders && !session.reloadShaders())
            std::fprintf(stderr, "swell: shader reload failed; the previous shaders stay in use:\n%s\n",
                         session.shaderMessage().text.c_str());

        // The panel may have changed the scene or the camera: draw with what it left.
        const Camera camera = frameCamera(view, session.scene());
        const glm::ivec2 size = window.framebufferSize();
        // The scale and the resolve for this frame, from the camera and the
        // last frame's time (not frame 1's, which measured the first frame's
        // replay, nor frame 0's, which has none).
        view.drawn = quality.next(view.quality, camera, frame > 1 ? frame_s * 1000.0 : 0.0);
        session.renderer().setRenderScale(view.drawn.renderScale);
        session.renderer().setTemporalResolve(view.drawn.temporal);
        session.renderer().setInteractive(true); // (the session may have made a new renderer)
        session.renderer().render(camera, view.time_s, size);
        stats.counters = session.renderer().counters();
        stats.size = size;
        stats.camera = camera;
        gui.endFrame();

        if (screenshot) {
            try {
                const fs::path path = writeScreenshot(size, nextScreenshotPath(fs::current_path()));
                panel.setScreenshotMessage({"Saved " + path.string()});
            } catch (const std::exception& e) {
                panel.setScreenshotMessage({std::string("Screenshot failed: ") + e.what(), true});
            }
        }
        const bool lastFrame = scripted && frame + 1 >= options.exitAfterFrames;
        if (lastFrame && !options.screenshotPath.empty()) {
            const fs::path path = options.screenshotPath;
            if (path.has_parent_path())
                fs::create_directories(path.parent_path());
            writeScreenshot(size, path);
        }
        window.swapBuffers();
        if (lastFrame)
            break;
    }
    if (!scriptedFrames_s.empty()) {
        // On stderr, so that stdout keeps only the screenshot's path.
        const glm::ivec2 size = window.framebufferSize();
        std::fprintf(stderr,
                     "swell view: %zu frames timed at %dx%d, render scale %.2f%s, temporal resolve on in %d: median "
                     "%.1f ms wall (%.1f frames a second), %.1f ms CPU a frame; the longest %.1f ms wall, %.1f ms "
                     "CPU\n",
                     scriptedFrames_s.size(), size.x, size.y, median(scriptedScales),
                     view.quality.dynamicScale
                         ? fmt::format(" (median; dynamic, target {:.0f} ms, last {:.2f})", view.quality.frameTarget_ms,
                                       view.drawn.renderScale)
                               .c_str()
                         : "",
                     scriptedTemporal, 1000.0 * median(scriptedFrames_s),
                     1.0 / median(scriptedFrames_s),
                     median(scriptedFramesCpu_ms),
                     1000.0 * *std::max_element(scriptedFrames_s.begin(), scriptedFrames_s.end()),
                     *std::max_element(scriptedFramesCpu_ms.begin(), scriptedFramesCpu_ms.end()));
    }
    return kExitOk;
}

} // namespace swell::app::viewer
