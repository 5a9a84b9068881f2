// Rigid bodies floating on a swell::SurfaceQuery: buoyancy from the hydrostatic
// pressure over the submerged part of a closed mesh, gravity, and linear
// hydrodynamic damping, integrated with semi-implicit Euler steps of a fixed
// length (kBodyStep_s) from t = 0. A body's pose at a time depends only on the
// body, the surface and that time, never on how often it was asked for: the
// headless renderer and the viewer draw the same poses bit for bit.
//
// Heave, roll, pitch and yaw are free (a body under way is held on its
// heading by a helm, kHelmPeriod_s); the horizontal position is carried
// along (at rest, or at a constant velocity for a boat under way), since
// hydrostatic forces on a body are vertical on flat water and the waves'
// horizontal forces are not modelled. docs/BODIES.md explains the model and
// its limits.
#pragma once

#include "swell/constants.h"
#include "swell/error.h"
#include "swell/export.h"
#include "swell/surface_query.h"

#include <glm/gtc/quaternion.hpp>
#include <glm/mat3x3.hpp>
#include <glm/mat4x4.hpp>
#include <glm/vec3.hpp>

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

namespace swell {

namespace detail {
struct BodyWater;
}

// The fixed integration step, s: 1/120 s resolves the heave and roll periods
// of bodies down to about 0.3 m across (about 0.5 s; 60 steps a period).
inline constexpr int kBodyStepsPerSecond = 120;
inline constexpr double kBodyStep_s = 1.0 / kBodyStepsPerSecond;
// The water under a body is sampled every this many steps (1/30 s) and
// interpolated linearly in time between: the shortest waves drawn (0.4 m,
// 0.5 s) change little in 1/30 s, and a query of the spectral model's CPU
// twin at a new time costs a transform of its fields.
inline constexpr int kBodyStepsPerWaterSample = 4;

// A body under way is steered: a helmsman holds it on the heading it
// starts with (BodyStart::yaw_deg) by a yaw torque, a critically damped
// spring of this period about the vertical. The hull's own directional
// stability and rudder are not modelled, and yaw has no hydrostatic
// stiffness, so without it the waves' yaw moments on a hull that is not
// symmetric fore and aft turn it off its course while it is carried along
// it. A moored body (no horizontal velocity) is not steered.
inline constexpr double kHelmPeriod_s = 4.0;

// The largest omega * kBodyStep_s (rad a step) of a body's fastest
// oscillation, heave or heel: semi-implicit Euler is stable for an undamped
// oscillator up to omega dt = 2 (Hairer, Lubich & Wanner 2006, ch. I.1), and
// a body's stiffness, measured upright at load, grows as it heels and dips
// in the waves, so half that is allowed: periods down to 2 pi steps (52 ms).
inline constexpr double kMaxBodyOmegaStep = 1.0;

// A body that cannot float, or whose motion the fixed step cannot follow
// (too light for its size, or too little inertia for its stiffness). Says
// which setting to change, so a scene names the key.
class SWELL_API BodyError : public InputError {
public:
    enum class Setting { Shape, Mass, Inertia };
    BodyError(Setting setting, const std::string& message) : InputError({}, message), setting_(setting) {}
    Setting setting() const { return setting_; }

private:
    Setting setting_;
};

// A closed triangle mesh in the body's own frame, m, triangles wound
// counter-clockwise seen from outside.
struct SWELL_API BodyShape {
    std::vector<glm::dvec3> positions_m;
    std::vector<std::uint32_t> indices;
};

// What a closed mesh of uniform density 1 kg/m^3 weighs and how it turns.
struct SWELL_API MassProperties {
    double volume_m3 = 0.0;
    glm::dvec3 centroid_m{0.0};
    glm::dmat3 inertiaAboutCentroid_kg_m2{0.0}; // for density 1 kg/m^3; scale by the density
};

// Volume, centroid and inertia of a closed mesh (Blow & Binstock 2004).
// Throws swell::InputError when the mesh is not closed (an edge not shared by
// exactly two triangles, vertices compared by position), is wound inside out
// (its triangles facing inwards), or encloses no volume.
SWELL_API MassProperties massPropertiesOf(const BodyShape& shape);

// How a body is built: its mass and how it turns. Zero inertia means the
// mesh's, for its mass spread evenly through its volume.
struct SWELL_API BodySettings {
    double mass_kg = 0.0;                  // > 0
    glm::dvec3 centerOfMassOffset_m{0.0};  // from the mesh's centroid, body frame
    glm::dvec3 principalInertia_kg_m2{0.0}; // about the centre of mass, body axes; all 0: from the mesh
    double dampingRatio = 0.1;             // fraction of critical damping in heave, roll and pitch, 0..2
    double waterDensity_kg_per_m3 = kSeaWaterDensity_kg_per_m3;
};

// Where the body starts and how it is carried.
struct SWELL_API BodyStart {
    glm::dvec3 origin_m{0.0};     // where the shape's origin is at t = 0: x, z; y is the height above rest
    double yaw_deg = 0.0;         // heading about +y at t = 0
    glm::dvec3 velocity_m_per_s{0.0}; // x, z: the horizontal velocity it is carried at; y: its heave velocity at t = 0
};

// The state at one step: the centre of mass and the orientation, world frame.
struct SWELL_API BodyState {
    std::int64_t step = 0;               // time = step * kBodyStep_s
    glm::dvec3 centerOfMass_m{0.0};
    double heaveVelocity_m_per_s = 0.0;
    glm::dquat orientation{1.0, 0.0, 0.0, 0.0}; // body to world
    glm::dvec3 angularVelocity_rad_per_s{0.0};  // world frame
};

class SWELL_API FloatingBody {
public:
    // Builds the body at rest on `surface` at t = 0 (heave equilibrium with
    // its yaw, then raised by start.origin_m.y). `surface` must outlive the
    // body; `filter` picks the surface the water is drawn with. Throws
    // swell::InputError when the shape is not closed or wound inside out,
    // and BodyError when the body would sink or oscillate faster than the
    // steps can follow (kMaxBodyOmegaStep). step() throws swell::Error
    // should its state still stop being finite, before the state is used.
    FloatingBody(const BodyShape& shape, const BodySettings& settings, const BodyStart& start,
                 const SurfaceQuery& surface, const SurfaceFilter& filter = {});
    ~FloatingBody();
    FloatingBody(FloatingBody&&) noexcept;
    FloatingBody& operator=(FloatingBody&&) noexcept;

