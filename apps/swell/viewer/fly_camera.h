// The viewer's free-flight camera: mouse look while the right button is held,
// WASD to move along the view, Q/E down and up, Shift to go faster, the wheel
// to change the cruising speed. Pure math on swell::Camera, no window.
#pragma once

#include "swell/camera.h"

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

namespace swell::app::viewer {

// One frame of input, already filtered (nothing while the panel has it).
struct FlyInput {
    glm::dvec2 look_px{0.0};  // cursor movement while looking, pixels; +x right, +y down
    glm::dvec3 move{0.0};     // -1, 0 or 1 along right (x), world up (y), forward (z)
    bool fast = false;        // Shift held
    double wheel = 0.0;       // scroll notches; + speeds up
};

class FlyCamera {
public:
    // Degrees of turn per pixel of cursor movement.
    static constexpr double kLookDegPerPixel = 0.15;
    // Speed factor while Shift is held.
    static constexpr double kFastFactor = 5.0;
    // Each wheel notch multiplies the speed by this.
    static constexpr double kWheelFactor = 1.25;
    // Cruising speed limits, m/s: slow enough to inspect ripples, fast
    // enough to cross the detailed grid (a few km) in seconds.
    static constexpr double kMinSpeed_mps = 0.5;
    static constexpr double kMaxSpeed_mps = 2000.0;

    // Starts from `pose` (position, heading, pitch and lens).
    void setPose(const Camera& pose) { camera_ = pose; }
    const Camera& camera() const { return camera_; }
    // The lens (field of view, clip planes) follows the scene's camera.
    void setLens(double fovY_deg, double near_m, double far_m);

    double speed_mps() const { return speed_mps_; }
    void setSpeed(double speed_mps);

    // Applies one frame of input over dt_s seconds.
    void update(const FlyInput& input, double dt_s);

    // Whether the input asks for any movement or turn.
    static bool moves(const FlyInput& input);

private:
    Camera camera_;
    double speed_mps_ = 10.0;
};

} // namespace swell::app::viewer
