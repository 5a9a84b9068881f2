#include "render/label_renderer.h"

#include "render/contact_map.h"
#include "render/gl_state.h"
#include "render/scene_world.h"
#include "render/view_frame.h"
#include "render/view_passes.h"
#include "swell/error.h"
#include "swell/gpu/bindings.h"
#include "swell/gpu/label_classes.h"

#include <fmt/format.h>
#include <glm/matrix.hpp>
#include <glm/trigonometric.hpp>

#include <algorithm>
#include <cmath>

namespace swell::detail {

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

void LabelRenderer::drawPass(RenderContext& context, const Camera& camera, const View& view, glm::ivec2 size,
                             const std::vector<ObjectLabel>& objects, std::optional<Alone> alone)
{
    Resources& resources = context.resources;
    updateLabelPrograms(resources.sources, programs_, resources.programs.flags);
    const LabelPrograms& p = *programs_;
    ViewFrame v = prepareView(context, view, size, false);
    // Where the world meets the water, as the colour frame draws it (an
    // object's silhouette alone needs none: its water's foam is not read).
    if (!alone) {
        SceneWorld whole(resources.world, resources.programs.meshInAir, resources.programs.mesh, v.poses, v.island,
                         v.seabed, context.telemetry.counters);
        whole.setIslandTolerance(context.islandTolerance_px);
        drawContact(context, v, &whole, nullptr, view);
    }
    // Which side of the surface each pixel looks out from, as the colour
    // frame decides it (render/waterline.h).
    const NearPlaneMedium medium =
        nearPlaneMedium(nearPlaneCorners(glm::inverse(v.viewProj), v.depth.nearNdcZ), context.simulation.reach());
    WaterlinePass{medium}.draw(context, waterline_, v);
    glBindTextureUnit(SWELL_UNIT_WATERLINE, waterline_.texture());

    LabelTarget& target = alone && alone->wide ? wideTarget_ : target_;
    target.resize(size);
    PassState pass;
    pass.slot = PassMain;
    pass.frame = v.base;
    pass.frame.viewportOrigin = glm::vec2(0.0f);
    pass.framebuffer = target.framebuffer();
    pass.viewport = glm::ivec4(0, 0, size);
    pass.depth = v.depth;
    pass.begin(resources, context.telemetry);
    target.clear(float(v.depth.cleared));

    // The world: the terrain, then each object with its class and instance;
    // the hulls' volumes into depth only.
    std::vector<glm::uvec2> objectLabels;
    for (const ObjectLabel& o : objects)
        objectLabels.emplace_back(o.semanticClass, o.instance);
    SceneWorld own(resources.world, p.mesh, p.mesh, v.poses, v.island, v.seabed, context.telemetry.counters);
    own.setLabels(glm::uvec2(SWELL_LABEL_TERRAIN, 0u), std::move(objectLabels));
    own.setMainPassInAir(false);
    own.setIslandTolerance(context.islandTolerance_px);
    own.setAlone(alone ? std::optional(alone->object) : std::nullopt);
    drawGeometry(context, pass, PassKind::Main, &own, nullptr, view);
    glColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);
    drawGeometry(context, pass, PassKind::WaterMask, &own, nullptr, view);
    glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);

    // The water, then whatever no geometry covers; for an object alone,
    // only where it can show (the rest keeps the clear's values).
    if (alone) {
        const glm::ivec4 r = alone->within_px;
        glEnable(GL_SCISSOR_TEST);
        glScissor(r.x, size.y - r.w, r.z - r.x, r.w - r.y);
    }
    const glm::dmat3 rays = rayFromPixel(camera, view.view, size);
    p.water.setRayFromPixel(rays);
    p.sky.setRayFromPixel(rays);
    p.water.use();
    context.simulation.bindForWater();
    glBindVertexArray(resources.waterGrid.vertexArray());
    resources.waterGrid.draw();
    ++context.telemetry.counters.drawCalls;
    p.sky.use();
    glDepthFunc(v.depth.testOrFar);
    glDepthMask(GL_FALSE);
    glBindVertexArray(resources.emptyVao.id());
    glDrawArrays(GL_TRIANGLES, 0, 3);
    ++context.telemetry.counters.drawCalls;
    glDepthMask(GL_TRUE);
    glDisable(GL_SCISSOR_TEST);
}

std::vector<ObjectLabel> LabelRenderer::objectLabels(RenderContext& context,
                                                     const std::vector<std::string>& classes) const
{
    // Each object: instance i + 1 for scene.objects[i], its class; and its
    // box, its mesh's at its pose (the sea frame's, lifted to the world's level).
    const Scene& scene = context.scene;
    const World& world = context.resources.world;
    const std::vector<glm::dmat4> poses = context.simulation.objectTransforms();
    const std::vector<std::optional<FloatingBody::Velocity>> velocities = context.simulation.objectVelocities();
    std::vector<ObjectLabel> objects;
    for (std::size_t i = 0; i < scene.objects.size(); ++i) {
        ObjectLabel o;
        o.instance = std::uint16_t(i + 1);
        o.className = objectClassOf(scene.objects[i]);
        o.semanticClass =
            std::uint16_t(std::find(classes.begin(), classes.end(), o.className) - classes.begin());
        if (i < poses.size())
            o.pose = objectPoseOf(poses[i]);
        if (i < velocities.size() && velocities[i]) {
            o.velocityKnown = true;
            o.velocity_m_per_s = velocities[i]->origin_m_per_s;
            o.angularVelocity_rad_per_s = velocities[i]->angular_rad_per_s;
        }
        if (i < world.meshBounds_m.size() && i < poses.size()) {
            const auto& [lo, hi] = world.meshBounds_m[i];
            for (int c = 0; c < 8; ++c) {
                const glm::dvec3 corner((c & 1) ? hi.x : lo.x, (c & 2) ? hi.y : lo.y, (c & 4) ? hi.z : lo.z);
                o.box3d_m[std::size_t(c)] = glm::dvec3(poses[i] * glm::dvec4(corner, 1.0));
            }
        }
        objects.push_back(std::move(o));
    }
    return objects;
}

FrameLabels LabelRenderer::draw(RenderContext& context, const Camera& camera, glm::ivec2 size)
{
    context.simulation.require();
    if (size.x <= 0 || size.y <= 0)
        throw Error(fmt::format("renderLabels: the size must be positive, not {}x{}", size.x, size.y));
    FrameLabels labels;
    labels.size = size;
    labels.classes = labelClassesOf(context.scene);
    labels.objects = objectLabels(context, labels.classes);
    const View view = viewOf(camera, size);
    {
        const HostStateScope hostState;
        drawPass(context, camera, view, size, labels.objects);
        target_.read(labels.range_m, labels.normal, labels.semantic, labels.instance);
        measureSilhouettes(context, camera, labels);
    }
    labels.camera = calibrationOf(camera, size);
    labels.horizon = horizonOf(labels.camera);
    const double eyeHeight_m = context.simulation.sea().heightInSea(camera.position_m.y);
    labels.trueHorizonDip_deg = glm::degrees(horizonDip_rad(eyeHeight_m));
    labels.trueHorizon_px = trueHorizonOf(labels.camera, eyeHeight_m);
    measureObjectBoxes(labels);
    measureOcclusion(labels);
    measureShoreline(labels);
    return labels;
}

} // namespace swell::detail
