// What a frame tells about itself: its counters (swell/renderer.h's
// FrameCounters), the calling thread's CPU time by part (render/cpu_parts.h),
// and the pass observer told when each pass begins and ends. Every part of
// the renderer reports through one Telemetry. Library-internal.
#pragma once

#include "render/cpu_parts.h"
#include "swell/pass_observer.h"
#include "swell/debug.h"
#include "swell/wave_model_gpu.h"

#include <exception>

namespace swell::detail {

class Telemetry {
public:
    Telemetry() = default;
    // The relay points at this object: it stays where it was made.
    Telemetry(const Telemetry&) = delete;
    Telemetry& operator=(const Telemetry&) = delete;

    FrameCounters counters;
    // Charges the calling thread's CPU time to counters.simulationCpu's
    // parts; paused while the observer runs.
    mutable CpuParts cpu;

    // Observes the passes of later frames; null stops. Not owned.
    void setObserver(PassObserver* observer) { observer_ = observer; }

    // Tells the observer a pass begins or ends, its time charged to no part.
    void notify(bool begin, const char* pass) const
    {
        if (!observer_)
            return;
        cpu.pause();
        begin ? observer_->beginPass(pass) : observer_->endPass(pass);
        cpu.resume();
    }

    // The wave model's stages, passed on to the observer as passes inside
    // "ocean" (WaveModelGpu::setStageObserver).
    PassObserver* stageRelay() { return &relay_; }

    // The wave model's work, for advanceTo()'s frame (simulationGpu) or
    // for a view (viewsGpu).
    void addWork(const WaveModelGpu::Work& work, GpuWork& gpu)
    {
        counters.oceanTransforms += work.transforms;
        counters.foamSteps += work.foamSteps;
        addWork(GpuWork{work.dispatches, work.barriers, work.mipmaps, work.bytesWritten}, gpu);
    }
    static void addWork(const GpuWork& work, GpuWork& gpu)
    {
        gpu.dispatches += work.dispatches;
        gpu.barriers += work.barriers;
        gpu.mipmaps += work.mipmaps;
        gpu.bytesWritten += work.bytesWritten;
    }

private:
    struct Relay final : PassObserver {
        const Telemetry* owner;
        explicit Relay(const Telemetry* t) : owner(t) {}
        void beginPass(const char* name) override { owner->notify(true, name); }
        void endPass(const char* name) override { owner->notify(false, name); }
    };
    PassObserver* observer_ = nullptr;
    Relay relay_{this};
};

// A pass told to the observer for the scope's length. A pass left by an
// exception is not told to have ended: the observer's own code must not run
// (and perhaps throw) while the exception unwinds.
class ObservedPass {
public:
    ObservedPass(const Telemetry& telemetry, const char* name)
        : telemetry_(telemetry), name_(name), exceptions_(std::uncaught_exceptions())
    {
        telemetry_.notify(true, name_);
    }
    ~ObservedPass()
    {
        if (std::uncaught_exceptions() == exceptions_)
            telemetry_.notify(false, name_);
    }
    ObservedPass(const ObservedPass&) = delete;
    ObservedPass& operator=(const ObservedPass&) = delete;

private:
    const Telemetry& telemetry_;
    const char* name_;
    int exceptions_;
};

} // namespace swell::detail
