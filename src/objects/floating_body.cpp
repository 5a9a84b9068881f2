// A rigid body on the water, stepped at a fixed rate (swell/floating_body.h).
//
// Each step is semi-implicit (symplectic) Euler: velocities from the forces
// at the start of the step, then positions from the new velocities; it keeps
// an undamped oscillator's energy bounded, where explicit Euler would pump it
// up (Hairer, Lubich & Wanner 2006, Geometric Numerical Integration, ch. I.1).
// Rotation follows Euler's equations, I dw/dt = tau - w x I w, in the body
// frame, with the gyroscopic and damping torques at the step's end (see
// step()), and dq/dt = 1/2 (0, w) q for the orientation. The damping of heave
// is taken at the step's end too, so no damping however strong can overshoot.
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

#include "objects/hull_simplify.h"
#include "objects/hydrostatics.h"
#include "swell/constants.h"
#include "swell/error.h"

#include <fmt/format.h>
#include <glm/geometric.hpp>
#include <glm/gtc/constants.hpp>
#include <glm/gtc/matrix_transform.hpp>
#include <glm/matrix.hpp>
#include <glm/trigonometric.hpp>

#include <algorithm>
#include <cmath>
#include <vector>

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

// The orientations a body's check visits: each of these directions of the
// body's own frame pointing up (the faces, edges and corners of a cube), so
// that every axis of the body, its least inertia's included, lies
// horizontal in some of them, as it does once a body tumbles.
std::vector<glm::dquat> checkedOrientations()
{
    // The shortest rotation taking unit vector `from` to unit vector `to`.
    auto turning = [](glm::dvec3 from, glm::dvec3 to) {
        const double c = glm::dot(from, to);
        if (c < -1.0 + 1e-12) // opposite: half a turn about any perpendicular axis
            return glm::angleAxis(glm::pi<double>(), glm::dvec3(1.0, 0.0, 0.0));
        return glm::angleAxis(std::acos(std::min(c, 1.0)), c > 1.0 - 1e-12 ? glm::dvec3(1.0, 0.0, 0.0)
                                                                          : glm::normalize(glm::cross(from, to)));
    };
    std::vector<glm::dquat> orientations;
    for (int x = -1; x <= 1; ++x)
        for (int y = -1; y <= 1; ++y)
            for (int z = -1; z <= 1; ++z)
                if (x != 0 || y != 0 || z != 0)
                    orientations.push_back(turning(glm::normalize(glm::dvec3(x, y, z)), glm::dvec3(0.0, 1.0, 0.0)));
    return orientations;
}

