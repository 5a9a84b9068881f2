// A rigid body on the water, stepped at a fixed rate (swell/floating_body.h).
//
// Each step is semi-implicit (symplectic) Euler: velocities from the forces
// at the start of the step, then positions from the new velocities; it keeps
// an undamped oscillator's energy bounded, where explicit Euler would pump it
// up (Hairer, Lubich & Wanner 2006, Geometric Numerical Integration, ch. I.1).
// Rotation follows Euler's equations, I dw/dt = tau - w x I w, in the world
// frame, and dq/dt = 1/2 (0, w) q for the orientation.
//
// Damping is linear in the velocity relative to the water, b = 2 kappa
// sqrt(m c) for each degree of freedom with restoring stiffness c: the
// mass-spring-damper model of a floating body's heave, roll and pitch
// (Journee & Massie 2001, Offshore Hydromechanics, TU Delft, sec. 6.3),
// with kappa the dimensionless damping ratio. The added mass a of that model
// is left out (m + a becomes m): the water a body drags along makes its real
// heave and roll periods longer than these (Newman 1977, Marine
// Hydrodynamics, MIT Press, ch. 4).
#include "swell/floating_body.h"

#include "objects/hydrostatics.h"
#include "swell/constants.h"
#include "swell/error.h"

#include <fmt/format.h>
#include <glm/geometric.hpp>
#include <glm/gtc/matrix_transform.hpp>
#include <glm/matrix.hpp>

#include <algorithm>
#include <cmath>

