// Screenshots: the default framebuffer read back as an image, and the next
// free name for one (swell-screenshot-0001.png, -0002, ...).
#pragma once

#include "swell/image.h"

#include <glm/vec2.hpp>

#include <filesystem>

namespace swell::app::viewer {

// Reads the back buffer of the current context's default framebuffer, `size`
// pixels, top row first, alpha forced opaque. Call after the frame is drawn
// and before it is swapped.
Image readDefaultFramebuffer(glm::ivec2 size);

// `folder`/swell-screenshot-NNNN.png with the lowest NNNN from 0001 not yet taken.
std::filesystem::path nextScreenshotPath(const std::filesystem::path& folder);

} // namespace swell::app::viewer
