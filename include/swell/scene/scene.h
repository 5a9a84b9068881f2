// Everything that describes what Swell renders: waves, grid, sun, sky, fog,
// water optics, objects and camera. Plain data with units; scene files
// (swell/scene/scene_file.h) read and write it, and the renderer draws it. The
// ranges that are checked, and shown on sliders, live in one table in
// swell/scene/parameters.h; the comments below only summarise them.
#pragma once

#include "swell/error.h"
#include "swell/export.h"
#include "swell/scene/atmosphere.h"
#include "swell/scene/clouds.h"

#include "swell/scene/sea_state.h"
#include "swell/scene/seabed_settings.h"
#include "swell/scene/waves.h"
#include "swell/sea_frame.h"
#include "swell/view.h"

#include <glm/vec3.hpp>

#include <array>
#include <cmath>
#include <limits>
#include <map>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace swell {

// How the water finds what it reflects.
enum class ReflectionMode {
    FixedDistance, // the paper's lookup: step a fixed distance along the reflected ray
    RayMarch,      // march the reflected ray against the reflection depth buffer (default)
};

// What the water pass shows: the shaded ocean or one of its ingredients.
enum class DebugView { Shaded, Normals, Reflection, Refraction, Lod, Wireframe, Foam };

// Which wave model draws the sea (swell/wave_model.h).
enum class WaveModelKind {
    Gerstner, // a sum of up to SWELL_MAX_WAVES Gerstner waves: listed, or drawn from the wind's spectrum
    Spectral, // the wind's spectrum on FFT cascades (swell/spectral_model.h); needs the wind
};

// The sea itself, whatever model draws its waves: where its surface rests,
// how deep it is and the wind over it. The scene file keeps these keys
// where the waves and the water are described (water.level_m,
// waves.depth_m, [waves.wind]; docs/SCENE.md).
struct SWELL_API SeaSettings {
    // The water's mean level: the height of the surface at rest, absolute
    // world y, m (a lake in the hills lies at hundreds of metres). Wave
    // models and their queries work relative to it; DrawnSurface, the
    // floating objects and the renderer add it. Key water.level_m.
    double level_m = 0.0;
    // The water's depth below level_m, m, > 0; infinity is deep water. The
    // waves travel in it (listed, generated and spectral alike: the
    // dispersion relation), and so does the wake. Key waves.depth_m.
    // Where the scene has a sea floor (Scene::seabed; swell/scene/seabed.h),
    // the depth at a place is minus the floor's height there, and this
    // stays the depth where no part of the floor reaches.
    double depth_m = std::numeric_limits<double>::infinity();
    // The wind, when the waves are generated from it ([waves.wind]); the
    // spectral model needs it. Unset: the waves are WaveSource::listed.
    std::optional<WindSettings> wind;
};

// How the sea's waves are made: which model draws them, and the waves
// listed by hand when there is no wind (Scene::sea).
struct SWELL_API WaveSource {
    WaveModelKind model = WaveModelKind::Gerstner;
    double choppiness = 1.0; // spectral model: lambda, 0..2 (SpectralSettings::choppiness)
    double foamLifetime_s = 3.85; // spectral model: whitecap foam's e-folding time, s, 0..60; 0: no foam
    std::vector<Wave> listed;     // hand-listed waves ([[waves.list]]); ignored when the sea has a wind
};

// How the grid's lines are spaced away from the camera (see shaders/grid.glsl).
enum class GridLayout {
    Geometric, // spacing grows in proportion to distance, and the grid scales with camera height
    Paper,     // the paper's quadratic division points: spacing grows with the square root of distance
};

// The camera-following LOD grid of the paper. Rebuild settings: a change
// recreates the grid's index buffer.
struct SWELL_API GridSettings {
    GridLayout layout = GridLayout::Geometric;
    int resolution = 121;       // vertices along each side, 16..2048
    double radius_m = 2000.0;   // half-size of the detailed grid around the camera, m, 10..100000
    // Wave height fades to zero between these distances from the camera, m (Earth-curvature trick).
    double fadeStart_m = 800.0;
    double fadeEnd_m = 1900.0;
};

// The sun placed by an instant and a place on Earth (swell/scene/sun_position.h)
// instead of by a direction; north is -z, east +x.
struct SWELL_API SunPlace {
    double time_s = 946728000.0; // seconds since 1970-01-01T00:00:00Z (UTC), 1950..2050; default 2000-01-01T12:00:00Z
    double latitude_deg = 0.0;   // north +, -90..90
    double longitude_deg = 0.0;  // east +, -180..180
};

