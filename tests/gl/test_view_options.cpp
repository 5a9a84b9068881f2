// Render scale, antialiasing and the temporal resolve as a view's own
// options (swell::DrawOptions), which draw() honours as render() does
// (issue 43; docs/LIBRARY.md "Views"):
//   - draw() of Swell's own world into a cleared framebuffer of the host's,
//     through the view's own target, is render()'s frame byte for byte, at
//     a render scale, with FXAA and MSAA, and resolved over time;
//   - resolved over time, it converges to the full-resolution frame within
//     render()'s own bounds (tests/gl/test_temporal_resolve.cpp);
//   - two views of one framebuffer (split screen) each keep their own
//     targets and history: each half is byte for byte its view drawn alone;
//   - the host's depth holds the water's after a view drawn through the
//     target, as after one drawn straight in.
#include "support/gl_test.h"

#include "host_frame.h"
#include "swell/debug.h"
#include "swell/renderer.h"
#include "support/open_sea.h"

#include <gtest/gtest.h>

#include <epoxy/gl.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

namespace {

using namespace swell;
using test::HostTarget;

class ViewOptions : public test::GlTest {};

constexpr glm::ivec2 kViewOptionsSize{192, 108};
constexpr double kViewOptionsTime_s = 20.0;

struct Options {
    const char* name;
    double scale;
    Antialiasing antialiasing;
    bool temporal;
};

const Options kCases[] = {
    {"scale 0.5", 0.5, Antialiasing::Off, false},
    {"FXAA", 1.0, Antialiasing::Fxaa, false},
    {"MSAA", 1.0, Antialiasing::Msaa4, false},
    {"FXAA at 0.75", 0.75, Antialiasing::Fxaa, false},
    {"temporal at 0.5", 0.5, Antialiasing::Off, true},
};

// The host's framebuffer cleared as render() clears its own: black, opaque,
// the depth at the far plane.
void clear(const HostTarget& target)
{
    glBindFramebuffer(GL_FRAMEBUFFER, target.framebuffer());
    glDisable(GL_SCISSOR_TEST);
    glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
    glDepthMask(GL_TRUE);
    glClearColor(0.0f, 0.0f, 0.0f, 1.0f);
    glClearDepth(1.0);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
}

DrawOptions drawOptions(const Options& o, std::uint32_t viewId = 0)
{
    DrawOptions d;
    d.sceneWorld = true;
    d.sky = true;
    d.renderScale = o.scale;
    d.antialiasing = o.antialiasing;
    d.temporal = o.temporal;
    d.viewId = viewId;
    return d;
}

// render()'s frame after `frames` frames of a still camera.
std::vector<std::uint8_t> rendered(const Scene& base, const Camera& camera, const Options& o, int frames)
{
    Scene scene = base;
    scene.antialiasing = o.antialiasing;
    Renderer renderer(scene);
    renderer.setRenderScale(o.scale);
    renderer.setTemporalResolve(o.temporal);
    const HostTarget target(kViewOptionsSize);
    for (int i = 0; i < frames; ++i) {
        clear(target);
        renderer.render(camera, kViewOptionsTime_s, kViewOptionsSize, target.framebuffer());
    }
    return target.pixels();
}

// draw()'s, into the host's framebuffer cleared each frame.
std::vector<std::uint8_t> drawn(const Scene& scene, const Camera& camera, const Options& o, int frames)
{
    Renderer renderer(scene);
    const HostTarget target(kViewOptionsSize);
    for (int i = 0; i < frames; ++i) {
        clear(target);
        renderer.advanceTo(kViewOptionsTime_s, camera.position_m);
        renderer.draw(viewOf(camera, kViewOptionsSize), target.framebuffer(), drawOptions(o));
    }
    return target.pixels();
}

// The channels (R, G, B) that differ, and by how much at most.
struct Differing {
    long long channels = 0;
    int most = 0;
};

Differing differing(const std::vector<std::uint8_t>& a, const std::vector<std::uint8_t>& b)
{
    Differing d;
    for (std::size_t i = 0; i < a.size() && i < b.size(); ++i) {
        if (i % 4 == 3 || a[i] == b[i])
            continue;
        ++d.channels;
        d.most = std::max(d.most, std::abs(int(a[i]) - int(b[i])));
    }
    return d;
}

TEST_F(ViewOptions, DrawThroughTheViewsTargetIsWhatRenderDraws)
{
    const Scene scene = defaultScene();
    const Camera camera = cameraAt(scene.camera, 0.0);
    for (const Options& o : kCases) {
        const int frames = o.temporal ? 12 : 1;
        const Differing d = differing(rendered(scene, camera, o, frames), drawn(scene, camera, o, frames));
        EXPECT_EQ(d.channels, 0) << o.name << ": " << d.channels << " channels differ, by up to " << d.most;
    }
}

// The mean and 99th percentile of the channels' differences, 8-bit levels.
struct ViewOptionsDifference {
    double mean = 0.0, p99 = 0.0;
};

ViewOptionsDifference viewOptionsDifference(const std::vector<std::uint8_t>& a, const Image& b)
{
    std::vector<int> d;
    double sum = 0.0;
    // b is top row first, a bottom row first.
    for (int y = 0; y < kViewOptionsSize.y; ++y)
        for (int x = 0; x < kViewOptionsSize.x; ++x)
            for (int c = 0; c < 3; ++c) {
                const int v = std::abs(int(a[(std::size_t(y) * kViewOptionsSize.x + x) * 4 + c]) -
                                       int(b.pixel(x, kViewOptionsSize.y - 1 - y)[c]));
                d.push_back(v);
                sum += v;
            }
    std::sort(d.begin(), d.end());
    return {sum / double(d.size()), double(d[std::size_t(std::ceil(0.99 * double(d.size()))) - 1])};
}

TEST_F(ViewOptions, AHostsViewResolvedOverTimeConvergesToTheFullResolutionFrame)
{
    const Scene scene = defaultScene();
    const Camera camera = cameraAt(scene.camera, 0.0);
    Renderer full(scene);
    const Image reference = full.renderImage(camera, kViewOptionsTime_s, kViewOptionsSize);
    const ViewOptionsDifference resolved = viewOptionsDifference(drawn(scene, camera, {"temporal", 0.5, Antialiasing::Off, true}, 48),
                                           reference);
    std::printf("draw() resolved after 48 frames: %.2f mean, %.0f p99\n", resolved.mean, resolved.p99);
    // render()'s bounds (TemporalResolve.AStillCameraConvergesToTheFullResolutionFrame).
    EXPECT_LT(resolved.mean, 3.2);
    EXPECT_LT(resolved.p99, 32.0);
}

// Two views side by side in one framebuffer of the host's, each with its
// own camera and id, against each drawn alone (by a renderer of its own)
// into a framebuffer of its size.
TEST_F(ViewOptions, SplitScreenViewsKeepTheirOwnHistories)
{
    const Scene scene = defaultScene();
    Camera left = cameraAt(scene.camera, 0.0), right = left;
    right.yaw_deg += 40.0;
    right.position_m.y += 3.0;
    const glm::dvec3 viewpoint = left.position_m;
    const glm::ivec2 half(kViewOptionsSize.x / 2, kViewOptionsSize.y);
    for (const Options& o : {kCases[4], kCases[3], Options{"MSAA at 0.75", 0.75, Antialiasing::Msaa4, false}}) {
        const int frames = o.temporal ? 12 : 1;
        Renderer both(scene), leftOnly(scene), rightOnly(scene);
        const HostTarget split(kViewOptionsSize), leftAlone(half), rightAlone(half);
        for (int i = 0; i < frames; ++i) {
            for (const HostTarget* t : {&split, &leftAlone, &rightAlone})
                clear(*t);
            both.advanceTo(kViewOptionsTime_s, viewpoint);
            View l = viewOf(left, half), r = viewOf(right, half);
            r.viewport.x = half.x;
            both.draw(l, split.framebuffer(), drawOptions(o, 0));
            both.draw(r, split.framebuffer(), drawOptions(o, 1));
            leftOnly.advanceTo(kViewOptionsTime_s, viewpoint);
            leftOnly.draw(viewOf(left, half), leftAlone.framebuffer(), drawOptions(o, 7));
            rightOnly.advanceTo(kViewOptionsTime_s, viewpoint);
            rightOnly.draw(viewOf(right, half), rightAlone.framebuffer(), drawOptions(o, 8));
        }
        const std::vector<std::uint8_t> s = split.pixels(), a = leftAlone.pixels(), b = rightAlone.pixels();
        std::vector<std::uint8_t> leftHalf, rightHalf;
        for (int y = 0; y < kViewOptionsSize.y; ++y) {
            const auto row = s.begin() + std::ptrdiff_t(y) * kViewOptionsSize.x * 4;
            leftHalf.insert(leftHalf.end(), row, row + half.x * 4);
            rightHalf.insert(rightHalf.end(), row + half.x * 4, row + kViewOptionsSize.x * 4);
        }
        const Differing l = differing(leftHalf, a), r = differing(rightHalf, b);
        EXPECT_EQ(l.channels, 0) << o.name << ", left: " << l.channels << " channels differ, by up to " << l.most;
        EXPECT_EQ(r.channels, 0) << o.name << ", right: " << r.channels << " channels differ, by up to " << r.most;
    }
}

TEST_F(ViewOptions, TheHostsDepthHoldsTheWaterThroughTheTarget)
{
    const Scene scene = defaultScene();
    const Camera camera = cameraAt(scene.camera, 0.0);
    std::vector<float> straight, through;
    for (const Antialiasing a : {Antialiasing::Off, Antialiasing::Fxaa}) {
        Renderer renderer(scene);
        const HostTarget target(kViewOptionsSize);
        clear(target);
        renderer.advanceTo(kViewOptionsTime_s, camera.position_m);
        renderer.draw(viewOf(camera, kViewOptionsSize), target.framebuffer(), drawOptions({"", 1.0, a, false}));
        (a == Antialiasing::Off ? straight : through) = target.depths();
    }
    long long nearer = 0, differ = 0;
    for (std::size_t i = 0; i < straight.size(); ++i) {
        nearer += straight[i] < 1.0f ? 1 : 0;
        differ += straight[i] != through[i] ? 1 : 0;
    }
    // The water and the world cover the lower part of the frame at least.
    EXPECT_GT(nearer, (long long)(straight.size() / 3));
    EXPECT_EQ(differ, 0) << differ << " of " << straight.size() << " depths differ";
}

} // namespace
