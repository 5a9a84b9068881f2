// The camera's rows of the scene parameter table (parameter_table_camera.h).
#include "core/parameter_table_camera.h"

#include "core/parameter_fields.h"
#include "swell/scene/scene.h"

#include <array>
#include <string_view>

namespace swell::detail {

namespace {

using namespace parameter_fields;
using K = ParameterKind;
using L = ParameterList;
using E = ParameterEffect;

// The TOML names of the lens models, indexed by the enum's value.
constexpr std::array<std::string_view, 2> kLensModels{"brown_conrady", "kannala_brandt"};
static_assert(static_cast<int>(LensModel::BrownConrady) == 0 && static_cast<int>(LensModel::KannalaBrandt) == 1);

} // namespace

std::vector<Parameter> cameraParameters()
{
    return {
        // [camera]
        at([](auto& s, std::size_t) -> auto& { return s.camera.position_m; },
           {.key = "camera.position_m", .kind = K::Vector3, .unit = "m", .min = -kWorldLimit_m, .max = kWorldLimit_m,
            .sliderMin = -1000.0, .sliderMax = 1000.0, .description = "world position [x, y, z]; y is up"}),
        at([](auto& s, std::size_t) -> auto& { return s.camera.yaw_deg; },
           {.key = "camera.yaw_deg", .unit = "deg", .min = -kAngleLimit_deg, .max = kAngleLimit_deg, .sliderMin = -180.0,
            .sliderMax = 180.0, .description = "heading, from -z towards +x"}),
        at([](auto& s, std::size_t) -> auto& { return s.camera.pitch_deg; },
           {.key = "camera.pitch_deg", .unit = "deg", .min = -89.0, .max = 89.0, .sliderMin = -89.0, .sliderMax = 89.0,
            .description = "up (+) or down (-) from the horizon"}),
        at([](auto& s, std::size_t) -> auto& { return s.camera.roll_deg; },
           {.key = "camera.roll_deg", .unit = "deg", .min = -180.0, .max = 180.0, .sliderMin = -180.0,
            .sliderMax = 180.0, .description = "about the view direction: + banks right (the horizon turns counter-clockwise)"}),
        at([](auto& s, std::size_t) -> auto& { return s.camera.fovY_deg; },
           {.key = "camera.fov_y_deg", .unit = "deg", .min = 10.0, .max = 150.0, .sliderMin = 10.0, .sliderMax = 150.0,
            .description = "vertical field of view"}),
        at([](auto& s, std::size_t) -> auto& { return s.camera.near_m; },
           {.key = "camera.near_m", .unit = "m", .min = 0.0, .max = 1000.0, .minExclusive = true, .sliderMin = 0.01,
            .sliderMax = 10.0, .logarithmic = true, .description = "near clip plane"}),
        at([](auto& s, std::size_t) -> auto& { return s.camera.far_m; },
           {.key = "camera.far_m", .effect = E::Grid | E::Bodies, .unit = "m", .min = 0.0, .max = 1.0e7, .minExclusive = true, .sliderMin = 100.0,
            .sliderMax = 100000.0, .logarithmic = true, .description = "far clip plane; > near_m"}),
        at([](auto& s, std::size_t) -> auto& { return s.camera.mountObject; },
           {.key = "camera.mount_object", .kind = K::Integer, .min = -1.0, .max = double(kMaxSceneObjects) - 1.0,
            .sliderMin = -1.0, .sliderMax = 8.0,
            .description = "index of the [[objects]] item the camera rides on (a rigid body or a fixed object); "
                           "-1: none. Mounted, yaw, pitch and roll turn it from the object's axes"}),
        at([](auto& s, std::size_t) -> auto& { return s.camera.mountOffset_m; },
           {.key = "camera.mount_offset_m", .kind = K::Vector3, .unit = "m", .min = -1.0e3, .max = 1.0e3,
            .sliderMin = -20.0, .sliderMax = 20.0,
            .description = "where a mounted camera stands in its object's axes (unscaled) [x, y, z]"}),
        at([](auto& s, std::size_t) -> auto& { return s.camera.lens; },
           {.key = "camera.lens", .kind = K::Choice, .min = 0.0, .max = kLensModels.size() - 1.0, .sliderMin = 0.0,
            .sliderMax = kLensModels.size() - 1.0,
            .description = "the lens's model: brown_conrady (camera.distortion_*) or kannala_brandt, a fisheye "
                           "(camera.fisheye_*; fov_y_deg then the angle between the top and bottom borders' rays)",
            .choices = kLensModels}),
        at([](auto& s, std::size_t) -> auto& { return s.camera.distortionK1; },
           {.key = "camera.distortion_k1", .min = -1.0, .max = 1.0, .sliderMin = -0.5, .sliderMax = 0.5,
            .description = "lens: Brown-Conrady radial k1 (< 0 barrel, > 0 pincushion), on normalised image coordinates"}),
        at([](auto& s, std::size_t) -> auto& { return s.camera.distortionK2; },
           {.key = "camera.distortion_k2", .min = -1.0, .max = 1.0, .sliderMin = -0.5, .sliderMax = 0.5,
            .description = "lens: radial k2 (r^4)"}),
        at([](auto& s, std::size_t) -> auto& { return s.camera.distortionK3; },
           {.key = "camera.distortion_k3", .min = -1.0, .max = 1.0, .sliderMin = -0.5, .sliderMax = 0.5,
            .description = "lens: radial k3 (r^6)"}),
        at([](auto& s, std::size_t) -> auto& { return s.camera.distortionP1; },
           {.key = "camera.distortion_p1", .min = -0.1, .max = 0.1, .sliderMin = -0.02, .sliderMax = 0.02,
            .description = "lens: tangential p1 (decentring)"}),
        at([](auto& s, std::size_t) -> auto& { return s.camera.distortionP2; },
           {.key = "camera.distortion_p2", .min = -0.1, .max = 0.1, .sliderMin = -0.02, .sliderMax = 0.02,
            .description = "lens: tangential p2 (decentring)"}),
        at([](auto& s, std::size_t) -> auto& { return s.camera.fisheyeK1; },
           {.key = "camera.fisheye_k1", .min = -1.0, .max = 1.0, .sliderMin = -0.2, .sliderMax = 0.2,
            .description = "lens: Kannala-Brandt fisheye k1 (theta^3 in theta_d), OpenCV's cv2.fisheye; with "
                           "camera.lens = \"kannala_brandt\""}),
        at([](auto& s, std::size_t) -> auto& { return s.camera.fisheyeK2; },
           {.key = "camera.fisheye_k2", .min = -1.0, .max = 1.0, .sliderMin = -0.2, .sliderMax = 0.2,
            .description = "lens: fisheye k2 (theta^5)"}),
        at([](auto& s, std::size_t) -> auto& { return s.camera.fisheyeK3; },
           {.key = "camera.fisheye_k3", .min = -1.0, .max = 1.0, .sliderMin = -0.2, .sliderMax = 0.2,
            .description = "lens: fisheye k3 (theta^7)"}),
        at([](auto& s, std::size_t) -> auto& { return s.camera.fisheyeK4; },
           {.key = "camera.fisheye_k4", .min = -1.0, .max = 1.0, .sliderMin = -0.2, .sliderMax = 0.2,
            .description = "lens: fisheye k4 (theta^9)"}),
        at([](auto& s, std::size_t) -> auto& { return s.camera.exposure_ev; },
           {.key = "camera.exposure_ev", .unit = "EV", .min = -10.0, .max = 10.0, .sliderMin = -4.0, .sliderMax = 4.0,
            .description = "sensor exposure: the linear colour times 2^ev (what passes 1 clips)"}),
        at([](auto& s, std::size_t) -> auto& { return s.camera.noiseStdDev; },
           {.key = "camera.noise_std", .min = 0.0, .max = 0.5, .sliderMin = 0.0, .sliderMax = 0.1,
            .description = "sensor noise: Gaussian, standard deviation of each 8-bit channel as a share of full scale"}),
        at([](auto& s, std::size_t) -> auto& { return s.camera.noiseSeed; },
           {.key = "camera.noise_seed", .kind = K::Integer, .min = 0.0, .max = 4294967295.0, .sliderMin = 0.0,
            .sliderMax = 100.0, .description = "sensor noise: its random seed (with the frame's time: the same noise "
                                               "for the same frame)"}),
        at([](auto& s, std::size_t) -> auto& { return s.camera.shutter_s; },
           {.key = "camera.shutter_s", .unit = "s", .min = 0.0, .max = 1.0, .sliderMin = 0.0, .sliderMax = 0.1,
            .description = "sensor: how long each row gathers light (motion blur); 0: an instant"}),
        at([](auto& s, std::size_t) -> auto& { return s.camera.readout_s; },
           {.key = "camera.readout_s", .unit = "s", .min = 0.0, .max = 1.0, .sliderMin = 0.0, .sliderMax = 0.1,
            .description = "sensor: rolling shutter, from the top row's exposure to the bottom row's; 0: global"}),
        at([](auto& s, std::size_t) -> auto& { return s.camera.motionSamples; },
           {.key = "camera.motion_samples", .kind = K::Integer, .min = 2.0, .max = 256.0, .sliderMin = 2.0,
            .sliderMax = 64.0, .description = "sensor: frames drawn over shutter_s + readout_s, when either is set"}),
        // [[camera.path]]
        at([](auto& s, std::size_t i) -> auto& { return s.camera.path[i].time_s; },
           {.key = "camera.path.time_s", .list = L::CameraPath, .unit = "s", .min = 0.0, .max = 1.0e6, .sliderMin = 0.0,
            .sliderMax = 600.0, .description = "when the camera is here; keys strictly increase"}),
        at([](auto& s, std::size_t i) -> auto& { return s.camera.path[i].position_m; },
           {.key = "camera.path.position_m", .kind = K::Vector3, .list = L::CameraPath, .unit = "m",
            .min = -kWorldLimit_m, .max = kWorldLimit_m, .sliderMin = -1000.0, .sliderMax = 1000.0,
            .description = "world position [x, y, z]"}),
        at([](auto& s, std::size_t i) -> auto& { return s.camera.path[i].yaw_deg; },
           {.key = "camera.path.yaw_deg", .list = L::CameraPath, .unit = "deg", .min = -kAngleLimit_deg,
            .max = kAngleLimit_deg, .sliderMin = -180.0, .sliderMax = 180.0, .description = "heading, from -z towards +x"}),
        at([](auto& s, std::size_t i) -> auto& { return s.camera.path[i].pitch_deg; },
           {.key = "camera.path.pitch_deg", .list = L::CameraPath, .unit = "deg", .min = -89.0, .max = 89.0,
            .sliderMin = -89.0, .sliderMax = 89.0, .description = "up (+) or down (-) from the horizon"}),
        at([](auto& s, std::size_t i) -> auto& { return s.camera.path[i].roll_deg; },
           {.key = "camera.path.roll_deg", .list = L::CameraPath, .unit = "deg", .min = -180.0, .max = 180.0,
            .sliderMin = -180.0, .sliderMax = 180.0,
            .description = "about the view direction: + banks right (the horizon turns counter-clockwise)"}),
        // [[camera.rig]] (its name is a string: scene_file.h reads it)
        at([](auto& s, std::size_t i) -> auto& { return s.camera.rig[i].position_m; },
           {.key = "camera.rig.position_m", .kind = K::Vector3, .list = L::CameraRig, .unit = "m", .min = -1.0e3,
            .max = 1.0e3, .sliderMin = -5.0, .sliderMax = 5.0,
            .description = "where the rig camera stands in the platform's axes (the [camera]'s: x right, y up, z back) [x, y, z]"}),
        at([](auto& s, std::size_t i) -> auto& { return s.camera.rig[i].yaw_deg; },
           {.key = "camera.rig.yaw_deg", .list = L::CameraRig, .unit = "deg", .min = -180.0, .max = 180.0,
            .sliderMin = -180.0, .sliderMax = 180.0, .description = "heading from the platform's, towards its right"}),
        at([](auto& s, std::size_t i) -> auto& { return s.camera.rig[i].pitch_deg; },
           {.key = "camera.rig.pitch_deg", .list = L::CameraRig, .unit = "deg", .min = -89.0, .max = 89.0,
            .sliderMin = -89.0, .sliderMax = 89.0, .description = "up (+) or down (-) from the platform's"}),
        at([](auto& s, std::size_t i) -> auto& { return s.camera.rig[i].roll_deg; },
           {.key = "camera.rig.roll_deg", .list = L::CameraRig, .unit = "deg", .min = -180.0, .max = 180.0,
            .sliderMin = -180.0, .sliderMax = 180.0, .description = "about its view direction: + banks right"}),
        at([](auto& s, std::size_t i) -> auto& { return s.camera.rig[i].fovY_deg; },
           {.key = "camera.rig.fov_y_deg", .list = L::CameraRig, .unit = "deg", .min = 0.0, .max = 150.0,
            .sliderMin = 0.0, .sliderMax = 150.0, .description = "vertical field of view; 0: the [camera]'s"}),
    };
}

} // namespace swell::detail
