// Brown-Conrady's and Kannala-Brandt's lenses (swell/dataset/sensor.h), and which lenses a frame
// can be drawn through (core/lens_fold.h).
#include "swell/dataset/sensor.h"

#include "core/lens_fold.h"
#include "swell/error.h"

#include <fmt/format.h>
#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

namespace swell {

LensDistortion lensOf(const CameraSettings& c)
{
    if (c.lens == LensModel::KannalaBrandt)
        return {c.fisheyeK1, c.fisheyeK2, c.fisheyeK3, 0.0, 0.0, c.fisheyeK4, LensModel::KannalaBrandt};
    return {c.distortionK1, c.distortionK2, c.distortionK3, c.distortionP1, c.distortionP2};
}

LensDistortion lensOf(const CameraCalibration& c) { return {c.k1, c.k2, c.k3, c.p1, c.p2, c.k4, c.lensModel}; }

void setLens(CameraCalibration& c, const LensDistortion& l)
{
    c.lensModel = l.model;
    c.k1 = l.k1;
    c.k2 = l.k2;
    c.k3 = l.k3;
    c.k4 = l.k4;
    c.p1 = l.p1;
    c.p2 = l.p2;
}

double fisheyeThetaD(const LensDistortion& l, double theta)
{
    const double t2 = theta * theta;
    return theta * (1.0 + t2 * (l.k1 + t2 * (l.k2 + t2 * (l.k3 + t2 * l.k4))));
}

namespace {

// d theta_d / d theta: where it is positive the fisheye keeps the image's
// orientation.
double fisheyeSlope(const LensDistortion& l, double theta)
{
    const double t2 = theta * theta;
    return 1.0 + t2 * (3.0 * l.k1 + t2 * (5.0 * l.k2 + t2 * (7.0 * l.k3 + t2 * 9.0 * l.k4)));
}

} // namespace

CameraCalibration sensorCalibrationOf(const Camera& camera, const LensDistortion& lens, glm::ivec2 size)
{
    CameraCalibration c = calibrationOf(camera, size);
    setLens(c, lens);
    if (lens.model == LensModel::KannalaBrandt) {
        // The field's borders at fovY / 2 from the axis: theta_d(fovY / 2)
        // focal lengths from the centre, half the image's height.
        c.fy_px = 0.5 * double(size.y) / fisheyeThetaD(lens, 0.5 * glm::radians(camera.fovY_deg));
        c.fx_px = c.fy_px;
    }
    return c;
}

glm::dvec2 distort(const LensDistortion& l, glm::dvec2 u)
{
    if (l.model == LensModel::KannalaBrandt) {
        const double r = glm::length(u);
        if (r == 0.0)
            return u;
        return u * (fisheyeThetaD(l, std::atan(r)) / r);
    }
    const double x = u.x, y = u.y, r2 = x * x + y * y;
    const double radial = 1.0 + r2 * (l.k1 + r2 * (l.k2 + r2 * l.k3));
    return {x * radial + 2.0 * l.p1 * x * y + l.p2 * (r2 + 2.0 * x * x),
            y * radial + l.p1 * (r2 + 2.0 * y * y) + 2.0 * l.p2 * x * y};
}

glm::dvec2 undistort(const LensDistortion& l, glm::dvec2 d)
{
    if (l.model == LensModel::KannalaBrandt) {
        // theta from theta_d by Newton's method, from theta = theta_d.
        const double thetaD = glm::length(d);
        if (thetaD == 0.0)
            return d;
        double theta = thetaD;
        for (int i = 0; i < 50; ++i) {
            const double step = (fisheyeThetaD(l, theta) - thetaD) / fisheyeSlope(l, theta);
            theta -= step;
            if (!(std::abs(step) > 1e-14))
                break;
        }
        // A ray at 90 degrees or more has no place on the pinhole plane:
        // NaN, which no caller takes for a ray (lensFoldProblem refuses it).
        if (!(theta >= 0.0 && theta < 0.5 * 3.14159265358979323846))
            return glm::dvec2(std::numeric_limits<double>::quiet_NaN());
        return d * (std::tan(theta) / thetaD);
    }
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
    if (l.model == LensModel::KannalaBrandt) {
        // A radial map d = g(r) u / r has the determinant g'(r) g(r) / r;
        // with g(r) = theta_d(atan r), g'(r) = theta_d'(theta) / (1 + r^2).
        const double r = glm::length(u), theta = std::atan(r);
        const double gOverR = r == 0.0 ? 1.0 : fisheyeThetaD(l, theta) / r;
        return fisheyeSlope(l, theta) / (1.0 + r * r) * gOverR;
    }
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

// A fisheye's own rule: theta_d grows with theta from the axis out to the
// ray of the image's farthest pixel, which must lie under 90 degrees from
// the axis (the pinhole frame holds no ray at 90 degrees or more).
std::string fisheyeFieldProblem(const LensDistortion& lens, const CameraCalibration& c, double fovY_deg,
                                const std::string& image)
{
    double farthest = 0.0; // theta_d of the farthest border pixel
    for (const glm::dvec2& px : borderPixels(c.size))
        farthest = std::max(farthest, glm::length(normalised(c, px)));
    // Out to the field's border and the farthest pixel, whichever is farther,
    // in steps of 1/4096 of a right angle (a dip narrower passes).
    const double halfField = 0.5 * glm::radians(fovY_deg), quarter = 0.5 * 3.14159265358979323846;
    constexpr int kSteps = 4096;
    for (int i = 1; i <= kSteps; ++i) {
        const double theta = quarter * double(i) / kSteps;
        if (!(fisheyeSlope(lens, theta) > 0.0))
            return fmt::format("theta_d stops growing with theta at {:.1f} degrees from the axis, inside the field of {}: "
                               "the lens folds the image over (two places of the scene would meet in one pixel)",
                               glm::degrees(theta), image);
        if (theta >= halfField && fisheyeThetaD(lens, theta) >= farthest)
            return {};
    }
    return fmt::format("the rays of {} reach 90 degrees from the axis and more (its corners); a fisheye is drawn "
                       "up to about {:g} degrees across the diagonal",
                       image, kFisheyeDiagonalField_deg);
}

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
    if (lens.model == LensModel::KannalaBrandt)
        if (std::string problem = fisheyeFieldProblem(lens, c, fovY_deg, image); !problem.empty())
            return problem;
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
                           "{}x{} pixels, over {} times the image's side ({})",
                           image, wide.x, wide.y, kMaxPinholeOverOutput,
                           lens.model == LensModel::KannalaBrandt
                               ? fmt::format("the field is {:.1f} degrees across the diagonal; a fisheye is drawn "
                                             "up to about {:g}",
                                             2.0 * glm::degrees(std::atan(std::hypot(reach.x, reach.y))),
                                             kFisheyeDiagonalField_deg)
                               : std::string("the lens nearly folds"));
    return {};
}

} // namespace detail