// Throws BodyError when the body's fastest oscillation, in heave or in heel,
// is faster than the steps can follow (kMaxBodyOmegaStep): a hull of cubic
// metres weighing a gram would otherwise gain energy every step until its
// state overflowed. The stiffness is measured in every checked orientation
// at drafts from the body clear of the water to the body under it (the
// waterplane, and so the stiffness, is largest at some draft and
// orientation, rarely the rest's), the heel about four horizontal axes
// against the inertia about each. loadAt(y, q) is the hydrostatic load with
// the centre of mass at height y and the orientation q.
template <class LoadAt>
void checkStepFollows(LoadAt loadAt, double waterHere_m, double reach_m, double mass_kg, double volume_m3,
                      const glm::dmat3& inertiaBody_kg_m2)
{
    const double omegaMax_rad_per_s = kMaxBodyOmegaStep / kBodyStep_s;
    const double limit = omegaMax_rad_per_s * omegaMax_rad_per_s;
    const double shortestPeriod_s = 2.0 * glm::pi<double>() / omegaMax_rad_per_s;
    auto period_s = [](double inertia, double stiffness) { return 2.0 * glm::pi<double>() * std::sqrt(inertia / stiffness); };
    constexpr int kDrafts = 8;
    const double h_m = 2.0 * reach_m / kDrafts;
    const std::vector<glm::dquat> orientations = checkedOrientations();
    double heave_N_per_m = 0.0;
    for (const glm::dquat& q : orientations)
        for (int i = 0; i < kDrafts; ++i) {
            const double y = waterHere_m - reach_m + (i + 0.5) * h_m;
            heave_N_per_m =
                std::max(heave_N_per_m, (loadAt(y - 0.5 * h_m, q).force_N.y - loadAt(y + 0.5 * h_m, q).force_N.y) / h_m);
        }
    const double minimumMass_kg = heave_N_per_m / limit;
    if (mass_kg < minimumMass_kg)
        throw BodyError(BodyError::Setting::Mass,
                        fmt::format("too light for the fixed step of 1/{} s: the water's stiffness of {:.4g} N/m would "
                                    "heave {:.4g} kg with a period of {:.3g} s, and the steps follow periods down to "
                                    "{:.3g} s; it needs at least {:.4g} kg ({:.4g} kg/m^3 over its {:.4g} m^3)",
                                    kBodyStepsPerSecond, heave_N_per_m, mass_kg, period_s(mass_kg, heave_N_per_m),
                                    shortestPeriod_s, minimumMass_kg, minimumMass_kg / volume_m3, volume_m3));

    for (const glm::dquat& q : orientations) {
        const glm::dmat3 R = glm::mat3_cast(q);
        const glm::dmat3 inertiaWorld = R * inertiaBody_kg_m2 * glm::transpose(R);
        for (int i = 0; i < kDrafts; ++i) {
            const double y = waterHere_m - reach_m + (i + 0.5) * h_m;
            // Heel: about horizontal axes only (the pressure's forces are
            // vertical, so they never turn a body about the vertical).
            for (const glm::dvec3& axis : {glm::dvec3(1.0, 0.0, 0.0), glm::dvec3(0.0, 0.0, 1.0),
                                           glm::normalize(glm::dvec3(1.0, 0.0, 1.0)),
                                           glm::normalize(glm::dvec3(1.0, 0.0, -1.0))}) {
                const double inertia = glm::dot(axis, inertiaWorld * axis);
                const glm::dquat tilt = glm::angleAxis(kStiffnessTilt_rad, axis);
                const double plus = glm::dot(loadAt(y, tilt * q).torque_N_m, axis);
                const double minus = glm::dot(loadAt(y, glm::inverse(tilt) * q).torque_N_m, axis);
                const double heel_N_m_per_rad = std::abs(minus - plus) / (2.0 * kStiffnessTilt_rad);
                if (heel_N_m_per_rad > inertia * limit)
                    throw BodyError(
                        BodyError::Setting::Inertia,
                        fmt::format("too little inertia for the fixed step of 1/{} s: heeled in the water, it meets a "
                                    "stiffness of {:.4g} N m/rad that would turn its {:.4g} kg m^2 about that axis "
                                    "with a period of {:.3g} s, and the steps follow periods down to {:.3g} s; it "
                                    "needs at least {:.4g} kg m^2 about each axis (more mass, or its mass further out)",
                                    kBodyStepsPerSecond, heel_N_m_per_rad, inertia, period_s(inertia, heel_N_m_per_rad),
                                    shortestPeriod_s, heel_N_m_per_rad / limit));
            }
        }
    }
}

} // namespace

