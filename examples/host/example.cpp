#include "example.h"

#include "gl_functions.h"

namespace host {

namespace {

// The camera's lens: vertical field of view and near plane (the far plane
// is at infinity).
constexpr double kFovY_deg = 55.0;
constexpr double kNear_m = 0.1;
// The tone mapper's exposure: ACES's fit maps 1.0 to 0.8 and the hazy
// horizon (the scene's horizon colour, 0.7..0.9) to about 0.7, off white.
constexpr float kExposure = 0.9f;

} // namespace

swell::Scene harbourScene()
{
    swell::Scene scene = swell::defaultScene();
    scene.showTerrain = false; // the host brings its own world
    scene.objects.clear();
    scene.sun.direction = {0.55, 0.35, -0.75};
    // Sheltered water: a light breeze over 5 km of fetch, and a low swell
    // from abeam (travelling towards +x) that rolls the ship.
    swell::WindSettings wind;
    wind.windSpeed_mps = 3.5;
    wind.windDirection_deg = 30.0;
    wind.fetch_km = 5.0;
    wind.minWavelength_m = 0.2;
    swell::SwellSettings swellFromAbeam;
    swellFromAbeam.height_m = 0.4;
    swellFromAbeam.period_s = 9.0;
    swellFromAbeam.direction_deg = 0.0;
    wind.swell = swellFromAbeam;
    scene.sea.wind = wind;
    return scene;
}

Example::Example(const swell::Scene& scene) : scene_(scene), renderer_(scene), harbour_(scene.sea.level_m)
{
    // The host lights its boxes with Swell's sun and sky, so the two agree.
    boxes_.light.towardsSun = glm::normalize(glm::vec3(scene.sun.direction));
    boxes_.light.sun = glm::vec3(scene.sun.color * scene.sun.intensity);
    boxes_.light.sky = glm::vec3(scene.sky.zenithColor) * 0.45f;
    boxes_.light.ground = glm::vec3(scene.sky.horizonColor) * 0.45f;
    // The host's own sea floor: the waves feel its depth and its mole
    // shelters the pier.
    renderer_.setSeabedHeights(harbour_.seabed());
}

void Example::frame(double time_s, GLuint framebuffer, glm::ivec2 size)
{
    if (!hdr_ || hdr_->size() != size)
        hdr_ = std::make_unique<Target>(size, GL_RGBA16F);

    // 1, 2: the simulation, then everything that floats placed on it.
    const glm::dvec3 viewpoint_m = harbour_.viewpoint_m();
    renderer_.advanceTo(time_s, viewpoint_m);
    harbour_.update(time_s, renderer_.drawnSurface(viewpoint_m), boxes_.boxes);

    const double aspect = double(size.x) / double(size.y);
    swell::View view;
    view.view = harbour_.eyeView();                   // world to eye, double, rolling with the ship
    view.projection = reversedInfiniteProjection(kFovY_deg, aspect, kNear_m);
    view.viewport = {0, 0, size.x, size.y};
    view.depth = swell::DepthMode::Reversed;          // glClipControl(GL_LOWER_LEFT, GL_ZERO_TO_ONE), GL_GREATER
    // The grid's detail where the height queries were made, so the crate
    // sits on exactly the water that is drawn.
    view.lodViewpoint_m = viewpoint_m;

    // 3: the host's opaque pass into its RGBA16F target, depth cleared to 0.
    // Alpha 0 where nothing is drawn; Swell's sky fills it.
    const float clear[4] = {0.0f, 0.0f, 0.0f, 0.0f};
    beginFrame(*hdr_, clear);
    boxes_.draw(view.projection * view.view);

    // 4: the water, the boxes in its reflection and refraction, the sky.
    swell::DrawOptions options;
    options.geometry = &boxes_;
    options.sky = true;
    options.encoding = swell::OutputEncoding::Linear;
    renderer_.draw(view, hdr_->framebuffer(), options);

    // 5: the host's tone mapping to the display.
    toneMapper_.apply(hdr_->colorTexture(), framebuffer, size, kExposure);
}

} // namespace host