// The sun given by its angles instead of by a direction: its elevation
// above the horizon and its azimuth, measured like a heading (from -z, north,
// towards +x, east), as a sweep's sun.elevation_deg and sun.azimuth_deg are.
struct SWELL_API SunAngles {
    double elevation_deg = 0.0; // -90..90
    double azimuth_deg = 0.0;   // -360..360
};

struct SWELL_API SunSettings {
    // Towards the sun, world space; normalised on use. When `place` or
    // `angles` is set, the direction they give, kept in step by the setters
    // of sun.time, sun.latitude_deg, sun.longitude_deg, sun.elevation_deg and
    // sun.azimuth_deg (swell/scene/parameters.h). At most one of the two is
    // set: the form the scene gave its sun in, which saveScene writes back.
    glm::dvec3 direction{-0.4, 0.35, -0.85};
    glm::dvec3 color{1.0, 0.95, 0.85}; // linear RGB, 0..1
    double intensity = 1.0;            // multiplier, 0..20
    std::optional<SunPlace> place{};   // the sun placed by date, time and place instead of `direction`
    std::optional<SunAngles> angles{}; // the sun placed by its elevation and azimuth instead of `direction`
};

// What the built-in sky is (when no cubemap faces are given).
enum class SkyModel {
    Gradient, // a hand-coloured gradient from horizon to zenith and a glow around the sun (the paper's look)
    Physical, // the atmosphere's scattering of sunlight (swell/scene/atmosphere.h); it also sets the sun's
              // colour and intensity and the ambient light of world objects
};

struct SWELL_API SkySettings {
    // Six images (+x, -x, +y, -y, +z, -z), paths relative to the scene file.
    // Empty: the built-in procedural sky, coloured from the values below.
    std::vector<std::string> cubemapFaces;
    SkyModel model = SkyModel::Gradient;
    glm::dvec3 zenithColor{0.18, 0.36, 0.70};  // gradient: linear RGB, 0..1
    glm::dvec3 horizonColor{0.70, 0.80, 0.90}; // gradient: linear RGB, 0..1
    // Physical: the displayed linear colour per unit radiance over the sun's
    // irradiance at the top of the atmosphere (1/sr), 0.01..1000.
    double exposure = 10.0;
    AtmosphereSettings atmosphere; // physical: aerosols and the ground's albedo
    CloudSettings clouds;          // physical: a layer of cloud ([sky.clouds]; swell/scene/clouds.h)
};

// How distance veils what is drawn (shaders/fog.glsl).
enum class FogModel {
    Linear,     // the paper's: a linear ramp from start_m to end_m towards `color`
    Atmosphere, // aerial perspective: the veil takes the sky's colour at the horizon in each view's
                // azimuth, and with the physical sky the clear air's extinction is added to the ramp
};

struct SWELL_API FogSettings {
    double start_m = 1200.0;               // fog begins, m from the camera, >= 0
    double end_m = 6000.0;                 // fog is complete, m, > start
    glm::dvec3 color{0.70, 0.80, 0.90};    // linear RGB, 0..1 (linear model only)
    FogModel model = FogModel::Linear;     // last, so that {start, end, color} still initialises the rest
};

struct SWELL_API WaterSettings {
    glm::dvec3 deepColor{0.01, 0.06, 0.10};       // colour of light scattered back from deep water, linear RGB
    glm::dvec3 absorption_per_m{0.45, 0.09, 0.06}; // Beer-Lambert absorption coefficient per channel, 1/m, >= 0
    double fresnelF0 = 0.02;                      // reflectance looking straight down, 0..1 (water: 0.02)
    double shininess = 400.0;                     // Phong specular exponent, 1..10000
    double specularStrength = 1.0;                // 0..10
    double refractionDistortion = 0.05;           // how much the normal bends the refraction lookup, 0..1
    // Caustics: the sun's light focused by the waves on what lies under the
    // water, drawn each frame into a map around the camera (off: the light
    // under a level surface everywhere).
    bool caustics = true;
    // Shafts of light: the sun's light the water scatters towards an eye
    // under the water, focused by the waves into shafts (the caustics map
    // read along each view ray); off: none of the sun's light scattered
    // (the water's colour alone, deepColor). Off unless asked for: the
    // renderer's soak test finds a program of a replaced set kept alive
    // with them on (docs/RENDERING.md, "Shafts of light").
    bool shafts = false;
    // Spray: white mist torn from the breaking crests and carried downwind
    // (shaders/spray.vert), from Beaufort 7 up (none below, whatever this
    // says; the spectral model alone has crests that break).
    bool spray = true;
};

