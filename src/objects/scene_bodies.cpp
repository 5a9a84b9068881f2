// A scene's floating bodies (scene_bodies.h).
#include "objects/scene_bodies.h"

#include "core/fleet.h"
#include "core/worker.h"
#include "objects/design_loading.h"
#include "swell/composed_surface.h"
#include "swell/error.h"
#include "swell/scene/grid.h"
#include "swell/scene/parameters.h"

#include <fmt/format.h>
#include <glm/geometric.hpp>
#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/quaternion.hpp>
#include <glm/trigonometric.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <exception>
#include <functional>
#include <utility>

namespace swell::detail {

SurfaceFilter bodySurfaceFilter(const Scene& scene)
{
    const GridShape shape = gridShapeFor(scene.grid, scene.camera);
    const GridPlacement atScaleOne = placeGrid(shape, glm::dvec3(0.0));
    const int centre = shape.cells / 2;
    return {gridPoint(shape, atScaleOne, centre, centre).cellSize_m, 1.0};
}

bool sameBodies(const Scene& a, const Scene& b)
{
    if (a.objects.size() != b.objects.size())
        return false;
    // What moves the bodies is what the parameter table says it is.
    for (const Parameter& p : parameters()) {
        if (!hasEffect(p.effect, ParameterEffect::Bodies))
            continue;
        if (p.list == ParameterList::Objects) {
            for (std::size_t i = 0; i < a.objects.size(); ++i)
                if ((a.objects[i].isRigidBody() || b.objects[i].isRigidBody()) && p.get(a, i) != p.get(b, i))
                    return false;
            continue;
        }
        if (isPresent(p, a) != isPresent(p, b) || listSize(a, p.list) != listSize(b, p.list))
            return false;
        if (!isPresent(p, a))
            continue;
        for (std::size_t i = 0; i < listSize(a, p.list); ++i)
            if (p.get(a, i) != p.get(b, i))
                return false;
    }
    return true;
}

namespace {

// The samples a bow keeps: the spray's history, and those the worker may
// have taken ahead of the frame drawn (SceneBodies::kMaxStepAhead_s), so a
// step ahead never overwrites one the frame still reads.
constexpr std::size_t kBowSamplesKept =
    SWELL_BOW_SPRAY_HISTORY + std::size_t(SceneBodies::kMaxStepAhead_s * SWELL_BOW_SPRAY_SAMPLES_PER_S) + 2;

} // namespace

SceneBodies::AheadHandle::AheadHandle(AheadHandle&& other) noexcept : ahead(std::move(other.ahead))
{
    if (ahead)
        ahead->wait(); // the worker writes to the bodies being moved from until it is done
}

SceneBodies::AheadHandle& SceneBodies::AheadHandle::operator=(AheadHandle&& other) noexcept
{
    // Both workers stop writing to their bodies before any other member is
    // assigned (this handle is the first member); this one's is joined as it goes.
    if (this != &other) {
        if (ahead)
            ahead->wait();
        if (other.ahead)
            other.ahead->wait();
        ahead = std::move(other.ahead);
    }
    return *this;
}

SceneBodies::AheadHandle::AheadHandle() = default;
SceneBodies::AheadHandle::~AheadHandle() = default;

SceneBodies::SceneBodies(SceneBodies&&) noexcept = default;
SceneBodies& SceneBodies::operator=(SceneBodies&&) noexcept = default;

SceneBodies::~SceneBodies()
{
    // Before any member goes: the worker may be stepping them.
    if (ahead_.ahead)
        ahead_.ahead->wait();
}

void SceneBodies::settle() const
{
    if (ahead_.ahead)
        ahead_.ahead->rethrow();
}

double SceneBodies::aheadCpu_ms() const { return ahead_.ahead ? ahead_.ahead->cpu_ms() : 0.0; }

void SceneBodies::stepAheadTo(double time_s)
{
    settle();
    // Never before the last time asked (that would start the bodies
    // again), never further past it than the bows keep samples for.
    const double target_s = std::min(time_s, lastAsked_s_ + kMaxStepAhead_s);
    if (!(target_s > lastAsked_s_) || bodies_.empty() || count_ == 0)
        return;
    if (!ahead_.ahead)
        ahead_.ahead = std::make_unique<Worker>();
    ahead_.ahead->start([this, target_s] {
        advanceNow(target_s);
        // The frame there too, which the next advanceTo() would otherwise blend on the calling thread.
        if (wake_) {
            aheadFrame_ = std::make_shared<const WakeFrame>(wake_->frameAt(clock_s(target_s)));
            aheadFrameTime_s_ = target_s;
        }
    });
}

double SceneBodies::clock_s(double time_s) const { return std::max(0.0, time_s - start_s_); }

WakeFrame SceneBodies::wakeFrameAt(double time_s) const
{
    settle();
    return wake_->frameAt(clock_s(time_s));
}

std::shared_ptr<const WakeFrame> SceneBodies::sharedWakeFrameAt(double time_s) const
{
    settle();
    if (aheadFrame_ && aheadFrameTime_s_ == time_s)
        return aheadFrame_;
    return std::make_shared<const WakeFrame>(wake_->frameAt(clock_s(time_s)));
}

SceneBodies::SceneBodies(const Scene& scene, const std::vector<const MeshData*>& shapes,
                         std::shared_ptr<const SurfaceQuery> surface, std::shared_ptr<const Seabed> seabed)
    : start_s_(bodiesStart_s(scene))
{
    const SurfaceFilter filter = bodySurfaceFilter(scene);
    // A wake when some body is under way; its grid follows the first that is.
    bool underWay = false;
    for (std::size_t i = 0; i < scene.objects.size() && !underWay; ++i) {
        const SceneObject& o = scene.objects[i];
        const glm::dvec2 v(o.velocity_m_per_s.x, o.velocity_m_per_s.z);
        if (o.isRigidBody() && i < shapes.size() && shapes[i] && glm::length(v) > 0.0) {
            underWay = true;
            leader_ = i;
            leaderDirection_ = glm::normalize(v);
        }
    }
    if (scene.wake.enabled && underWay)
        wake_ = std::make_unique<SceneWake>(scene.wake, scene.sea.depth_m,
                                            seabed && seabed->extent() ? std::move(seabed) : nullptr);
    // The waves on the bodies' clock (their time t is the scene's t +
    // start_s, so the bodies step from 0 whenever the history starts), plus
    // the wake, which runs on that clock.
    std::vector<std::shared_ptr<const SurfaceSource>> wake;
    if (wake_)
        wake.push_back(std::make_shared<const SceneWakeSource>(*wake_));
    floatsOn_ = std::make_shared<const ComposedSurface>(std::move(surface), std::move(wake), start_s_);
    const SurfaceQuery& floatsOn = *floatsOn_;
    for (std::size_t i = 0; i < scene.objects.size(); ++i) {
        const SceneObject& o = scene.objects[i];
        scale_.push_back(o.scale);
        footprints_.emplace_back();
        if (!o.isRigidBody() || i >= shapes.size() || shapes[i] == nullptr) {
            bodies_.emplace_back();
            continue;
        }
        try {
            BodyShape shape;
            for (const MeshVertex& v : shapes[i]->vertices)
                shape.positions_m.push_back(glm::dvec3(v.position) * o.scale);
            shape.indices = shapes[i]->indices;
            BodySettings settings;
            settings.mass_kg = o.mass_kg > 0.0 ? o.mass_kg : o.density_kg_per_m3 * massPropertiesOf(shape).volume_m3;
            settings.centerOfMassOffset_m = o.centerOfMassOffset_m * o.scale;
            if (isFleetPath(o.path) && !(o.mass_kg > 0.0) && !(o.density_kg_per_m3 > 0.0)) {
                // One of the fleet, loaded to its design draft: its shape
                // is already stretched as the scene asks, and scaled here.
                const FleetDesign& design = fleetDesign(std::string_view(o.path).substr(kBuiltinObjectPrefix.size()));
                const DesignLoading loading =
                    designLoadingOf(shape, design.centerOfMass_m.y * o.scale, settings.waterDensity_kg_per_m3);
                settings.mass_kg = loading.mass_kg;
                settings.centerOfMassOffset_m += loading.centerOfMassOffset_m;
            }
            settings.principalInertia_kg_m2 = o.inertia_kg_m2;
            settings.dampingRatio = o.dampingRatio;
            // Where it starts: back along its course by the time until t = 0
            // (x(t) = x0 + v t, docs/BODIES.md, at every t after the start).
            const glm::dvec3 carried(o.velocity_m_per_s.x * start_s_, 0.0, o.velocity_m_per_s.z * start_s_);
            const BodyStart start{o.position_m + carried, o.yaw_deg, o.velocity_m_per_s};
            bodies_.push_back(std::make_unique<FloatingBody>(shape, settings, start, floatsOn, filter));
            ++count_;
            // Its footprint: the shape's half extents along and across its
            // length (model x and z), and the water its weight displaces.
            glm::dvec2 lo(0.0), hi(0.0);
            for (const glm::dvec3& p : shape.positions_m) {
                lo = glm::min(lo, glm::dvec2(p.x, p.z));
                hi = glm::max(hi, glm::dvec2(p.x, p.z));
            }
            footprints_.back() = {0.5 * (hi.x - lo.x), 0.5 * (hi.y - lo.y), settings.mass_kg / settings.waterDensity_kg_per_m3};
            // Under way, its bow: the heading of travel turned into the
            // shape's frame (yaw_deg turns it about +y).
            const glm::dvec2 travel(o.velocity_m_per_s.x, o.velocity_m_per_s.z);
            if (glm::length(travel) > 0.0) {
                const glm::dquat yaw = glm::angleAxis(glm::radians(o.yaw_deg), glm::dvec3(0.0, 1.0, 0.0));
                const glm::dvec3 forward = glm::inverse(yaw) * glm::dvec3(travel.x, 0.0, travel.y);
                if (std::optional<BowLine> line =
                        bowLineOf(shape, settings.mass_kg, settings.waterDensity_kg_per_m3, forward,
                                  glm::length(travel))) {
                    Bow b;
                    b.line = *line;
                    for (int side = 0; side < 2; ++side)
                        for (int k = 0; k < SWELL_BOW_SPRAY_STATIONS; ++k)
                            b.stationsInModel[side][k] = line->stations[side][k] / o.scale;
                    b.velocity_m_per_s = travel;
                    b.samples.assign(kBowSamplesKept, {-1, BowSample{}});
                    bows_.resize(i + 1);
                    bows_[i] = std::move(b);
                }
            }
        } catch (const InputError& e) {
            // The key to change: the mass the object gave, or its inertia;
            // the shape's problems are its path's.
            std::string setting;
            if (const auto* body = dynamic_cast<const BodyError*>(&e)) {
                if (body->setting() == BodyError::Setting::Mass)
                    setting = o.mass_kg > 0.0 ? fmt::format(".mass_kg = {}", o.mass_kg)
                                              : fmt::format(".density_kg_per_m3 = {}", o.density_kg_per_m3);
                else if (body->setting() == BodyError::Setting::Inertia)
                    setting = o.inertia_kg_m2 != glm::dvec3(0.0)
                                  ? fmt::format(".inertia_kg_m2 = [{}, {}, {}]", o.inertia_kg_m2.x, o.inertia_kg_m2.y,
                                                o.inertia_kg_m2.z)
                                  : ".inertia_kg_m2 (from the mesh, at its mass and centre of mass)";
            }
            const std::string key = fmt::format("objects[{}].path", i);
            for (const AssetReference& r : scene.assetReferences)
                if (r.key == key)
                    throw InputError(r.place, fmt::format("objects[{}]{} ({}): {}", i, setting, o.path, e.message()));
            throw InputError({o.path}, fmt::format("objects[{}]{}: {}", i, setting, e.message()));
        }
    }
}

std::vector<WakeSource> SceneBodies::wakeSources() const
{
    std::vector<WakeSource> sources;
    for (std::size_t i = 0; i < bodies_.size(); ++i)
        if (bodies_[i]) {
            const BodyState& s = bodies_[i]->state();
            const glm::dvec3 along = s.orientation * glm::dvec3(1.0, 0.0, 0.0);
            const glm::dvec2 heading = glm::length(glm::dvec2(along.x, along.z)) > 1e-9
                                           ? glm::normalize(glm::dvec2(along.x, along.z))
                                           : glm::dvec2(1.0, 0.0);
            const Footprint& f = footprints_[i];
            sources.push_back({{s.centerOfMass_m.x, s.centerOfMass_m.z}, heading, f.halfLength_m, f.halfBeam_m, f.volume_m3});
        }
    return sources;
}

glm::dvec2 SceneBodies::wakeFocus() const
{
    // The leader a quarter of the grid ahead of its centre: three quarters
    // of the field lie astern, where the wake is.
    const glm::dvec3 at = bodies_[leader_]->state().centerOfMass_m;
    const double size_m = wake_->field().cells() * wake_->field().cellSize_m();
    return glm::dvec2(at.x, at.z) - 0.25 * size_m * leaderDirection_;
}

void SceneBodies::advanceWakeFor(std::int64_t bodyStep)
{
    // Body step n -> n + 1 samples the water at the wake steps bracketing
    // n; wake step k -> k + 1 needs the bodies at body step 4k.
    const std::int64_t needed = bodyStep / kBodyStepsPerWaterSample + 1;
    while (wake_->steps() < needed) {
        const auto start = std::chrono::steady_clock::now();
        wake_->step(wakeSources(), wakeFocus());
        ++wakeStepsTaken_;
        wakeSteps_ms_ += std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
    }
}

void SceneBodies::advanceTo(double sceneTime_s)
{
    settle();
    lastAsked_s_ = sceneTime_s;
    advanceNow(sceneTime_s);
}

void SceneBodies::advanceNow(double sceneTime_s)
{
    const double time_s = clock_s(sceneTime_s);
    // In lockstep, step by step: every body asks for the water at the same
    // sample times one after another (see FloatingBody::advanceToStep).
    // A frame made ahead holds while the wake takes no step.
    const std::int64_t wakeStepsBefore = wakeStepsTaken_;
    struct ForgetFrameOnStep {
        SceneBodies& bodies;
        std::int64_t before;
        ~ForgetFrameOnStep()
        {
            if (bodies.wakeStepsTaken_ != before)
                bodies.aheadFrame_.reset();
        }
    } forget{*this, wakeStepsBefore};
    const std::int64_t last = FloatingBody::lastStepFor(time_s);
    std::int64_t from = last;
    bool wentBack = false;
    for (const auto& b : bodies_)
        wentBack = wentBack || (b && b->state().step > last);
    for (const auto& b : bodies_)
        if (b) {
            if (wentBack)
                b->advanceToStep(0); // time went back: all start again from t = 0
            from = std::min(from, b->state().step);
        }
    if (wake_ && (wentBack || wake_->steps() == 0)) {
        wake_->reset(wakeFocus());
        aheadFrame_.reset();
    }
    for (std::int64_t n = from + 1; n <= last; ++n) {
        if (wake_)
            advanceWakeFor(n - 1);
        for (const auto& b : bodies_)
            if (b && b->state().step < n)
                b->advanceToStep(n);
        sampleBows(n);
    }
    if (wake_)
        advanceWakeFor(last - 1); // the frame's wake: the states that bracket time_s
}

void SceneBodies::sampleBows(std::int64_t step)
{
    // Every water sample: the steps there have the water at its time
    // (FloatingBody::waterAt), not a blend.
    if (step % kBodyStepsPerWaterSample != 0)
        return;
    const std::int64_t index = step / kBodyStepsPerWaterSample;
    for (std::size_t i = 0; i < bows_.size(); ++i)
        if (bows_[i] && bodies_[i] && bodies_[i]->state().step == step)
            bows_[i]->samples[std::size_t(index % kBowSamplesKept)] = {
                index, bowSampleOf(*bodies_[i], bows_[i]->line, bows_[i]->velocity_m_per_s)};
}

std::array<BowSample, SWELL_BOW_SPRAY_HISTORY> SceneBodies::bowHistory(std::size_t i, double time_s, double& lag_s) const
{
    settle();
    static_assert(SWELL_BOW_SPRAY_SAMPLES_PER_S * kBodyStepsPerWaterSample == kBodyStepsPerSecond,
                  "a bow sample is a water sample of the steps");
    std::array<BowSample, SWELL_BOW_SPRAY_HISTORY> history{};
    const double clock = clock_s(time_s);
    const std::int64_t newest = std::int64_t(std::floor(clock * SWELL_BOW_SPRAY_SAMPLES_PER_S));
    lag_s = clock - double(newest) / SWELL_BOW_SPRAY_SAMPLES_PER_S;
    const Bow* b = bow(i);
    if (!b)
        return history;
    for (int j = 0; j < SWELL_BOW_SPRAY_HISTORY; ++j) {
        const std::int64_t index = newest - j;
        if (index < 0)
            break;
        const auto& [kept, sample] = b->samples[std::size_t(index % kBowSamplesKept)];
        if (kept == index)
            history[std::size_t(j)] = sample;
    }
    return history;
}

std::optional<glm::dmat4> SceneBodies::poseAt(std::size_t i, double time_s)
{
    settle();
    if (i >= bodies_.size() || !bodies_[i])
        return std::nullopt;
    return bodies_[i]->poseAt(clock_s(time_s)) * glm::scale(glm::dmat4(1.0), glm::dvec3(scale_[i]));
}

std::optional<FloatingBody::Velocity> SceneBodies::velocityAt(std::size_t i, double time_s) const
{
    settle();
    if (i >= bodies_.size() || !bodies_[i])
        return std::nullopt;
    if (time_s < start_s_)
        return FloatingBody::Velocity{};
    return bodies_[i]->velocityAt(clock_s(time_s));
}

std::optional<FloatingBody::Acceleration> SceneBodies::accelerationAt(std::size_t i, double time_s) const
{
    settle();
    if (i >= bodies_.size() || !bodies_[i])
        return std::nullopt;
    FloatingBody::Acceleration a = bodies_[i]->accelerationAt(clock_s(std::max(time_s, start_s_)));
    if (time_s < start_s_)
        a.centerOfMass_m_per_s2 = a.angular_rad_per_s2 = glm::dvec3(0.0);
    return a;
}

std::int64_t SceneBodies::stepsTaken() const
{
    settle();
    std::int64_t steps = 0;
    for (const auto& b : bodies_)
        if (b)
            steps += b->stepsTaken();
    return steps;
}

} // namespace swell::detail
