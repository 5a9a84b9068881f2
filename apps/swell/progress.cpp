// Progress of a long job on stderr: the count, the elapsed time and an
// estimate of the time left (the mean time per step so far times the steps
// to go), as a bar redrawn in place on a terminal and as a line every 10%
// otherwise (logs, pipes).
#include "progress.h"

#include <fmt/format.h>

#include <cstdio>
#include <unistd.h>

namespace swell::app {

namespace {

// "42s", "3m 05s", "1h 02m": short enough for a bar that redraws in place.
std::string duration(double seconds)
{
    const long s = long(seconds + 0.5);
    if (s < 60)
        return fmt::format("{}s", s);
    if (s < 3600)
        return fmt::format("{}m {:02}s", s / 60, s % 60);
    return fmt::format("{}h {:02}m", s / 3600, (s % 3600) / 60);
}

} // namespace

Progress::Progress(std::string label, int total)
    : label_(std::move(label)), total_(total), terminal_(::isatty(STDERR_FILENO)), start_(std::chrono::steady_clock::now())
{
}

double Progress::remaining_s(double elapsed_s) const
{
    return done_ > 0 ? elapsed_s / double(done_) * double(total_ - done_) : 0.0;
}

void Progress::advance()
{
    ++done_;
    if (total_ <= 1)
        return;
    const int percent = done_ * 100 / total_;
    const double elapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
    const std::string left = done_ < total_ ? ", about " + duration(remaining_s(elapsed)) + " left" : std::string();
    if (terminal_) {
        const int width = 30, filled = done_ * width / total_;
        // Trailing spaces wipe the end of a longer line drawn before.
        std::fprintf(stderr, "\r%s [%.*s%*s] %d/%d %3d%% %s%s    ", label_.c_str(), filled,
                     "##############################", width - filled, "", done_, total_, percent,
                     duration(elapsed).c_str(), left.c_str());
    } else if (percent / 10 != lastPercent_ / 10 || done_ == total_) {
        std::fprintf(stderr, "%s: %d/%d (%d%%), %s%s\n", label_.c_str(), done_, total_, percent,
                     duration(elapsed).c_str(), left.c_str());
    }
    lastPercent_ = percent;
}

void Progress::finish()
{
    if (terminal_ && total_ > 1)
        std::fprintf(stderr, "\n");
}

} // namespace swell::app
