// The ocean renderer: owns the GPU state of a scene and draws its passes.
#include "swell/renderer.h"

#include "core/mesh_data.h"
#include "render/gpu_types.h"
#include "render/mesh.h"
#include "render/render_target.h"
#include "render/sky_cubemap.h"
#include "render/water_grid.h"
#include "swell/error.h"
#include "swell/gl/shader.h"
#include "swell/grid.h"

#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/type_ptr.hpp>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <optional>
#include <string>

namespace swell {

using namespace detail;

namespace {

constexpr double kIslandSize_m = 1400.0;
constexpr double kIslandPeak_m = 70.0;
constexpr int kIslandResolution = 192;
// Where the built-in island stands: ahead-left of the default camera.
constexpr glm::dvec3 kIslandPosition_m{-700.0, 0.0, -1700.0};

enum Pass { PassReflection = 0, PassRefraction = 1, PassMain = 2, PassCount = 3 };

glm::vec4 vec4Of(glm::dvec3 v, double w = 0.0) { return glm::vec4(glm::dvec4(v, w)); }

int debugViewDefine(DebugView v)
{
    switch (v) {
    case DebugView::Shaded: return SWELL_VIEW_SHADED;
    case DebugView::Normals: return SWELL_VIEW_NORMALS;
    case DebugView::Reflection: return SWELL_VIEW_REFLECTION;
    case DebugView::Refraction: return SWELL_VIEW_REFRACTION;
    case DebugView::Lod: return SWELL_VIEW_LOD;
    case DebugView::Wireframe: return SWELL_VIEW_WIREFRAME;
    }
    return SWELL_VIEW_SHADED;
}

struct Programs {
    gl::Program water, sky, mesh, capture, skyBake;
};

// What the world draws: the island, one mesh per scene object, the sky
// cubemap (the user's six images, or the procedural sky baked by render()).
struct World {
    GpuMesh island;
    std::vector<std::unique_ptr<GpuMesh>> meshes;
    // Per scene object, the farthest any vertex lies from the model's origin, m (unscaled).
    std::vector<double> meshReach_m;
    // Per scene object, the closed volume of its open hull, or null (see drawHullVolumes).
    std::vector<std::unique_ptr<GpuMesh>> hullVolumes;
    gl::Texture skyCube;
};

} // namespace

struct Renderer::Impl {
    Scene scene;
    WaveSet waves;
    GridShape gridShape;
    gl::ShaderSources sources;
    Programs programs;
    gl::Buffer frameUbo[PassCount];
    gl::Buffer waveUbo;
    gl::VertexArray emptyVao;
    WaterGrid waterGrid;
    WaveReach reach; // how far the waves move the surface, for culling
    World world;
    RenderTarget reflection, refraction, output;
    FrameCounters counters;
    PassObserver* observer = nullptr;
    // The sun and sky world.skyCube was baked for; empty when it must be (re)baked.
    std::optional<SkyBakeKey> bakedSky;

    void notify(bool begin, const char* pass) const
    {
        if (observer)
            begin ? observer->beginPass(pass) : observer->endPass(pass);
    }

    explicit Impl(RendererOptions options) : sources(std::move(options.shaders)) {}

    // The programs for a scene's variant: its debug view.
    Programs buildPrograms(const Scene& variant) const
    {
        const std::vector<std::string> defines{"SWELL_DEBUG_VIEW " + std::to_string(debugViewDefine(variant.debugView))};
        Programs p;
        p.water = gl::buildProgram(sources, {{GL_VERTEX_SHADER, "water.vert"}, {GL_FRAGMENT_SHADER, "water.frag"}}, defines);
        p.sky = gl::buildProgram(sources, {{GL_VERTEX_SHADER, "fullscreen.vert"}, {GL_FRAGMENT_SHADER, "sky.frag"}}, defines);
        p.mesh = gl::buildProgram(sources, {{GL_VERTEX_SHADER, "mesh.vert"}, {GL_FRAGMENT_SHADER, "mesh.frag"}}, defines);
        p.skyBake = gl::buildProgram(sources, {{GL_VERTEX_SHADER, "fullscreen.vert"}, {GL_FRAGMENT_SHADER, "sky_bake.frag"}}, defines);
        p.capture = gl::buildProgram(sources, {{GL_VERTEX_SHADER, "water.vert"}}, defines,
                                     {"vRestPoint", "vPosition", "vNormal"});
        return p;
    }

