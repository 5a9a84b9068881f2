#include "label_files.h"

#include "label_kitti.h"
#include "label_object_json.h"
#include "label_world_frame.h"

#include "swell/dataset/atomic_file.h"
#include "swell/image.h"
#include "swell/scene/spectrum.h"

#include "swell/error.h"
#include "swell/gpu/label_classes.h"

#include <fmt/format.h>
#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>
#include <nlohmann/json.hpp>

#include <bit>
#include <cmath>
#include <cstring>

#include <unistd.h>

namespace swell::app {

namespace fs = std::filesystem;

namespace {

fs::path besides(const fs::path& colour, const std::string& suffix)
{
    return colour.parent_path() / fmt::format("{}{}", colour.stem().string(), suffix);
}

// A colour per class, and objects tinted by instance so that two boats differ.
std::array<std::uint8_t, 3> previewColour(std::uint16_t semantic, std::uint16_t instance)
{
    switch (semantic) {
    case SWELL_LABEL_NONE: return {0, 0, 0};
    case SWELL_LABEL_SKY: return {120, 170, 230};
    case SWELL_LABEL_WATER: return {20, 60, 120};
    case SWELL_LABEL_WHITECAP_FOAM: return {240, 240, 240};
    case SWELL_LABEL_WAKE_FOAM: return {250, 200, 60};
    case SWELL_LABEL_TERRAIN: return {110, 90, 60};
    case SWELL_LABEL_SURF: return {170, 240, 235};
    case SWELL_LABEL_WET_SAND: return {70, 55, 35};
    default: break;
    }
    // Golden-angle hues: neighbouring ids far apart.
    const double hue = std::fmod(double(instance) * 137.508, 360.0) / 60.0;
    const double x = 1.0 - std::abs(std::fmod(hue, 2.0) - 1.0);
    const int sector = int(hue);
    const double rgb[6][3] = {{1, x, 0}, {x, 1, 0}, {0, 1, x}, {0, x, 1}, {x, 0, 1}, {1, 0, x}};
    const double* c = rgb[sector % 6];
    return {std::uint8_t(60 + 195 * c[0]), std::uint8_t(60 + 195 * c[1]), std::uint8_t(60 + 195 * c[2])};
}


} // namespace

void writePngAtomically(const Image& image, const fs::path& path)
{
    const fs::path temp = path.parent_path() / fmt::format(".{}.{}.tmp", path.filename().string(), ::getpid());
    writePng(image, temp);
    std::error_code error;
    fs::rename(temp, path, error);
    if (error) {
        fs::remove(temp, error);
        throw Error(fmt::format("cannot write {}: {}", path.string(), error.message()));
    }
}

std::string npyBytes(const void* data, std::size_t bytes, const std::string& descr, const std::vector<int>& shape)
{
    std::string dims; // "H, W", or "N," for one dimension (a Python tuple)
    for (std::size_t i = 0; i < shape.size(); ++i)
        dims += fmt::format("{}{}", i ? ", " : "", shape[i]);
    if (shape.size() == 1)
        dims += ",";
    std::string header = fmt::format("{{'descr': '{}', 'fortran_order': False, 'shape': ({}), }}", descr, dims);
    // Magic, version 1.0, the header's length, the header padded with
    // spaces to a multiple of 64 bytes in all and ended by a newline.
    const std::size_t prefix = 10;
    const std::size_t total = (prefix + header.size() + 1 + 63) / 64 * 64;
    header.append(total - prefix - header.size() - 1, ' ');
    header += '\n';
    std::string out("\x93NUMPY\x01\x00", 8);
    out += char(header.size() & 0xff);
    out += char(header.size() >> 8);
    out += header;
    out.append(static_cast<const char*>(data), bytes);
    return out;
}

Json matrixJson(const glm::dmat4& m)
{
    Json rows = Json::array();
    for (int r = 0; r < 4; ++r)
        rows.push_back({m[0][r], m[1][r], m[2][r], m[3][r]});
    return rows;
}

fs::path rigCameraPath(const fs::path& colour, const std::string& camera)
{
    if (camera.empty())
        return colour;
    return colour.parent_path() / fmt::format("{}.{}{}", colour.stem().string(), camera, colour.extension().string());
}

std::vector<fs::path> labelFilePaths(const fs::path& colour)
{
    return {besides(colour, ".range.npy"),    besides(colour, ".normal.npy"), besides(colour, ".semantic.npy"),
            besides(colour, ".instance.npy"), besides(colour, ".depth.npy"),  besides(colour, ".labels.png"),
            besides(colour, ".amodal.npy"),   besides(colour, ".kitti.txt"),  besides(colour, ".kitti_calib.txt"),
            besides(colour, ".json")};
}

void writeLabelArrays(const FrameLabels& swellLabels, const fs::path& colour, LabelWorldFrame frame)
{
    const FrameLabels labels = inWorldFrame(swellLabels, frame);
    const std::vector<fs::path> paths = labelFilePaths(colour);
    const int w = labels.size.x, h = labels.size.y;
    const std::size_t pixels = std::size_t(w) * std::size_t(h);
    static_assert(std::endian::native == std::endian::little, "the .npy descriptors say little-endian");
    writeFileAtomically(paths[0], npyBytes(labels.range_m.data(), pixels * sizeof(float), "<f4", {h, w}));
    writeFileAtomically(paths[1], npyBytes(labels.normal.data(), pixels * sizeof(glm::vec3), "<f4", {h, w, 3}));
    writeFileAtomically(paths[2], npyBytes(labels.semantic.data(), pixels * 2, "<u2", {h, w}));
    writeFileAtomically(paths[3], npyBytes(labels.instance.data(), pixels * 2, "<u2", {h, w}));
    const std::vector<float> depth = zDepthOf(labels);
    writeFileAtomically(paths[4], npyBytes(depth.data(), pixels * sizeof(float), "<f4", {h, w}));

    Image preview;
    preview.width = w;
    preview.height = h;
    preview.rgba.resize(pixels * 4);
    for (std::size_t i = 0; i < pixels; ++i) {
        const auto c = previewColour(labels.semantic[i], labels.instance[i]);
        std::memcpy(&preview.rgba[4 * i], c.data(), 3);
        preview.rgba[4 * i + 3] = 255;
    }
    writePngAtomically(preview, paths[5]);
    // Each object's amodal mask, in the JSON's object order: (N, H, W).
    writeFileAtomically(paths[6], npyBytes(labels.amodal.data(), labels.amodal.size(), "|u1",
                                           {int(labels.objects.size()), h, w}));
    const glm::dvec3 up = frameFromSwell(frame) * glm::dvec3(0.0, 1.0, 0.0);
    writeFileAtomically(paths[7], kittiLabels(labels, up));
    writeFileAtomically(paths[8], kittiCalibration(labels, up));
}

namespace {

// An object's pose (docs/LABELS.md, "objects"): in world axes, and its
// model's axes in the camera's (OpenCV's: x right, y down, z forward).
Json poseJson(const ObjectPose& p, const CameraCalibration& c)
{
    const glm::dmat4 cameraFromObject = c.cameraFromWorld * p.worldFromObject;
    const glm::dvec3 inCamera(cameraFromObject[3]);
    return {{"position_m", {p.position_m.x, p.position_m.y, p.position_m.z}},
            {"yaw_deg", p.yaw_deg},
            {"pitch_deg", p.pitch_deg},
            {"roll_deg", p.roll_deg},
            {"heading_deg", p.heading_deg},
            {"scale", p.scale},
            {"world_from_object", matrixJson(p.worldFromObject)},
            {"camera_position_m", {inCamera.x, inCamera.y, inCamera.z}},
            {"camera_from_object", matrixJson(cameraFromObject)}};
}

} // namespace

Json frameJson(const FrameLabels& swellLabels, const Scene& scene, double time_s, double significantHeight_m,
               const fs::path& colour)
{
    const FrameLabels labels = inWorldFrame(swellLabels, scene.labels.worldFrame);
    Json j;
    j["image"] = colour.filename().string();
    j["world_frame"] = worldFrameName(scene.labels.worldFrame);
    j["size"] = {labels.size.x, labels.size.y};
    j["time_s"] = time_s;
    const CameraCalibration& c = labels.camera;
    j["camera"] = {{"model", "pinhole"},
                   {"fx_px", c.fx_px},
                   {"fy_px", c.fy_px},
                   {"cx_px", c.cx_px},
                   {"cy_px", c.cy_px},
                   {"distortion_model", c.lensModel == LensModel::KannalaBrandt ? "kannala-brandt" : "brown-conrady"},
                   // OpenCV's order for each model: cv2.fisheye's D, or the
                   // distCoeffs of cv2.projectPoints.
                   {"distortion", c.lensModel == LensModel::KannalaBrandt ? Json{c.k1, c.k2, c.k3, c.k4}
                                                                           : Json{c.k1, c.k2, c.p1, c.p2, c.k3}},
                   {"camera_from_world", matrixJson(c.cameraFromWorld)},
                   {"world_from_camera", matrixJson(c.worldFromCamera)}};
    Json horizon = {{"line", {labels.horizon.line.x, labels.horizon.line.y, labels.horizon.line.z}},
                    {"visible", labels.horizon.visible}};
    if (labels.horizon.visible) {
        horizon["from_px"] = {labels.horizon.from_px.x, labels.horizon.from_px.y};
        horizon["to_px"] = {labels.horizon.to_px.x, labels.horizon.to_px.y};
    }
    if (!labels.horizon.curve_px.empty()) {
        Json curve = Json::array();
        for (const glm::dvec2& p : labels.horizon.curve_px)
            curve.push_back({p.x, p.y});
        horizon["curve_px"] = curve;
    }
    // The true horizon of a round Earth for the camera's height.
    horizon["true_dip_deg"] = labels.trueHorizonDip_deg;
    Json truePoints = Json::array();
    for (const glm::dvec2& p : labels.trueHorizon_px)
        truePoints.push_back({p.x, p.y});
    horizon["true_px"] = truePoints;
    j["horizon"] = horizon;
    // Where the water meets the land (swell::measureShoreline); a corner's
    // water point with no finite range is null (JSON has no NaN).
    Json shoreline = Json::array();
    for (const ShoreLine& line : labels.shoreline) {
        Json px = Json::array(), m = Json::array();
        for (const glm::dvec2& p : line.points_px)
            px.push_back({p.x, p.y});
        for (const glm::dvec3& p : line.points_m)
            m.push_back(std::isfinite(p.x) ? Json{p.x, p.y, p.z} : Json(nullptr));
        shoreline.push_back({{"points_px", px}, {"points_m", m}});
    }
    j["shoreline"] = shoreline;
    Json classes = Json::object();
    for (std::size_t i = 0; i < labels.classes.size(); ++i)
        if (!labels.classes[i].empty())
            classes[std::to_string(i)] = labels.classes[i];
    j["classes"] = classes;
    Json objects = Json::array();
    for (const ObjectLabel& o : labels.objects) {
        Json box3d = Json::array();
        for (const glm::dvec3& p : o.box3d_m)
            box3d.push_back({p.x, p.y, p.z});
        objects.push_back({{"instance", o.instance},
                           {"class", o.className},
                           {"class_id", o.semanticClass},
                           {"visible_pixels", o.visiblePixels},
                           {"box_px", {o.box_px.x, o.box_px.y, o.box_px.z, o.box_px.w}},
                           {"box3d_m", box3d},
                           {"pose", poseJson(o.pose, c)},
                           {"velocity", velocityJson(o, c)},
                           {"amodal_pixels", o.amodalPixels},
                           {"occlusion", o.occlusion},
                           {"truncation", o.truncation}});
    }
    j["objects"] = objects;
    Json sea = {{"level_m", scene.sea.level_m}, {"significant_wave_height_m", significantHeight_m}};
    if (scene.sea.wind) {
        sea["wind_speed_mps"] = scene.sea.wind->windSpeed_mps;
        sea["wind_direction_deg"] = scene.sea.wind->windDirection_deg;
        sea["fetch_km"] = scene.sea.wind->fetch_km;
        // The peak period of the wind sea's JONSWAP spectrum (and the swell's).
        const SeaSpectrum spectrum(*scene.sea.wind);
        const std::span<const SeaComponent> parts = spectrum.components();
        if (!parts.empty())
            sea["peak_period_s"] = 2.0 * 3.14159265358979323846 / parts[0].spectrum.peakFrequency_radps;
        if (parts.size() > 1)
            sea["swell_peak_period_s"] = 2.0 * 3.14159265358979323846 / parts[1].spectrum.peakFrequency_radps;
    }
    const glm::dvec3 sunInSwell = glm::normalize(scene.sun.direction);
    const glm::dvec3 sun = frameFromSwell(scene.labels.worldFrame) * sunInSwell;
    sea["sun_direction"] = {sun.x, sun.y, sun.z};
    sea["sun_elevation_deg"] = glm::degrees(std::asin(sunInSwell.y));
    j["sea"] = sea;
    return j;
}

void writeFrameJson(const Json& json, const fs::path& colour)
{
    writeFileAtomically(labelFilePaths(colour).back(), json.dump(2) + "\n");
}

void writeLabelFiles(const FrameLabels& labels, const Scene& scene, double time_s, double significantHeight_m,
                     const fs::path& colour)
{
    writeLabelArrays(labels, colour, scene.labels.worldFrame);
    writeFrameJson(frameJson(labels, scene, time_s, significantHeight_m, colour), colour);
}

} // namespace swell::app