namespace swell {

using detail::hydrostaticLoad;
using detail::sampleWater;

namespace detail {

struct BodyWater {
    std::int64_t firstStep = -1; // `from` is the water at this step, `to` kBodyStepsPerWaterSample later
    WaterPatch from, to;
};

} // namespace detail

namespace {

// Past its reach, the water patch round a body extends this much further
// (at least 0.5 m), so a body under way stays inside it for a while and
// each new sample time needs one sampling, not two.
constexpr double kPatchMarginOfReach = 0.25;

// Tilt used to measure roll and pitch stiffness at rest, rad: small enough
// to stay in the linear range of any body that floats upright.
constexpr double kStiffnessTilt_rad = 0.01;

} // namespace

FloatingBody::FloatingBody(const BodyShape& shape, const BodySettings& settings, const BodyStart& start,
                           const WaveModel& surface, const SurfaceFilter& filter)
    : start_(start), surface_(&surface), filter_(filter)
{
    const MassProperties props = massPropertiesOf(shape);
    if (!(settings.mass_kg > 0.0) || !std::isfinite(settings.mass_kg))
        throw InputError({}, fmt::format("a floating body needs a mass > 0 kg (got {})", settings.mass_kg));
    mass_kg_ = settings.mass_kg;
    volume_m3_ = props.volume_m3;
    waterDensity_ = settings.waterDensity_kg_per_m3;
    if (mass_kg_ >= waterDensity_ * volume_m3_)
        throw InputError({}, fmt::format("a body of {:.6g} kg and {:.6g} m^3 sinks: the water it can displace "
                                         "weighs {:.6g} kg",
                                         mass_kg_, volume_m3_, waterDensity_ * volume_m3_));
    centerOfMassInShape_m_ = props.centroid_m + settings.centerOfMassOffset_m;

    // The inertia: given principal moments, or the mesh's at this mass
    // (moved to the centre of mass by the parallel-axis theorem).
    const glm::dvec3 given = settings.principalInertia_kg_m2;
    if (given.x > 0.0 && given.y > 0.0 && given.z > 0.0) {
        inertiaBody_ = glm::dmat3(given.x, 0, 0, 0, given.y, 0, 0, 0, given.z);
    } else {
        const double density = mass_kg_ / volume_m3_;
        const glm::dvec3 o = settings.centerOfMassOffset_m;
        inertiaBody_ = density * props.inertiaAboutCentroid_kg_m2 +
                       mass_kg_ * (glm::dot(o, o) * glm::dmat3(1.0) - glm::outerProduct(o, o));
    }
    inverseInertiaBody_ = glm::inverse(inertiaBody_);

    // The shape about its centre of mass, wound outwards.
    points_m_.reserve(shape.positions_m.size());
    for (const glm::dvec3& p : shape.positions_m) {
        points_m_.push_back(p - centerOfMassInShape_m_);
        reach_m_ = std::max(reach_m_, glm::length(points_m_.back()));
    }
    indices_ = shape.indices;
    double signedVolume = 0.0;
    for (std::size_t t = 0; t < indices_.size(); t += 3)
        signedVolume += glm::dot(shape.positions_m[indices_[t]],
                                 glm::cross(shape.positions_m[indices_[t + 1]], shape.positions_m[indices_[t + 2]]));
    if (signedVolume < 0.0)
        for (std::size_t t = 0; t < indices_.size(); t += 3)
            std::swap(indices_[t + 1], indices_[t + 2]);

    // At rest at t = 0: the heave that balances the weight, found by
    // bisection (the buoyancy only grows as the body goes down).
    const glm::dquat q0 = glm::angleAxis(glm::radians(start.yaw_deg), glm::dvec3(0.0, 1.0, 0.0));
    const glm::dvec3 com0 = start.origin_m + q0 * centerOfMassInShape_m_;
    const glm::dvec2 xz(com0.x, com0.z);
    const detail::WaterPatch water0 = sampleWater(surface, xz, reach_m_, 0.0, filter);
    const double weight_N = mass_kg_ * kGravity;
    auto loadAt = [&](double y, const glm::dquat& q) {
        std::vector<glm::dvec3> world(points_m_.size());
        const glm::dvec3 com(com0.x, y, com0.z);
        for (std::size_t i = 0; i < world.size(); ++i)
            world[i] = com + q * points_m_[i];
        return hydrostaticLoad(world, indices_, com, water0, waterDensity_);
    };
    const double waterHere = water0.heightAt(xz);
    double lo = waterHere - 2.0 * reach_m_ - 1.0, hi = waterHere + 2.0 * reach_m_ + 1.0;
    for (int i = 0; i < 200 && hi - lo > 1e-12 * (1.0 + std::abs(hi)); ++i) {
        const double mid = 0.5 * (lo + hi);
        (loadAt(mid, q0).force_N.y > weight_N ? lo : hi) = mid;
    }
    const double restY = 0.5 * (lo + hi);

    // Stiffnesses at rest, for the damping: heave (rho g A_waterplane for a
    // wall-sided body) and roll and pitch about the body's x and z axes.
    const double dy = 1e-3 * reach_m_;
    const double heaveStiffness = (loadAt(restY - dy, q0).force_N.y - loadAt(restY + dy, q0).force_N.y) / (2.0 * dy);
    heaveDamping_ = 2.0 * settings.dampingRatio * std::sqrt(mass_kg_ * std::max(heaveStiffness, 0.0));
    for (int axis : {0, 2}) {
        glm::dvec3 bodyAxis(0.0);
        bodyAxis[axis] = 1.0;
        const glm::dvec3 worldAxis = q0 * bodyAxis;
        const glm::dquat tilt = glm::angleAxis(kStiffnessTilt_rad, worldAxis);
        const double plus = glm::dot(loadAt(restY, tilt * q0).torque_N_m, worldAxis);
        const double minus = glm::dot(loadAt(restY, glm::inverse(tilt) * q0).torque_N_m, worldAxis);
        // An unstable body (c < 0) is still damped as if it were stable.
        const double stiffness = std::abs(minus - plus) / (2.0 * kStiffnessTilt_rad);
        rotationDamping_[axis] = 2.0 * settings.dampingRatio * std::sqrt(inertiaBody_[axis][axis] * stiffness);
    }
    // Yaw has no hydrostatic stiffness; it is damped like roll and pitch on average.
    rotationDamping_.y = 0.5 * (rotationDamping_.x + rotationDamping_.z);

    initial_.step = 0;
    initial_.centerOfMass_m = {com0.x, restY + start.origin_m.y, com0.z};
    initial_.orientation = q0;
    initial_.heaveVelocity_m_per_s = start.velocity_m_per_s.y;
    water_ = std::make_unique<detail::BodyWater>();
    restart();
}

FloatingBody::~FloatingBody() = default;
FloatingBody::FloatingBody(FloatingBody&&) noexcept = default;
FloatingBody& FloatingBody::operator=(FloatingBody&&) noexcept = default;

void FloatingBody::restart()
{
    previous_ = next_ = initial_;
    water_->firstStep = -1;
}

glm::dvec2 FloatingBody::carriedAt(std::int64_t n) const
{
    // From the start, never accumulated, so a long run does not drift.
    const glm::dvec2 v(start_.velocity_m_per_s.x, start_.velocity_m_per_s.z);
    return glm::dvec2(initial_.centerOfMass_m.x, initial_.centerOfMass_m.z) + double(n) * kBodyStep_s * v;
}

void FloatingBody::sampleWaterFor(std::int64_t n)
{
    const std::int64_t first = n / kBodyStepsPerWaterSample * kBodyStepsPerWaterSample;
    detail::BodyWater& w = *water_;
    if (w.firstStep == first)
        return;
    const std::int64_t last = first + kBodyStepsPerWaterSample;
    const glm::dvec2 a = carriedAt(first), b = carriedAt(last);
    const double t1 = double(last) * kBodyStep_s;
    // The last sampling carries on when the body stays inside its square;
    // else both ends are sampled again round the middle of the interval.
    if (w.firstStep == first - kBodyStepsPerWaterSample && w.to.covers(a, reach_m_) && w.to.covers(b, reach_m_)) {
        w.from = w.to;
        w.to = sampleWater(*surface_, w.from.centre_m, w.from.halfSize_m, t1, filter_);
    } else {
        const double half = reach_m_ + std::max(0.5, kPatchMarginOfReach * reach_m_) + 0.5 * glm::length(b - a);
        const glm::dvec2 centre = 0.5 * (a + b);
        w.from = sampleWater(*surface_, centre, half, double(first) * kBodyStep_s, filter_);
        w.to = sampleWater(*surface_, centre, half, t1, filter_);
    }
    w.firstStep = first;
}

void FloatingBody::step()
{
    const BodyState& s = next_;
    const glm::dmat3 R = glm::mat3_cast(s.orientation);
    const glm::dvec2 xz(s.centerOfMass_m.x, s.centerOfMass_m.z);
    sampleWaterFor(s.step);
    const detail::BodyWater& sampled = *water_;
    const double within = double(s.step - sampled.firstStep) / kBodyStepsPerWaterSample;
    const detail::WaterPatch water = detail::blend(sampled.from, sampled.to, within);
    std::vector<glm::dvec3> world(points_m_.size());
    for (std::size_t i = 0; i < world.size(); ++i)
        world[i] = s.centerOfMass_m + R * points_m_[i];
    const detail::HydrostaticLoad load = hydrostaticLoad(world, indices_, s.centerOfMass_m, water, waterDensity_);

    // Damping acts only on the wetted body: scaled by how much of its rest
    // displacement is under water, and relative to the water's own heave.
    const double wetted = std::clamp(load.submergedVolume_m3 * waterDensity_ / mass_kg_, 0.0, 1.0);
    const double waterHeave_m_per_s =
        (sampled.to.heightAt(xz) - sampled.from.heightAt(xz)) / (kBodyStepsPerWaterSample * kBodyStep_s);

    BodyState n = s;
    n.step = s.step + 1;
    const double heaveForce_N = load.force_N.y - mass_kg_ * kGravity -
                                wetted * heaveDamping_ * (s.heaveVelocity_m_per_s - waterHeave_m_per_s);
    n.heaveVelocity_m_per_s = s.heaveVelocity_m_per_s + heaveForce_N / mass_kg_ * kBodyStep_s;
    n.centerOfMass_m.y = s.centerOfMass_m.y + n.heaveVelocity_m_per_s * kBodyStep_s;
    const glm::dvec2 carried = carriedAt(n.step);
    n.centerOfMass_m.x = carried.x;
    n.centerOfMass_m.z = carried.y;

    const glm::dvec3 w = s.angularVelocity_rad_per_s;
    const glm::dvec3 dampingTorque = R * (rotationDamping_ * (glm::transpose(R) * w));
    const glm::dvec3 torque = load.torque_N_m - wetted * dampingTorque;
    const glm::dmat3 inertia = R * inertiaBody_ * glm::transpose(R);
    const glm::dmat3 inverseInertia = R * inverseInertiaBody_ * glm::transpose(R);
    n.angularVelocity_rad_per_s = w + inverseInertia * (torque - glm::cross(w, inertia * w)) * kBodyStep_s;
    const glm::dvec3 w1 = n.angularVelocity_rad_per_s;
    n.orientation = glm::normalize(s.orientation + 0.5 * kBodyStep_s * (glm::dquat(0.0, w1) * s.orientation));

    previous_ = s;
    next_ = n;
    ++stepsTaken_;
}

std::int64_t FloatingBody::lastStepFor(double time_s)
{
    // The step whose end is the first after time_s: state k covers
    // [(k - 1) dt, k dt). Computed from time_s alone, never from earlier calls.
    // Negative, NaN and infinite times (no frame asks for them) are t = 0 rather than undefined.
    const double t = std::isfinite(time_s) && time_s > 0.0 ? time_s : 0.0;
    return std::int64_t(std::floor(t * kBodyStepsPerSecond)) + 1;
}

void FloatingBody::advanceToStep(std::int64_t last)
{
    if (last < next_.step)
        restart();
    while (next_.step < last)
        step();
}

glm::dmat4 FloatingBody::poseAt(double time_s)
{
    const std::int64_t last = lastStepFor(time_s);
    advanceToStep(last);
    const double t = std::isfinite(time_s) && time_s > 0.0 ? time_s : 0.0;
    const double f = t * kBodyStepsPerSecond - double(last - 1);
    const glm::dvec3 com = glm::mix(previous_.centerOfMass_m, next_.centerOfMass_m, f);
    const glm::dquat q = glm::slerp(previous_.orientation, next_.orientation, f);
    return glm::translate(glm::dmat4(1.0), com) * glm::mat4_cast(q) *
           glm::translate(glm::dmat4(1.0), -centerOfMassInShape_m_);
}

} // namespace swell