std::string lensProblem(const LensDistortion& lens, double fovY_deg, glm::ivec2 size)
{
    Camera camera;
    camera.fovY_deg = fovY_deg;
    // A fisheye whose theta_d falls before the field's border gets a
    // meaningless focal length here; lensFoldProblem's walk refuses it first.
    return detail::lensFoldProblem(lens, sensorCalibrationOf(camera, lens, size), fovY_deg);
}

void checkLens(const Scene& scene, glm::ivec2 size, double fovY_deg, const std::filesystem::path& sceneFile)
{
    const LensDistortion lens = lensOf(scene.camera);
    const std::string problem = lensProblem(lens, fovY_deg, size);
    if (problem.empty())
        return;
    // Named by the coefficients the scene sets, at the first one's place
    // (a fisheye's camera.lens named first, its place where no coefficient
    // is set).
    const bool fisheye = lens.model == LensModel::KannalaBrandt;
    struct Coefficient {
        const char* key;
        double value;
    };
    const std::vector<Coefficient> coefficients =
        fisheye ? std::vector<Coefficient>{{"camera.fisheye_k1", lens.k1},
                                           {"camera.fisheye_k2", lens.k2},
                                           {"camera.fisheye_k3", lens.k3},
                                           {"camera.fisheye_k4", lens.k4}}
                : std::vector<Coefficient>{{"camera.distortion_k1", lens.k1},
                                           {"camera.distortion_k2", lens.k2},
                                           {"camera.distortion_k3", lens.k3},
                                           {"camera.distortion_p1", lens.p1},
                                           {"camera.distortion_p2", lens.p2}};
    std::vector<std::string> set;
    if (fisheye)
        set.push_back("camera.lens = \"kannala_brandt\"");
    std::optional<SourcePlace> place;
    for (const auto& [key, value] : coefficients) {
        if (value == 0.0)
            continue;
        set.push_back(fmt::format("{} = {:g}", key, value));
        if (const auto at = scene.keyPlaces.find(key); !place && at != scene.keyPlaces.end())
            place = at->second;
    }
    if (const auto at = scene.keyPlaces.find("camera.lens"); fisheye && !place && at != scene.keyPlaces.end())
        place = at->second;
    const std::string keys = set.size() == 1 ? set[0]
                                             : fmt::format("{} and {}", fmt::join(set.begin(), set.end() - 1, ", "),
                                                           set.back());
    throw InputError(place.value_or(SourcePlace{sceneFile.empty() ? std::string("camera") : sceneFile.string()}),
                     fmt::format("{}: {}; {} or narrow the field (docs/SCENE.md, \"The lens\")", keys, problem,
                                 fisheye ? "change the fisheye's coefficients" : set.size() == 1 ? "weaken it" : "weaken them"));
}

} // namespace swell
