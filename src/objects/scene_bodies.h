// The floating rigid bodies of a scene (SceneObject::isRigidBody()), one
// swell::FloatingBody each, built from the objects' closed shapes and kept
// stepping by the renderer, which asks for their poses once a frame.
//
// Their steps, the wake's and the water samples they take can run ahead on
// a worker thread of their own (stepAheadTo) while the frame is drawn: the
// same steps in the same order as advanceTo() takes them, each a function
// of the scene and its step number alone, so what any call returns does not
// depend on whether or when they ran ahead. Every other call waits for the
// worker first; only one thread calls a SceneBodies.
#pragma once

#include "assets/mesh_data.h"
#include "objects/bow_spray.h"
#include "objects/scene_wake.h"
#include "swell/floating_body.h"
#include "swell/scene/scene.h"

#include <glm/mat4x4.hpp>

#include <array>
#include <cstdint>
#include <limits>
#include <memory>
#include <optional>
#include <vector>

namespace swell::detail {

class Worker;

// The surface bodies float on: the one the water grid draws next to the
// camera (the filter of its finest cells at scale 1), without the horizon
// fade. From the scene's settings alone, so a body's motion does not depend
// on where a viewer's camera wanders.
SurfaceFilter bodySurfaceFilter(const Scene& scene);

// Whether two scenes' objects would move alike: as many objects, and the
// same values of every parameter the table marks ParameterEffect::Bodies
// (an object's only where it is a rigid body in either scene). Paths and
// hull nodes are the assets' (ParameterEffect::World).
bool sameBodies(const Scene& a, const Scene& b);

class SceneBodies {
public:
    SceneBodies() = default;
    // shapes[i]: object i's closed shape in model space (its hull volume,
    // else its mesh); read only for rigid bodies. `surface`: the water on
    // the scene's clock (the waves, plus a host's sources). With scene.wake
    // on and a body under way, the bodies stir a wake field and float on the
    // surface plus it (objects/scene_wake.h). Throws swell::InputError at
    // the object's path key (or naming the object) when a body cannot be
    // built. The wake feels `seabed` where it has a shape (null: the sea's
    // depth everywhere).
    SceneBodies(const Scene& scene, const std::vector<const MeshData*>& shapes,
                std::shared_ptr<const SurfaceQuery> surface, std::shared_ptr<const Seabed> seabed = nullptr);

    SceneBodies(SceneBodies&&) noexcept;
    SceneBodies& operator=(SceneBodies&&) noexcept;
    ~SceneBodies();

    bool empty() const { return count_ == 0; }
    std::size_t count() const { return count_; }
    // Steps every body to time_s together (see FloatingBody::advanceToStep).
    void advanceTo(double time_s);
    // Starts advanceTo(time_s) on the worker thread and returns at once:
    // for a host that knows the next frame's time, to step towards it while
    // this frame is drawn. The next call of any other kind waits for it
    // (and throws what it threw). Asking for a time before the last
    // advanceTo()'s would start the bodies again from their start, so such
    // a time, or one more than kMaxStepAhead_s past it, is clamped there;
    // nothing runs ahead of a time the next frame then goes back before
    // (the bodies would start again, as they do when time goes back).
    // Until the next advanceTo(), poses and the wake's frame are asked for
    // at that time or later (the bows' histories at any time drawn since).
    void stepAheadTo(double time_s);
    // How far ahead of the last advanceTo() the worker may step, s: the
    // bows keep their samples that much longer (bowHistory).
    static constexpr double kMaxStepAhead_s = 0.5;
    // The CPU time the worker thread has spent so far, ms (its own clock,
    // CLOCK_THREAD_CPUTIME_ID; for the benchmark).
    double aheadCpu_ms() const;
    // Object i's transform from model space (scale included) to the world at
    // time_s, stepping its body there; nothing when it is not a rigid body.
    std::optional<glm::dmat4> poseAt(std::size_t i, double time_s);
    // How object i moves at time_s, sea frame (its model origin's velocity,
    // m/s, and its angular velocity, rad/s), once poseAt(i, time_s) has
    // stepped it there (FloatingBody::velocityAt); zero before the bodies'
    // start, where they wait; nothing when it is not a rigid body.
    std::optional<FloatingBody::Velocity> velocityAt(std::size_t i, double time_s) const;
    // Its accelerations at time_s, sea frame (FloatingBody::accelerationAt),
    // on the same terms; zero before the bodies' start.
    std::optional<FloatingBody::Acceleration> accelerationAt(std::size_t i, double time_s) const;
    // Integration steps taken by all bodies so far.
    std::int64_t stepsTaken() const;

    // What the bodies float on, on their clock (startTime_s() is its 0): the
    // surface they were given plus the wake.
    const SurfaceQuery& surface() const
    {
        settle();
        return *floatsOn_;
    }

