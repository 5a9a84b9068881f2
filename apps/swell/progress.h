// Progress of a long job: a bar on a terminal, plain lines otherwise.
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
    std::string label_;
    int total_, done_ = 0, lastPercent_ = -1;
    bool terminal_;
    std::chrono::steady_clock::time_point start_;
};

} // namespace swell::app
