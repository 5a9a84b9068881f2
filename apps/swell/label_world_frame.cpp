#include "label_world_frame.h"

#include <glm/mat4x4.hpp>
#include <glm/matrix.hpp>

namespace swell::app {

glm::dmat3 frameFromSwell(LabelWorldFrame frame)
{
    // Columns: where Swell's x (east), y (up) and z (south) go.
    switch (frame) {
    case LabelWorldFrame::Enu: return glm::dmat3(glm::dvec3(1, 0, 0), glm::dvec3(0, 0, 1), glm::dvec3(0, -1, 0));
    case LabelWorldFrame::Ned: return glm::dmat3(glm::dvec3(0, 1, 0), glm::dvec3(0, 0, -1), glm::dvec3(-1, 0, 0));
    case LabelWorldFrame::Swell: break;
    }
    return glm::dmat3(1.0);
}

std::string_view worldFrameName(LabelWorldFrame frame)
{
    switch (frame) {
    case LabelWorldFrame::Enu: return "enu";
    case LabelWorldFrame::Ned: return "ned";
    case LabelWorldFrame::Swell: break;
    }
    return "swell";
}

FrameLabels inWorldFrame(const FrameLabels& labels, LabelWorldFrame frame)
{
    FrameLabels out = labels;
    if (frame == LabelWorldFrame::Swell)
        return out;
    const glm::dmat3 turn = frameFromSwell(frame);
    const glm::dmat4 turn4(turn);
    out.camera.worldFromCamera = turn4 * labels.camera.worldFromCamera;
    out.camera.cameraFromWorld = labels.camera.cameraFromWorld * glm::transpose(turn4);
    const glm::mat3 turnFloat(turn);
    for (glm::vec3& n : out.normal)
        n = turnFloat * n;
    for (ObjectLabel& o : out.objects) {
        for (glm::dvec3& corner : o.box3d_m)
            corner = turn * corner;
        o.pose.worldFromObject = turn4 * o.pose.worldFromObject;
        o.pose.position_m = turn * o.pose.position_m;
        o.velocity_m_per_s = turn * o.velocity_m_per_s;
        o.angularVelocity_rad_per_s = turn * o.angularVelocity_rad_per_s;
    }
    for (ShoreLine& line : out.shoreline)
        for (glm::dvec3& p : line.points_m)
            p = turn * p; // NaN (no water point) stays NaN
    return out;
}

} // namespace swell::app
