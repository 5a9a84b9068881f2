// Physical and mathematical constants used across Swell, each defined once.
#pragma once

#include <numbers>

namespace swell {

// pi and 2*pi, rad.
inline constexpr double kPi = std::numbers::pi;
inline constexpr double kTwoPi = 2.0 * std::numbers::pi;

// Standard gravity, m/s^2 (CGPM 1901; ISO 80000-3).
inline constexpr double kGravity = 9.80665;

} // namespace swell
