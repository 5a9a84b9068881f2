// One view's passes (Renderer::Impl, render/renderer_impl.h): the view's
// setup, the reflection, the refraction, the waterline mask and the main
// pass into the host's frame or Swell's own, with the host's geometry
// through its callback.
#include "render/renderer_impl.h"

#include "render/gl_state.h"
#include "swell/error.h"
#include "swell/gpu/bindings.h"
#include "swell/gpu/underwater.h"

#include <fmt/format.h>
#include <glm/matrix.hpp>
#include <glm/trigonometric.hpp>

#include <algorithm>
#include <cmath>

namespace swell {

// Per-view setup shared by drawing and capture: the render origin is the
// eye's x,z; the surface is phased at the snapped grid centre around the
// LOD viewpoint; the water tiles in view are chosen.
Renderer::Impl::ViewFrame Renderer::Impl::prepareView(const View& view, glm::ivec2 size, bool hostGeometry)
{
    SimulationCpuTime& cpu = counters.simulationCpu;
    const CpuPartScope viewPart(cpuParts, cpu.views_ms);
    ViewFrame v;
    v.size = size;
    v.depth = depthConventionOf(view.depth);
    v.eye = toSea(view.eye_m());
    v.origin = glm::dvec3(v.eye.x, 0.0, v.eye.z);
    const glm::dvec3 lod = view.lodViewpoint_m ? toSea(*view.lodViewpoint_m) : v.eye;
    const GridPlacement grid = placeGrid(gridShape, lod);
    cpuParts.switchTo(&cpu.model_ms);
    modelGpu->prepareView(grid.center_m);
    addWork(modelGpu->takeWork(), counters.viewsGpu); // no transforms, unless a view simulated: the counters would show it
    modelGpu->bind();
    cpuParts.switchTo(&cpu.views_ms);
    // World = sea + level: relative = world - (origin + level).
    const glm::dmat4 viewRelative = view.view * glm::translate(glm::dmat4(1.0), v.origin + glm::dvec3(0.0, level(), 0.0));
    v.viewProj = view.projection * viewRelative;
    const glm::dmat4& viewProj = v.viewProj;
    FrameUniforms& f = v.base;
    f = frameUniforms(scene, currentSkyLight(), gridShape, grid, v.eye, viewProj, v.origin, size);
    setDepthConvention(f, view.depth);
    f.projectionFocalY = float(view.projection[1][1]);
    f.waveHeightDeviation_m = float(model().heightDeviation_m());
    f.waveMeanSquareSlope = float(seaMeanSquareSlope);
    wakeTexture.place(v.origin);
    wakeTexture.bind();
    sourceParameters.upload(simulated->sources, simulated->time_s, v.origin + glm::dvec3(0.0, level(), 0.0));
    const WaveReach reach = simulatedReach();
    // What the waterline mask's rays that meet no water are judged by
    // (shaders/underwater.glsl): the band the surface stays in, and the
    // eye's own side of it.
    f.waveReachVertical_m = float(reach.vertical_m);
    cpuParts.switchTo(&cpu.queries_ms);
    // The frame's query answered it for the simulated viewpoint (the eye a
    // view matrix gives back differs from it by rounding); another eye
    // asks the model.
    constexpr double kSameEye_m = 1e-6;
    const bool atViewpoint = std::abs(v.eye.x - simulated->viewpoint.x) < kSameEye_m &&
                             std::abs(v.eye.z - simulated->viewpoint.z) < kSameEye_m;
    f.eyeUnderwater = (atViewpoint ? v.eye.y < simulated->viewpointWaterHeight_m
                                   : eyeUnderwater(v.eye, model(), simulated->time_s, reach.vertical_m))
                          ? 1
                          : 0;
    cpuParts.switchTo(&cpu.views_ms);
    for (const glm::dmat4& pose : simulated->poses)
        v.poses.emplace_back(glm::translate(glm::dmat4(1.0), -v.origin) * pose);
    v.island = glm::mat4(glm::translate(glm::dmat4(1.0), kIslandPosition_m - v.origin));
    // A host's geometry has no boxes Swell knows of: every reflected ray
    // is marched.
    f.worldBoxCount =
        hostGeometry ? -1 : worldBoxes(world, seaScene, reach, v.origin, simulated->poses, f.worldBoxes);
    waterGrid.cull(gridShape, grid, reach, viewProj, v.depth.zeroToOne(), grid.center_m - glm::dvec2(v.origin.x, v.origin.z));
    counters.cullBoxesTested += waterGrid.boxesTested();
    return v;
}

const SkyLight& Renderer::Impl::currentSkyLight()
{
    const std::pair<SkyBakeKey, bool> key{skyBakeKeyOf(scene), usesPhysicalSky(scene)};
    if (skyLightKey != key) {
        std::shared_ptr<const Atmosphere> next = key.second ? atmosphereFor(scene.sky.atmosphere) : nullptr;
        // The tables depend on the atmosphere alone, not on the sun: uploaded
        // again only for another one (drawView), given back while the sky is
        // not physical.
        if (next != atmosphere)
            atmosphereTextures = {};
        if (!next)
            physicalSkyBake = {};
        atmosphere = std::move(next);
        skyLight = skyLightOf(scene, atmosphere.get());
        skyLightKey = key;
    }
    return skyLight;
}

void Renderer::Impl::drawSky(bool inAir, const DepthConvention& depth)
{
    (inAir ? programs.skyInAir : programs.sky).use();
    glBindTextureUnit(SWELL_UNIT_SKY, world.skyCube.id());
    glDepthFunc(depth.testOrFar);
    glDepthMask(GL_FALSE);
    glBindVertexArray(emptyVao.id());
    glDrawArrays(GL_TRIANGLES, 0, 3);
    ++counters.drawCalls;
    glDepthMask(GL_TRUE);
    glDepthFunc(depth.test);
}

namespace {

// Whether any of the world's boxes (relative to the render origin) that
// stays put reaches below the mean level inside the caustics map's square
// (`floating[i]`: box i rides the water). Where none does, nothing the map
// lights is drawn (the default scene's island lies 1.7 km from its camera)
// or what it lights is a floating hull's underside, which from the air
// shows hardly any of it: the pass is left out. Unbounded worlds always do.
bool worldUnderMap(const FrameUniforms& f, const CausticsUniforms& map, const std::vector<bool>& floating)
{
    if (f.worldBoxCount < 0)
        return true;
    const glm::vec2 lo = map.mapCorner_m, hi = map.mapCorner_m + map.mapSize_m;
    for (int i = 0; i < f.worldBoxCount; ++i) {
        const WorldBoxUniform& box = f.worldBoxes[i];
        if (std::size_t(i) < floating.size() && floating[std::size_t(i)])
            continue;
        if (box.min_m.y < 0.0f && box.max_m.x >= lo.x && box.min_m.x <= hi.x && box.max_m.z >= lo.y &&
            box.min_m.z <= hi.y)
            return true;
    }
    return false;
}

} // namespace

void Renderer::Impl::drawCaustics(const ViewFrame& v, bool ownWorld)
{
    caustics.place(v.origin, v.base.gridCenter, v.base.sunDirection);
    // The world's boxes in worldBoxes()' order: the island's, then each object's.
    std::vector<bool> floating;
    if (world.island.indexCount() > 0)
        floating.push_back(false);
    for (const SceneObject& o : seaScene.objects)
        floating.push_back(o.floats);
    // Seen from under the water, the caustics on anything there (a hull's
    // underside included) are in full view.
    const bool wanted = v.base.eyeUnderwater != 0 || worldUnderMap(v.base, caustics.uniforms(), floating);
    // The shafts of light read it along the rays of any pixel under the water, the world drawn or not:
    // wherever the main pass's near plane is not wholly in the air (its programs then have no shafts).
    const bool shafts = programs.flags.water.underwater.shafts &&
                        nearPlaneMedium(nearPlaneCorners(glm::inverse(v.viewProj), v.depth.nearNdcZ),
                                        simulatedReach()) != NearPlaneMedium::Air;
    if (programs.caustics && v.base.sunDirection.y > 0.0f && ((ownWorld && wanted) || shafts)) {
        notify(true, "caustics");
        modelGpu->bind();
        counters.causticsTriangles += caustics.render(programs.caustics);
        const GpuWork work = CausticsMap::renderWork();
        counters.viewsGpu.dispatches += work.dispatches;
        counters.viewsGpu.barriers += work.barriers;
        counters.viewsGpu.mipmaps += work.mipmaps;
        counters.viewsGpu.bytesWritten += work.bytesWritten;
        counters.drawCalls += SWELL_CAUSTICS_SLICES; // a draw a slice
        notify(false, "caustics");
    }
    caustics.bind();
}

void Renderer::Impl::drawWater(bool inAir)
{
    (inAir ? programs.waterInAir : programs.water).use();
    glBindTextureUnit(SWELL_UNIT_SKY, world.skyCube.id());
    glBindTextureUnit(SWELL_UNIT_REFLECTION_COLOR, reflection.color());
    glBindTextureUnit(SWELL_UNIT_REFLECTION_DEPTH, reflection.depth());
    glBindTextureUnit(SWELL_UNIT_REFRACTION_COLOR, refraction.color());
    glBindTextureUnit(SWELL_UNIT_REFRACTION_DEPTH, refraction.depth());
    wakeTexture.bind();
    glBindVertexArray(waterGrid.vertexArray());
    if (scene.debugView == DebugView::Wireframe)
        glPolygonMode(GL_FRONT_AND_BACK, GL_LINE);
    counters.waterTriangles += waterGrid.draw();
    glPolygonMode(GL_FRONT_AND_BACK, GL_FILL);
    ++counters.drawCalls;
}


// The waterline mask for the main pass (render/waterline.h): drawn from
// the water grid when the near plane can lie on either side of the
// waves, else cleared to the side it lies on. Draws into its own target
// with its own frame uniforms (the viewport at its origin).
void Renderer::Impl::drawWaterline(NearPlaneMedium medium, const ViewFrame& v)
{
    waterline.resize(v.size);
    if (medium != NearPlaneMedium::Both) {
        waterline.fill(medium);
        return;
    }
    notify(true, "waterline");
    FrameUniforms f = v.base;
    f.viewportOrigin = glm::vec2(0.0f);
    bindFrame(PassWaterline, f);
    beginPass(waterline.framebuffer(), glm::ivec4(0, 0, v.size), v.depth, glm::vec4(SWELL_WATERLINE_NO_HIT));
    glBindTextureUnit(SWELL_UNIT_WATERLINE, waterline.allAbove()); // never the target itself
    programs.waterline.use();
    wakeTexture.bind();
    glBindVertexArray(waterGrid.vertexArray());
    waterGrid.draw();
    ++counters.drawCalls;
    notify(false, "waterline");
}

// Every pass sets all the state it depends on, so passes can be
// reordered; a clear colour clears colour and depth, none keeps both.
void Renderer::Impl::beginPass(GLuint framebuffer, glm::ivec4 viewport, const DepthConvention& depth,
               std::optional<glm::vec4> clear)
{
    glBindFramebuffer(GL_FRAMEBUFFER, framebuffer);
    setPassState(viewport, depth);
    if (clear) {
        glClearColor(clear->r, clear->g, clear->b, clear->a);
        glClearDepth(depth.cleared);
        glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    }
}

void Renderer::Impl::setPassState(glm::ivec4 viewport, const DepthConvention& depth)
{
    glViewport(viewport.x, viewport.y, viewport.z, viewport.w);
    glDisable(GL_BLEND);
    glDisable(GL_CULL_FACE);
    glDisable(GL_SCISSOR_TEST);
    glDisable(GL_RASTERIZER_DISCARD);
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(depth.test);
    glDepthMask(GL_TRUE);
    glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
    glClipControl(GL_LOWER_LEFT, depth.clipDepth);
    glPolygonMode(GL_FRONT_AND_BACK, GL_FILL);
    // The shaders write display-ready (sRGB-encoded) colour, or linear
    // colour for a linear target: never encoded again on the way.
    glDisable(GL_FRAMEBUFFER_SRGB);
    // Filter across cubemap face edges (off by default even in core profiles).
    glEnable(GL_TEXTURE_CUBE_MAP_SEAMLESS);
}

// Calls a host's geometry for a pass and puts back the state the pass
// draws with: the host may change any of it.
void Renderer::Impl::drawHost(PassGeometry& geometry, const PassView& pass, Pass uniforms, const FrameUniforms& f,
              GLuint framebuffer, bool mirrored)
{
    geometry.drawPass(pass);
    const GLenum error = glGetError();
    if (error != GL_NO_ERROR)
        throw Error(fmt::format("the host's geometry left GL error 0x{:04x} in the {} pass", error,
                                passName(pass.pass)));
    glBindFramebuffer(GL_FRAMEBUFFER, framebuffer);
    setPassState(pass.viewport, depthConventionOf(pass.depth));
    glFrontFace(mirrored ? GL_CW : GL_CCW);
    if (pass.pass == PassKind::Reflection || pass.pass == PassKind::Refraction)
        glEnable(GL_CLIP_DISTANCE0);
    bindFrame(uniforms, f);
    modelGpu->bind();
    wakeTexture.bind();
    caustics.bind();
    sourceParameters.bind();
}

// The geometry of a pass: Swell's own world and the host's, each through
// the same callback; the pass's view in absolute world coordinates.
void Renderer::Impl::drawGeometry(PassKind kind, SceneWorld* own, PassGeometry* host, const View& view, Pass uniforms,
                  const FrameUniforms& f, GLuint framebuffer, glm::ivec4 viewport)
{
    const bool mirrored = kind == PassKind::Reflection;
    PassView pass;
    pass.pass = kind;
    pass.view = mirrored ? view.view * mirrorAbout(level()) : view.view;
    pass.projection = view.projection;
    pass.viewport = viewport;
    pass.depth = view.depth;
    const glm::dvec3 eye = view.eye_m();
    pass.eye_m = mirrored ? glm::dvec3(eye.x, 2.0 * level() - eye.y, eye.z) : eye;
    // The pass's clip plane, relative to the render origin, is the
    // world's plane moved by the origin (its y at the sea level).
    const glm::dvec4 plane(f.clipPlane);
    pass.clipPlane_m = glm::dvec4(glm::dvec3(plane), plane.w - plane.y * level());
    glFrontFace(mirrored ? GL_CW : GL_CCW);
    // The world is drawn before the sky and the water, which bind the sky
    // cubemap for themselves; its fog looks the sky up too (fog.glsl's
    // aerial perspective), and the unit may hold nothing yet (a bake leaves
    // it empty) or what another frame left there.
    glBindTextureUnit(SWELL_UNIT_SKY, world.skyCube.id());
    if (own)
        own->drawPass(pass);
    if (host)
        drawHost(*host, pass, uniforms, f, framebuffer, mirrored);
    glFrontFace(GL_CCW);
}

// The passes of one view. ownsFrame: render()'s frame (cleared, the main
// pass through mainTarget at the render scale); else draw()'s
// compositing into the host's framebuffer at the view's viewport.
void Renderer::Impl::drawView(const View& view, GLuint framebuffer, const DrawOptions& options, bool ownsFrame,
              glm::ivec2 outputSize)
{
    const glm::ivec2 size = ownsFrame ? scaledFrameSize(outputSize, renderScale) : glm::ivec2(view.viewport.z, view.viewport.w);
    ViewFrame v = prepareView(view, size, options.geometry != nullptr);
    ++counters.views;
    SceneWorld own(world, programs.meshInAir, programs.mesh, v.poses, v.island, counters);
    own.setIslandTolerance(islandTolerance_px);
    SceneWorld* ownWorld = options.sceneWorld ? &own : nullptr;
    // Drawn for the temporal resolve below the output's size: the water's
    // detail filtered by the output pixel's footprint (frame.glsl).
    if (ownsFrame && temporalViewProj && size.x < outputSize.x)
        v.base.footprintScale = float(double(size.x) / double(outputSize.x));
    const FrameUniforms& base = v.base;
    // The procedural sky is baked into the cubemap when first needed and
    // after the sun or sky changed (the bake reads the frame uniforms).
    if (scene.sky.cubemapFaces.empty() && bakedSky != skyBakeKeyOf(scene)) {
        bindFrame(PassMain, base);
        glClipControl(GL_LOWER_LEFT, GL_NEGATIVE_ONE_TO_ONE);
        if (usesPhysicalSky(scene)) {
            if (!physicalSkyBake)
                physicalSkyBake = SkyBakeProgram(sources, true);
            if (!atmosphereTextures.transmittance)
                atmosphereTextures.upload(*atmosphere);
            atmosphereTextures.bind();
            physicalSkyBake.setAtmosphere(scene.sky.exposure, scene.sky.atmosphere);
            physicalSkyBake.setClouds(scene.sky.clouds);
            bakeProceduralSky(physicalSkyBake, world.skyCube, emptyVao.id());
            glBindTextureUnit(SWELL_UNIT_SKY_TRANSMITTANCE, 0);
            glBindTextureUnit(SWELL_UNIT_SKY_MULTISCATTER, 0);
        } else {
            bakeProceduralSky(programs.skyBake, world.skyCube, emptyVao.id());
        }
        counters.drawCalls += kSkyFaces;
        bakedSky = skyBakeKeyOf(scene);
    }
    // The cloud layer's shadows, baked again only when the clouds, the sun
    // or the camera's neighbourhood changed; before every pass that reads them.
    if (programs.flags.water.underwater.cloudShadows) {
        if (!cloudShadowBake)
            cloudShadowBake = CloudShadowBakeProgram(sources);
        notify(true, "cloud shadows");
        if (cloudShadow.update(cloudShadowBake, emptyVao.id(), scene.sky.clouds, base.sunDirection, v.origin,
                               float(currentSkyLight().sunCloudTransmittance))) {
            ++counters.drawCalls;
            ++counters.viewsGpu.mipmaps;
        }
        notify(false, "cloud shadows");
        cloudShadow.bind();
    } else if (cloudShadow.texture() != 0) {
        // No layer now: the map and its bake program are given back, as the
        // physical sky's are (a scene may drop its clouds for good).
        cloudShadow = {};
        cloudShadowBake = {};
    }
    // The sun's light under the water, before every pass that draws the world.
    drawCaustics(v, ownWorld != nullptr);
    const glm::ivec2 scaled = glm::max(glm::ivec2(glm::dvec2(size) * scene.reflection.resolutionScale), glm::ivec2(1));
    const glm::ivec4 passViewport(0, 0, scaled);
    reflection.resize(scaled);
    refraction.resize(scaled);
    // Passes before the main one see nothing from below the water.
    waterline.resize(size);
    glBindTextureUnit(SWELL_UNIT_WATERLINE, waterline.allAbove());

    // Pass 1: the world mirrored about the water plane, clipped just below it.
    FrameUniforms f = base;
    const glm::mat4 mirror = glm::scale(glm::mat4(1.0f), glm::vec3(1.0f, -1.0f, 1.0f));
    f.passViewProj = base.cameraViewProj * mirror;
    f.passInvViewProj = glm::inverse(f.passViewProj);
    f.clipPlane = glm::vec4(0.0f, 1.0f, 0.0f, float(scene.reflection.clipOffset_m));
    f.eyePosition.y = -base.eyePosition.y;
    setViewport(f, scaled);
    notify(true, "reflection");
    bindFrame(PassReflection, f);
    beginPass(reflection.framebuffer(), passViewport, v.depth, glm::vec4(0.0f));
    glEnable(GL_CLIP_DISTANCE0);
    // The mirror turns every triangle's winding around on screen: without
    // the front face turned too, the faces seen would count as back
    // faces, and mesh.frag, which turns a back face's normal round,
    // would light each object's reflection from the wrong side.
    drawGeometry(PassKind::Reflection, ownWorld, options.geometry, view, PassReflection, f,
                 reflection.framebuffer(), passViewport);
    glDisable(GL_CLIP_DISTANCE0);
    drawSky(true, v.depth);
    notify(false, "reflection");

    // Pass 1b: the world below the water, for refraction.
    f = base;
    f.clipPlane = glm::vec4(0.0f, -1.0f, 0.0f, float(scene.reflection.clipOffset_m));
    // Underwater hook: an eye below the surface looks up through it, so
    // this pass holds the world above the water instead.
    if (base.eyeUnderwater != 0)
        f.clipPlane = glm::vec4(0.0f, 1.0f, 0.0f, float(scene.reflection.clipOffset_m));
    setViewport(f, scaled);
    notify(true, "refraction");
    bindFrame(PassRefraction, f);
    beginPass(refraction.framebuffer(), passViewport, v.depth, glm::vec4(0.0f));
    glEnable(GL_CLIP_DISTANCE0);
    drawGeometry(PassKind::Refraction, ownWorld, options.geometry, view, PassRefraction, f,
                 refraction.framebuffer(), passViewport);
    glDisable(GL_CLIP_DISTANCE0);
    notify(false, "refraction");

    // Pass 2: the world (Swell's frame only: a host drew its own), the
    // water depth-tested against it, so objects crossing the surface meet
    // it cleanly; the sky last, only where nothing else was drawn (its
    // depth test passes at the far plane alone), so its shader runs on
    // the visible sky's pixels only.
    f = base;
    f.passEncodesSrgb = options.encoding == OutputEncoding::Srgb ? 1 : 0;
    f.passMarksWater = ownsFrame && temporalViewProj ? 1 : 0;
    // The waterline mask is drawn at the main pass's size, so the main
    // pass (multisampled or not) reads it on the same pixel grid.
    const WaveReach reach = simulatedReach();
    const NearPlaneMedium medium = nearPlaneMedium(nearPlaneCorners(glm::inverse(v.viewProj), v.depth.nearNdcZ), reach);
    drawWaterline(medium, v);
    glBindTextureUnit(SWELL_UNIT_WATERLINE, waterline.texture());
    const bool inAir = medium == NearPlaneMedium::Air;
    own.setMainPassInAir(inAir);
    notify(true, "main");
    GLuint mainFramebuffer = framebuffer;
    glm::ivec4 mainViewport = view.viewport;
    // The temporal resolve brings its own anti-aliasing (the jitter): the
    // main pass draws into its target, plain, and the resolve reads it.
    const bool temporalFrame = ownsFrame && temporalViewProj.has_value();
    if (ownsFrame) {
        mainFramebuffer = mainTarget.begin(size, outputSize, framebuffer,
                                           temporalFrame ? Antialiasing::Off : scene.antialiasing, temporalFrame);
        mainViewport = glm::ivec4(0, 0, size);
    }
    f.viewportOrigin = glm::vec2(mainViewport.x, mainViewport.y);
    bindFrame(PassMain, f);
    beginPass(mainFramebuffer, mainViewport, v.depth,
              ownsFrame ? std::optional<glm::vec4>(glm::vec4(0.0f, 0.0f, 0.0f, 1.0f)) : std::nullopt);
    // The host's geometry seen from below the water is fogged by it, as
    // Swell's own is, before Swell's own is drawn in (draw() only: in
    // render() there is no host's frame).
    if (!ownsFrame && medium != NearPlaneMedium::Air)
        fogHostUnderwater(framebuffer, mainViewport, v.depth);
    // The world, then the closed volumes the water must not show inside.
    // In draw() the host drew its own opaque scene and volumes already:
    // only Swell's own world joins them.
    PassGeometry* host = ownsFrame ? options.geometry : nullptr;
    if (ownWorld || host) {
        drawGeometry(PassKind::Main, ownWorld, host, view, PassMain, f, mainFramebuffer, mainViewport);
        glColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);
        drawGeometry(PassKind::WaterMask, ownWorld, host, view, PassMain, f, mainFramebuffer, mainViewport);
        glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
    }
    notify(true, "water");
    drawWater(inAir);
    notify(false, "water");
    if (ownsFrame || options.sky)
        drawSky(inAir, v.depth);
    // From under the water the surface hides the spray (and the depth
    // test hides a particle's part below the surface from above).
    if (base.eyeUnderwater == 0)
        drawSpray(v, view);
    notify(false, "main");