    void buildGrid()
    {
        gridShape = gridShapeFor(scene.grid, scene.camera);
        waterGrid.build(gridShape);
    }

    // Builds the meshes and sky of `from` without touching the current ones,
    // so a bad asset leaves the renderer as it was.
    static World buildWorld(const Scene& from)
    {
        // A path from the scene, found relative to the scene file's folder.
        auto assetPath = [&from](const std::string& path) {
            const std::filesystem::path p(path);
            return p.is_absolute() || from.assetFolder.empty() ? p : std::filesystem::path(from.assetFolder) / p;
        };
        World world;
        if (from.showTerrain)
            world.island = GpuMesh(makeIsland(kIslandSize_m, kIslandPeak_m, kIslandResolution));
        for (const SceneObject& o : from.objects) {
            const bool builtin = o.path.starts_with("builtin:");
            const MeshData data = builtin ? makeBuiltinModel(o.path.substr(8)) : loadGltf(assetPath(o.path));
            if (data.vertices.empty())
                throw InputError({o.path}, "model has no triangles");
            world.meshes.push_back(std::make_unique<GpuMesh>(data));
            double reach = 0.0;
            for (const MeshVertex& v : data.vertices)
                reach = std::max(reach, double(glm::length(v.position)));
            world.meshReach_m.push_back(reach);
            // User models have no hull volume: a glTF file cannot say which
            // part of a model is an open hull (docs/RENDERING.md).
            const MeshData volume = builtin ? makeBuiltinHullVolume(o.path.substr(8)) : MeshData{};
            world.hullVolumes.push_back(volume.indices.empty() ? nullptr : std::make_unique<GpuMesh>(volume));
        }
        if (!from.sky.cubemapFaces.empty()) {
            std::vector<Image> faces;
            for (const std::string& f : from.sky.cubemapFaces) {
                faces.push_back(readImage(assetPath(f)));
                const Image& face = faces.back();
                if (face.width != face.height || face.width != faces.front().width)
                    throw InputError({assetPath(f).string()},
                                     "sky cubemap face is " + std::to_string(face.width) + "x" + std::to_string(face.height) +
                                         "; faces must be square and all the size of the first (" +
                                         std::to_string(faces.front().width) + "x" + std::to_string(faces.front().width) + ")");
            }
            world.skyCube = gl::Texture::create(GLenum(GL_TEXTURE_CUBE_MAP));
            const int n = faces.front().width;
            // A full mip chain: user photos may be far more detailed than the
            // pixels the sky pass samples them with.
            const int levels = 1 + int(std::floor(std::log2(double(n))));
            glTextureStorage2D(world.skyCube.id(), levels, GL_SRGB8_ALPHA8, n, n);
            for (int face = 0; face < 6; ++face)
                glTextureSubImage3D(world.skyCube.id(), 0, 0, 0, face, n, n, 1, GL_RGBA, GL_UNSIGNED_BYTE,
                                    faces[size_t(face)].rgba.data());
            glGenerateTextureMipmap(world.skyCube.id());
            glTextureParameteri(world.skyCube.id(), GL_TEXTURE_MIN_FILTER, GL_LINEAR_MIPMAP_LINEAR);
            glTextureParameteri(world.skyCube.id(), GL_TEXTURE_MAG_FILTER, GL_LINEAR);
        }
        return world;
    }

    void uploadWaves(const GridPlacement& grid, double time_s)
    {
        WaveUniforms u{};
        const int count = std::min<int>(int(waves.waves.size()), SWELL_MAX_WAVES);
        // Longest first: the shaders stop at the first wave their cells or
        // pixels cannot resolve, since every later one is shorter still.
        std::vector<const Wave*> order;
        for (int i = 0; i < count; ++i)
            order.push_back(&waves.waves[size_t(i)]);
        std::stable_sort(order.begin(), order.end(),
                         [](const Wave* a, const Wave* b) { return a->wavelength_m > b->wavelength_m; });
        for (int i = 0; i < count; ++i) {
            const Wave& w = *order[size_t(i)];
            // Exactly the k*d the CPU wave functions use.
            const glm::dvec2 kd = wavenumberVector(w);
            const double k = glm::length(kd);
            const glm::dvec2 d = kd / k;
            u.waveShape[i] = glm::vec4(glm::dvec4(d.x, d.y, k, w.amplitude_m));
            u.wavePhase[i] = glm::vec4(glm::dvec4(w.steepness, wrappedPhase(w, waves.depth_m, grid.center_m, time_s),
                                                  w.wavelength_m, 0.0));
        }
        u.waveCount = glm::ivec4(count, 0, 0, 0);
        glNamedBufferSubData(waveUbo.id(), 0, sizeof(u), &u);
        glBindBufferBase(GL_UNIFORM_BUFFER, SWELL_BINDING_WAVES, waveUbo.id());
    }

