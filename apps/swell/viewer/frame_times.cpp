#include "viewer/frame_times.h"

#include <algorithm>

namespace swell::app::viewer {

void FrameTimes::add(float ms)
{
    values_[std::size_t(next_)] = ms;
    next_ = (next_ + 1) % kCount;
    filled_ = std::min(filled_ + 1, kCount);
}

float FrameTimes::average() const
{
    if (filled_ == 0)
        return 0.0f;
    float sum = 0.0f;
    for (float v : values_)
        sum += v;
    return sum / float(filled_);
}

float FrameTimes::maximum() const { return *std::max_element(values_.begin(), values_.end()); }

float FrameTimes::latest() const { return values_[std::size_t((next_ + kCount - 1) % kCount)]; }

} // namespace swell::app::viewer