    if (temporalFrame) {
        notify(true, "temporal resolve");
        glClipControl(GL_LOWER_LEFT, GL_NEGATIVE_ONE_TO_ONE);
        counters.drawCalls += temporal.resolve(programs.temporal, emptyVao.id(), mainTarget.drawnColor(),
                                               mainTarget.drawnDepth(), size, outputSize, framebuffer, *temporalViewProj,
                                               glm::dvec2(v.depth.ndcScale, v.depth.ndcOffset), simulated->time_s);
        notify(false, "temporal resolve");
        return;
    }
    // The MSAA resolve, the FXAA filter and the render scale's filtering.
    if (ownsFrame && mainTarget.presents()) {
        notify(true, "present");
        glClipControl(GL_LOWER_LEFT, GL_NEGATIVE_ONE_TO_ONE);
        counters.drawCalls += mainTarget.present(programs.fxaa, emptyVao.id());
        notify(false, "present");
    }
}

// The underwater pass over the host's geometry (underwater_host.frag):
// on its copied depth, blending in-scattering and transmittance.
void Renderer::Impl::fogHostUnderwater(GLuint framebuffer, glm::ivec4 viewport, const DepthConvention& depth)
{
    notify(true, "underwater host");
    const GLuint copy = hostDepth.copy(framebuffer, viewport);
    glBindFramebuffer(GL_FRAMEBUFFER, framebuffer);
    setPassState(viewport, depth);
    glDisable(GL_DEPTH_TEST);
    glDepthMask(GL_FALSE);
    glEnable(GL_BLEND);
    glBlendEquation(GL_FUNC_ADD);
    glBlendFunc(GL_ONE, GL_SRC1_COLOR);
    programs.underwaterHost.use();
    glBindTextureUnit(SWELL_UNIT_HOST_DEPTH, copy);
    glBindVertexArray(emptyVao.id());
    glDrawArrays(GL_TRIANGLES, 0, 3);
    ++counters.drawCalls;
    glDisable(GL_BLEND);
    setPassState(viewport, depth);
    notify(false, "underwater host");
}