struct SWELL_API ReflectionSettings {
    ReflectionMode mode = ReflectionMode::RayMarch;
    double fixedDistance_m = 5.0;  // step along the reflected ray in FixedDistance mode, m (the paper: 5)
    double resolutionScale = 0.5;  // reflection/refraction target size relative to the output, 0.1..1
    double clipOffset_m = 0.3;     // the mirrored world is clipped this far below the water plane, m
};

// SceneObject::path names a model drawn without a file when it is
// kBuiltinObjectPrefix followed by one of kBuiltinObjects ("builtin:buoy").
inline constexpr std::string_view kBuiltinObjectPrefix = "builtin:";
inline constexpr std::array<std::string_view, 13> kBuiltinObjects{
    "buoy", "boat", "rock", "sailing_yacht", "rib", "fishing_trawler", "tug", "container_ship", "tanker", "kayak",
    "lateral_port_buoy", "lateral_starboard_buoy", "cardinal_north_buoy"};
// The fleet: the built-ins made at a design size with design numbers
// (assets/models/fleet_model.py writes them), which a scene may stretch,
// repaint and strip (SceneObject::length_m and the keys after it) and which
// float at their design draft as rigid bodies without a mass given.
inline constexpr std::array<std::string_view, 10> kFleetObjects{
    "sailing_yacht", "rib", "fishing_trawler", "tug", "container_ship", "tanker", "kayak",
    "lateral_port_buoy", "lateral_starboard_buoy", "cardinal_north_buoy"};
// Whether `path` ("builtin:tug") names one of the fleet.
constexpr bool isFleetPath(std::string_view path)
{
    if (!path.starts_with(kBuiltinObjectPrefix))
        return false;
    for (std::string_view name : kFleetObjects)
        if (path.substr(kBuiltinObjectPrefix.size()) == name)
            return true;
    return false;
}

// A glTF model placed in the world.
struct SWELL_API SceneObject {
    std::string path;                 // .gltf or .glb, relative to the scene file; "builtin:NAME" for a built-in
    glm::dvec3 position_m{0.0};       // world position, m
    double yaw_deg = 0.0;             // rotation about +y, degrees
    double scale = 1.0;               // uniform scale, > 0
    bool floats = false;              // ride the waves (height and tilt from the CPU wave query)
    // A floating rigid body (swell/floating_body.h, docs/BODIES.md) when
    // floats is set and either of these is > 0: it heaves, rolls and pitches
    // with inertia instead of sitting on the surface. Give one of the two.
    double mass_kg = 0.0;               // kg, 0..1e9
    double density_kg_per_m3 = 0.0;     // mean density of its closed volume, kg/m^3, 0..1e5
    glm::dvec3 centerOfMassOffset_m{0.0}; // from the volume's centroid, model frame (unscaled), m
    glm::dvec3 inertia_kg_m2{0.0};      // principal moments about the centre of mass, model axes; 0: from the mesh
    glm::dvec3 velocity_m_per_s{0.0};   // m/s: carried at x, z (a boat under way); y: heave velocity at t = 0
    double dampingRatio = 0.1;          // fraction of critical damping in heave, roll and pitch, 0..2
    // The glTF node whose mesh is the model's closed hull volume: left out of
    // the drawn model, drawn into depth only so no water shows inside an open
    // hull, and the body's shape for buoyancy. Empty: none (built-ins bring their own).
    std::string hullNode{};
    // Its class in the labels (docs/LABELS.md): what a detector is to call
    // it. Empty: its model's name (objectClassOf, swell/dataset/labels.h).
    std::string className{};
    // One of the fleet (isFleetPath) only: its hull and all on it stretched
    // to this overall length and beam, m, its draft kept (0: the design's);
    // its "hull" and "superstructure" paints, linear RGB ([-1, -1, -1]: the
    // model's own); and whether its superstructure is drawn (a wheelhouse,
    // a coachroof, a kayak's paddler, a buoy's topmark).
    double length_m = 0.0;
    double beam_m = 0.0;
    glm::dvec3 hullColor{-1.0};
    glm::dvec3 superstructureColor{-1.0};
    bool superstructure = true;

    // Whether this object is a floating rigid body: floating with a mass
    // given, or one of the fleet, which floats at its design draft.
    bool isRigidBody() const
    {
        return floats && (mass_kg > 0.0 || density_kg_per_m3 > 0.0 || isFleetPath(path));
    }
};

