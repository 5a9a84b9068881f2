// The calling thread's CPU time: what the frame's parts (render/cpu_parts.h)
// and a worker thread's tasks (core/worker.h) are measured with; and the
// process's, which the apps report (`swell bench`, the viewer, `swell
// dataset`). Library-internal.
#pragma once

#include <time.h>

namespace swell::detail {

// CLOCK_THREAD_CPUTIME_ID, ms.
inline double threadCpu_ms()
{
    timespec t{};
    ::clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
    return double(t.tv_sec) * 1e3 + double(t.tv_nsec) * 1e-6;
}

// CLOCK_PROCESS_CPUTIME_ID, ms: every thread of the process, a software
// rasteriser's included, which varies much less than wall time on a
// machine shared with other work.
inline double processCpu_ms()
{
    timespec t{};
    ::clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
    return double(t.tv_sec) * 1e3 + double(t.tv_nsec) * 1e-6;
}

} // namespace swell::detail
