// The label pass (swell/dataset/labels.h, docs/LABELS.md): the frame's geometry
// drawn once more, at the output's size with one sample per pixel, by
// programs that write each pixel's range, normal, class and instance
// (shaders/labels.glsl) instead of a colour. Same view setup, grid, culling
// and vertex shaders as the colour frame, so each label lies on the pixel
// its colour does. Library-internal.
#pragma once

#include "render/label_target.h"
#include "render/programs.h"
#include "render/waterline.h"
#include "swell/camera.h"
#include "swell/dataset/labels.h"
#include "swell/view.h"

#include <cstddef>
#include <optional>
#include <vector>

namespace swell::detail {

struct RenderContext;

class LabelRenderer {
public:
    // The labels of `camera`'s frame of `size` pixels at the simulated time.
    // Throws swell::Error before the first advanceTo(), or for an empty size.
    FrameLabels draw(RenderContext& context, const Camera& camera, glm::ivec2 size);
    // The shaders were reloaded: the programs are built again when next asked for.
    void forgetPrograms() { programs_.reset(); }

private:
    // Each object's instance, class and 3D box at its pose.
    std::vector<ObjectLabel> objectLabels(RenderContext& context, const std::vector<std::string>& classes) const;
    // One object drawn alone (its silhouette, over the water): its index,
    // and the pixels the water and the sky are drawn on (x0, y0, x1, y1,
    // rows top first: where its box can show; nothing can show elsewhere).
    struct Alone {
        std::size_t object = 0;
        glm::ivec4 within_px{0};
        bool wide = false; // into wideTarget_ (the truncation's wide field), not target_
    };
    // The label pass; with `alone`, that object alone.
    void drawPass(RenderContext& context, const Camera& camera, const View& view, glm::ivec2 size,
                  const std::vector<ObjectLabel>& objects, std::optional<Alone> alone = std::nullopt);
    // Each object's silhouette drawn alone (label_silhouettes.cpp): the
    // amodal masks, and each object's truncation and silhouettePixels.
    void measureSilhouettes(RenderContext& context, const Camera& camera, FrameLabels& labels);
    // Object k's silhouette over a field three times the image's width and
    // height, centred on it: its pixels there, and those inside the image.
    struct Silhouette {
        long long total = 0, inImage = 0;
    };
    Silhouette wideSilhouette(RenderContext& context, const Camera& camera, const FrameLabels& labels, std::size_t k);

    // Built when first asked for and again where the colour programs' flags change.
    std::optional<LabelPrograms> programs_;
    LabelTarget target_;
    // The silhouettes' wide field (three times the image's width and
    // height): kept apart, so neither target is made again each frame.
    LabelTarget wideTarget_;
    WaterlineMask waterline_;
};

} // namespace swell::detail
