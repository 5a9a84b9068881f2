// Runs a piece of loading in a child process under hard limits, so a test can
// show that an input is read within a memory and time bound without
// measuring anything a busy machine changes:
//   - memory: RLIMIT_AS caps the child's address space at what it had when it
//     started plus a budget; an allocation past it fails (std::bad_alloc, or
//     a decoder's "out of memory"), however loaded the machine is. For the
//     record, the child's peak resident growth is reported: the kernel's
//     high-water mark is reset at the start (/proc/self/clear_refs), and the
//     growth is VmHWM minus the VmRSS then.
//   - time: the child's own CPU time (getrusage), which waiting for a core
//     on a busy machine does not add to. RLIMIT_CPU also stops a runaway.
// Under AddressSanitizer the address-space cap is left off (the sanitizer
// reserves terabytes of shadow memory); the outcome and CPU time still count.
#pragma once

#include "swell/error.h"

#include <cstdint>
#include <cstdio>
#include <fstream>
#include <functional>
#include <new>
#include <string>

#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

namespace swell::test {

#if defined(__SANITIZE_ADDRESS__)
inline constexpr bool kUnderAddressSanitizer = true;
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
inline constexpr bool kUnderAddressSanitizer = true;
#else
inline constexpr bool kUnderAddressSanitizer = false;
#endif
#else
inline constexpr bool kUnderAddressSanitizer = false;
#endif

enum class Outcome { Loaded, Refused, OutOfMemory, OtherException, Killed };

struct BoundedResult {
    Outcome outcome = Outcome::Killed;
    std::string message;           // the InputError's what(), when refused
    double cpu_s = 0.0;            // the child's CPU time, user + system
    std::uint64_t peakGrowth_bytes = 0; // peak resident growth (VmHWM - VmRSS at the start)
    int signal = 0;                // when killed
};

namespace detail {

// A field of /proc/self/status in bytes ("VmSize", "VmPeak").
inline std::uint64_t procStatus(const char* field)
{
    std::ifstream in("/proc/self/status");
    std::string key;
    while (in >> key) {
        std::uint64_t kib = 0;
        if (key == std::string(field) + ":" && in >> kib)
            return kib * 1024;
        in.ignore(1 << 20, '\n');
    }
    return 0;
}

inline double cpuSeconds()
{
    rusage u{};
    getrusage(RUSAGE_SELF, &u);
    return double(u.ru_utime.tv_sec + u.ru_stime.tv_sec) + 1e-6 * double(u.ru_utime.tv_usec + u.ru_stime.tv_usec);
}

} // namespace detail

// Runs `load` in a child with `budget_bytes` more address space than it
// starts with and at most `cpuLimit_s` CPU seconds (a backstop; compare
// cpu_s with the bound itself).
inline BoundedResult runBounded(const std::function<void()>& load, std::uint64_t budget_bytes, int cpuLimit_s = 20)
{
    int fds[2];
    if (pipe(fds) != 0)
        return {};
    std::fflush(nullptr);
    const pid_t child = fork();
    if (child == 0) {
        close(fds[0]);
        const std::uint64_t start = detail::procStatus("VmSize");
        if (!kUnderAddressSanitizer) {
            const rlimit memory{rlim_t(start + budget_bytes), rlim_t(start + budget_bytes)};
            setrlimit(RLIMIT_AS, &memory);
        }
        const rlimit cpuLimit{rlim_t(cpuLimit_s), rlim_t(cpuLimit_s + 1)};
        setrlimit(RLIMIT_CPU, &cpuLimit);
        std::ofstream("/proc/self/clear_refs") << "5"; // resets VmHWM to the current RSS
        const std::uint64_t residentStart = detail::procStatus("VmRSS");
        const double cpuStart = detail::cpuSeconds();
        Outcome outcome = Outcome::Loaded;
        std::string message;
        try {
            load();
        } catch (const InputError& e) {
            outcome = Outcome::Refused;
            message = e.what();
        } catch (const std::bad_alloc&) {
            outcome = Outcome::OutOfMemory;
        } catch (const std::exception& e) {
            outcome = Outcome::OtherException;
            message = e.what();
        }
        const double cpu = detail::cpuSeconds() - cpuStart;
        const std::uint64_t peak = detail::procStatus("VmHWM");
        const std::string report = std::to_string(int(outcome)) + " " + std::to_string(cpu) + " " +
                                   std::to_string(peak > residentStart ? peak - residentStart : 0) + " " + message;
        for (std::size_t written = 0; written < report.size();) {
            const ssize_t n = write(fds[1], report.data() + written, report.size() - written);
            if (n <= 0)
                break;
            written += std::size_t(n);
        }
        _exit(0);
    }
    close(fds[1]);
    std::string report;
    char buffer[4096];
    for (ssize_t n; (n = read(fds[0], buffer, sizeof buffer)) > 0;)
        report.append(buffer, std::size_t(n));
    close(fds[0]);
    int status = 0;
    waitpid(child, &status, 0);
    BoundedResult r;
    if (WIFSIGNALED(status)) {
        r.signal = WTERMSIG(status);
        return r;
    }
    int outcome = 0;
    double cpu = 0.0;
    unsigned long long peak = 0;
    int consumed = 0;
    if (std::sscanf(report.c_str(), "%d %lf %llu %n", &outcome, &cpu, &peak, &consumed) >= 3) {
        r.outcome = Outcome(outcome);
        r.cpu_s = cpu;
        r.peakGrowth_bytes = peak;
        r.message = report.substr(std::size_t(consumed));
    }
    return r;
}

} // namespace swell::test