    // Boxes holding all world geometry, relative to the render origin: a
    // reflected ray that misses them all can only meet the sky. Objects may
    // turn and tilt, so each is boxed as a sphere round its origin; floating
    // ones also rise and fall with the waves. Returns the count, or -1 when
    // there are more than fit (every ray is then marched).
    int worldBoxes(glm::dvec3 origin, glm::vec4* boxes) const
    {
        int count = 0;
        auto add = [&](glm::dvec3 lo, glm::dvec3 hi) {
            if (count < SWELL_MAX_WORLD_BOXES) {
                boxes[2 * count] = vec4Of(lo - origin);
                boxes[2 * count + 1] = vec4Of(hi - origin);
            }
            ++count;
        };
        if (world.island.indexCount() > 0) {
            const glm::dvec3 half(0.5 * kIslandSize_m, 0.0, 0.5 * kIslandSize_m);
            add(kIslandPosition_m - half - glm::dvec3(0.0, 1.0, 0.0),
                kIslandPosition_m + half + glm::dvec3(0.0, kIslandPeak_m + 1.0, 0.0));
        }
        for (size_t i = 0; i < world.meshes.size() && i < scene.objects.size(); ++i) {
            const SceneObject& o = scene.objects[i];
            const double r = world.meshReach_m[i] * o.scale;
            const glm::dvec3 pad(r, r + (o.floats ? reach.vertical_m : 0.0), r);
            add(o.position_m - pad, o.position_m + pad);
        }
        return count <= SWELL_MAX_WORLD_BOXES ? count : -1;
    }

    // The uniforms shared by every pass; pass-specific fields are set by the caller.
    FrameUniforms frameUniforms(const Camera& camera, const glm::dmat4& viewProj, const GridPlacement& grid,
                                glm::dvec3 origin, glm::ivec2 size) const
    {
        FrameUniforms f{};
        f.cameraViewProj = glm::mat4(viewProj);
        f.cameraInvViewProj = glm::mat4(glm::inverse(viewProj));
        f.passViewProj = f.cameraViewProj;
        f.passInvViewProj = f.cameraInvViewProj;
        f.clipPlane = glm::vec4(0.0f, 0.0f, 0.0f, 1.0f);
        f.eyePosition = vec4Of(camera.position_m - origin, 1.0);
        f.sunDirection = vec4Of(glm::normalize(scene.sun.direction), scene.sun.intensity);
        f.sunColor = vec4Of(scene.sun.color);
        // The sky's fog layer: the height at which a ray at the fog's end distance has
        // risen by 2% of it, so the sky stays clear a few degrees above the horizon.
        f.fogColor = vec4Of(scene.fog.color, 0.02 * scene.fog.end_m);
        f.fogRange = glm::vec4(float(scene.fog.start_m), float(scene.fog.end_m), 0.0f, 0.0f);
        f.skyZenith = vec4Of(scene.sky.zenithColor);
        f.skyHorizon = vec4Of(scene.sky.horizonColor);
        f.waterDeep = vec4Of(scene.water.deepColor);
        f.waterAbsorption = vec4Of(scene.water.absorption_per_m);
        f.waterOptics = glm::vec4(glm::dvec4(scene.water.fresnelF0, scene.water.shininess,
                                             scene.water.specularStrength, scene.water.refractionDistortion));
        f.gridShape = glm::vec4(glm::dvec4(gridShape.radius_m, gridShape.cells, gridShape.skirt_m, grid.finestStep_m));
        const HorizonFade fade = horizonFadeFor(scene.grid, gridShape);
        f.gridFade = glm::vec4(glm::dvec4(fade.start_m, fade.end_m, 0.0, 0.0));
        const glm::dvec2 centre = grid.center_m - glm::dvec2(origin.x, origin.z);
        f.gridCenter = glm::vec4(glm::dvec4(centre.x, 0.0, centre.y, 0.0));
        f.gridLayout = glm::vec4(glm::dvec4(gridShape.layout == GridLayout::Paper ? 1.0 : 0.0,
                                            grid.scale * gridShape.innerScale_m, gridShape.growth, grid.scale));
        for (int l = 0; l < SWELL_GRID_LEVELS; ++l)
            f.snapOffsets[l] = glm::vec4(glm::dvec4(grid.snapOffsets[size_t(l)], gridShape.levelFirstRing[size_t(l)], 0.0));
        const int boxes = worldBoxes(origin, f.worldBoxes);
        f.reflectionParams = glm::vec4(glm::dvec4(scene.reflection.fixedDistance_m, scene.reflection.clipOffset_m,
                                                  scene.reflection.mode == ReflectionMode::RayMarch ? 1.0 : 0.0, boxes));
        f.viewport = glm::vec4(float(size.x), float(size.y), 1.0f / float(size.x), 1.0f / float(size.y));
        return f;
    }

