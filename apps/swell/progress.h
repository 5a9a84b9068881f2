// Progress of a long job on stderr: a bar on a terminal, plain lines
// otherwise; both with the time elapsed and an estimate of the time left.
#pragma once

#include <chrono>
#include <string>

namespace swell::app {

class Progress {
public:
    Progress(std::string label, int total);
    void advance();
    void finish();

private:
    // The time left, s, at the mean time per step so far.
    double remaining_s(double elapsed_s) const;

    std::string label_;
    int total_, done_ = 0, lastPercent_ = -1;
    bool terminal_;
    std::chrono::steady_clock::time_point start_;
};

} // namespace swell::app
