// swell_soak: renders many frames headless while the scene keeps changing,
// and fails when memory grows with the frame count or GL objects are not all
// given back. The changes follow a schedule that repeats every --cycle
// frames; within a cycle, on fixed periods (frames):
//   every  3: the output size, from a list that includes 0x0 and 1x1 (the
//             frame's target is resized with it; 0x0 frees it)
//   every  4: a frame into a framebuffer of our own, created and deleted here
//   every  5: the wind's seed (new waves)
//   every  7: the grid's resolution (the grid's buffers are rebuilt)
//   every  9: renderImage (an offscreen frame read back)
//   every 11: the debug view (every program is rebuilt)
//   every 13: the reflection targets' scale (offscreen targets recreated)
//   every 17: another preset through setScene (objects, terrain change)
//   every 19: shafts of light on or off (every program is rebuilt)
//   every 50: a shader reload
//
// Memory: resident set size from /proc/self/statm (after malloc_trim); each
// cycle after --warmup frames gives one sample, its lowest reading (the loop
// says why), so every sample comes from the same work. A least-squares line
// through the samples gives the growth per frame. (Readings at one step of
// the cycle would be noisier: RSS swings by 10 to 27 MiB with the allocator's
// arenas and the driver's lazily freed shader code.)
// GL objects: every name of every kind is probed (support/gl_objects.h) in
// one fixed state before the run and again after it.
//
// Usage: swell_soak [--frames N] [--warmup N] [--cycle N] [--max-slope B] [--size WxH]
//                   [--no-memory-verdict]
// (--max-slope: the growth limit in bytes per frame; the default is below.
// --no-memory-verdict: report the memory slope but judge only GL objects and
// errors, which do not depend on how busy the machine is)
// Exit: 0 passed; 2 bad arguments; 3 GL objects not back to baseline;
// 4 memory grows faster than the threshold; 5 a GL error or high-severity
// debug message; 1 anything else (no context, a bad preset).
#include "render/render_target.h"
#include "support/gl_objects.h"

#include "swell/camera.h"
#include "swell/error.h"
#include "swell/gl/context.h"
#include "swell/renderer.h"
#include "swell/scene/scene_file.h"

#include <epoxy/gl.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <string>
#include <vector>

#include <malloc.h>
#include <unistd.h>

