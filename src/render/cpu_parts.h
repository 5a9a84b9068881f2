// The calling thread's CPU time spent in named parts of a frame
// (FrameCounters::simulationCpu): one clock, charged to one part at a time,
// paused while a PassObserver runs. The thread's clock, not the process's:
// a software rasteriser's worker threads (the emulated GPU) are not Swell's
// CPU cost. Library-internal.
#pragma once

#include "core/thread_cpu.h"

namespace swell::detail {

class CpuParts {
public:
    // Charges the time from now on to *part (nullptr: to none), and what
    // ran since the last switch to the part before.
    void switchTo(double* part)
    {
        const double now = threadCpu_ms();
        if (current_)
            *current_ += now - start_;
        current_ = part;
        start_ = now;
    }
    double* current() const { return current_; }
    // Around a call that is not Swell's (a PassObserver's): its time goes
    // to no part.
    void pause() { previous_ = current_, switchTo(nullptr); }
    void resume() { switchTo(previous_); }

private:
    double* current_ = nullptr;
    double* previous_ = nullptr;
    double start_ = 0.0;
};

// Charges a scope to a part, and the part that ran before it again after.
class CpuPartScope {
public:
    CpuPartScope(CpuParts& parts, double& part) : parts_(parts), before_(parts.current()) { parts_.switchTo(&part); }
    ~CpuPartScope() { parts_.switchTo(before_); }
    CpuPartScope(const CpuPartScope&) = delete;
    CpuPartScope& operator=(const CpuPartScope&) = delete;

private:
    CpuParts& parts_;
    double* before_;
};

} // namespace swell::detail