FloatingBody::FloatingBody(const BodyShape& shape, const BodySettings& settings, const BodyStart& start,
                           const SurfaceQuery& surface, const SurfaceFilter& filter)
    : start_(start), surface_(&surface), filter_(filter)
{
    const MassProperties props = massPropertiesOf(shape);
    if (!(settings.mass_kg > 0.0) || !std::isfinite(settings.mass_kg))
        throw InputError({}, fmt::format("a floating body needs a mass > 0 kg (got {})", settings.mass_kg));
    mass_kg_ = settings.mass_kg;
    volume_m3_ = props.volume_m3;
    waterDensity_ = settings.waterDensity_kg_per_m3;
    // As heavy as the water it displaces, it floats awash (BODIES.md); heavier, it sinks.
    if (mass_kg_ > waterDensity_ * volume_m3_)
        throw BodyError(BodyError::Setting::Mass,
                        fmt::format("a body of {:.6g} kg and {:.6g} m^3 sinks: the water it can displace weighs "
                                    "{:.6g} kg",
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

    // The shape about its centre of mass, with at most
    // kMaxHydrostaticTriangles for the pressure's sum (hull_simplify.h).
    for (const glm::dvec3& p : shape.positions_m)
        reach_m_ = std::max(reach_m_, glm::length(p - centerOfMassInShape_m_));
    const BodyShape hull = detail::hydrostaticHull(shape, props.volume_m3, props.centroid_m);
    points_m_.reserve(hull.positions_m.size());
    for (const glm::dvec3& p : hull.positions_m) {
        points_m_.push_back(p - centerOfMassInShape_m_);
        reach_m_ = std::max(reach_m_, glm::length(points_m_.back())); // scaled to the volume, a hair further out
    }
    indices_ = hull.indices; // wound outwards: massPropertiesOf() refuses a shape wound inside out

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
    // Under way, the helm: a critically damped spring on the heading. Its
    // inertia is the one a torque about the vertical turns (q0 is a turn
    // about it), 1 / (I^-1)_yy, which is less than I_yy when a centre of
    // mass off the body's axes couples yaw to roll and pitch: sized by
    // I_yy, such a body's helm would turn faster than the step follows.
    if (start.velocity_m_per_s.x != 0.0 || start.velocity_m_per_s.z != 0.0) {
        const double omega_rad_per_s = kTwoPi / kHelmPeriod_s;
        const double yawInertia_kg_m2 = 1.0 / glm::inverse(inertiaBody_)[1][1];
        helmStiffness_N_m_per_rad_ = yawInertia_kg_m2 * omega_rad_per_s * omega_rad_per_s;
        helmDamping_N_m_s_ = 2.0 * yawInertia_kg_m2 * omega_rad_per_s;
    }

    checkStepFollows(loadAt, waterHere, reach_m_, mass_kg_, volume_m3_, inertiaBody_);

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
    // The damping at the step's end velocity (implicit): stable however
    // large the damping is against the mass or inertia (the yaw's, borrowed
    // from roll and pitch, can be far larger than a slender body's yaw
    // inertia), where the damping at the start's velocity would overshoot.
    const double heaveDamping_N_s_per_m = wetted * heaveDamping_;
    n.heaveVelocity_m_per_s =
        (s.heaveVelocity_m_per_s +
         (load.force_N.y - mass_kg_ * kGravity + heaveDamping_N_s_per_m * waterHeave_m_per_s) / mass_kg_ * kBodyStep_s) /
        (1.0 + heaveDamping_N_s_per_m / mass_kg_ * kBodyStep_s);
    n.centerOfMass_m.y = s.centerOfMass_m.y + n.heaveVelocity_m_per_s * kBodyStep_s;
    const glm::dvec2 carried = carriedAt(n.step);
    n.centerOfMass_m.x = carried.x;
    n.centerOfMass_m.z = carried.y;

    // Euler's equations in the body frame, I dw/dt = tau - w x I w - D w,
    // with the gyroscopic and damping torques taken at the step's end:
    // f(w1) = I (w1 - w) + dt (w1 x I w1 + D w1 - tau) = 0, solved by one
    // Newton step from w (Catto 2015, "Numerical Methods", GDC physics
    // tutorial: implicit gyroscopic torque). Taken at the step's start,
    // they add energy to a body whose moments differ by orders of magnitude
    // (a centre of mass far off a small hull) until it spins without bound.
    const glm::dmat3 Rt = glm::transpose(R);
    const glm::dvec3 wBody = Rt * s.angularVelocity_rad_per_s;
    glm::dvec3 torque_N_m = load.torque_N_m;
    glm::dmat3 damping(wetted * rotationDamping_.x, 0.0, 0.0, 0.0, wetted * rotationDamping_.y, 0.0, 0.0, 0.0,
                       wetted * rotationDamping_.z);
    if (helmStiffness_N_m_per_rad_ > 0.0) {
        // The heading, as yaw_deg measures it: the bow (body +x) turned from
        // +x towards -z about +y. Its error is taken the short way round.
        // Both taken at the step's end, as the damping is: the heading then
        // is the error plus dt times the yaw rate, so the spring adds k dt
        // to the damping about the vertical (in body axes), and neither can
        // add energy however the body's inertia couples yaw to heel.
        const glm::dvec3 bow = R * glm::dvec3(1.0, 0.0, 0.0);
        if (bow.x * bow.x + bow.z * bow.z > 1e-12) {
            const double error_rad =
                std::remainder(std::atan2(-bow.z, bow.x) - glm::radians(start_.yaw_deg), kTwoPi);
            torque_N_m.y -= helmStiffness_N_m_per_rad_ * error_rad;
        }
        const glm::dvec3 up = Rt * glm::dvec3(0.0, 1.0, 0.0);
        damping += (helmDamping_N_m_s_ + helmStiffness_N_m_per_rad_ * kBodyStep_s) * glm::outerProduct(up, up);
    }
    const glm::dvec3 torqueBody = Rt * torque_N_m;
    auto skew = [](glm::dvec3 v) { return glm::dmat3(0.0, v.z, -v.y, -v.z, 0.0, v.x, v.y, -v.x, 0.0); };
    const glm::dvec3 residual =
        kBodyStep_s * (glm::cross(wBody, inertiaBody_ * wBody) + damping * wBody - torqueBody);
    const glm::dmat3 jacobian =
        inertiaBody_ + kBodyStep_s * (skew(wBody) * inertiaBody_ - skew(inertiaBody_ * wBody) + damping);
    n.angularVelocity_rad_per_s = R * (wBody - glm::inverse(jacobian) * residual);
    const glm::dvec3 w1 = n.angularVelocity_rad_per_s;
    n.orientation = glm::normalize(s.orientation + 0.5 * kBodyStep_s * (glm::dquat(0.0, w1) * s.orientation));
    // The boundary: a state that is not finite never reaches the water's
    // lookup (where a NaN would become an index) or a frame.
    const double numbers[] = {n.heaveVelocity_m_per_s,      n.centerOfMass_m.y,           n.angularVelocity_rad_per_s.x,
                              n.angularVelocity_rad_per_s.y, n.angularVelocity_rad_per_s.z, n.orientation.w,
                              n.orientation.x,               n.orientation.y,               n.orientation.z};
    const bool finite = std::all_of(std::begin(numbers), std::end(numbers), [](double x) { return std::isfinite(x); });
    if (!finite)
        throw Error(fmt::format("a floating body of {:.6g} kg: its state stopped being finite at t = {:.6g} s", mass_kg_,
                                double(n.step) * kBodyStep_s));

    previous_ = s;
    next_ = n;
    ++stepsTaken_;
}

FloatingBody::PointMotion FloatingBody::pointAt(glm::dvec3 shapePoint_m) const
{
    // The velocity the last step moved it with: its path between the two
    // states, as poseAt() interpolates it (rigid: the centre of mass's
    // velocity plus the turn's, but exactly what the drawn poses do).
    auto place = [&](const BodyState& s) { return s.centerOfMass_m + s.orientation * (shapePoint_m - centerOfMassInShape_m_); };
    PointMotion m;
    m.position_m = place(next_);
    if (next_.step > previous_.step)
        m.velocity_m_per_s = (m.position_m - place(previous_)) / (double(next_.step - previous_.step) * kBodyStep_s);
    return m;
}

FloatingBody::WaterMotion FloatingBody::waterAt(glm::dvec2 xz_m) const
{
    // The samples bracket the last step's start (step() sampled for it):
    // its end lies within them too, at most at `to`.
    const detail::BodyWater& w = *water_;
    if (w.firstStep < 0)
        return {};
    const double sample_s = kBodyStepsPerWaterSample * kBodyStep_s;
    const double within = std::clamp(double(next_.step - w.firstStep) / kBodyStepsPerWaterSample, 0.0, 1.0);
    const double from = w.from.heightAt(xz_m), to = w.to.heightAt(xz_m);
    return {from + (to - from) * within, (to - from) / sample_s};
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

FloatingBody::Acceleration FloatingBody::accelerationAt(double time_s) const
{
    const double t = std::isfinite(time_s) && time_s > 0.0 ? time_s : 0.0;
    const double f = std::clamp(t * kBodyStepsPerSecond - double(next_.step - 1), 0.0, 1.0);
    Acceleration a;
    a.centerOfMass_m = glm::mix(previous_.centerOfMass_m, next_.centerOfMass_m, f);
    if (next_.step <= previous_.step)
        return a;
    const double span_s = double(next_.step - previous_.step) * kBodyStep_s;
    // Carried at a constant velocity across the water: only the heave changes.
    a.centerOfMass_m_per_s2.y = (next_.heaveVelocity_m_per_s - previous_.heaveVelocity_m_per_s) / span_s;
    a.angular_rad_per_s2 = (next_.angularVelocity_rad_per_s - previous_.angularVelocity_rad_per_s) / span_s;
    return a;
}

FloatingBody::Velocity FloatingBody::velocityAt(double time_s) const
{
    const double t = std::isfinite(time_s) && time_s > 0.0 ? time_s : 0.0;
    const double f = std::clamp(t * kBodyStepsPerSecond - double(next_.step - 1), 0.0, 1.0);
    const glm::dquat q = glm::slerp(previous_.orientation, next_.orientation, f);
    // The centre of mass: carried at the start's horizontal velocity, heaving at the state's.
    const glm::dvec3 centre(start_.velocity_m_per_s.x, next_.heaveVelocity_m_per_s, start_.velocity_m_per_s.z);
    const glm::dvec3 w = next_.angularVelocity_rad_per_s;
    // The shape's origin stands at -centerOfMassInShape_m_ from the centre of mass, turned.
    return {centre + glm::cross(w, q * -centerOfMassInShape_m_), w};
}

} // namespace swell
