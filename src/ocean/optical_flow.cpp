// Forward optical flow between two labelled frames (swell/dataset/flow.h,
// docs/LABELS.md "Optical flow"), on the CPU: each pixel's point rebuilt
// from its range along its centre ray, moved as what it shows moves, and
// projected with the second frame's camera.
#include "swell/dataset/flow.h"

#include "ocean/drawn_search.h"
#include "swell/dataset/sensor.h"
#include "swell/drawn_surface.h"
#include "swell/error.h"
#include "swell/gpu/label_classes.h"

#include <fmt/format.h>
#include <glm/geometric.hpp>
#include <glm/matrix.hpp>

#include <algorithm>
#include <cmath>
#include <memory>
#include <optional>
#include <unordered_map>

namespace swell {

namespace {

// The world direction of pixel (x, y)'s centre ray, through the lens.
glm::dvec3 centreRay(const CameraCalibration& c, int x, int y)
{
    const LensDistortion lens = lensOf(c);
    const glm::dvec2 u = undistort(lens, {(x + 0.5 - c.cx_px) / c.fx_px, (y + 0.5 - c.cy_px) / c.fy_px});
    return glm::normalize(glm::dmat3(c.worldFromCamera) * glm::dvec3(u, 1.0));
}

glm::dvec3 eyeOf(const CameraCalibration& c) { return glm::dvec3(c.worldFromCamera[3]); }

// A water point and the drawn triangle under it at the first time.
struct WaterPoint {
    std::size_t pixel = 0;
    glm::dvec3 position_m{0.0}; // absolute world, at time_s
    std::optional<DrawnPoint> drawn;
};

// The grid vertices of one DrawnSurface, each displaced once however many
// pixels ask for it (a cell near the eye spans many pixels).
class VertexCache {
public:
    explicit VertexCache(const DrawnSurface& surface) : surface_(surface) {}
    glm::dvec3 operator()(int i, int j)
    {
        const std::int64_t key = (std::int64_t(i) << 32) | std::int64_t(std::uint32_t(j));
        auto [at, added] = vertices_.try_emplace(key);
        if (added)
            at->second = surface_.vertex(i, j);
        return at->second;
    }

private:
    const DrawnSurface& surface_;
    std::unordered_map<std::int64_t, glm::dvec3> vertices_;
};

// How far the range's point may lie from the triangle it was measured to,
// m: the label's float32 and the rasteriser's, well under a centimetre.
constexpr double kOnTriangle_m = 0.02;

// The drawn triangle under water point p: searched first round the cell of
// the pixel before (neighbouring pixels mostly share a cell or touch), and
// kept only if p lies on it (where the grid folds over itself, another
// triangle may cover the same x, z); else as DrawnSurface::at() searches,
// from the cell over the rest point under p.
std::optional<DrawnPoint> drawnTriangleUnder(glm::dvec3 p, const SeaMotion& sea, const DrawnSurface& surface,
                                             double time_s, VertexCache& vertices,
                                             const std::optional<DrawnPoint>& before)
{
    const detail::DrawnVertexFunction vertex = [&](int i, int j) { return std::optional<glm::dvec3>(vertices(i, j)); };
    const glm::dvec2 place(p.x, p.z);
    if (before) {
        const glm::ivec2 cell(before->cellI, before->cellJ);
        std::optional<DrawnPoint> hit = detail::searchDrawnCells(sea.shape, cell, place, 1, vertex);
        if (hit && std::abs(hit->position_m.y - p.y) <= kOnTriangle_m)
            return hit;
    }
    const GridPlacement& placement = surface.placement();
    const glm::dvec2 rest = sea.surface->restPointUnder(place, time_s);
    return detail::searchDrawnCells(sea.shape, detail::restCellOf(sea.shape, placement, rest - placement.center_m),
                                    place, detail::kMaxDrawnSearchRings, vertex);
}

// Moves each water point from time_s to time_s + interval_s as the same
// material point of the drawn surface: the drawn triangle under it (the
// plane the label's range was measured to) at time_s, its grid vertices
// at time_s + interval_s (the grid left where the first frame's eye put
// it, so each vertex is one rest point: the waves displace it, filtered as
// its cell and the horizon fade filter it), weighted alike. Where no
// triangle is under it (the still plane past the grid) it stays. All of one
// time first, then all of the other: the spectral twin holds one time's
// fields at once.
void moveWater(std::vector<WaterPoint>& points, const SeaMotion& sea, glm::dvec3 eye_m, double time_s,
               double interval_s)
{
    // Borrowed, not owned (SeaMotion's contract): an empty owner.
    const std::shared_ptr<const SurfaceQuery> surface(std::shared_ptr<const SurfaceQuery>(), sea.surface);
    const glm::dvec3 eyeSea = sea.sea.toSea(eye_m);
    const DrawnSurface before(surface, sea.shape, sea.fade, eyeSea, time_s, sea.sea);
    VertexCache verticesBefore(before);
    std::optional<DrawnPoint> last;
    for (WaterPoint& p : points) {
        p.drawn = drawnTriangleUnder(p.position_m, sea, before, time_s, verticesBefore, last);
        last = p.drawn;
    }
    const DrawnSurface after(surface, sea.shape, sea.fade, eyeSea, time_s + interval_s, sea.sea);
    VertexCache verticesAfter(after);
    for (WaterPoint& p : points) {
        if (!p.drawn)
            continue;
        glm::dvec3 moved(0.0);
        for (std::size_t k = 0; k < 3; ++k)
            moved += p.drawn->weights[int(k)] * verticesAfter(p.drawn->corners[k].x, p.drawn->corners[k].y);
        // The range's point lies on the triangle (to float32): carry what it lies off it along.
        p.position_m = moved + (p.position_m - p.drawn->position_m);
    }
}

const ObjectLabel* objectWithInstance(const std::vector<ObjectLabel>& objects, std::uint16_t instance)
{
    for (const ObjectLabel& o : objects)
        if (o.instance == instance)
            return &o;
    return nullptr;
}

// Where each pixel's point is at the second frame's time (absolute world,
// m), or empty for the sky and whatever has no point.
std::vector<std::optional<glm::dvec3>> movedPoints(const FrameLabels& now, double time_s, const FrameLabels& next,
                                                   double interval_s, const SeaMotion& sea)
{
    const int w = now.size.x, h = now.size.y;
    std::vector<std::optional<glm::dvec3>> moved(std::size_t(w) * std::size_t(h));
    std::vector<WaterPoint> water;
    const glm::dvec3 eye = eyeOf(now.camera);
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            const std::size_t i = std::size_t(y) * std::size_t(w) + std::size_t(x);
            const double range_m = now.range_m[i];
            if (!std::isfinite(range_m) || now.semantic[i] == SWELL_LABEL_SKY || now.semantic[i] == SWELL_LABEL_NONE)
                continue;
            const glm::dvec3 p = eye + range_m * centreRay(now.camera, x, y);
            if (now.instance[i] != 0) {
                // The point keeps its place in the object's axes.
                const ObjectLabel* before = objectWithInstance(now.objects, now.instance[i]);
                const ObjectLabel* after = objectWithInstance(next.objects, now.instance[i]);
                if (before && after)
                    moved[i] = glm::dvec3(after->pose.worldFromObject * glm::inverse(before->pose.worldFromObject) *
                                          glm::dvec4(p, 1.0));
            } else if (isSeaClass(now.semantic[i])) {
                water.push_back(WaterPoint{i, p, std::nullopt});
            } else {
                moved[i] = p; // the land does not move
            }
        }
    if (!water.empty()) {
        if (!sea.surface)
            throw Error("opticalFlowOf: the frame shows water but the sea's motion has no surface (null)");
        moveWater(water, sea, eye, time_s, interval_s);
    }
    for (const WaterPoint& p : water)
        moved[p.pixel] = p.position_m;
    return moved;
}

} // namespace

