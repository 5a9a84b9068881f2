// Brown-Conrady lens distortion (swell/dataset/sensor.h), and which lenses a frame
// can be drawn through (core/lens_fold.h).
#include "swell/dataset/sensor.h"

#include "core/lens_fold.h"
#include "swell/error.h"

#include <fmt/format.h>
#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>

#include <algorithm>
#include <cmath>
#include <vector>

namespace swell {

LensDistortion lensOf(const CameraSettings& c)
{
    return {c.distortionK1, c.distortionK2, c.distortionK3, c.distortionP1, c.distortionP2};
}

glm::dvec2 distort(const LensDistortion& l, glm::dvec2 u)
{
    const double x = u.x, y = u.y, r2 = x * x + y * y;
    const double radial = 1.0 + r2 * (l.k1 + r2 * (l.k2 + r2 * l.k3));
    return {x * radial + 2.0 * l.p1 * x * y + l.p2 * (r2 + 2.0 * x * x),
            y * radial + l.p1 * (r2 + 2.0 * y * y) + 2.0 * l.p2 * x * y};
}

glm::dvec2 undistort(const LensDistortion& l, glm::dvec2 d)
{
    // x = (x_d - tangential(x)) / radial(x), iterated from x = x_d (as
    // OpenCV's undistortPoints does).
    glm::dvec2 u = d;
    for (int i = 0; i < 50; ++i) {
        const double x = u.x, y = u.y, r2 = x * x + y * y;
        const double radial = 1.0 + r2 * (l.k1 + r2 * (l.k2 + r2 * l.k3));
        const glm::dvec2 tangential(2.0 * l.p1 * x * y + l.p2 * (r2 + 2.0 * x * x),
                                    l.p1 * (r2 + 2.0 * y * y) + 2.0 * l.p2 * x * y);
        const glm::dvec2 next = (d - tangential) / radial;
        const double step = glm::distance(next, u);
        u = next;
        if (step < 1e-12)
            break;
    }
    return u;
}

namespace {

// The determinant of distort()'s Jacobian at u: positive where the lens
// keeps the image's orientation, zero where it folds.
double jacobian(const LensDistortion& l, glm::dvec2 u)
{
    const double x = u.x, y = u.y, r2 = x * x + y * y;
    const double radial = 1.0 + r2 * (l.k1 + r2 * (l.k2 + r2 * l.k3));
    const double dRadial = l.k1 + r2 * (2.0 * l.k2 + 3.0 * r2 * l.k3); // d radial / d r^2
    const double xx = radial + 2.0 * x * x * dRadial + 2.0 * l.p1 * y + 6.0 * l.p2 * x;
    const double xy = 2.0 * x * y * dRadial + 2.0 * l.p1 * x + 2.0 * l.p2 * y;
    const double yy = radial + 2.0 * y * y * dRadial + 6.0 * l.p1 * y + 2.0 * l.p2 * x;
    return xx * yy - xy * xy;
}

// Steps along a ray from the centre at which insideFold() looks at the
// Jacobian: a point past the fold by more than 1/256 of its way out is found.
constexpr int kInsideFoldSteps = 256;

} // namespace

bool insideFold(const LensDistortion& lens, glm::dvec2 u)
{
    if (lens.none())
        return true;
    for (int i = 1; i <= kInsideFoldSteps; ++i)
        if (!(jacobian(lens, u * (double(i) / kInsideFoldSteps)) > 0.0))
            return false;
    return true;
}

namespace detail {

namespace {

// Every pixel corner along the output's border, in pixels.
std::vector<glm::dvec2> borderPixels(glm::ivec2 size)
{
    std::vector<glm::dvec2> points;
    points.reserve(2 * std::size_t(size.x + size.y) + 4);
    for (int x = 0; x <= size.x; ++x) {
        points.emplace_back(x, 0.0);
        points.emplace_back(x, size.y);
    }
    for (int y = 0; y <= size.y; ++y) {
        points.emplace_back(0.0, y);
        points.emplace_back(size.x, y);
    }
    return points;
}

glm::dvec2 normalised(const CameraCalibration& c, glm::dvec2 px)
{
    return {(px.x - c.cx_px) / c.fx_px, (px.y - c.cy_px) / c.fy_px};
}

// The pinhole frame holding rays that reach `h` focal lengths out on each axis.
glm::ivec2 pinholeHolding(glm::dvec2 h, const CameraCalibration& c)
{
    const double f = kPinholeScale * c.fy_px;
    return {2 * int(std::ceil(h.x * f + 1.0)), 2 * int(std::ceil(h.y * f + 1.0))};
}

// Steps along each ray from the centre out to a border pixel's ray at which
// the Jacobian is looked at (a fold narrower than 1/64 of the way passes).
constexpr int kFoldSteps = 64;

} // namespace

glm::ivec2 pinholeSize(const LensDistortion& lens, const CameraCalibration& c)
{
    glm::dvec2 reach(0.0);
    for (const glm::dvec2& px : borderPixels(c.size))
        reach = glm::max(reach, glm::abs(undistort(lens, normalised(c, px))));
    return pinholeHolding(reach, c);
}

std::string lensFoldProblem(const LensDistortion& lens, const CameraCalibration& c, double fovY_deg)
{
    if (lens.none())
        return {};
    const std::string image = fmt::format("a {}x{} image at {:g} degrees of vertical field", c.size.x, c.size.y, fovY_deg);
    glm::dvec2 reach(0.0);
    for (const glm::dvec2& px : borderPixels(c.size)) {
        const glm::dvec2 d = normalised(c, px);
        const glm::dvec2 u = undistort(lens, d);
        if (!(glm::distance(distort(lens, u), d) <= 1e-9 * (1.0 + glm::length(d))))
            return fmt::format("no ray reaches the border of {} at pixel ({:g}, {:g}): the lens folds the image "
                               "back before it",
                               image, px.x, px.y);
        for (int i = 1; i <= kFoldSteps; ++i)
            if (!(jacobian(lens, u * (double(i) / kFoldSteps)) > 0.0))
                return fmt::format("the lens folds {} over between its centre and pixel ({:g}, {:g}) of its "
                                   "border: two places of the scene would meet in one pixel",
                                   image, px.x, px.y);
        reach = glm::max(reach, glm::abs(u));
    }
    const glm::ivec2 wide = pinholeHolding(reach, c);
    if (wide.x > kMaxPinholeOverOutput * c.size.x || wide.y > kMaxPinholeOverOutput * c.size.y)
        return fmt::format("the rays of {} reach so far out that the pinhole frame drawn to hold them would be "
                           "{}x{} pixels, over {} times the image's side (the lens nearly folds)",
                           image, wide.x, wide.y, kMaxPinholeOverOutput);
    return {};
}

} // namespace detail

std::string lensProblem(const LensDistortion& lens, double fovY_deg, glm::ivec2 size)
{
    Camera camera;
    camera.fovY_deg = fovY_deg;
    CameraCalibration c = calibrationOf(camera, size);
    return detail::lensFoldProblem(lens, c, fovY_deg);
}

void checkLens(const Scene& scene, glm::ivec2 size, double fovY_deg, const std::filesystem::path& sceneFile)
{
    const LensDistortion lens = lensOf(scene.camera);
    const std::string problem = lensProblem(lens, fovY_deg, size);
    if (problem.empty())
        return;
    // Named by the coefficients the scene sets, at the first one's place.
    const struct {
        const char* key;
        double value;
    } coefficients[] = {{"camera.distortion_k1", lens.k1}, {"camera.distortion_k2", lens.k2},
                        {"camera.distortion_k3", lens.k3}, {"camera.distortion_p1", lens.p1},
                        {"camera.distortion_p2", lens.p2}};
    std::vector<std::string> set;
    std::optional<SourcePlace> place;
    for (const auto& [key, value] : coefficients) {
        if (value == 0.0)
            continue;
        set.push_back(fmt::format("{} = {:g}", key, value));
        if (const auto at = scene.keyPlaces.find(key); !place && at != scene.keyPlaces.end())
            place = at->second;
    }
    const std::string keys = set.size() == 1 ? set[0]
                                             : fmt::format("{} and {}", fmt::join(set.begin(), set.end() - 1, ", "),
                                                           set.back());
    throw InputError(place.value_or(SourcePlace{sceneFile.empty() ? std::string("camera") : sceneFile.string()}),
                     fmt::format("{}: {}; weaken {} or narrow the field (docs/SCENE.md, \"The lens\")", keys, problem,
                                 set.size() == 1 ? "it" : "them"));
}

} // namespace swell
