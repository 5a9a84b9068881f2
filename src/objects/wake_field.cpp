// The wake field's spectral step (wake_field.h).
#include "objects/wake_field.h"

#include "objects/wake_frame.h"

#include "swell/gpu/ocean.h"

#include <glm/common.hpp>
#include <kiss_fftnd.h>

#include <algorithm>
#include <cmath>
#include <type_traits>

namespace swell::detail {

namespace {

// The narrowest footprint, in cells each side of the centre: a body
// narrower than 2 cells would be sampled by a cell or two, and its
// footprint would flicker from cell to cell as it moves instead of gliding.
constexpr double kMinFootprintHalfCells = 2.0;

// Of what enters the sponge at its outer edge, the fraction a step keeps:
// a quadratic ramp from 1 at its inner edge, gentle enough that waves are
// absorbed rather than reflected by the change. A wave of group speed c_g
// stays h / (c_g dt) steps in each cell of size h: a 20 m wave (c_g = 2.8
// m/s) loses a factor e^-25 of its amplitude crossing a 32-cell sponge of
// 1 m cells once, shorter and slower waves far more.
constexpr double kSpongeKeptAtEdge = 0.8;

// Foam, made two ways, then fading with the spectral whitecaps' lifetime
// (ocean/spectral/whitecaps.h), 3.85 s:
// - a wave breaks where its slope nears Stokes' limit (ak = 0.44, the
//   120 deg crest; Stokes 1880, Mathematical and Physical Papers I, p. 227);
//   linear waves have no crest to sharpen, so foam starts at a slope of
//   kFoamOnsetSlope and is full at kFoamFullSlope;
// - the water closing in behind a moving hull breaks into its stern wash:
//   foam where the footprint's draft falls faster than kWashOnset_m_per_s,
//   full from kWashFull_m_per_s (a 7 m boat at 4 m/s leaves its water at
//   about 0.5 m/s; at 1 m/s, a quarter of that, it leaves no white water).
constexpr double kFoamOnsetSlope = 0.3;
constexpr double kFoamFullSlope = 0.44;
constexpr double kWashOnset_m_per_s = 0.15;
constexpr double kWashFull_m_per_s = 0.4;
constexpr double kFoamLifetime_s = SWELL_SOURCE_FOAM_LIFETIME_S;

// The integral of (1 - u^2)^2 over -1..1.
constexpr double kFootprintShapeIntegral = 16.0 / 15.0;

} // namespace

struct WakeField::Transforms {
    kiss_fftnd_cfg forward = nullptr, inverse = nullptr;
    explicit Transforms(int n)
    {
        const int dims[2] = {n, n};
        forward = kiss_fftnd_alloc(dims, 2, 0, nullptr, nullptr);
        inverse = kiss_fftnd_alloc(dims, 2, 1, nullptr, nullptr);
    }
    ~Transforms()
    {
        kiss_fft_free(forward);
        kiss_fft_free(inverse);
    }
    Transforms(const Transforms&) = delete;
    Transforms& operator=(const Transforms&) = delete;
};

int wakeCellOf(double x_m, double cellSize_m) { return int(std::floor(x_m / cellSize_m)); }

WakeField::WakeField(const WakeFieldSettings& settings) : settings_(settings), modes_(settings)
{
    const int n = settings_.cells;
    const std::size_t count = std::size_t(n) * std::size_t(n);
    field_.assign(count, {0.0f, 0.0f});
    foam_.assign(count, 0.0f);
    draftChange_.assign(count, 0.0f);
    spectrum_.resize(count);
    turned_.resize(count);
    spongeOfIndex_.assign(n, 1.0f);
    const int width = std::clamp(settings_.spongeCells, 1, n / 4);
    spongeWidth_ = width;
    for (int i = 0; i < n; ++i) {
        const int fromEdge = std::min(i, n - 1 - i);
        if (fromEdge < width) {
            const double depth = double(width - fromEdge) / width; // 1 at the edge, 0 inside
            spongeOfIndex_[i] = float(1.0 - (1.0 - kSpongeKeptAtEdge) * depth * depth);
        }
    }
    fft_ = std::make_unique<Transforms>(n);
    reset(glm::dvec2(0.0));
}

void WakeField::setDepth(double depth_m)
{
    settings_.depth_m = depth_m;
    modes_ = WakeModes(settings_);
}

WakeField::~WakeField() = default;
WakeField::WakeField(WakeField&&) noexcept = default;
WakeField& WakeField::operator=(WakeField&&) noexcept = default;

glm::dvec2 WakeField::corner_m() const { return glm::dvec2(cornerCell_) * settings_.cellSize_m; }

void WakeField::reset(glm::dvec2 focus_m)
{
    std::fill(field_.begin(), field_.end(), std::complex<float>(0.0f, 0.0f));
    std::fill(foam_.begin(), foam_.end(), 0.0f);
    lastSources_.clear();
    steps_ = 0;
    const int n = settings_.cells;
    cornerCell_ = glm::ivec2(int(std::lround(focus_m.x / settings_.cellSize_m)) - n / 2,
                             int(std::lround(focus_m.y / settings_.cellSize_m)) - n / 2);
}

void WakeField::recentre(glm::dvec2 focus_m)
{
    const int n = settings_.cells;
    const glm::ivec2 corner(int(std::lround(focus_m.x / settings_.cellSize_m)) - n / 2,
                            int(std::lround(focus_m.y / settings_.cellSize_m)) - n / 2);
    const glm::ivec2 shift = corner - cornerCell_;
    if (shift == glm::ivec2(0))
        return;
    // Cell (i, j) of the new grid is cell (i, j) + shift of the old one.
    auto move = [&](auto& cells) {
        using Cells = std::remove_reference_t<decltype(cells)>;
        Cells moved(cells.size(), typename Cells::value_type{});
        for (int j = 0; j < n; ++j) {
            const int oldJ = j + shift.y;
            if (oldJ < 0 || oldJ >= n)
                continue;
            for (int i = 0; i < n; ++i) {
                const int oldI = i + shift.x;
                if (oldI >= 0 && oldI < n)
                    moved[std::size_t(i) + std::size_t(j) * n] = cells[std::size_t(oldI) + std::size_t(oldJ) * n];
            }
        }
        cells = std::move(moved);
    };
    move(field_);
    move(foam_);
    cornerCell_ = corner;
}

void WakeField::addFootprints(const std::vector<WakeSource>& sources, double sign)
{
    const int n = settings_.cells;
    const double h = settings_.cellSize_m;
    const glm::dvec2 corner = corner_m();
    const double minHalf_m = kMinFootprintHalfCells * h;
    for (const WakeSource& s : sources) {
        const double a = std::max(s.halfLength_m, minHalf_m), b = std::max(s.halfBeam_m, minHalf_m);
        const double peak_m = s.volume_m3 / (a * b * kFootprintShapeIntegral * kFootprintShapeIntegral);
        const glm::dvec2 along = s.heading, across(-s.heading.y, s.heading.x);
        const double reach = std::hypot(a, b);
        const int i0 = std::max(0, int(std::floor((s.centre_m.x - reach - corner.x) / h)));
        const int i1 = std::min(n - 1, int(std::ceil((s.centre_m.x + reach - corner.x) / h)));
        const int j0 = std::max(0, int(std::floor((s.centre_m.y - reach - corner.y) / h)));
        const int j1 = std::min(n - 1, int(std::ceil((s.centre_m.y + reach - corner.y) / h)));
        for (int j = j0; j <= j1; ++j)
            for (int i = i0; i <= i1; ++i) {
                const glm::dvec2 d = corner + glm::dvec2(i, j) * h - s.centre_m;
                const double u = (d.x * along.x + d.y * along.y) / a;
                const double v = (d.x * across.x + d.y * across.y) / b;
                if (std::abs(u) >= 1.0 || std::abs(v) >= 1.0)
                    continue;
                const double du = 1.0 - u * u, dv = 1.0 - v * v;
                const float draft_m = float(sign * peak_m * du * du * dv * dv);
                field_[std::size_t(i) + std::size_t(j) * n] += std::complex<float>(draft_m, 0.0f);
                draftChange_[std::size_t(i) + std::size_t(j) * n] += draft_m;
            }
    }
}

void WakeField::absorbAtBorder()
{
    // Only the sponge's cells: inside it both factors are 1, and a cell times 1 is itself.
    const int n = settings_.cells, width = spongeWidth_;
    auto absorb = [&](int i, int j, float sj) { field_[std::size_t(i) + std::size_t(j) * n] *= sj * spongeOfIndex_[i]; };
    for (int j = 0; j < n; ++j) {
        const float sj = spongeOfIndex_[j];
        if (j < width || j >= n - width) {
            for (int i = 0; i < n; ++i)
                absorb(i, j, sj);
            continue;
        }
        for (int i = 0; i < width; ++i)
            absorb(i, j, sj);
        for (int i = n - width; i < n; ++i)
            absorb(i, j, sj);
    }
}

void WakeField::step(const std::vector<WakeSource>& sources)
{
    // The held pressure changes from last step's footprints to today's: E
    // (= eta + D) changes by as much, eta does not. At step 0 the bodies
    // are where they start, on water at rest round them: nothing changes.
    if (steps_ == 0)
        lastSources_ = sources;
    std::fill(draftChange_.begin(), draftChange_.end(), 0.0f);
    addFootprints(lastSources_, -1.0);
    addFootprints(sources, 1.0);
    lastSources_ = sources;

    const int n = settings_.cells;
    auto* in = reinterpret_cast<kiss_fft_cpx*>(field_.data());
    kiss_fftnd(fft_->forward, in, reinterpret_cast<kiss_fft_cpx*>(spectrum_.data()));
    // Each mode turned over the step (WakeModes::turn); the inverse
    // transform is unnormalised: 1 / n^2 goes in there.
    modes_.turn(spectrum_.data(), 1.0f / float(n) / float(n), turned_.data());
    kiss_fftnd(fft_->inverse, reinterpret_cast<kiss_fft_cpx*>(turned_.data()), in);
    absorbAtBorder();
    updateFoam();
    ++steps_;
}

void WakeField::updateFoam()
{
    const int n = settings_.cells;
    const float keep = float(std::exp(-kWakeStep_s / kFoamLifetime_s));
    const float toSlope = float(0.5 / settings_.cellSize_m);
    // Cell (i, j) from its neighbours' E (west, east, south, north).
    // Most cells are gentler than the onset and under no hull that left
    // them: there both amounts are 0 without the square root, and the
    // margin keeps the cells at the onset itself on the exact path.
    const double gentleSlopeSquared = kFoamOnsetSlope * kFoamOnsetSlope * (1.0 - 1e-9);
    auto foamAt = [&](std::size_t m, float west, float east, float south, float north) {
        const float sx = (east - west) * toSlope, sz = (north - south) * toSlope;
        const double slopeSquared = double(sx) * sx + double(sz) * sz;
        float breaking = 0.0f, wash = 0.0f;
        if (!(slopeSquared < gentleSlopeSquared)) {
            const double slope = std::sqrt(slopeSquared);
            breaking = float(std::clamp((slope - kFoamOnsetSlope) / (kFoamFullSlope - kFoamOnsetSlope), 0.0, 1.0));
        }
        if (draftChange_[m] < 0.0f) {
            const double leaving_m_per_s = -draftChange_[m] / kWakeStep_s;
            wash = float(std::clamp((leaving_m_per_s - kWashOnset_m_per_s) / (kWashFull_m_per_s - kWashOnset_m_per_s), 0.0, 1.0));
        }
        float& f = foam_[m];
        f = std::max(f * keep, std::max(breaking, wash));
    };
    // Along the border the neighbour beyond the grid is the border cell itself.
    auto e = [&](int i, int j) { return field_[std::size_t(std::clamp(i, 0, n - 1)) + std::size_t(std::clamp(j, 0, n - 1)) * n].real(); };
    auto clamped = [&](int i, int j) { foamAt(std::size_t(i) + std::size_t(j) * n, e(i - 1, j), e(i + 1, j), e(i, j - 1), e(i, j + 1)); };
    for (int j = 0; j < n; ++j) {
        if (j == 0 || j == n - 1) {
            for (int i = 0; i < n; ++i)
                clamped(i, j);
            continue;
        }
        clamped(0, j);
        const std::size_t row = std::size_t(j) * n;
        for (int i = 1; i < n - 1; ++i) {
            const std::size_t m = row + std::size_t(i);
            foamAt(m, field_[m - 1].real(), field_[m + 1].real(), field_[m - n].real(), field_[m + n].real());
        }
        clamped(n - 1, j);
    }
}

std::vector<float> WakeField::heights() const
{
    std::vector<float> out;
    heightsInto(out);
    return out;
}

void WakeField::heightsInto(std::vector<float>& out) const
{
    out.resize(field_.size());
    for (std::size_t m = 0; m < field_.size(); ++m)
        out[m] = field_[m].real();
}

double WakeField::heightAt(glm::dvec2 world_m) const
{
    const int n = settings_.cells;
    return bilinearOverCells((world_m - corner_m()) / settings_.cellSize_m, n,
                             [&](int i, int j) { return field_[std::size_t(i) + std::size_t(j) * n].real(); });
}

} // namespace swell::detail