SeaMotion seaMotionOf(const Scene& scene, const SurfaceQuery& surface)
{
    SeaMotion motion;
    motion.surface = &surface;
    motion.shape = gridShapeFor(scene.grid, scene.camera);
    motion.fade = horizonFadeFor(scene.grid, motion.shape);
    motion.sea = seaFrameOf(scene);
    return motion;
}

bool visibleAt(const FrameLabels& next, glm::dvec2 place_px, double range_m)
{
    const int w = next.size.x, h = next.size.y;
    if (!(place_px.x >= 0.0 && place_px.y >= 0.0 && place_px.x < w && place_px.y < h))
        return false;
    const double tolerance_m = 0.02 * range_m + 0.05;
    const glm::ivec2 first(glm::floor(place_px - 0.5));
    for (int dy = 0; dy < 2; ++dy)
        for (int dx = 0; dx < 2; ++dx) {
            const int x = std::clamp(first.x + dx, 0, w - 1), y = std::clamp(first.y + dy, 0, h - 1);
            if (double(next.range_m[std::size_t(y) * std::size_t(w) + std::size_t(x)]) >= range_m - tolerance_m)
                return true;
        }
    return false;
}

FrameFlow opticalFlowOf(const FrameLabels& now, double time_s, const FrameLabels& next, double interval_s,
                        const SeaMotion& sea)
{
    if (now.size != next.size)
        throw Error(fmt::format("opticalFlowOf: the frames' sizes differ ({}x{} and {}x{})", now.size.x, now.size.y,
                                next.size.x, next.size.y));
    const int w = now.size.x, h = now.size.y;
    FrameFlow flow;
    flow.size = now.size;
    flow.interval_s = interval_s;
    flow.flow_px.assign(std::size_t(w) * std::size_t(h), glm::vec2(0.0f));
    flow.valid.assign(flow.flow_px.size(), 0);
    const std::vector<std::optional<glm::dvec3>> moved = movedPoints(now, time_s, next, interval_s, sea);
    const glm::dvec3 eyeNext = eyeOf(next.camera);
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            const std::size_t i = std::size_t(y) * std::size_t(w) + std::size_t(x);
            const glm::dvec2 centre(x + 0.5, y + 0.5);
            // The sky's direction, a point at infinity, turns with the camera alone.
            const glm::dvec3 target = moved[i] ? *moved[i] : eyeNext + 1.0e9 * centreRay(now.camera, x, y);
            const std::optional<glm::dvec2> seen = projectToImage(next.camera, target);
            if (!seen)
                continue;
            flow.flow_px[i] = glm::vec2(*seen - centre);
            if (moved[i])
                flow.valid[i] = visibleAt(next, *seen, glm::distance(*moved[i], eyeNext)) ? 1 : 0;
        }
    return flow;
}

} // namespace swell
