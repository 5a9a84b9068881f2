// A frame through the scene camera's lens and sensor (swell/dataset/sensor.h).
#include "swell/dataset/sensor.h"

#include "core/counter_random.h"
#include "core/lens_fold.h"
#include "render/sensor_silhouettes.h"
#include "swell/error.h"
#include "swell/gpu/label_classes.h"
#include "swell/renderer.h"

#include <fmt/format.h>
#include <glm/common.hpp>
#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <cstdint>
#include <functional>
#include <optional>
#include <utility>
#include <vector>

namespace swell {

namespace {

// sRGB's transfer function (IEC 61966-2-1:1999), both ways.
double decodeSrgb(double v) { return v <= 0.04045 ? v / 12.92 : std::pow((v + 0.055) / 1.055, 2.4); }
double encodeSrgb(double v) { return v <= 0.0031308 ? 12.92 * v : 1.055 * std::pow(v, 1.0 / 2.4) - 0.055; }

const std::array<double, 256>& srgbToLinear()
{
    static const std::array<double, 256> table = [] {
        std::array<double, 256> t{};
        for (int i = 0; i < 256; ++i)
            t[std::size_t(i)] = decodeSrgb(i / 255.0);
        return t;
    }();
    return table;
}

std::uint8_t toByte(double linear) { return std::uint8_t(std::lround(std::clamp(encodeSrgb(std::max(linear, 0.0)), 0.0, 1.0) * 255.0)); }

// A uniform in (0, 1) from its own key (core/counter_random.h): each
// pixel's noise depends on its key alone. Never 0, for Box-Muller's log.
double uniform(std::uint64_t key) { return detail::unitFromBits(detail::splitMix64(key)) + 0x1.0p-54; }

// Where the output's pixel (x, y) looks in the pinhole frame of `wide`
// pixels, pixels (its top-left corner at 0, 0).
glm::dvec2 sourceOf(const LensDistortion& lens, const CameraCalibration& c, glm::ivec2 wide, int x, int y)
{
    const glm::dvec2 u = undistort(lens, {(x + 0.5 - c.cx_px) / c.fx_px, (y + 0.5 - c.cy_px) / c.fy_px});
    return detail::kPinholeScale * c.fy_px * u + 0.5 * glm::dvec2(wide);
}

void distortImage(const Image& wide, Image& out, const LensDistortion& lens, const CameraCalibration& c)
{
    const std::array<double, 256>& linear = srgbToLinear();
    const glm::ivec2 wideSize(wide.width, wide.height);
    for (int y = 0; y < out.height; ++y)
        for (int x = 0; x < out.width; ++x) {
            // Bilinear, in linear light.
            const glm::dvec2 s = sourceOf(lens, c, wideSize, x, y) - 0.5;
            const int x0 = std::clamp(int(std::floor(s.x)), 0, wide.width - 2);
            const int y0 = std::clamp(int(std::floor(s.y)), 0, wide.height - 2);
            const double fx = std::clamp(s.x - x0, 0.0, 1.0), fy = std::clamp(s.y - y0, 0.0, 1.0);
            std::uint8_t* o = out.pixel(x, y);
            for (int ch = 0; ch < 3; ++ch) {
                auto at = [&](int px, int py) { return linear[wide.pixel(px, py)[ch]]; };
                const double v = (1.0 - fy) * ((1.0 - fx) * at(x0, y0) + fx * at(x0 + 1, y0)) +
                                 fy * ((1.0 - fx) * at(x0, y0 + 1) + fx * at(x0 + 1, y0 + 1));
                o[ch] = toByte(v);
            }
            o[3] = 255;
        }
}

// Whether two pixels of the pinhole frame's labels show one surface, with a
// finite range: one object, or the water (foam or not), or the island.
bool oneSurface(const FrameLabels& wide, std::size_t a, std::size_t b)
{
    const std::uint16_t sa = wide.semantic[a], sb = wide.semantic[b];
    return std::isfinite(wide.range_m[b]) && wide.instance[a] == wide.instance[b] &&
           (sa == sb || (isSeaClass(sa) && isSeaClass(sb)) || (isGroundClass(sa) && isGroundClass(sb)));
}

// The range along the ray through s (the pinhole frame's pixels, continuous)
// from the labels of the pinhole pixel (sx, sy) nearest it (docs/LABELS.md:
// a range is the pixel centre's ray's). On a plane the inverse of the depth
// along the optical axis is affine in the pixel's place (a plane n . X = c
// holds 1 / Z = n . (x, y, 1) / c), so it is carried from the nearest
// pixel's centre to s along each axis: exact on a plane, second order on a
// curved surface. Along each axis it is interpolated towards the neighbour
// on s's side where that neighbour continues the surface, else extrapolated
// from the other side's (across an occluding edge, the two sides' slopes of
// the inverse depth differ many times over); neither, not carried.
float rangeAlongRay(const FrameLabels& wide, double pinholeFocal_px, glm::dvec2 s, int sx, int sy)
{
    const std::size_t w = std::size_t(wide.size.x);
    const std::size_t from = std::size_t(sy) * w + std::size_t(sx);
    const float nearest_m = wide.range_m[from];
    if (!std::isfinite(nearest_m) || !(nearest_m > 0.0))
        return nearest_m;
    // Inverse depth of a pixel: |(x, y, 1)| / range, with (x, y) its
    // centre's normalised place (the frame is centred on the optical axis).
    auto inverseDepth = [&](int px, int py) {
        const glm::dvec2 u = (glm::dvec2(px + 0.5, py + 0.5) - 0.5 * glm::dvec2(wide.size)) / pinholeFocal_px;
        return std::sqrt(1.0 + glm::dot(u, u)) / double(wide.range_m[std::size_t(py) * w + std::size_t(px)]);
    };
    const double here = inverseDepth(sx, sy);
    const glm::dvec2 offset = s - glm::dvec2(sx + 0.5, sy + 0.5);
    // The slope of the inverse depth along one axis (step (dx, dy)), per pixel.
    auto slope = [&](int dx, int dy, double towards) {
        std::optional<double> side[2]; // [0]: on s's side, [1]: the other
        for (int k = 0; k < 2; ++k) {
            const int sign = (towards >= 0.0) == (k == 0) ? 1 : -1;
            const int nx = sx + sign * dx, ny = sy + sign * dy;
            if (nx >= 0 && ny >= 0 && nx < wide.size.x && ny < wide.size.y &&
                oneSurface(wide, from, std::size_t(ny) * w + std::size_t(nx)))
                side[k] = sign * (inverseDepth(nx, ny) - here);
        }
        constexpr double kEdge = 3.0; // slopes this many times apart: an occluding edge between
        if (side[0] && (!side[1] || std::abs(*side[0]) <= kEdge * std::abs(*side[1])))
            return *side[0];
        return side[1].value_or(0.0);
    };
    const double atRay = here + slope(1, 0, offset.x) * offset.x + slope(0, 1, offset.y) * offset.y;
    if (!(atRay > 0.0))
        return nearest_m; // past the surface's vanishing line: the nearest pixel's own range
    const glm::dvec2 u = (s - 0.5 * glm::dvec2(wide.size)) / pinholeFocal_px;
    return float(std::sqrt(1.0 + glm::dot(u, u)) / atRay);
}

FrameLabels distortLabels(const FrameLabels& wide, const LensDistortion& lens, const CameraCalibration& c)
{
    FrameLabels out;
    out.size = c.size;
    const std::size_t pixels = std::size_t(c.size.x) * std::size_t(c.size.y);
    out.range_m.resize(pixels);
    out.normal.resize(pixels);
    out.semantic.resize(pixels);
    out.instance.resize(pixels);
    std::vector<std::size_t> sources(pixels); // each pixel's pinhole pixel
    for (int y = 0; y < c.size.y; ++y)
        for (int x = 0; x < c.size.x; ++x) {
            // Nearest: a label is never a blend of two; the range the
            // nearest's surface's along this pixel's own centre ray.
            const glm::dvec2 s = sourceOf(lens, c, wide.size, x, y);
            const int sx = std::clamp(int(std::floor(s.x)), 0, wide.size.x - 1);
            const int sy = std::clamp(int(std::floor(s.y)), 0, wide.size.y - 1);
            const std::size_t from = std::size_t(sy) * std::size_t(wide.size.x) + std::size_t(sx);
            const std::size_t to = std::size_t(y) * std::size_t(c.size.x) + std::size_t(x);
            out.range_m[to] = rangeAlongRay(wide, detail::kPinholeScale * c.fy_px, s, sx, sy);
            out.normal[to] = wide.normal[from];
            out.semantic[to] = wide.semantic[from];
            out.instance[to] = wide.instance[from];
            sources[to] = from;
        }
    out.classes = wide.classes;
    out.trueHorizonDip_deg = wide.trueHorizonDip_deg;
    out.objects = wide.objects;
    out.camera = c;
    out.horizon = horizonOf(c);
    out.horizon.curve_px = horizonCurveOf(c, out.horizon);
    detail::distortSilhouettes(wide, lens, c, detail::kPinholeScale * c.fy_px, sources, out);
    measureObjectBoxes(out);
    measureOcclusion(out);
    measureShoreline(out);
    return out;
}

// Exposure, then noise, on the encoded image (decoded to linear light first).
void exposeAndNoise(Image& image, const CameraSettings& s, double time_s)
{
    if (s.exposure_ev == 0.0 && s.noiseStdDev == 0.0)
        return;
    const std::array<double, 256>& linear = srgbToLinear();
    const double gain = std::exp2(s.exposure_ev);
    const std::uint64_t frameKey =
        detail::splitMix64(detail::splitMix64(std::uint64_t(s.noiseSeed)) ^ std::bit_cast<std::uint64_t>(time_s));
    for (std::size_t i = 0; i < image.rgba.size(); ++i) {
        if (i % 4 == 3)
            continue;
        double v = encodeSrgb(std::min(linear[image.rgba[i]] * gain, 1.0));
        if (s.noiseStdDev > 0.0) {
            // Box-Muller: a standard normal from two uniforms of the pixel's own key.
            const double u1 = uniform(frameKey ^ (2 * i)), u2 = uniform(frameKey ^ (2 * i + 1));
            v += s.noiseStdDev * std::sqrt(-2.0 * std::log(u1)) * std::cos(2.0 * 3.14159265358979323846 * u2);
        }
        image.rgba[i] = std::uint8_t(std::lround(std::clamp(v, 0.0, 1.0) * 255.0));
    }
}

// The rows of `draws` (images of one size, drawn at timing.drawTimes_s)
// each averaged over the draws it gathers light from, in linear light.
Image exposeRows(const std::vector<Image>& draws, const SensorTiming& timing)
{
    const std::array<double, 256>& linear = srgbToLinear();
    Image out;
    out.width = draws.front().width;
    out.height = draws.front().height;
    out.rgba.resize(draws.front().rgba.size());
    const std::size_t row = std::size_t(out.width) * 4;
    for (int y = 0; y < out.height; ++y) {
        const glm::ivec2 from = timing.rowDraws[std::size_t(y)];
        const double weight = 1.0 / double(from.y - from.x + 1);
        for (std::size_t i = std::size_t(y) * row; i < std::size_t(y + 1) * row; ++i) {
            if (i % 4 == 3) {
                out.rgba[i] = 255;
                continue;
            }
            double sum = 0.0;
            for (int j = from.x; j <= from.y; ++j)
                sum += linear[draws[std::size_t(j)].rgba[i]];
            out.rgba[i] = toByte(sum * weight);
        }
    }
    return out;
}

} // namespace

namespace {

// The frame's image (when `image`) and its labels (when `labels`).
SensorFrame sensorFrame(Renderer& renderer, const CameraAt& cameraAt, double time_s, glm::ivec2 size, bool image,
                        bool labels, const CameraAt& around = {})
{
    // Where the simulation is advanced for a draw at time t: around the
    // platform of a rig (its eye at t), else around the drawn camera.
    auto aroundAt = [&around](double t) {
        return around ? std::optional<glm::dvec3>(around(t).position_m) : std::nullopt;
    };
    const CameraSettings& settings = renderer.scene().camera;
    const LensDistortion lens = lensOf(settings);
    const SensorTiming timing = image ? sensorTimingOf(settings, time_s, size.y) : SensorTiming{{time_s}, {}};
    // The camera of each time is asked for in the order of the times: a
    // camera on a deck steps its body there, and a step back in time would
    // simulate the bodies again from their start.
    SensorFrame frame;
    auto cameraNow = [&] {
        frame.camera = cameraAt(time_s);
        return frame.camera;
    };
    // The image one draw at time t makes through the lens, and the labels
    // of the simulated time.
    std::function<Image(double)> drawAt;
    std::function<FrameLabels()> labelsNow;
    if (lens.none()) {
        drawAt = [&](double t) {
            return renderer.renderImage(t == time_s ? cameraNow() : cameraAt(t), t, size, aroundAt(t));
        };
        labelsNow = [&] { return renderer.renderLabels(frame.camera, size); };
    } else {
        // The rule scenes and sweeps are checked by (the field is the
        // scene's, whatever the time).
        checkLens(renderer.scene(), size, settings.fovY_deg);
        auto calibrated = [&lens, size](const Camera& at) { return sensorCalibrationOf(at, lens, size); };
        auto pinholeOf = [&lens](const Camera& at, const CameraCalibration& c) {
            const glm::ivec2 wide = detail::pinholeSize(lens, c);
            Camera pinhole = at;
            pinhole.fovY_deg = glm::degrees(2.0 * std::atan(0.5 * wide.y / (detail::kPinholeScale * c.fy_px)));
            return std::pair(pinhole, wide);
        };
        drawAt = [&, calibrated, pinholeOf](double t) {
            const Camera at = t == time_s ? cameraNow() : cameraAt(t);
            const CameraCalibration c = calibrated(at);
            const auto [pinhole, wide] = pinholeOf(at, c);
            const Image source = renderer.renderImage(pinhole, t, wide, aroundAt(t));
            Image out;
            out.width = size.x;
            out.height = size.y;
            out.rgba.resize(std::size_t(size.x) * std::size_t(size.y) * 4);
            distortImage(source, out, lens, c);
            return out;
        };
        labelsNow = [&, calibrated, pinholeOf] {
            const CameraCalibration c = calibrated(frame.camera);
            const auto [pinhole, wide] = pinholeOf(frame.camera, c);
            FrameLabels out = distortLabels(renderer.renderLabels(pinhole, wide), lens, c);
            out.trueHorizon_px =
                trueHorizonOf(c, seaFrameOf(renderer.scene()).heightInSea(frame.camera.position_m.y));
            return out;
        };
    }
    // The labels' instant among the draws (at its place in time): the
    // simulation advanced there for the camera of that time.
    auto labelTheInstant = [&] {
        renderer.advanceTo(time_s, aroundAt(time_s).value_or(cameraNow().position_m));
        frame.labels = labelsNow();
    };
    if (!image) {
        labelTheInstant();
        return frame;
    }
    if (timing.drawTimes_s.size() == 1) {
        frame.image = drawAt(time_s);
        if (labels)
            frame.labels = labelsNow();
    } else {
        std::vector<Image> draws;
        for (const double t : timing.drawTimes_s) {
            if (labels && !frame.labels && t > time_s)
                labelTheInstant();
            draws.push_back(drawAt(t));
        }
        if (labels && !frame.labels)
            labelTheInstant();
        if (!labels)
            (void)cameraNow(); // the camera of the instant, for the frame's JSON
        frame.image = exposeRows(draws, timing);
    }
    exposeAndNoise(frame.image, settings, time_s);
    return frame;
}

} // namespace

SensorFrame renderSensorFrame(Renderer& renderer, const Camera& camera, double time_s, glm::ivec2 size, bool labels)
{
    return sensorFrame(renderer, [&camera](double) { return camera; }, time_s, size, true, labels);
}

SensorFrame renderSensorFrame(Renderer& renderer, const CameraAt& cameraAt, double time_s, glm::ivec2 size, bool labels,
                              const CameraAt& simulatedAround)
{
    return sensorFrame(renderer, cameraAt, time_s, size, true, labels, simulatedAround);
}

std::vector<RigFrame> renderRigFrames(Renderer& renderer, double time_s, glm::ivec2 size, bool labels)
{
    const CameraAt platformAt = [&renderer](double t) { return renderer.sceneCameraAt(t); };
    std::vector<RigFrame> frames;
    for (const RigCamera& rig : renderer.scene().camera.rig) {
        const CameraAt cameraAt = [&platformAt, &rig](double t) { return rigCameraOf(platformAt(t), rig); };
        SensorFrame frame = sensorFrame(renderer, cameraAt, time_s, size, true, labels, platformAt);
        frames.push_back({rig.name, frame.camera, std::move(frame)});
    }
    return frames;
}

FrameLabels renderSensorLabels(Renderer& renderer, const Camera& camera, double time_s, glm::ivec2 size)
{
    return *sensorFrame(renderer, [&camera](double) { return camera; }, time_s, size, false, true).labels;
}

} // namespace swell
