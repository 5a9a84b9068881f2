#include "label_kitti.h"

#include <fmt/format.h>
#include <glm/geometric.hpp>
#include <glm/matrix.hpp>

#include <algorithm>
#include <cctype>
#include <cmath>

namespace swell::app {

namespace {

constexpr double kPi = 3.14159265358979323846;

double wrapToPi(double angle_rad)
{
    const double wrapped = std::remainder(angle_rad, 2.0 * kPi);
    return wrapped <= -kPi ? wrapped + 2.0 * kPi : wrapped;
}

// KITTI's occluded column from the share hidden: the devkit names the
// states (0 fully visible, 1 partly occluded, 2 largely occluded) without
// numbers; a share under 1% is taken as none, half or more as largely.
int occludedState(double occlusion)
{
    if (occlusion < 0.01)
        return 0;
    return occlusion < 0.5 ? 1 : 2;
}

// A class name as one column: spaces would split it.
std::string kittiType(std::string name)
{
    std::replace_if(name.begin(), name.end(), [](char c) { return std::isspace(static_cast<unsigned char>(c)); }, '_');
    return name;
}

// "name: m00 m01 ... " of a matrix's first `rows` rows, `cols` columns.
std::string matrixLine(const char* name, const glm::dmat4& m, int rows, int cols)
{
    std::string line = name;
    line += ':';
    for (int r = 0; r < rows; ++r)
        for (int c = 0; c < cols; ++c)
            line += fmt::format(" {:.12e}", m[c][r]);
    return line + "\n";
}

// One object's line: its model box (box3d_m's corners 0 and 7 taken back to
// its model axes) as KITTI's box in the levelled camera.
std::string objectLine(const ObjectLabel& o, const glm::dmat4& levelFromWorld)
{
    const glm::dmat4 objectFromWorld = glm::inverse(o.pose.worldFromObject);
    const glm::dvec3 lo(objectFromWorld * glm::dvec4(o.box3d_m[0], 1.0));
    const glm::dvec3 hi(objectFromWorld * glm::dvec4(o.box3d_m[7], 1.0));
    const double s = o.pose.scale;
    const double height = (hi.y - lo.y) * s, width = (hi.z - lo.z) * s, length = (hi.x - lo.x) * s;
    const glm::dvec3 bottomCentre(0.5 * (lo.x + hi.x), lo.y, 0.5 * (lo.z + hi.z));
    const glm::dmat4 levelFromObject = levelFromWorld * o.pose.worldFromObject;
    const glm::dvec3 location(levelFromObject * glm::dvec4(bottomCentre, 1.0));
    // rotation_y turns KITTI's object x (its length) to (cos ry, 0, -sin ry):
    // the model's +x (the bow) seen from above.
    const glm::dvec3 bow = glm::dmat3(levelFromObject) * glm::dvec3(1.0, 0.0, 0.0);
    const double rotationY = std::atan2(-bow.z, bow.x);
    const double alpha = wrapToPi(rotationY - std::atan2(location.x, location.z));
    // The devkit's columns: type truncated occluded alpha, bbox (4), h w l, x y z, rotation_y.
    return fmt::format("{} {:.6f} {} {:.6f} {:.2f} {:.2f} {:.2f} {:.2f} {:.6f} {:.6f} {:.6f} {:.6f} {:.6f} {:.6f} "
                       "{:.6f}\n",
                       kittiType(o.className), std::clamp(o.truncation, 0.0, 1.0), occludedState(o.occlusion), alpha,
                       double(o.box_px.x), double(o.box_px.y), double(o.box_px.z), double(o.box_px.w), height, width,
                       length, location.x, location.y, location.z, rotationY);
}

} // namespace

glm::dmat4 levelFromWorld(const CameraCalibration& camera, glm::dvec3 up)
{
    const glm::dmat3 worldFromCamera(camera.worldFromCamera);
    const glm::dvec3 down = -up;
    const auto level = [up](glm::dvec3 v) { return v - glm::dot(v, up) * up; };
    glm::dvec3 ahead = level(worldFromCamera * glm::dvec3(0.0, 0.0, 1.0));
    if (glm::length(ahead) < 1e-9) // looking straight up or down: the image's down, levelled
        ahead = level(worldFromCamera * glm::dvec3(0.0, 1.0, 0.0));
    ahead = glm::normalize(ahead);
    const glm::dvec3 right = glm::cross(down, ahead);
    glm::dmat3 rows; // columns of the transpose: the level axes as rows
    rows[0] = glm::dvec3(right.x, down.x, ahead.x);
    rows[1] = glm::dvec3(right.y, down.y, ahead.y);
    rows[2] = glm::dvec3(right.z, down.z, ahead.z);
    const glm::dvec3 eye(camera.worldFromCamera[3]);
    glm::dmat4 m(rows);
    m[3] = glm::dvec4(-(rows * eye), 1.0);
    return m;
}

std::string kittiLabels(const FrameLabels& labels, glm::dvec3 up)
{
    const glm::dmat4 level = levelFromWorld(labels.camera, up);
    std::string out;
    for (const ObjectLabel& o : labels.objects)
        if (o.amodalPixels > 0)
            out += objectLine(o, level);
    return out;
}

std::string kittiCalibration(const FrameLabels& labels, glm::dvec3 up)
{
    const CameraCalibration& c = labels.camera;
    glm::dmat4 k(1.0);
    k[0][0] = c.fx_px;
    k[1][1] = c.fy_px;
    k[2][0] = c.cx_px;
    k[2][1] = c.cy_px;
    const glm::dmat4 cameraFromLevel = c.cameraFromWorld * glm::inverse(levelFromWorld(c, up));
    // K [R | 0]: the levelled camera shares the eye, so no translation.
    const glm::dmat4 turn{glm::dmat3(cameraFromLevel)};
    const glm::dmat4 p = k * turn;
    std::string out;
    for (const char* name : {"P0", "P1", "P2", "P3"})
        out += matrixLine(name, p, 3, 4);
    out += matrixLine("R0_rect", glm::dmat4(1.0), 3, 3);
    out += matrixLine("Tr_velo_to_cam", levelFromWorld(c, up), 3, 4);
    out += matrixLine("Tr_imu_to_velo", glm::dmat4(1.0), 3, 4);
    return out;
}

} // namespace swell::app