    // Steps from the current state (or from t = 0, when time_s is earlier
    // than it) until time_s lies in the last step, then returns the
    // transform from the shape's frame to the world, interpolated between
    // the two states that bracket time_s. Negative times are t = 0.
    glm::dmat4 poseAt(double time_s);

    // The step whose state poseAt(time_s) needs last: floor(t / step) + 1.
    static std::int64_t lastStepFor(double time_s);
    // Steps (or starts again from t = 0 and steps) until state().step is
    // `step`. Bodies advanced in lockstep query the surface at the same
    // times one after another, which a model that caches a time's fields
    // answers once.
    void advanceToStep(std::int64_t step);

    // The state after the steps taken so far, and the one before it.
    const BodyState& state() const { return next_; }
    const BodyState& previousState() const { return previous_; }

    // A point of the shape (its own frame, m) at the last step (state()):
    // where it is and how fast it moves, world frame. Between the steps'
    // states, as poseAt() is.
    struct PointMotion {
        glm::dvec3 position_m{0.0};
        glm::dvec3 velocity_m_per_s{0.0};
    };
    PointMotion pointAt(glm::dvec3 shapePoint_m) const;
    // How the shape's origin and axes move at time_s, world frame, once
    // poseAt(time_s) has stepped there (the state brackets time_s): the
    // origin's velocity, m/s, and the angular velocity, rad/s. The state's
    // own velocities: a semi-implicit Euler step moves the state with the
    // velocities it ends with, so over the step poseAt() interpolates
    // within they are the drawn pose's derivative (exactly for the centre of
    // mass, to first order in the step for the turn slerp takes).
    struct Velocity {
        glm::dvec3 origin_m_per_s{0.0};
        glm::dvec3 angular_rad_per_s{0.0};
    };
    Velocity velocityAt(double time_s) const;
    // How fast the state's velocities change over the step that brackets
    // time_s (once poseAt(time_s) has stepped there), world frame: the
    // centre of mass's acceleration, m/s^2, and the angular acceleration,
    // rad/s^2, the differences of the two states' velocities over the step.
    // A semi-implicit Euler step changes the velocities by exactly the
    // forces' acceleration times the step, so these are what moved the body
    // (the pose is interpolated within the step with the step's end
    // velocities); with centerOfMass_m, the centre of mass where poseAt()
    // puts it at time_s. All 0 before the first step.
    struct Acceleration {
        glm::dvec3 centerOfMass_m{0.0};
        glm::dvec3 centerOfMass_m_per_s2{0.0};
        glm::dvec3 angular_rad_per_s2{0.0};
    };
    Acceleration accelerationAt(double time_s) const;
    // The water the steps float the body on at world x, z near it (within
    // its reach of the centre of mass), at the last step: its height, m, and
    // how fast it rises there, m/s (the samples' interpolation in time the
    // steps use). Both 0 before the first step.
    struct WaterMotion {
        double height_m = 0.0;
        double rise_m_per_s = 0.0;
    };
    WaterMotion waterAt(glm::dvec2 xz_m) const;

    double mass_kg() const { return mass_kg_; }
    double volume_m3() const { return volume_m3_; }
    // The linear damping coefficients used: heave, N s/m; roll and pitch (body x, z), N m s.
    double heaveDamping_N_s_per_m() const { return heaveDamping_; }
    // Steps taken since construction (restarts included), for the benchmark.
    std::int64_t stepsTaken() const { return stepsTaken_; }

private:
    void restart();
    void step();
    // The water patches that bracket step n (sampled at multiples of kBodyStepsPerWaterSample).
    void sampleWaterFor(std::int64_t n);
    glm::dvec2 carriedAt(std::int64_t step) const; // the centre of mass's x, z at a step

    std::vector<glm::dvec3> points_m_; // the shape relative to its centre of mass
    std::vector<std::uint32_t> indices_;
    double reach_m_ = 0.0;             // farthest point from the centre of mass
    double mass_kg_ = 0.0, volume_m3_ = 0.0, waterDensity_ = 0.0;
    glm::dmat3 inertiaBody_{1.0};
    glm::dvec3 centerOfMassInShape_m_{0.0};
    double heaveDamping_ = 0.0;
    glm::dvec3 rotationDamping_{0.0}; // about body axes, N m s
    // The helm (kHelmPeriod_s), about the vertical: 0 for a moored body.
    double helmStiffness_N_m_per_rad_ = 0.0, helmDamping_N_m_s_ = 0.0;
    BodyStart start_;
    const SurfaceQuery* surface_ = nullptr;
    SurfaceFilter filter_;
    BodyState initial_, previous_, next_;
    // The water sampled round the body at the two sample times that bracket the step.
    std::unique_ptr<detail::BodyWater> water_;
    std::int64_t stepsTaken_ = 0;

};

} // namespace swell