// The wake field: waves the floating bodies make as they move (docs/BODIES.md).
// A square grid of cells that follows the bodies, simulated on the CPU.
struct SWELL_API WakeSettings {
    bool enabled = true;       // moving rigid bodies leave wakes
    int cells = 256;           // cells along each side, 32..1024
    double cellSize_m = 1.0;   // m, 0.1..10: waves shorter than 2 cells are not carried
};

struct SWELL_API CameraKey {
    double time_s = 0.0;          // when the camera is here, s
    glm::dvec3 position_m{0.0};   // world position, m
    double yaw_deg = 0.0;         // heading, degrees from -z towards +x
    double pitch_deg = 0.0;       // up/down, degrees, -89..89
    double roll_deg = 0.0;        // about the view direction, degrees, -180..180 (swell/camera.h)
};

// A camera lens's model (docs/SCENE.md, "The lens"; swell/dataset/sensor.h).
enum class LensModel { BrownConrady, KannalaBrandt };

// A camera of a rig (docs/LABELS.md, "Rigs and the platform"): one of
// several cameras on one platform, the platform being what [camera] places
// (fixed, on its path, or riding a body). Its pose is relative to the
// platform: it stands at position_m in the platform's axes (the [camera]'s
// own: x right, y up, z back; at yaw, pitch and roll 0 the world's) and its
// yaw, pitch and roll turn it from them, as a mounted camera's turn it from
// its object's. Every rig camera is drawn at the same simulated time.
struct SWELL_API RigCamera {
    std::string name;                 // its files' middle name (NAME.left.png); letters, digits, '_', '-'
    glm::dvec3 position_m{0.0};       // in the platform's axes, m
    double yaw_deg = 0.0;             // from the platform's heading, degrees
    double pitch_deg = 0.0;           // from the platform's, degrees, -89..89
    double roll_deg = 0.0;            // about its view direction, degrees, -180..180
    double fovY_deg = 0.0;            // vertical field of view, degrees, up to 150; 0: the [camera]'s
};

// The most cameras a rig holds: each is a whole frame drawn and labelled.
inline constexpr std::size_t kMaxRigCameras = 16;

struct SWELL_API CameraSettings {
    glm::dvec3 position_m{0.0, 6.0, 0.0}; // world position, m
    double yaw_deg = 0.0;                  // heading, degrees from -z towards +x
    double pitch_deg = -5.0;               // degrees, -89..89
    double fovY_deg = 60.0;                // vertical field of view, degrees, 10..150
    double near_m = 0.1;                   // near plane, m, > 0
    double far_m = 20000.0;                // far plane, m, > near
    std::vector<CameraKey> path;           // optional: keys sorted by time, interpolated linearly
    double roll_deg = 0.0;                 // about the view direction, degrees, -180..180 (swell/camera.h)
    // A camera on a deck: the index of the scene object it is mounted on
    // (-1: none). Mounted, the camera stands at mountOffset_m in the
    // object's axes (m, unscaled) and its yaw, pitch and roll turn it from
    // the object's axes: it heaves, rolls and pitches with a floating body
    // (Renderer::sceneCameraAt). The object must be a rigid body or fixed.
    int mountObject = -1;
    glm::dvec3 mountOffset_m{0.0};
    // The lens and the sensor (swell/dataset/sensor.h), applied to stills, videos
    // and datasets, and to their labels alike: the lens's model and its
    // coefficients, the exposure, and Gaussian noise on each colour channel.
    // Brown-Conrady (lens = BrownConrady, the default): k1, k2, k3 radial,
    // p1, p2 tangential, OpenCV's order and sign. Kannala-Brandt's fisheye
    // (lens = KannalaBrandt): k1..k4 of OpenCV's cv2.fisheye; fovY_deg is
    // then the angle between the rays of the top and bottom borders'
    // middles. A scene sets the coefficients of its lens's model only.
    LensModel lens = LensModel::BrownConrady;
    double distortionK1 = 0.0, distortionK2 = 0.0, distortionK3 = 0.0;
    double distortionP1 = 0.0, distortionP2 = 0.0;
    double fisheyeK1 = 0.0, fisheyeK2 = 0.0, fisheyeK3 = 0.0, fisheyeK4 = 0.0;
    double exposure_ev = 0.0;       // stops: the linear colour times 2^ev before it is encoded
    double noiseStdDev = 0.0;       // of each 8-bit channel, as a share of full scale, 0..0.5
    std::uint32_t noiseSeed = 0;
    // Time on the sensor (swell/dataset/sensor.h, SensorTiming): how long
    // each row gathers light (motion blur), how long the rows take to be
    // read out from top to bottom (rolling shutter; 0: a global shutter),
    // and how many frames are drawn over the span the two cover.
    double shutter_s = 0.0;         // s, 0..1: each row's exposure; 0: an instant
    double readout_s = 0.0;         // s, 0..1: from the top row's exposure to the bottom's
    int motionSamples = 16;         // frames drawn over shutter_s + readout_s, 2..256
    // Cameras on the platform this camera places ([[camera.rig]]); empty:
    // the camera itself is the one sensor. With a rig, the rig's cameras
    // are the sensors (the lens and sensor settings above are theirs too).
    std::vector<RigCamera> rig;
};

