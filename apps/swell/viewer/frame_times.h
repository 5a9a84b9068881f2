// The last frame times of the viewer, for the panel's plot and averages.
#pragma once

#include <array>

namespace swell::app::viewer {

// The last kCount frame times, for the plot.
class FrameTimes {
public:
    static constexpr int kCount = 240;
    void add(float ms);
    // Oldest first from offset(), wrapping, as ImGui::PlotLines takes them.
    const float* values() const { return values_.data(); }
    int offset() const { return next_; }
    int count() const { return kCount; }
    float average() const;
    float maximum() const;
    float latest() const;

private:
    std::array<float, kCount> values_{};
    int next_ = 0;
    int filled_ = 0;
};

} // namespace swell::app::viewer