    // Per-frame setup shared by drawing and capture: the render origin is the
    // camera's x,z; waves are phased at the snapped grid centre; the water
    // tiles in view are chosen.
    FrameUniforms prepareFrame(const Camera& camera, double time_s, glm::ivec2 size, glm::dvec3& origin)
    {
        origin = glm::dvec3(camera.position_m.x, 0.0, camera.position_m.z);
        const GridPlacement grid = placeGrid(gridShape, camera.position_m);
        uploadWaves(grid, time_s);
        const glm::dmat4 viewProj = camera.projection(double(size.x) / double(size.y)) * camera.viewRelativeTo(origin);
        const FrameUniforms f = frameUniforms(camera, viewProj, grid, origin, size);
        waterGrid.cull(gridShape, grid, reach, viewProj, grid.center_m - glm::dvec2(origin.x, origin.z));
        return f;
    }

    void bindFrame(Pass pass, const FrameUniforms& f)
    {
        glNamedBufferSubData(frameUbo[pass].id(), 0, sizeof(f), &f);
        glBindBufferBase(GL_UNIFORM_BUFFER, SWELL_BINDING_FRAME, frameUbo[pass].id());
    }

    glm::dmat4 objectModel(const SceneObject& o, glm::dvec3 origin, double time_s) const
    {
        glm::dvec3 position = o.position_m;
        glm::dmat4 tilt(1.0);
        if (o.floats) {
            // One inverse solve serves both the height and the tilt.
            const glm::dvec2 rest = restPointUnder(waves, {o.position_m.x, o.position_m.z}, time_s);
            position.y += displacementAt(waves, rest, time_s).y;
            const glm::dvec3 n = normalAt(waves, rest, time_s);
            // A body larger than the short waves does not follow every ripple:
            // tilt half way towards the surface normal.
            const glm::dvec3 up = glm::normalize(glm::mix(glm::dvec3(0, 1, 0), n, 0.5));
            const glm::dvec3 axis = glm::cross(glm::dvec3(0, 1, 0), up);
            const double s = glm::length(axis);
            if (s > 1e-9)
                tilt = glm::rotate(glm::dmat4(1.0), std::asin(std::min(s, 1.0)), axis / s);
        }
        return glm::translate(glm::dmat4(1.0), position - origin) * tilt *
               glm::rotate(glm::dmat4(1.0), glm::radians(o.yaw_deg), glm::dvec3(0, 1, 0)) *
               glm::scale(glm::dmat4(1.0), glm::dvec3(o.scale));
    }

    void drawWorld(glm::dvec3 origin, double time_s)
    {
        glUseProgram(programs.mesh.id());
        const GpuMesh& island = world.island;
        if (island.indexCount() > 0) {
            const glm::mat4 model(glm::translate(glm::dmat4(1.0), kIslandPosition_m - origin));
            glUniformMatrix4fv(0, 1, GL_FALSE, glm::value_ptr(model));
            island.draw();
            counters.worldTriangles += island.indexCount() / 3;
            ++counters.drawCalls;
        }
        for (size_t i = 0; i < world.meshes.size(); ++i) {
            const glm::mat4 model(objectModel(scene.objects[i], origin, time_s));
            glUniformMatrix4fv(0, 1, GL_FALSE, glm::value_ptr(model));
            world.meshes[i]->draw();
            counters.worldTriangles += world.meshes[i]->indexCount() / 3;
            ++counters.drawCalls;
        }
    }

