// The calling thread's CPU time: what the frame's parts (render/cpu_parts.h)
// and a worker thread's tasks (core/worker.h) are measured with.
// Library-internal.
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

} // namespace swell::detail