namespace {

namespace fs = std::filesystem;
using swell::test::GlObjectCounts;

constexpr int kExitBadArguments = 2;
constexpr int kExitGlObjects = 3;
constexpr int kExitMemoryGrowth = 4;
constexpr int kExitGlError = 5;

// Largest growth of the resident set accepted by default, bytes per frame.
// Without a leak the fitted slope is allocator and driver noise: the lowest
// RSS of a cycle still wanders by up to 0.4 MiB, once by 1.2 MiB (glibc
// returns memory in page-sized steps, the driver's caches grow in chunks),
// which over the full run's 9,000 measured frames is tens of bytes per frame
// (measured: 15). A real leak of anything the loop recreates is far above
// this: one 160x90 RGBA8 texture is 57,600 bytes, one program tens of KiB,
// the waves of one rebuild 2 KiB. 512 B/frame is 5 MB over 10,000 frames.
constexpr double kMaxSlope_bytesPerFrame = 512.0;

struct Options {
    // Whether the run fails on memory growth. Resident memory is a reading of
    // the whole machine's weather as much as of Swell (see TESTING.md): CTest's
    // run leaves the verdict to GL objects and errors, which are exact.
    bool memoryVerdict = true;
    int frames = 10000;
    int warmup = 1000;
    int cycle = 200;
    double maxSlope_bytesPerFrame = kMaxSlope_bytesPerFrame;
    glm::ivec2 size{160, 90};
};

bool parseInt(const char* text, int& value)
{
    char* end = nullptr;
    const long v = std::strtol(text, &end, 10);
    if (end == text || *end != '\0' || v < 0 || v > 100000000)
        return false;
    value = int(v);
    return true;
}

bool parseArguments(int argc, char** argv, Options& o)
{
    for (int i = 1; i < argc; ++i) {
        const std::string arg = argv[i];
        if (arg == "--no-memory-verdict") {
            o.memoryVerdict = false;
            continue;
        }
        if (i + 1 >= argc)
            return false;
        const char* value = argv[++i];
        if (arg == "--frames") {
            if (!parseInt(value, o.frames))
                return false;
        } else if (arg == "--warmup") {
            if (!parseInt(value, o.warmup))
                return false;
        } else if (arg == "--cycle") {
            if (!parseInt(value, o.cycle) || o.cycle < 50)
                return false;
        } else if (arg == "--max-slope") {
            int v = 0;
            if (!parseInt(value, v) || v == 0)
                return false;
            o.maxSlope_bytesPerFrame = v;
        } else if (arg == "--size") {
            if (std::sscanf(value, "%dx%d", &o.size.x, &o.size.y) != 2 || o.size.x <= 0 || o.size.y <= 0 ||
                o.size.x > 4096 || o.size.y > 4096)
                return false;
        } else {
            return false;
        }
    }
    // At least three samples after the warm-up, or there is no line to fit.
    return o.frames - o.warmup >= 3 * o.cycle;
}

// Resident set size, bytes.
double residentBytes()
{
    std::ifstream statm("/proc/self/statm");
    long pages = 0, resident = 0;
    statm >> pages >> resident;
    return double(resident) * double(sysconf(_SC_PAGESIZE));
}

// Least-squares slope of y over x.
double slope(const std::vector<double>& x, const std::vector<double>& y)
{
    const double n = double(x.size());
    double sx = 0, sy = 0, sxx = 0, sxy = 0;
    for (std::size_t i = 0; i < x.size(); ++i) {
        sx += x[i];
        sy += y[i];
        sxx += x[i] * x[i];
        sxy += x[i] * y[i];
    }
    return (n * sxy - sx * sy) / (n * sxx - sx * sx);
}

// The scene at `step` (the frame's place in its cycle): a preset with the changes applied.
swell::Scene sceneAt(const std::vector<swell::Scene>& presets, int step)
{
    swell::Scene scene = presets[std::size_t(step / 17) % presets.size()];
    if (!scene.sea.wind)
        scene.sea.wind = swell::WindSettings{};
    scene.sea.wind->seed = std::uint32_t(step / 5);
    // Shafts of light in every other stretch: with them the caustics map is
    // drawn in more frames, by the frame's only program with a geometry stage.
    scene.water.shafts = (step / 19) % 2 == 1;
    const int resolutions[] = {256, 16, 64, 128};
    scene.grid.resolution = resolutions[(step / 7) % 4];
    const swell::DebugView views[] = {swell::DebugView::Shaded, swell::DebugView::Normals, swell::DebugView::Lod,
                                      swell::DebugView::Wireframe};
    scene.debugView = views[(step / 11) % 4];
    const double scales[] = {0.5, 1.0, 0.1, 0.25};
    scene.reflection.resolutionScale = scales[(step / 13) % 4];
    return scene;
}

bool changesScene(int step)
{
    return step % 5 == 0 || step % 7 == 0 || step % 11 == 0 || step % 13 == 0 || step % 17 == 0 || step % 19 == 0;
}
bool reloadsShaders(int step) { return step % 50 == 0; }

glm::ivec2 sizeAt(glm::ivec2 base, int step)
{
    const glm::ivec2 sizes[] = {base, {0, 0}, {1, 1}, base * 2, {base.x, 1}, {0, base.y}, base / 2 + 1};
    return sizes[(step / 3) % 7];
}

// A frame into a framebuffer of our own, created and deleted around it.
// (A headless context has no default framebuffer: every frame goes to one of ours.)
void renderIntoOwnFramebuffer(swell::Renderer& renderer, const swell::Camera& camera, double time_s, glm::ivec2 size)
{
    GLuint color = 0, depth = 0, framebuffer = 0;
    glCreateTextures(GL_TEXTURE_2D, 1, &color);
    glTextureStorage2D(color, 1, GL_RGBA8, size.x, size.y);
    glCreateRenderbuffers(1, &depth);
    glNamedRenderbufferStorage(depth, GL_DEPTH_COMPONENT24, size.x, size.y);
    glCreateFramebuffers(1, &framebuffer);
    glNamedFramebufferTexture(framebuffer, GL_COLOR_ATTACHMENT0, color, 0);
    glNamedFramebufferRenderbuffer(framebuffer, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, depth);
    renderer.render(camera, time_s, size, framebuffer);
    glDeleteFramebuffers(1, &framebuffer);
    glDeleteRenderbuffers(1, &depth);
    glDeleteTextures(1, &color);
}

int soak(const Options& o)
{
    swell::gl::HeadlessContext context(true);
    int glErrors = 0;
    swell::gl::DebugHandler handler = [&](const swell::gl::DebugMessage& m) {
        if (m.isError() && glErrors++ < 10)
            std::fprintf(stderr, "swell_soak: %s\n", m.str().c_str());
    };
    if (!swell::gl::installDebugHandler(&handler)) {
        std::fprintf(stderr, "swell_soak: the context has no debug output\n");
        return EXIT_FAILURE;
    }
    std::printf("swell_soak: %s, %d frames at %dx%d, warm-up %d, cycles of %d\n", context.description().c_str(),
                o.frames, o.size.x, o.size.y, o.warmup, o.cycle);

    std::vector<swell::Scene> presets{swell::defaultScene()};
    for (const char* name : {"calm", "storm", "sunset", "fog", "trade-wind"})
        presets.push_back(swell::loadScene(fs::path(SWELL_SOURCE_DIR) / "scenes" / (std::string(name) + ".toml")));

    const GlObjectCounts empty = swell::test::countLiveGlObjects();
    GlObjectCounts baseline;
    std::vector<double> frames, rss;
    const auto start = std::chrono::steady_clock::now();
    {
        swell::Renderer renderer(sceneAt(presets, 0));
        swell::detail::RenderTarget target;
        // The state the baseline is counted in, and the end compared in: the
        // first scene, our target and the renderer's own output target (kept
        // by renderImage between calls) both at the first size.
        auto settle = [&] {
            renderer.setScene(sceneAt(presets, 0));
            const glm::ivec2 size = sizeAt(o.size, 0);
            target.resize(size, GL_RGBA8);
            const swell::Camera camera = swell::cameraAt(renderer.scene().camera, 0.0);
            renderer.render(camera, 0.0, size, target.framebuffer());
            (void)renderer.renderImage(camera, 0.0, size);
            glFinish();
        };
        settle();
        baseline = swell::test::countLiveGlObjects();
        double cycleLowest = 0.0;
        for (int frame = 1; frame <= o.frames; ++frame) {
            const int step = frame % o.cycle;
            const double time_s = step / 60.0;
            if (changesScene(step))
                renderer.setScene(sceneAt(presets, step));
            if (reloadsShaders(step))
                renderer.reloadShaders();
            const swell::Camera camera = swell::cameraAt(renderer.scene().camera, time_s);
            const glm::ivec2 size = sizeAt(o.size, step);
            target.resize(size, GL_RGBA8);
            if (step % 4 == 0 && size.x > 0 && size.y > 0)
                renderIntoOwnFramebuffer(renderer, camera, time_s, size);
            else if (step % 9 == 0 && size.x > 0 && size.y > 0)
                (void)renderer.renderImage(camera, time_s, size);
            else
                renderer.render(camera, time_s, size, target.framebuffer()); // 0x0: draws nothing
            glFinish();
            // RSS is read on the frames that rebuilt nothing (the driver frees a
            // deleted program's compiled code lazily, a few frames later), after
            // giving freed heap memory back to the system: otherwise which of
            // glibc's per-thread arenas (the driver's threads have their own)
            // keeps freed blocks swings RSS by 10 MiB or more. A leak is memory
            // in use, which malloc_trim cannot return. The lowest reading of
            // each cycle is its sample: memory in use that never comes back
            // raises the lowest reading too, while transient peaks do not.
            if (!changesScene(step) && !reloadsShaders(step)) {
                malloc_trim(0);
                const double bytes = residentBytes();
                cycleLowest = cycleLowest == 0.0 ? bytes : std::min(cycleLowest, bytes);
            }
            if (step == o.cycle - 1) {
                const double bytes = cycleLowest;
                cycleLowest = 0.0;
                if (frame > o.warmup) {
                    frames.push_back(frame);
                    rss.push_back(bytes);
                }
                std::printf("swell_soak: cycle ending at frame %d: lowest RSS %.2f MiB%s\n", frame, bytes / 1048576.0,
                            frame > o.warmup ? "" : " (warm-up)");
            }
        }
        settle();
        const GlObjectCounts end = swell::test::countLiveGlObjects();
        const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        const double growth = slope(frames, rss);
        std::printf("swell_soak: %d frames in %.1f s (%.2f ms/frame)\n", o.frames, seconds, 1000.0 * seconds / o.frames);
        std::printf("swell_soak: RSS %.1f MiB after warm-up, %.1f MiB at the end; fitted slope %.1f B/frame "
                    "(limit %.0f), %zu samples\n",
                    rss.front() / 1048576.0, rss.back() / 1048576.0, growth, o.maxSlope_bytesPerFrame, rss.size());
        std::printf("swell_soak: GL objects at baseline: %s\n", baseline.str().c_str());
        std::printf("swell_soak: GL objects at the end:  %s\n", end.str().c_str());
        if (glErrors > 0) {
            std::printf("swell_soak: FAILED: %d GL errors or high-severity debug messages\n", glErrors);
            return kExitGlError;
        }
        if (!(end == baseline)) {
            std::printf("swell_soak: FAILED: GL objects did not return to the baseline\n");
            return kExitGlObjects;
        }
        if (!o.memoryVerdict)
            std::printf("swell_soak: memory not judged (--no-memory-verdict): the slope above is for information\n");
        else if (!(growth <= o.maxSlope_bytesPerFrame)) {
            std::printf("swell_soak: FAILED: resident memory grows %.1f B/frame, over the limit of %.0f\n", growth,
                        o.maxSlope_bytesPerFrame);
            return kExitMemoryGrowth;
        }
    }
    // With the renderer and our target gone, so is everything they made.
    const GlObjectCounts after = swell::test::countLiveGlObjects();
    if (!(after == empty)) {
        std::printf("swell_soak: FAILED: GL objects left after the renderer was destroyed: %s (before it: %s)\n",
                    after.str().c_str(), empty.str().c_str());
        return kExitGlObjects;
    }
    std::printf("swell_soak: passed\n");
    return EXIT_SUCCESS;
}

} // namespace

int main(int argc, char** argv)
{
    // Line by line, so that progress shows in a log while the run goes on.
    std::setvbuf(stdout, nullptr, _IOLBF, 0);
    Options options;
    if (!parseArguments(argc, argv, options)) {
        std::fprintf(stderr, "usage: swell_soak [--frames N] [--warmup N] [--cycle N] [--max-slope B] [--size WxH]\n"
                             "                  [--no-memory-verdict]\n"
                             "  (cycle >= 50; frames - warmup must span at least 3 cycles)\n");
        return kExitBadArguments;
    }
    try {
        return soak(options);
    } catch (const std::exception& e) {
        std::fprintf(stderr, "swell_soak: %s\n", e.what());
        return EXIT_FAILURE;
    }
}
