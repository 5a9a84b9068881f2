// The CPU side of a frame's ground truth (swell/dataset/labels.h): the camera's
// calibration, projection, the horizon line, object classes and boxes.
#include "swell/dataset/labels.h"

#include "swell/dataset/sensor.h"
#include "swell/gpu/label_classes.h"

#include <glm/geometric.hpp>
#include <glm/gtc/matrix_transform.hpp>
#include <glm/trigonometric.hpp>
#include <glm/matrix.hpp>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <limits>

namespace swell {

namespace {

// OpenGL's camera axes (x right, y up, z back) to computer vision's (x
// right, y down, z forward).
const glm::dmat4 kVisionFromGl = glm::dmat4(glm::dvec4(1, 0, 0, 0), glm::dvec4(0, -1, 0, 0), glm::dvec4(0, 0, -1, 0),
                                            glm::dvec4(0, 0, 0, 1));

} // namespace

CameraCalibration calibrationOf(const Camera& camera, glm::ivec2 size)
{
    CameraCalibration c;
    c.size = size;
    // glm::perspective: the image's half height is tan(fov / 2) at unit
    // distance; pixels are square (the aspect is the image's).
    c.fy_px = 0.5 * double(size.y) / std::tan(0.5 * glm::radians(camera.fovY_deg));
    c.fx_px = c.fy_px;
    c.cx_px = 0.5 * double(size.x);
    c.cy_px = 0.5 * double(size.y);
    c.cameraFromWorld = kVisionFromGl * camera.viewRelativeTo(glm::dvec3(0.0));
    c.worldFromCamera = glm::inverse(c.cameraFromWorld);
    return c;
}

std::optional<glm::dvec2> projectToImage(const CameraCalibration& camera, glm::dvec3 world_m)
{
    const glm::dvec4 p = camera.cameraFromWorld * glm::dvec4(world_m, 1.0);
    if (p.z <= 0.0)
        return std::nullopt;
    const LensDistortion lens = lensOf(camera);
    const glm::dvec2 u(p.x / p.z, p.y / p.z);
    if (!insideFold(lens, u))
        return std::nullopt; // the lens shows another ray where distort() puts it
    const glm::dvec2 d = distort(lens, u);
    return glm::dvec2(camera.fx_px * d.x + camera.cx_px, camera.fy_px * d.y + camera.cy_px);
}

HorizonLine horizonOf(const CameraCalibration& camera)
{
    // A pixel p = (x, y, 1) looks along d = R^T K^-1 p (R: world to camera
    // axes, K: the intrinsics), which rises above the sea level's plane
    // where d.y > 0: d.y = (K^-T R e_y) . p, so l = K^-T R e_y is the line
    // (Hartley & Zisserman 2004, sec. 8.6: the vanishing line of a plane).
    const glm::dvec3 up = glm::dmat3(camera.cameraFromWorld) * glm::dvec3(0.0, 1.0, 0.0);
    const glm::dvec3 l(up.x / camera.fx_px, up.y / camera.fy_px,
                       up.z - up.x * camera.cx_px / camera.fx_px - up.y * camera.cy_px / camera.fy_px);
    HorizonLine h;
    const double norm = std::hypot(l.x, l.y);
    if (norm == 0.0)
        return h; // looking straight up or down: no horizon in the image
    h.line = l / norm;
    // Where it meets the border: each side's crossing inside the image.
    const double w = camera.size.x, ht = camera.size.y;
    std::vector<glm::dvec2> hits;
    auto add = [&](glm::dvec2 p) {
        if (p.x < 0.0 || p.x > w || p.y < 0.0 || p.y > ht)
            return;
        for (const glm::dvec2& q : hits)
            if (glm::distance(p, q) < 1e-9)
                return; // a corner, met from both sides
        hits.push_back(p);
    };
    const glm::dvec3 n = h.line;
    if (n.y != 0.0) {
        add({0.0, -n.z / n.y});
        add({w, -(n.x * w + n.z) / n.y});
    }
    if (n.x != 0.0) {
        add({-n.z / n.x, 0.0});
        add({-(n.y * ht + n.z) / n.x, ht});
    }
    if (hits.size() >= 2) {
        h.visible = true;
        h.from_px = hits[0];
        h.to_px = hits[1];
        if (h.from_px.x > h.to_px.x)
            std::swap(h.from_px, h.to_px);
    }
    return h;
}

std::vector<glm::dvec2> horizonCurveOf(const CameraCalibration& c, const HorizonLine& horizon)
{
    std::vector<glm::dvec2> points;
    const LensDistortion lens = lensOf(c);
    const glm::dvec3 l = horizon.line;
    if (lens.none() || (l.x == 0.0 && l.y == 0.0))
        return points;
    // Points along the pinhole line (its foot nearest the principal point,
    // then every 4 px along it both ways), each through the lens.
    const glm::dvec2 centre(c.cx_px, c.cy_px), along(-l.y, l.x);
    const glm::dvec2 foot = centre - (glm::dot(glm::dvec2(l), centre) + l.z) * glm::dvec2(l.x, l.y);
    const double reach = 2.0 * std::hypot(double(c.size.x), double(c.size.y));
    for (double t = -reach; t <= reach; t += 4.0) {
        const glm::dvec2 p = foot + t * along;
        const glm::dvec2 u((p.x - c.cx_px) / c.fx_px, (p.y - c.cy_px) / c.fy_px);
        if (!insideFold(lens, u))
            continue; // past the fold this point of the line is shown nowhere
        const glm::dvec2 d = distort(lens, u);
        const glm::dvec2 q(d.x * c.fx_px + c.cx_px, d.y * c.fy_px + c.cy_px);
        if (q.x >= 0.0 && q.y >= 0.0 && q.x <= c.size.x && q.y <= c.size.y)
            points.push_back(q);
    }
    return points;
}

double horizonDip_rad(double eyeHeight_m)
{
    constexpr double kEarthRadius_m = 6371000.0; // IUGG mean radius
    return eyeHeight_m > 0.0 ? std::acos(kEarthRadius_m / (kEarthRadius_m + eyeHeight_m)) : 0.0;
}

std::vector<glm::dvec2> trueHorizonOf(const CameraCalibration& camera, double eyeHeight_m)
{
    const double dip = horizonDip_rad(eyeHeight_m);
    const glm::dvec3 eye(camera.worldFromCamera[3]);
    // About 2 px apart at the image's centre: an azimuth step of 2 / f.
    const double step = 2.0 / std::max(camera.fx_px, 1.0);
    std::vector<glm::dvec2> points;
    for (double azimuth = 0.0; azimuth < 2.0 * 3.14159265358979323846; azimuth += step) {
        const glm::dvec3 d(std::cos(-dip) * std::cos(azimuth), std::sin(-dip), std::cos(-dip) * std::sin(azimuth));
        const std::optional<glm::dvec2> p = projectToImage(camera, eye + 1000.0 * d);
        if (p && p->x >= 0.0 && p->y >= 0.0 && p->x <= camera.size.x && p->y <= camera.size.y)
            points.push_back(*p);
    }
    return points;
}

ObjectPose objectPoseOf(const glm::dmat4& worldFromObject)
{
    ObjectPose p;
    p.worldFromObject = worldFromObject;
    p.position_m = glm::dvec3(worldFromObject[3]);
    const glm::dmat3 scaled(worldFromObject);
    p.scale = glm::length(scaled[0]);
    const glm::dmat3 r = p.scale > 0.0 ? scaled / p.scale : glm::dmat3(1.0);
    // R = Ry(yaw) Rz(pitch) Rx(roll): R e_x = (cos yaw cos pitch, sin pitch,
    // -sin yaw cos pitch); the y components of R e_y and R e_z are
    // cos pitch cos roll and -cos pitch sin roll.
    p.pitch_deg = glm::degrees(std::asin(std::clamp(r[0].y, -1.0, 1.0)));
    p.yaw_deg = glm::degrees(std::atan2(-r[0].z, r[0].x));
    p.roll_deg = glm::degrees(std::atan2(-r[2].y, r[1].y));
    // The bow's bearing on the sea: from -z towards +x.
    const double bearing = glm::degrees(std::atan2(r[0].x, -r[0].z));
    p.heading_deg = bearing < 0.0 ? bearing + 360.0 : bearing;
    return p;
}

glm::dmat4 worldFromObjectOf(glm::dvec3 position_m, double yaw_deg, double pitch_deg, double roll_deg, double scale)
{
    const glm::dmat4 yaw = glm::rotate(glm::dmat4(1.0), glm::radians(yaw_deg), glm::dvec3(0, 1, 0));
    const glm::dmat4 pitch = glm::rotate(glm::dmat4(1.0), glm::radians(pitch_deg), glm::dvec3(0, 0, 1));
    const glm::dmat4 roll = glm::rotate(glm::dmat4(1.0), glm::radians(roll_deg), glm::dvec3(1, 0, 0));
    return glm::translate(glm::dmat4(1.0), position_m) * yaw * pitch * roll * glm::scale(glm::dmat4(1.0), glm::dvec3(scale));
}

std::vector<float> zDepthOf(const FrameLabels& labels)
{
    const CameraCalibration& c = labels.camera;
    const LensDistortion lens = lensOf(c);
    std::vector<float> depth(labels.range_m.size());
    for (int y = 0; y < labels.size.y; ++y)
        for (int x = 0; x < labels.size.x; ++x) {
            const std::size_t i = std::size_t(y) * std::size_t(labels.size.x) + std::size_t(x);
            if (i >= depth.size())
                return depth;
            const glm::dvec2 u = undistort(lens, {(x + 0.5 - c.cx_px) / c.fx_px, (y + 0.5 - c.cy_px) / c.fy_px});
            depth[i] = float(double(labels.range_m[i]) / std::sqrt(1.0 + glm::dot(u, u)));
        }
    return depth;
}

std::string objectClassOf(const SceneObject& object)
{
    if (!object.className.empty())
        return object.className;
    if (object.path.starts_with(kBuiltinObjectPrefix))
        return object.path.substr(kBuiltinObjectPrefix.size());
    return std::filesystem::path(object.path).stem().string();
}

std::vector<std::string> labelClassesOf(const Scene& scene)
{
    std::vector<std::string> classes(SWELL_LABEL_FIRST_OBJECT_CLASS);
    classes[SWELL_LABEL_NONE] = "none";
    classes[SWELL_LABEL_SKY] = "sky";
    classes[SWELL_LABEL_WATER] = "water";
    classes[SWELL_LABEL_WHITECAP_FOAM] = "whitecap_foam";
    classes[SWELL_LABEL_WAKE_FOAM] = "wake_foam";
    classes[SWELL_LABEL_TERRAIN] = "terrain";
    classes[SWELL_LABEL_SURF] = "surf";
    classes[SWELL_LABEL_WET_SAND] = "wet_sand";
    for (const SceneObject& object : scene.objects) {
        const std::string name = objectClassOf(object);
        if (std::find(classes.begin() + SWELL_LABEL_FIRST_OBJECT_CLASS, classes.end(), name) == classes.end())
            classes.push_back(name);
    }
    return classes;
}

void measureObjectBoxes(FrameLabels& labels)
{
    const int w = labels.size.x, h = labels.size.y;
    for (ObjectLabel& o : labels.objects) {
        o.visiblePixels = 0;
        o.box_px = glm::ivec4(std::numeric_limits<int>::max(), std::numeric_limits<int>::max(), 0, 0);
    }
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            const std::uint16_t id = labels.instance[std::size_t(y) * std::size_t(w) + std::size_t(x)];
            if (id == 0 || id > labels.objects.size())
                continue;
            ObjectLabel& o = labels.objects[id - 1u];
            ++o.visiblePixels;
            o.box_px = glm::ivec4(std::min(o.box_px.x, x), std::min(o.box_px.y, y), std::max(o.box_px.z, x + 1),
                                  std::max(o.box_px.w, y + 1));
        }
    for (ObjectLabel& o : labels.objects)
        if (o.visiblePixels == 0)
            o.box_px = glm::ivec4(0);
}

void measureOcclusion(FrameLabels& labels)
{
    const std::size_t pixels = std::size_t(labels.size.x) * std::size_t(labels.size.y);
    for (std::size_t k = 0; k < labels.objects.size(); ++k) {
        ObjectLabel& o = labels.objects[k];
        o.amodalPixels = 0;
        if ((k + 1) * pixels <= labels.amodal.size())
            o.amodalPixels = std::count(labels.amodal.begin() + std::ptrdiff_t(k * pixels),
                                        labels.amodal.begin() + std::ptrdiff_t((k + 1) * pixels), std::uint8_t(1));
        o.occlusion = o.amodalPixels > 0 ? std::max(0.0, 1.0 - double(o.visiblePixels) / double(o.amodalPixels)) : 0.0;
    }
}

} // namespace swell