    // Pass 3's clean intersections: each open hull's closed volume is drawn
    // into depth only, after the world and before the water. Its outer surface
    // coincides with the hull's, so only its lid at the gunwale changes the
    // depth buffer: a ray into the open hull meets the lid before the water
    // inside, and that water fails the depth test. (The reflection and
    // refraction passes draw no water, so they need no mask.)
    void drawHullVolumes(glm::dvec3 origin, double time_s)
    {
        glUseProgram(programs.mesh.id());
        glColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);
        for (size_t i = 0; i < world.hullVolumes.size(); ++i)
            if (world.hullVolumes[i]) {
                const glm::mat4 model(objectModel(scene.objects[i], origin, time_s));
                glUniformMatrix4fv(0, 1, GL_FALSE, glm::value_ptr(model));
                world.hullVolumes[i]->draw();
                ++counters.drawCalls;
            }
        glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
    }

    void drawSky()
    {
        glUseProgram(programs.sky.id());
        glBindTextureUnit(SWELL_UNIT_SKY, world.skyCube.id());
        glDepthFunc(GL_LEQUAL);
        glDepthMask(GL_FALSE);
        glBindVertexArray(emptyVao.id());
        glDrawArrays(GL_TRIANGLES, 0, 3);
        ++counters.drawCalls;
        glDepthMask(GL_TRUE);
        glDepthFunc(GL_LESS);
    }

    void drawWater()
    {
        glUseProgram(programs.water.id());
        glBindTextureUnit(SWELL_UNIT_SKY, world.skyCube.id());
        glBindTextureUnit(SWELL_UNIT_REFLECTION_COLOR, reflection.color());
        glBindTextureUnit(SWELL_UNIT_REFLECTION_DEPTH, reflection.depth());
        glBindTextureUnit(SWELL_UNIT_REFRACTION_COLOR, refraction.color());
        glBindTextureUnit(SWELL_UNIT_REFRACTION_DEPTH, refraction.depth());
        glBindVertexArray(waterGrid.vertexArray());
        if (scene.debugView == DebugView::Wireframe)
            glPolygonMode(GL_FRONT_AND_BACK, GL_LINE);
        counters.waterTriangles += waterGrid.draw();
        glPolygonMode(GL_FRONT_AND_BACK, GL_FILL);
        ++counters.drawCalls;
    }

    // Every pass sets all the state it depends on, so passes can be reordered.
    void beginPass(GLuint framebuffer, glm::ivec2 size, glm::vec4 clear)
    {
        glBindFramebuffer(GL_FRAMEBUFFER, framebuffer);
        glViewport(0, 0, size.x, size.y);
        glDisable(GL_BLEND);
        glDisable(GL_CULL_FACE);
        glDisable(GL_SCISSOR_TEST);
        glEnable(GL_DEPTH_TEST);
        glDepthFunc(GL_LESS);
        glDepthMask(GL_TRUE);
        glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
        // The shaders write display-ready (sRGB-encoded) colour: a host that
        // enabled sRGB writes would have it encoded twice.
        glDisable(GL_FRAMEBUFFER_SRGB);
        // Filter across cubemap face edges (off by default even in core profiles).
        glEnable(GL_TEXTURE_CUBE_MAP_SEAMLESS);
        glClearColor(clear.r, clear.g, clear.b, clear.a);
        glClearDepth(1.0);
        glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    }

