#include "progress.h"

#include <cstdio>
#include <unistd.h>

namespace swell::app {

Progress::Progress(std::string label, int total)
    : label_(std::move(label)), total_(total), terminal_(::isatty(STDERR_FILENO)), start_(std::chrono::steady_clock::now())
{
}

void Progress::advance()
{
    ++done_;
    if (total_ <= 1)
        return;
    const int percent = done_ * 100 / total_;
    const double elapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
    if (terminal_) {
        const int width = 30, filled = done_ * width / total_;
        std::fprintf(stderr, "\r%s [%.*s%*s] %d/%d %3d%% %.1fs", label_.c_str(), filled,
                     "##############################", width - filled, "", done_, total_, percent, elapsed);
    } else if (percent / 10 != lastPercent_ / 10 || done_ == total_) {
        std::fprintf(stderr, "%s: %d/%d frames (%d%%), %.1fs\n", label_.c_str(), done_, total_, percent, elapsed);
    }
    lastPercent_ = percent;
}

void Progress::finish()
{
    if (terminal_ && total_ > 1)
        std::fprintf(stderr, "\n");
}

} // namespace swell::app
