// The label pass (swell/labels.h): the frame's geometry drawn once more, at
// the output's size with one sample per pixel, by programs that write each
// pixel's range, normal, class and instance (shaders/labels.glsl) instead
// of a colour. Same view setup, grid, culling and vertex shaders as the
// colour frame, so each label lies on the pixel its colour does.
#include "render/renderer_impl.h"

#include "render/gl_state.h"
#include "swell/gpu/bindings.h"
#include "swell/gpu/label_classes.h"

#include <fmt/format.h>
#include <glm/matrix.hpp>
#include <glm/trigonometric.hpp>

#include <algorithm>
#include <cmath>

namespace swell {

namespace {

// Window pixel (relative to the viewport's corner, 1) to the ray's direction
// in world axes, for the camera's symmetric perspective: the pixel's NDC
// (2 p / size - 1) scaled by the half-angles' tangents, looking down -z.
glm::dmat3 rayFromPixel(const Camera& camera, const glm::dmat4& view, glm::ivec2 size)
{
    const double tanY = std::tan(0.5 * glm::radians(camera.fovY_deg));
    const double tanX = tanY * double(size.x) / double(size.y);
    const glm::dmat3 viewFromPixel(glm::dvec3(2.0 * tanX / size.x, 0.0, 0.0), glm::dvec3(0.0, 2.0 * tanY / size.y, 0.0),
                                   glm::dvec3(-tanX, -tanY, -1.0));
    return glm::transpose(glm::dmat3(view)) * viewFromPixel;
}

} // namespace

void Renderer::Impl::drawLabelPass(const Camera& camera, const View& view, glm::ivec2 size,
                                   const std::vector<ObjectLabel>& objects)
{
    updateLabelPrograms(sources, labelPrograms, programs.flags);
    const LabelPrograms& p = *labelPrograms;
    ViewFrame v = prepareView(view, size, false);
    // Which side of the surface each pixel looks out from, as the colour
    // frame decides it (render/waterline.h).
    const NearPlaneMedium medium =
        nearPlaneMedium(nearPlaneCorners(glm::inverse(v.viewProj), v.depth.nearNdcZ), simulatedReach());
    drawWaterline(medium, v);
    glBindTextureUnit(SWELL_UNIT_WATERLINE, waterline.texture());

    labelTarget.resize(size);
    const glm::ivec4 viewport(0, 0, size);
    FrameUniforms f = v.base;
    f.viewportOrigin = glm::vec2(0.0f);
    bindFrame(PassMain, f);
    beginPass(labelTarget.framebuffer(), viewport, v.depth, std::nullopt);
    labelTarget.clear(float(v.depth.cleared));

    // The world: the terrain, then each object with its class and instance;
    // the hulls' volumes into depth only.
    std::vector<glm::uvec2> objectLabels;
    for (const ObjectLabel& o : objects)
        objectLabels.emplace_back(o.semanticClass, o.instance);
    SceneWorld own(world, p.mesh, p.mesh, v.poses, v.island, counters);
    own.setLabels(glm::uvec2(SWELL_LABEL_TERRAIN, 0u), std::move(objectLabels));
    own.setMainPassInAir(false);
    own.setIslandTolerance(islandTolerance_px);
    drawGeometry(PassKind::Main, &own, nullptr, view, PassMain, f, labelTarget.framebuffer(), viewport);
    glColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);
    drawGeometry(PassKind::WaterMask, &own, nullptr, view, PassMain, f, labelTarget.framebuffer(), viewport);
    glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);

    // The water, then whatever no geometry covers.
    const glm::dmat3 rays = rayFromPixel(camera, view.view, size);
    p.water.setRayFromPixel(rays);
    p.sky.setRayFromPixel(rays);
    p.water.use();
    wakeTexture.bind();
    glBindVertexArray(waterGrid.vertexArray());
    waterGrid.draw();
    ++counters.drawCalls;
    p.sky.use();
    glDepthFunc(v.depth.testOrFar);
    glDepthMask(GL_FALSE);
    glBindVertexArray(emptyVao.id());
    glDrawArrays(GL_TRIANGLES, 0, 3);
    ++counters.drawCalls;
    glDepthMask(GL_TRUE);
}

FrameLabels Renderer::Impl::drawLabels(const Camera& camera, glm::ivec2 size)
{
    requireSimulation();
    if (size.x <= 0 || size.y <= 0)
        throw Error(fmt::format("renderLabels: the size must be positive, not {}x{}", size.x, size.y));
    FrameLabels labels;
    labels.size = size;
    labels.classes = labelClassesOf(scene);
    // Each object: instance i + 1 for scene.objects[i], its class; and its
    // box, its mesh's at its pose (the sea frame's, lifted to the world's level).
    const glm::dmat4 toWorld = glm::translate(glm::dmat4(1.0), glm::dvec3(0.0, level(), 0.0));
    for (std::size_t i = 0; i < scene.objects.size(); ++i) {
        ObjectLabel o;
        o.instance = std::uint16_t(i + 1);
        o.className = objectClassOf(scene.objects[i]);
        o.semanticClass = std::uint16_t(std::find(labels.classes.begin(), labels.classes.end(), o.className) -
                                        labels.classes.begin());
        if (i < world.meshBounds_m.size() && i < simulated->poses.size()) {
            const auto& [lo, hi] = world.meshBounds_m[i];
            for (int c = 0; c < 8; ++c) {
                const glm::dvec3 corner((c & 1) ? hi.x : lo.x, (c & 2) ? hi.y : lo.y, (c & 4) ? hi.z : lo.z);
                o.box3d_m[std::size_t(c)] = glm::dvec3(toWorld * simulated->poses[i] * glm::dvec4(corner, 1.0));
            }
        }
        labels.objects.push_back(std::move(o));
    }
    const View view = viewOf(camera, size);
    {
        const SavedGlState saved;
        try {
            drawLabelPass(camera, view, size, labels.objects);
        } catch (...) {
            saved.restore();
            throw;
        }
        saved.restore();
    }
    labelTarget.read(labels.range_m, labels.normal, labels.semantic, labels.instance);
    labels.camera = calibrationOf(camera, size);
    labels.horizon = horizonOf(labels.camera);
    const double eyeHeight_m = camera.position_m.y - level();
    labels.trueHorizonDip_deg = glm::degrees(horizonDip_rad(eyeHeight_m));
    labels.trueHorizon_px = trueHorizonOf(labels.camera, eyeHeight_m);
    measureObjectBoxes(labels);
    return labels;
}

FrameLabels Renderer::renderLabels(const Camera& camera, glm::ivec2 size) { return impl_->drawLabels(camera, size); }

} // namespace swell