    // The wake, when the scene has one (wake on, a body under way); else null.
    // It runs on the bodies' own clock, from 0 at their start (startTime_s()).
    const SceneWake* wake() const
    {
        settle();
        return wake_.get();
    }
    // The wake's frame at scene time time_s (the wake must exist).
    WakeFrame wakeFrameAt(double time_s) const;
    // The same, shared: the one the worker made after its step ahead when
    // that was to time_s (the same numbers: the wake has not stepped since),
    // else made now.
    std::shared_ptr<const WakeFrame> sharedWakeFrameAt(double time_s) const;
    // When the bodies and the wake start, scene time, s (swell::bodiesStart_s):
    // each starts from rest there, at its position_m less velocity times the
    // time until t = 0, so that it passes position_m at t = 0.
    double startTime_s() const { return start_s_; }
    // Wake steps taken so far (restarts included), for the benchmark.
    std::int64_t wakeStepsTaken() const
    {
        settle();
        return wakeStepsTaken_;
    }
    // The wall time those steps took, ms (for the benchmark; never read by the simulation).
    double wakeSteps_ms() const
    {
        settle();
        return wakeSteps_ms_;
    }

    // A body under way's bow (objects/bow_spray.h), for the bow's spray.
    struct Bow {
        BowLine line; // in the body's shape frame (the object's scaled)
        // line.stations in the object's model frame: what its pose (poseAt) places.
        std::array<std::array<glm::dvec3, SWELL_BOW_SPRAY_STATIONS>, 2> stationsInModel{};
        glm::dvec2 velocity_m_per_s{0.0}; // over the ground, x, z
        // Its samples, one a water sample of the steps, each kept with its
        // index (a step of SWELL_BOW_SPRAY_SAMPLES_PER_S) in slot index % size
        // (the spray's SWELL_BOW_SPRAY_HISTORY, and those taken ahead).
        std::vector<std::pair<std::int64_t, BowSample>> samples;
    };
    // Object i's bow when it is a body under way (else null).
    const Bow* bow(std::size_t i) const
    {
        settle();
        return i < bows_.size() && bows_[i] ? &*bows_[i] : nullptr;
    }
    // Its samples at scene time time_s, newest first, one every
    // 1 / SWELL_BOW_SPRAY_SAMPLES_PER_S s (a sample not taken yet, before
    // the bodies' start, holds nothing); lag_s: the newest one's age at time_s.
    std::array<BowSample, SWELL_BOW_SPRAY_HISTORY> bowHistory(std::size_t i, double time_s, double& lag_s) const;

    // Waits for the worker (a no-op when none runs); rethrows what its
    // step ahead threw. Every other call does this first.
    void settle() const;

private:
    // The worker thread (core/worker.h), started on the first step ahead;
    // declared first, so that a move waits for the worker before any other
    // member moves.
    struct AheadHandle {
        std::unique_ptr<Worker> ahead;
        AheadHandle();
        AheadHandle(AheadHandle&& other) noexcept;
        AheadHandle& operator=(AheadHandle&& other) noexcept;
        ~AheadHandle();
    };
    AheadHandle ahead_;
    // The time of the last advanceTo() (-inf before any), s, scene time.
    double lastAsked_s_ = -std::numeric_limits<double>::infinity();
    // The wake's frame the worker made at the time it stepped ahead to
    // (null when the wake has stepped since, or there is none).
    std::shared_ptr<const WakeFrame> aheadFrame_;
    double aheadFrameTime_s_ = 0.0;

    // advanceTo() without the wait, on whichever thread.
    void advanceNow(double time_s);
    // Samples each bow at body step `step` when it is a water sample's.
    void sampleBows(std::int64_t step);
    // What each body's footprint on the wake is, besides where it stands.
    struct Footprint {
        double halfLength_m = 0.0, halfBeam_m = 0.0, volume_m3 = 0.0;
    };
    std::vector<WakeSource> wakeSources() const;
    glm::dvec2 wakeFocus() const;
    // Steps the wake until the bodies can sample the water for body step `bodyStep`.
    void advanceWakeFor(std::int64_t bodyStep);

    // The bodies' clock: scene time less start_s_, never below 0 (before
    // their start they wait where they start).
    double clock_s(double time_s) const;

    double start_s_ = 0.0;
    std::unique_ptr<SceneWake> wake_;
    // The surface on the bodies' clock plus the wake: what the bodies float on.
    std::shared_ptr<const SurfaceQuery> floatsOn_;
    std::vector<Footprint> footprints_; // per object, as bodies_
    std::size_t leader_ = 0;             // the body the wake's grid follows
    glm::dvec2 leaderDirection_{0.0};    // its heading of travel, unit (0 when it does not travel)
    std::int64_t wakeStepsTaken_ = 0;
    double wakeSteps_ms_ = 0.0;
    std::vector<std::unique_ptr<FloatingBody>> bodies_; // null for objects that are not bodies
    std::vector<std::optional<Bow>> bows_;             // per object: set for bodies under way
    std::vector<double> scale_;
    std::size_t count_ = 0;
};

} // namespace swell::detail
