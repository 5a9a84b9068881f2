// The objects' silhouettes in the labels (swell/dataset/labels.h: ObjectLabel's
// amodalPixels, occlusion and truncation; FrameLabels::amodal): each object
// drawn alone by the label pass (no other object, no island, no sea floor;
// the water kept, so what the sea's surface hides of a hull is no part of
// it), at the frame's own view, so that its visible pixels are among the
// alone-render's pixel for pixel; and, where it reaches the image's border,
// once more over a field three times as wide and high for the share outside.
#include "render/label_renderer.h"

#include "render/view_frame.h"

#include <glm/common.hpp>
#include <glm/trigonometric.hpp>

#include <cmath>
#include <limits>

namespace swell::detail {

namespace {

// Whether some corner of the object's box lies in front of the camera: one
// wholly behind it has no silhouette (and is not drawn for nothing).
bool inFrontOf(const CameraCalibration& camera, const ObjectLabel& object)
{
    for (const glm::dvec3& corner : object.box3d_m)
        if ((camera.cameraFromWorld * glm::dvec4(corner, 1.0)).z > 0.0)
            return true;
    return false;
}

// Where the object can show in an image of the calibration's size (its
// lens left aside: the label pass is a pinhole frame): the pixels its box's
// corners span, widened by one, clipped to the image (x0, y0, x1, y1, rows
// top first); the whole image when a corner is behind the eye; empty
// (x0 >= x1 or y0 >= y1) when the box lies beside the image.
glm::ivec4 boxInImage(const CameraCalibration& camera, const ObjectLabel& object)
{
    glm::dvec2 lo(std::numeric_limits<double>::infinity()), hi(-std::numeric_limits<double>::infinity());
    for (const glm::dvec3& corner : object.box3d_m) {
        const glm::dvec4 p = camera.cameraFromWorld * glm::dvec4(corner, 1.0);
        if (p.z <= 0.0)
            return glm::ivec4(0, 0, camera.size);
        const glm::dvec2 at(camera.fx_px * p.x / p.z + camera.cx_px, camera.fy_px * p.y / p.z + camera.cy_px);
        lo = glm::min(lo, at);
        hi = glm::max(hi, at);
    }
    const glm::dvec2 from = glm::clamp(glm::floor(lo) - 1.0, glm::dvec2(0.0), glm::dvec2(camera.size));
    const glm::dvec2 to = glm::clamp(glm::ceil(hi) + 1.0, glm::dvec2(0.0), glm::dvec2(camera.size));
    return glm::ivec4(int(from.x), int(from.y), int(to.x), int(to.y));
}

// How many times the image's width and height the truncation is measured over.
constexpr int kWideField = 3;

// Whether the frame shows nothing but the object, the sea and the sky
// where the object can show (its box's pixels): then nothing hides any of
// it, and its render alone (the water kept, over the same rectangle) is
// the frame's own pixels of it, so it need not be drawn again. Anything
// else there (another object, the ground), in front or behind, and it is.
bool nothingElseWithin(const FrameLabels& labels, std::uint16_t instance, glm::ivec4 within)
{
    for (int y = within.y; y < within.w; ++y)
        for (int x = within.x; x < within.z; ++x) {
            const std::size_t i = std::size_t(y) * std::size_t(labels.size.x) + std::size_t(x);
            const std::uint16_t shown = labels.instance[i];
            if ((shown != 0 && shown != instance) || isGroundClass(labels.semantic[i]))
                return false;
        }
    return true;
}

} // namespace

void LabelRenderer::measureSilhouettes(RenderContext& context, const Camera& camera, FrameLabels& labels)
{
    const glm::ivec2 size = labels.size;
    const std::size_t pixels = std::size_t(size.x) * std::size_t(size.y);
    labels.amodal.assign(labels.objects.size() * pixels, 0);
    const CameraCalibration calibration = calibrationOf(camera, size);
    const View view = viewOf(camera, size);
    std::vector<std::uint16_t> alone;
    for (std::size_t k = 0; k < labels.objects.size(); ++k) {
        ObjectLabel& o = labels.objects[k];
        o.truncation = 1.0; // until some of it is found in the image
        o.silhouettePixels = 0;
        if (!inFrontOf(calibration, o))
            continue;
        const glm::ivec4 within = boxInImage(calibration, o);
        if (within.x >= within.z || within.y >= within.w)
            continue; // beside the image
        const bool alreadyAlone = nothingElseWithin(labels, o.instance, within);
        if (!alreadyAlone) {
            drawPass(context, camera, view, size, labels.objects, Alone{k, within});
            target_.readInstance(alone);
        }
        const std::vector<std::uint16_t>& shown = alreadyAlone ? labels.instance : alone;
        std::uint8_t* mask = labels.amodal.data() + k * pixels;
        long long count = 0;
        bool atBorder = false;
        for (int y = 0; y < size.y; ++y)
            for (int x = 0; x < size.x; ++x) {
                const std::size_t i = std::size_t(y) * std::size_t(size.x) + std::size_t(x);
                if (shown[i] != o.instance)
                    continue;
                mask[i] = 1;
                ++count;
                atBorder = atBorder || x == 0 || y == 0 || x == size.x - 1 || y == size.y - 1;
            }
        if (count == 0)
            continue;
        // Wholly inside unless it reaches the border (a silhouette in two
        // parts, one beyond the border, is taken as whole: not measured).
        o.truncation = 0.0;
        o.silhouettePixels = count;
        if (!atBorder)
            continue;
        const Silhouette wide = wideSilhouette(context, camera, labels, k);
        if (wide.total > 0) {
            o.truncation = 1.0 - double(wide.inImage) / double(wide.total);
            o.silhouettePixels = wide.total;
        }
    }
}

LabelRenderer::Silhouette LabelRenderer::wideSilhouette(RenderContext& context, const Camera& camera,
                                                        const FrameLabels& labels, std::size_t k)
{
    // The same focal length and centre over kWideField times the size: the
    // image is the middle block of the wide frame, pixel for pixel.
    Camera wide = camera;
    wide.fovY_deg = glm::degrees(2.0 * std::atan(kWideField * std::tan(0.5 * glm::radians(camera.fovY_deg))));
    const glm::ivec2 size = kWideField * labels.size;
    const glm::ivec4 within = boxInImage(calibrationOf(wide, size), labels.objects[k]);
    drawPass(context, wide, viewOf(wide, size), size, labels.objects, Alone{k, within, true});
    std::vector<std::uint16_t> alone;
    wideTarget_.readInstance(alone);
    const glm::ivec2 lo = (kWideField - 1) / 2 * labels.size, hi = lo + labels.size;
    Silhouette s;
    for (int y = 0; y < size.y; ++y)
        for (int x = 0; x < size.x; ++x)
            if (alone[std::size_t(y) * std::size_t(size.x) + std::size_t(x)] == labels.objects[k].instance) {
                ++s.total;
                s.inImage += x >= lo.x && x < hi.x && y >= lo.y && y < hi.y;
            }
    return s;
}

} // namespace swell::detail