// Draws a view with the GL state put back afterwards, whatever happens.
void Renderer::Impl::drawRestoring(const View& view, GLuint framebuffer, const DrawOptions& options, bool ownsFrame,
                   glm::ivec2 outputSize)
{
    const SavedGlState saved;
    try {
        drawView(view, framebuffer, options, ownsFrame, outputSize);
    } catch (...) {
        saved.restore();
        throw;
    }
    saved.restore();
}

void Renderer::Impl::render(const Camera& camera, double time_s, glm::ivec2 outputSize, GLuint framebuffer)
{
    counters = {};
    if (outputSize.x <= 0 || outputSize.y <= 0)
        return;
    advanceTo(time_s, camera.position_m);
    DrawOptions options;
    options.sceneWorld = true;
    options.sky = true;
    const glm::ivec2 drawSize = scaledFrameSize(outputSize, renderScale);
    View view = viewOf(camera, drawSize);
    temporalViewProj.reset();
    if (temporalOn) {
        // The frame's projection moved by this frame's sub-pixel jitter;
        // the resolve reprojects with the unmoved one.
        temporalViewProj = view.projection * view.view;
        if (temporal.jitterEnabled())
            view.projection = jitteredProjection(view.projection, temporal.jitter_px(), drawSize);
    }
    drawRestoring(view, framebuffer, options, true, outputSize);
    temporalViewProj.reset();
}

} // namespace swell