    void render(const Camera& camera, double time_s, glm::ivec2 size, GLuint framebuffer)
    {
        counters = {};
        if (size.x <= 0 || size.y <= 0)
            return;
        glm::dvec3 origin;
        const FrameUniforms base = prepareFrame(camera, time_s, size, origin);
        // The procedural sky is baked into the cubemap when first needed and
        // after the sun or sky changed (the bake reads the frame uniforms).
        if (scene.sky.cubemapFaces.empty() && bakedSky != skyBakeKeyOf(scene)) {
            bindFrame(PassMain, base);
            bakeProceduralSky(programs.skyBake, world.skyCube, emptyVao.id());
            bakedSky = skyBakeKeyOf(scene);
        }
        const glm::ivec2 scaled = glm::max(glm::ivec2(glm::dvec2(size) * scene.reflection.resolutionScale), glm::ivec2(1));
        reflection.resize(scaled);
        refraction.resize(scaled);

        // Pass 1: the world mirrored about the water plane, clipped just below it.
        FrameUniforms f = base;
        const glm::mat4 mirror = glm::scale(glm::mat4(1.0f), glm::vec3(1.0f, -1.0f, 1.0f));
        f.passViewProj = base.cameraViewProj * mirror;
        f.passInvViewProj = glm::inverse(f.passViewProj);
        f.clipPlane = glm::vec4(0.0f, 1.0f, 0.0f, float(scene.reflection.clipOffset_m));
        f.eyePosition.y = -base.eyePosition.y;
        f.viewport = glm::vec4(float(scaled.x), float(scaled.y), 1.0f / float(scaled.x), 1.0f / float(scaled.y));
        notify(true, "reflection");
        bindFrame(PassReflection, f);
        beginPass(reflection.framebuffer(), scaled, glm::vec4(0.0f));
        glEnable(GL_CLIP_DISTANCE0);
        drawWorld(origin, time_s);
        drawSky();
        notify(false, "reflection");

        // Pass 1b: the world below the water, for refraction.
        f = base;
        f.clipPlane = glm::vec4(0.0f, -1.0f, 0.0f, float(scene.reflection.clipOffset_m));
        f.viewport = glm::vec4(float(scaled.x), float(scaled.y), 1.0f / float(scaled.x), 1.0f / float(scaled.y));
        notify(true, "refraction");
        bindFrame(PassRefraction, f);
        beginPass(refraction.framebuffer(), scaled, glm::vec4(0.0f));
        drawWorld(origin, time_s);
        glDisable(GL_CLIP_DISTANCE0);
        notify(false, "refraction");

        // Pass 2: world, sky, then the water depth-tested against the world, so
        // objects crossing the surface meet it cleanly.
        f = base;
        f.passFlags = glm::vec4(1.0f, 0.0f, 0.0f, 0.0f);
        notify(true, "main");
        bindFrame(PassMain, f);
        beginPass(framebuffer, size, glm::vec4(0.0f, 0.0f, 0.0f, 1.0f));
        drawWorld(origin, time_s);
        drawSky();
        drawHullVolumes(origin, time_s);
        notify(true, "water");
        drawWater();
        notify(false, "water");
        notify(false, "main");
        glBindVertexArray(0);
        glUseProgram(0);
    }
};

Renderer::Renderer(const Scene& scene, RendererOptions options) : impl_(std::make_unique<Impl>(std::move(options)))
{
    for (gl::Buffer& b : impl_->frameUbo) {
        b = gl::Buffer::create();
        glNamedBufferStorage(b.id(), sizeof(FrameUniforms), nullptr, GL_DYNAMIC_STORAGE_BIT);
    }
    impl_->waveUbo = gl::Buffer::create();
    glNamedBufferStorage(impl_->waveUbo.id(), sizeof(WaveUniforms), nullptr, GL_DYNAMIC_STORAGE_BIT);
    impl_->emptyVao = gl::VertexArray::create();
    setScene(scene);
}

Renderer::~Renderer() = default;