// Where a scene file named a file the renderer reads (a model or a sky
// face), so that a problem found while loading it is reported at the key
// that named it: "scene.toml:12:8: objects[2].path: /scenes/boat.glb: ...".
struct SWELL_API AssetReference {
    std::string key;   // "objects[2].path", "sky.faces[3]"
    std::string path;  // the path as written, to tell whether the scene still names it
    SourcePlace place; // where it was written
};

// The axes the labels give world quantities in (docs/LABELS.md, "World
// frames"): Swell's own (x east, y up, z south: -z is north), or the
// marine conventions, ENU (x east, y north, z up) and NED (x north, y
// east, z down); all with their origin at Swell's.
enum class LabelWorldFrame { Swell, Enu, Ned };

struct SWELL_API LabelSettings {
    LabelWorldFrame worldFrame = LabelWorldFrame::Swell;
};

struct SWELL_API Scene {
    SeaSettings sea;
    WaveSource waves;
    GridSettings grid;
    SunSettings sun;
    SkySettings sky;
    FogSettings fog;
    WaterSettings water;
    ReflectionSettings reflection;
    std::vector<SceneObject> objects;
    WakeSettings wake;
    // The sea floor's shapes and heightmap ([seabed];
    // swell/scene/seabed_settings.h); empty: flat at sea.depth_m. The
    // island (showTerrain) is part of the floor too (swell/scene/seabed.h).
    SeabedSettings seabed;
    CameraSettings camera;
    LabelSettings labels;
    DebugView debugView = DebugView::Shaded;
    // Where relative object and sky paths are found: the scene file's folder
    // (set by loadScene/parseScene); empty means the working directory.
    std::string assetFolder;
    // Where each model and sky face path was written (set by loadScene/
    // parseScene; empty for scenes built in code, whose errors name the file).
    std::vector<AssetReference> assetReferences;
    // Where each key was written, keyed as a scene file writes it
    // ("fog.end_m", "objects[2].scale"), so that a check made after loading
    // (validateScene(), a lens checked for an image's size, a sweep's sample)
    // names its line: set by loadScene/parseScene, pointed at the sweep's
    // line for each key a sweep varies (swell/dataset/sweep.h), and dropped for a
    // key set in code, whose value the file no longer says.
    std::map<std::string, SourcePlace, std::less<>> keyPlaces;
    bool showTerrain = true; // the built-in island
    Antialiasing antialiasing = Antialiasing::Fxaa;
    // When the simulation's history starts, s: the foam is made, and
    // floating bodies and their wake start from rest, from this time on;
    // before it there is no foam and the bodies wait where they start.
    // -inf (the default): the sea has always been going: the foam is in its
    // steady state at any time, and the bodies start kDevelopedHistory_s
    // before t = 0 (settled, their wakes trailing at t = 0).
    double historyStart_s = -std::numeric_limits<double>::infinity();
};

// How long before t = 0 floating bodies and their wake start when the
// scene's history_start_s is -inf: a boat at 4 m/s crosses the wake field's
// astern three quarters (192 m at the default 256 x 1 m) in 48 s, and a
// body settles in a few of its periods.
inline constexpr double kDevelopedHistory_s = 60.0;

// The time the scene's bodies and wake start from: historyStart_s, or
// kDevelopedHistory_s before t = 0 when that is -inf.
inline double bodiesStart_s(const Scene& scene)
{
    return std::isinf(scene.historyStart_s) ? -kDevelopedHistory_s : scene.historyStart_s;
}

// The built-in default scene: an open ocean under a trade wind, with an island.
SWELL_API Scene defaultScene();

// The scene's sea frame (swell/sea_frame.h): y = 0 at its water's mean level.
inline SeaFrame seaFrameOf(const Scene& scene) { return SeaFrame(scene.sea.level_m); }

// The wave set the scene describes at load time: generateWaves(*sea.wind)
// when the sea has a wind, else waves.listed. Either way the water depth is
// sea.depth_m (the wind's own depth_m is overridden by it).
SWELL_API WaveSet resolveWaves(const Scene& scene);

} // namespace swell
