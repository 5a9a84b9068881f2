#include "swell/view.h"

#include "swell/camera.h"

#include <glm/gtc/matrix_transform.hpp>
#include <glm/matrix.hpp>

namespace swell {

glm::dvec3 View::eye_m() const
{
    // The eye is where the view matrix takes the eye space's origin from.
    return glm::dvec3(glm::inverse(view)[3]);
}

View viewOf(const Camera& camera, glm::ivec2 size)
{
    View v;
    v.view = camera.viewRelativeTo(glm::dvec3(0.0));
    v.projection = camera.projection(size.y > 0 ? double(size.x) / double(size.y) : 1.0);
    v.viewport = glm::ivec4(0, 0, size.x, size.y);
    return v;
}

} // namespace swell