void Renderer::setScene(const Scene& scene)
{
    Impl& s = *impl_;
    const bool first = !s.programs.water;
    const bool programsChanged = first || scene.debugView != s.scene.debugView;
    const bool gridChanged = first || scene.grid.layout != s.scene.grid.layout ||
                             scene.grid.resolution != s.scene.grid.resolution ||
                             scene.grid.radius_m != s.scene.grid.radius_m || scene.camera.far_m != s.scene.camera.far_m;
    auto sameObjects = [](const std::vector<SceneObject>& a, const std::vector<SceneObject>& b) {
        return std::equal(a.begin(), a.end(), b.begin(), b.end(),
                          [](const SceneObject& x, const SceneObject& y) { return x.path == y.path; });
    };
    // Meshes and the sky cubemap are read from disk only when what they come from changed.
    const bool worldChanged = first || scene.showTerrain != s.scene.showTerrain ||
                              !sameObjects(scene.objects, s.scene.objects) ||
                              scene.sky.cubemapFaces != s.scene.sky.cubemapFaces || scene.assetFolder != s.scene.assetFolder;
    WaveSet waves = resolveWaves(scene.waves);
    limitSteepness(waves);
    if (const std::string problem = validate(waves); !problem.empty())
        throw InputError({}, "waves: " + problem);
    // Everything that can fail is built first; the renderer changes only when all succeeded.
    Programs programs;
    if (programsChanged)
        programs = s.buildPrograms(scene);
    World world;
    if (worldChanged)
        world = Impl::buildWorld(scene);
    s.scene = scene;
    s.waves = std::move(waves);
    s.reach = waveReach(s.waves);
    if (programsChanged)
        s.programs = std::move(programs);
    if (worldChanged) {
        s.world = std::move(world);
        s.bakedSky.reset();
    }
    if (gridChanged)
        s.buildGrid();
}

const Scene& Renderer::scene() const { return impl_->scene; }
const WaveSet& Renderer::waves() const { return impl_->waves; }
const FrameCounters& Renderer::counters() const { return impl_->counters; }
void Renderer::setPassObserver(PassObserver* observer) { impl_->observer = observer; }

void Renderer::reloadShaders()
{
    impl_->sources.forgetCachedFiles();
    impl_->programs = impl_->buildPrograms(impl_->scene);
    impl_->bakedSky.reset(); // the bake shader may have changed
}

void Renderer::render(const Camera& camera, double time_s, glm::ivec2 size, unsigned framebuffer)
{
    impl_->render(camera, time_s, size, framebuffer);
}

Image Renderer::renderImage(const Camera& camera, double time_s, glm::ivec2 size)
{
    Image image;
    if (size.x <= 0 || size.y <= 0)
        return image;
    impl_->output.resize(size, GL_RGBA8);
    impl_->render(camera, time_s, size, impl_->output.framebuffer());
    image.width = size.x;
    image.height = size.y;
    image.rgba.resize(size_t(size.x) * size_t(size.y) * 4);
    std::vector<std::uint8_t> bottomUp(image.rgba.size());
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    glGetTextureImage(impl_->output.color(), 0, GL_RGBA, GL_UNSIGNED_BYTE, GLsizei(bottomUp.size()), bottomUp.data());
    const size_t row = size_t(size.x) * 4;
    for (int y = 0; y < size.y; ++y)
        std::copy_n(&bottomUp[size_t(size.y - 1 - y) * row], row, &image.rgba[size_t(y) * row]);
    return image;
}

int Renderer::waterVertexCount() const { return (impl_->gridShape.cells + 1) * (impl_->gridShape.cells + 1); }

int Renderer::captureWaterVertices(const Camera& camera, double time_s, unsigned buffer, glm::ivec2 size,
                                   std::vector<std::uint32_t>* drawnIndices)
{
    Impl& s = *impl_;
    glm::dvec3 origin;
    s.bindFrame(PassMain, s.prepareFrame(camera, time_s, glm::max(size, glm::ivec2(1)), origin));
    if (drawnIndices)
        *drawnIndices = s.waterGrid.chosenIndices();
    // Drawing needs a complete framebuffer even with rasterisation discarded
    // (a headless context has no default one).
    if (s.output.size().x == 0)
        s.output.resize({1, 1}, GL_RGBA8);
    glBindFramebuffer(GL_FRAMEBUFFER, s.output.framebuffer());
    glUseProgram(s.programs.capture.id());
    glBindVertexArray(s.emptyVao.id());
    glEnable(GL_RASTERIZER_DISCARD);
    glBindBufferBase(GL_TRANSFORM_FEEDBACK_BUFFER, 0, buffer);
    glBeginTransformFeedback(GL_POINTS);
    const int count = waterVertexCount();
    glDrawArrays(GL_POINTS, 0, count);
    glEndTransformFeedback();
    glBindBufferBase(GL_TRANSFORM_FEEDBACK_BUFFER, 0, 0);
    glDisable(GL_RASTERIZER_DISCARD);
    glUseProgram(0);
    return count;
}

} // namespace swell
