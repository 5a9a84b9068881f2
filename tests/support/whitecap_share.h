// The whitecap share of a storm clip as the labels count it (docs/LABELS.md):
// in each 1 s window of a clip, the share of the visible sea (water,
// whitecap_foam and wake_foam pixels) labelled whitecap_foam, from the
// storm preset's own camera and from straight above it at 300 m, against
// Monahan & O'Muircheartaigh's (1980, eq. 3) cover at the wind.
// Used by tests/gl/test_whitecap_share.cpp (the storm's wind, in the
// default suite); other winds: stormWhitecapShares(8.0, ...) and so on.
#pragma once

#include "ocean/spectral/whitecaps.h"
#include "swell/dataset/labels.h"
#include "swell/gpu/label_classes.h"
#include "swell/renderer.h"
#include "swell/scene/scene.h"
#include "swell/scene/scene_file.h"

#include <algorithm>
#include <cstdio>
#include <string>
#include <vector>

namespace swell::test {

// Each window's share of the sea under whitecaps, from each viewpoint.
struct WhitecapShares {
    std::vector<double> presetCamera, from300m;
};

// The share of the visible sea a frame's labels call whitecap_foam.
inline double whitecapShare(const FrameLabels& labels)
{
    long long sea = 0, white = 0;
    for (const std::uint16_t c : labels.semantic) {
        const bool whitecap = c == SWELL_LABEL_WHITECAP_FOAM;
        sea += isSeaClass(c);
        white += whitecap;
    }
    return sea > 0 ? double(white) / double(sea) : 0.0;
}

// The storm preset at `windSpeed_mps`, run as a clip for `duration_s`: the
// simulation steps every kFoamReplayStep_s (0.5 s, the lattice a still's
// replay takes, so the foam is stepped as densely as a still's), and the
// labels of both views are taken once in each 1 s window, at its middle.
// The first window starts from a still's replayed history, as a clip does.
inline WhitecapShares stormWhitecapShares(double windSpeed_mps, double duration_s, glm::ivec2 size)
{
    Scene scene = loadScene(std::string(SWELL_SOURCE_DIR) + "/scenes/storm.toml");
    scene.sea.wind->windSpeed_mps = windSpeed_mps;
    Renderer renderer(scene);
    const Camera preset = cameraAt(scene.camera, 0.0);
    Camera above = preset;
    above.position_m = {preset.position_m.x, 300.0, preset.position_m.z};
    above.pitch_deg = -89.0;
    WhitecapShares shares;
    for (int window = 0; window < int(duration_s); ++window) {
        double presetShare = 0.0, aboveShare = 0.0;
        for (const double t_s : {double(window), window + 0.5}) {
            renderer.advanceTo(t_s, preset.position_m);
            presetShare += 0.5 * whitecapShare(renderer.renderLabels(preset, size));
            aboveShare += 0.5 * whitecapShare(renderer.renderLabels(above, size));
        }
        shares.presetCamera.push_back(presetShare);
        shares.from300m.push_back(aboveShare);
    }
    return shares;
}

// Prints the windows' shares and their range against Monahan's cover;
// returns the largest factor by which any window misses it (1: all equal).
inline double largestMissFactor(const char* what, double windSpeed_mps, const std::vector<double>& shares)
{
    const double monahan = spectral::monahanWhitecapCover(windSpeed_mps);
    double lowest = 1.0, highest = 0.0;
    std::printf("U10 %.0f m/s, %s: whitecap share per 1 s window:", windSpeed_mps, what);
    for (const double s : shares) {
        std::printf(" %.3f", s);
        lowest = std::min(lowest, s);
        highest = std::max(highest, s);
    }
    std::printf("\n  min %.4f, max %.4f; Monahan %.4f: %.2f to %.2f times it\n", lowest, highest, monahan,
                lowest / monahan, highest / monahan);
    return std::max(highest / monahan, lowest > 0.0 ? monahan / lowest : 1e9);
}

} // namespace swell::test
