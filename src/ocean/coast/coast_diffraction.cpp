// Diffraction into the lee of obstacles (coast_diffraction.h): a parabolic
// march of the wave's complex amplitude along its open-sea direction, on a
// grid turned to that direction, its answer read back onto the depth grid.
//
// The amplitude A of a wave exp(i (k s - omega t)) running along s obeys,
// in the wide-angle [1/1] Pade form of the parabolic equation (Kirby 1986,
// eq. 12, constant depth, no current),
//
//     (1 + X / 4) dA/ds = (i k / 2) X A,    X = (1 / k^2) d^2/dt^2,
//
// whose small-angle limit (X / 4 -> 0) is Radder's (1979) 2 i k dA/ds +
// d^2A/dt^2 = 0. For a semi-infinite screen it gives the Fresnel-integral
// solution that Sommerfeld's (1896) reduces to in the lee (Penney & Price
// 1952) near the march's axis; the Pade operator holds to some 40 degrees
// off it, and the side marches keep every point of a lee up to 60 degrees
// deep within 20 degrees of one's axis.
#include "ocean/coast/coast_diffraction.h"

#include "swell/constants.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <complex>
#include <limits>

namespace swell::coast {

namespace {

using Complex = std::complex<double>;

// Beside a shadow the ray solution's energy is its own numerical spreading
// into the shadow (first-order upwinding spreads across the rays, more for
// waves oblique to the grid): within a wavelength of a shadow, and never
// less than kShadowMargin samples, the march carries the wave instead.
constexpr int kShadowMargin = 3;
// How far the side marches turn from the open sea's direction: 40 degrees,
// so a lee point up to 60 degrees off is within 20 of one march's axis.
constexpr double kSideAngle_rad = 40.0 * kPi / 180.0;
// The imaginary part given to the Pade operator's 1/4 (see coefficientsOf).
constexpr double kPadeDamping = 0.02;

// The grid the march runs on: rows across the wave's open-sea direction,
// one depth-grid cell apart, covering the depth grid. Row r, column c lies
// at origin + cell (r along + c across); for a wave along +x its rows and
// columns are the depth grid's own samples.
struct MarchFrame {
    glm::dvec2 along, across, origin;
    double cell;
    int rows, columns;

    glm::dvec2 world(int row, int column) const { return origin + cell * (double(row) * along + double(column) * across); }
    // (row, column), fractional, of a world point.
    glm::dvec2 local(glm::dvec2 p) const { return {glm::dot(p - origin, along) / cell, glm::dot(p - origin, across) / cell}; }
};

MarchFrame frameOf(const DepthGrid& g, glm::dvec2 direction)
{
    MarchFrame f;
    f.along = direction;
    f.across = {-direction.y, direction.x};
    f.cell = g.cell_m;
    glm::dvec2 lo(std::numeric_limits<double>::infinity()), hi(-std::numeric_limits<double>::infinity());
    for (int corner = 0; corner < 4; ++corner) {
        const glm::dvec2 p = g.origin_m + g.cell_m * glm::dvec2(corner & 1 ? g.size.x - 1 : 0, corner & 2 ? g.size.y - 1 : 0);
        const glm::dvec2 st(glm::dot(p, f.along), glm::dot(p, f.across));
        lo = glm::min(lo, st);
        hi = glm::max(hi, st);
    }
    f.origin = lo.x * f.along + lo.y * f.across;
    // The small allowance keeps an exact multiple of the cell from taking one row more.
    f.rows = int(std::ceil((hi.x - lo.x) / f.cell - 1e-6)) + 1;
    f.columns = int(std::ceil((hi.y - lo.y) / f.cell - 1e-6)) + 1;
    return f;
}

// What the march needs of the depth grid at one of its cells: the nearest
// sample's, the grid's edge samples standing for the sea beyond it (its
// edges lie in the open sea, or a breakwater that runs off the grid goes on).
struct MarchCell {
    bool wet = true;
    bool rayTrusted = true; // away from a geometric shadow and its edge
    double wavenumber_radpm = 0.0;
    double rayEnergy = 1.0;
    double energyLimit = std::numeric_limits<double>::infinity();
};

struct DepthSampler {
    const DepthGrid& grid;
    const WaveMarch& march;
    const std::vector<double>& energyLimit;
    const std::vector<std::uint8_t>& rayTrusted;

    std::size_t nearest(glm::dvec2 world_m) const
    {
        const glm::dvec2 u = glm::clamp((world_m - grid.origin_m) / grid.cell_m + 0.5, glm::dvec2(0.0),
                                        glm::dvec2(grid.size) - 0.5);
        return std::size_t(u.y) * std::size_t(grid.size.x) + std::size_t(u.x);
    }

    MarchCell at(glm::dvec2 world_m) const
    {
        const std::size_t c = nearest(world_m);
        const bool wet = grid.depth_m[c] > 0.0f;
        return {wet, rayTrusted[c] != 0, march.localWavenumber_radpm[c], march.reached[c] ? march.energy[c] : 0.0,
                energyLimit[c]};
    }
};

// The operator's coefficients at a cell: the second difference across
// times implicitC on the new row, explicitC on the old (cell-long steps).
struct StepCoefficients {
    Complex implicitC, explicitC;
};

StepCoefficients coefficientsOf(double wavenumber_radpm, double cell_m)
{
    const double kc = wavenumber_radpm * cell_m;
    // Crank-Nicolson steps (half implicit) of the Pade operator with its
    // 1/4 turned slightly off the real axis: the modes it would otherwise
    // carry on unchanged where the true ones die out (|kt| > k, which the
    // one-cell corners of dry land start) decay within a few cells, and the
    // propagating ones lose a fraction of a percent per hundred metres.
    const Complex pade(0.25, -kPadeDamping);
    return {pade / (kc * kc) - Complex(0.0, 0.25 / kc), pade / (kc * kc) + Complex(0.0, 0.25 / kc)};
}

// The open sea's wave as the march carries it: a plane wave across the
// rows at transverse wavenumber kt, one step's factor `perRow` (the
// scheme's own, of modulus 1, so that the edges it is held at agree with
// the inside).
struct IncidentWave {
    double transverse_radpm = 0.0;
    Complex perRow = 1.0;

    Complex at(int row, int column, double cell_m) const
    {
        return std::pow(perRow / std::abs(perRow), row) * std::exp(Complex(0.0, transverse_radpm * cell_m * column));
    }
};

IncidentWave incidentOf(double wavenumber_radpm, double angle_rad, double cell_m)
{
    IncidentWave w;
    w.transverse_radpm = -wavenumber_radpm * std::sin(angle_rad);
    const double second = -4.0 * std::pow(std::sin(0.5 * w.transverse_radpm * cell_m), 2.0);
    const StepCoefficients c = coefficientsOf(wavenumber_radpm, cell_m);
    w.perRow = (1.0 + c.explicitC * second) / (1.0 + c.implicitC * second);
    return w;
}

// 1 / z without the library's care for infinities and NaNs, which none of
// the march's diagonals holds (each is 1 or has an imaginary part).
Complex reciprocal(Complex z) { return std::conj(z) / std::norm(z); }

// One step of the march along s for two fields at once (the diffraction
// coefficient A and the carried amplitude B share the operator): solves
// (1 + (1/4 - i w a) D) new = (1 + (1/4 + i (1 - w) a) D) old, D the
// second difference across divided by k^2 cell^2 and a = k cell / 2, by the
// Thomas algorithm. Dry cells hold nothing; an outer column in the lit sea
// holds the open sea's wave (edgeA, edgeB), one in a shadow takes no
// gradient across.
struct MarchStep {
    std::vector<Complex> lower, diagonal, upper, rhsA, rhsB;

    void solve(const std::vector<MarchCell>& row, double cell_m, std::vector<Complex>& a, std::vector<Complex>& b,
               const Complex edgeA[2], const Complex edgeB[2])
    {
        const std::size_t n = row.size();
        lower.assign(n, 0.0);
        diagonal.assign(n, 1.0);
        upper.assign(n, 0.0);
        rhsA.assign(n, 0.0);
        rhsB.assign(n, 0.0);
        for (std::size_t j = 0; j < n; ++j) {
            const bool outer = j == 0 || j + 1 == n;
            if (!row[j].wet || (outer && row[j].rayTrusted)) {
                rhsA[j] = row[j].wet ? edgeA[j == 0 ? 0 : 1] : 0.0;
                rhsB[j] = row[j].wet ? edgeB[j == 0 ? 0 : 1] : 0.0;
                continue;
            }
            // Beside dry land the second difference takes no gradient
            // across (a rigid wall, Sommerfeld's boundary): a wave running
            // along a breakwater's side keeps its height.
            const bool left = j > 0 && row[j - 1].wet, right = j + 1 < n && row[j + 1].wet;
            const StepCoefficients c = coefficientsOf(row[j].wavenumber_radpm, cell_m);
            lower[j] = left ? c.implicitC : 0.0;
            upper[j] = right ? c.implicitC : 0.0;
            diagonal[j] = 1.0 - double(int(left) + int(right)) * c.implicitC;
            const Complex secondA = (left ? a[j - 1] - a[j] : 0.0) + (right ? a[j + 1] - a[j] : 0.0);
            const Complex secondB = (left ? b[j - 1] - b[j] : 0.0) + (right ? b[j + 1] - b[j] : 0.0);
            rhsA[j] = a[j] + c.explicitC * secondA;
            rhsB[j] = b[j] + c.explicitC * secondB;
        }
        // diagonal[j] holds the reciprocal of the eliminated diagonal.
        diagonal[0] = reciprocal(diagonal[0]);
        for (std::size_t j = 1; j < n; ++j) {
            const Complex factor = lower[j] * diagonal[j - 1];
            diagonal[j] = reciprocal(diagonal[j] - factor * upper[j - 1]);
            rhsA[j] -= factor * rhsA[j - 1];
            rhsB[j] -= factor * rhsB[j - 1];
        }
        a[n - 1] = rhsA[n - 1] * diagonal[n - 1];
        b[n - 1] = rhsB[n - 1] * diagonal[n - 1];
        for (std::size_t j = n - 1; j-- > 0;) {
            a[j] = (rhsA[j] - upper[j] * a[j + 1]) * diagonal[j];
            b[j] = (rhsB[j] - upper[j] * b[j + 1]) * diagonal[j];
        }
    }
};

// One march's answer on its own cells (in the scratch's buffers).
struct MarchResult {
    int firstRow = 0, lastRow = -1;         // the rows marched; the others hold the open sea's wave
    std::vector<float>& coefficientSquared; // |A|^2: the diffraction coefficient's square
    std::vector<float>& carriedEnergy;      // |B|^2: the energy the march carries, ray solution included
    std::vector<std::uint8_t>& wet;
};

// A is the diffraction coefficient of the open sea's unit wave; B the
// wave's own amplitude: sqrt(ray energy) A where the ray solution is
// trusted, carried by the march alone in a shadow and beside it (unless
// the ray solution carries more there, behind an obstacle it has healed
// from), and cut at the breaking height. Both are divided, row by row, by
// what the operator's damping takes from the open sea's wave, so that only
// the modes the damping is there for lose height.
MarchResult marchAcross(const MarchFrame& f, const DepthSampler& sampler, const IncidentWave& incident, int firstRow,
                        int lastRow, MarchScratch& scratch)
{
    MarchResult r{firstRow, lastRow, scratch.coefficientSquared, scratch.carriedEnergy, scratch.wet};
    const std::size_t cells = std::size_t(f.rows) * std::size_t(f.columns);
    r.coefficientSquared.assign(cells, 0.0f);
    r.carriedEnergy.assign(cells, 0.0f);
    r.wet.assign(cells, 0);
    const std::size_t n = std::size_t(f.columns);
    std::vector<Complex> a(n), b(n);
    std::vector<MarchCell> row(n);
    MarchStep step;
    const double renormalise = 1.0 / std::abs(incident.perRow);
    for (int s = firstRow; s <= lastRow; ++s) {
        for (std::size_t j = 0; j < n; ++j)
            row[j] = sampler.at(f.world(s, int(j)));
        if (s == firstRow) {
            for (std::size_t j = 0; j < n; ++j)
                a[j] = incident.at(s, int(j), f.cell);
        } else {
            const Complex edgeA[2] = {incident.at(s, 0, f.cell), incident.at(s, int(n) - 1, f.cell)};
            const Complex edgeB[2] = {std::sqrt(row[0].rayEnergy) * edgeA[0], std::sqrt(row[n - 1].rayEnergy) * edgeA[1]};
            step.solve(row, f.cell, a, b, edgeA, edgeB);
        }
        for (std::size_t j = 0; j < n; ++j) {
            const MarchCell& cell = row[j];
            if (!cell.wet) {
                a[j] = b[j] = 0.0;
                continue;
            }
            if (s > firstRow && !(cell.rayTrusted && (j == 0 || j + 1 == n))) {
                a[j] *= renormalise;
                b[j] *= renormalise;
            }
            const Complex ray = std::sqrt(cell.rayEnergy) * a[j];
            if (s == firstRow || cell.rayTrusted || std::norm(ray) > std::norm(b[j]))
                b[j] = ray;
            if (std::norm(b[j]) > cell.energyLimit)
                b[j] *= std::sqrt(cell.energyLimit / std::norm(b[j]));
            const std::size_t at = std::size_t(s) * n + j;
            r.coefficientSquared[at] = float(std::norm(a[j]));
            r.carriedEnergy[at] = float(std::norm(b[j]));
            r.wet[at] = 1;
        }
    }
    return r;
}

// A march's answer at a depth-grid sample, bilinear over the wet march
// cells around it (the dry ones beside a shore give the wet nothing).
struct MarchAnswer {
    double coefficientSquared = 1.0;
    double carriedEnergy = 0.0;
};

MarchAnswer answerAt(const MarchFrame& f, const MarchResult& r, glm::dvec2 world_m)
{
    const glm::dvec2 u = glm::clamp(f.local(world_m), glm::dvec2(0.0), glm::dvec2(f.rows - 1, f.columns - 1));
    const int s0 = std::min(int(u.x), f.rows - 2), t0 = std::min(int(u.y), f.columns - 2);
    if (s0 < r.firstRow || s0 + 1 > r.lastRow)
        return {}; // the open sea's wave, no obstacle before it
    const double fs = u.x - s0, ft = u.y - t0;
    MarchAnswer answer{0.0, 0.0};
    double weight = 0.0;
    for (int corner = 0; corner < 4; ++corner) {
        const int s = s0 + (corner & 1), t = t0 + (corner >> 1);
        const std::size_t at = std::size_t(s) * std::size_t(f.columns) + std::size_t(t);
        const double w = (corner & 1 ? fs : 1.0 - fs) * (corner & 2 ? ft : 1.0 - ft);
        if (!r.wet[at] || w <= 0.0)
            continue;
        answer.coefficientSquared += w * r.coefficientSquared[at];
        answer.carriedEnergy += w * r.carriedEnergy[at];
        weight += w;
    }
    if (!(weight > 0.0))
        return {};
    answer.coefficientSquared /= weight;
    answer.carriedEnergy /= weight;
    return answer;
}

// The wet cells the open sea's straight rays reach only across dry land:
// the geometric shadow.
std::vector<std::uint8_t> shadowOf(const DepthGrid& g, glm::dvec2 direction)
{
    const MarchFrame f = frameOf(g, direction);
    const std::size_t columns = std::size_t(f.columns);
    std::vector<std::uint8_t> shadowed(std::size_t(f.rows) * columns, 0), crossed(columns, 0);
    auto nearestSample = [&](glm::dvec2 p) {
        const glm::dvec2 u = (p - g.origin_m) / g.cell_m;
        const long i = std::clamp(std::lround(u.x), 0L, long(g.size.x - 1));
        const long j = std::clamp(std::lround(u.y), 0L, long(g.size.y - 1));
        return std::size_t(j) * std::size_t(g.size.x) + std::size_t(i);
    };
    for (int s = 0; s < f.rows; ++s)
        for (std::size_t j = 0; j < columns; ++j) {
            crossed[j] = crossed[j] || !(g.depth_m[nearestSample(f.world(s, int(j)))] > 0.0f);
            shadowed[std::size_t(s) * columns + j] = crossed[j];
        }
    std::vector<std::uint8_t> untrusted(g.depth_m.size(), 0);
    for (int j = 0; j < g.size.y; ++j)
        for (int i = 0; i < g.size.x; ++i) {
            const glm::dvec2 u = glm::round(f.local(g.origin_m + g.cell_m * glm::dvec2(i, j)));
            const int s = std::clamp(int(u.x), 0, f.rows - 1), t = std::clamp(int(u.y), 0, f.columns - 1);
            const std::size_t c = std::size_t(j) * std::size_t(g.size.x) + std::size_t(i);
            untrusted[c] = g.depth_m[c] > 0.0f && shadowed[std::size_t(s) * columns + std::size_t(t)];
        }
    return untrusted;
}

// The shadow widened by `margin` samples: where the ray solution's energy
// is its own numerical spreading, not to be trusted.
std::vector<std::uint8_t> rayTrustOf(const DepthGrid& g, std::vector<std::uint8_t> untrusted, int margin)
{
    const std::size_t n = g.depth_m.size();
    // Widen along x, then along z (a square of 2 margin + 1 samples): each
    // sample's distance to the nearest untrusted one along the line, from a
    // sweep each way.
    for (int pass = 0; pass < 2; ++pass) {
        const int lines = pass == 0 ? g.size.y : g.size.x, length = pass == 0 ? g.size.x : g.size.y;
        const std::size_t stride = pass == 0 ? 1 : std::size_t(g.size.x);
        std::vector<std::uint8_t> wider(n, 0);
        for (int line = 0; line < lines; ++line) {
            const std::size_t start = pass == 0 ? std::size_t(line) * std::size_t(g.size.x) : std::size_t(line);
            int last = -margin - 1;
            for (int k = 0; k < length; ++k) {
                if (untrusted[start + std::size_t(k) * stride])
                    last = k;
                wider[start + std::size_t(k) * stride] = k - last <= margin;
            }
            last = length + margin;
            for (int k = length - 1; k >= 0; --k) {
                if (untrusted[start + std::size_t(k) * stride])
                    last = k;
                wider[start + std::size_t(k) * stride] |= std::uint8_t(last - k <= margin);
            }
        }
        untrusted = std::move(wider);
    }
    for (std::uint8_t& u : untrusted)
        u = !u;
    return untrusted;
}

glm::dvec2 samplePoint(const DepthGrid& g, std::size_t c)
{
    return g.origin_m + g.cell_m * glm::dvec2(double(c % std::size_t(g.size.x)), double(c / std::size_t(g.size.x)));
}

glm::dvec2 rotated(glm::dvec2 v, double angle_rad)
{
    const double c = std::cos(angle_rad), s = std::sin(angle_rad);
    return {c * v.x - s * v.y, s * v.x + c * v.y};
}

} // namespace

namespace {

// One march turned `angle` from the wave's open-sea direction, read back
// onto the depth grid: per reached sample, the ray energy times the
// coefficient's square where the ray solution is trusted (the march along
// the open-sea direction only), the carried energy where it is not; empty
// when the march has nothing to do.
//
// It starts at the first row that meets dry land or an untrusted sample
// (before it, the open sea's wave is all there is). Turned to a side, it
// ends past the last untrusted sample, the only ones that read it, and
// spans only their columns and a margin of lit sea beside them, from which
// the wave diffracts in.
// Into `energy` (left empty for no march).
void marchedEnergy(const DepthSampler& sampler, glm::dvec2 direction, double angle_rad, double openWavenumber_radpm,
                   int margin, MarchScratch& scratch, std::vector<double>& energy)
{
    energy.clear();
    const DepthGrid& depth = sampler.grid;
    const std::size_t n = depth.depth_m.size();
    const bool side = angle_rad != 0.0;
    MarchFrame frame = frameOf(depth, rotated(direction, angle_rad));
    glm::ivec2 untrustedLo(frame.rows, frame.columns), untrustedHi(-1);
    for (std::size_t c = 0; c < n; ++c)
        if (depth.depth_m[c] > 0.0f && !sampler.rayTrusted[c]) {
            const glm::ivec2 st(frame.local(samplePoint(depth, c)));
            untrustedLo = glm::min(untrustedLo, st);
            untrustedHi = glm::max(untrustedHi, st);
        }
    if (side && untrustedHi.x < 0)
        return; // no shadow: nothing reads a side march
    if (side) {
        const int first = std::max(0, untrustedLo.y - 2 * margin - 4);
        const int last = std::min(frame.columns - 1, untrustedHi.y + 2 * margin + 4);
        frame.origin += double(first) * frame.cell * frame.across;
        frame.columns = std::max(2, last - first + 1);
    }
    int firstDry = frame.rows;
    for (std::size_t c = 0; c < n; ++c)
        if (!(depth.depth_m[c] > 0.0f)) {
            const glm::dvec2 st = frame.local(samplePoint(depth, c));
            if (st.y >= -1.0 && st.y <= frame.columns)
                firstDry = std::min(firstDry, int(st.x));
        }
    const int firstRow = std::max(0, std::min(firstDry, untrustedLo.x) - 2);
    const int lastRow = side ? std::min(frame.rows - 1, untrustedHi.x + 2) : frame.rows - 1;
    if (firstRow > lastRow)
        return;
    const MarchResult result = marchAcross(frame, sampler, incidentOf(openWavenumber_radpm, angle_rad, depth.cell_m),
                                           firstRow, lastRow, scratch);
    energy.assign(n, 0.0);
    for (std::size_t c = 0; c < n; ++c) {
        const bool trusted = sampler.rayTrusted[c] != 0;
        if (!sampler.march.reached[c] || (side && trusted))
            continue;
        const MarchAnswer answer = answerAt(frame, result, samplePoint(depth, c));
        energy[c] = trusted ? sampler.march.energy[c] * answer.coefficientSquared : answer.carriedEnergy;
    }
}

} // namespace

void diffractWave(const DepthGrid& depth, const MarchedWave& wave, double breakerIndex, WaveMarch& march,
                  MarchScratch& scratch)
{
    const std::size_t n = depth.depth_m.size();
    scratch.shadowed.clear();
    if (std::all_of(depth.depth_m.begin(), depth.depth_m.end(), [](float h) { return h > 0.0f; }))
        return; // no obstacle: the ray solution stands
    std::vector<double>& energyLimit = scratch.energyLimit;
    energyLimit.resize(n);
    for (std::size_t c = 0; c < n; ++c)
        energyLimit[c] = breakingEnergyLimit(double(depth.depth_m[c]), wave.amplitude_m, breakerIndex);
    const int margin = std::max(kShadowMargin, int(std::ceil(kTwoPi / wave.wavenumber_radpm / depth.cell_m)));
    scratch.shadowed = shadowOf(depth, wave.direction);
    const std::vector<std::uint8_t> rayTrusted = rayTrustOf(depth, scratch.shadowed, margin);
    const DepthSampler sampler{depth, march, energyLimit, rayTrusted};
    const double openWavenumber = localWavenumber(wave.omega_radps, depth.outsideDepth_m);

    // Three marches: along the open sea's direction, and turned kSideAngle
    // to either side, so that no point of a lee up to 60 degrees deep is
    // more than 20 degrees off a march's axis, where the Pade operator holds.
    const double angles_rad[3] = {-kSideAngle_rad, 0.0, kSideAngle_rad};
    for (int i = 0; i < 3; ++i)
        marchedEnergy(sampler, wave.direction, angles_rad[i], openWavenumber, margin, scratch, scratch.energy[i]);
    const std::vector<double>(&energy)[3] = scratch.energy;
    if (energy[1].empty())
        return; // the dry land lies past the last row: nothing behind it
    // A sample in a shadow or beside it takes the marches on either side of
    // the direction its wave runs in there (the phase's gradient), weighed
    // by angle; one in the lit sea the fringes of the march along its
    // open-sea direction.
    // What diffraction takes from a wave is not breaking: the energy it
    // would have unbroken (the surf's measure, coast_field.cpp) takes the
    // same factor, so a lee shows surf only where its diffracted wave
    // breaks (before, 60 degrees into a deep lee the measure read 0.38
    // where no wave breaks: CoastField.ALeeWhereNoWaveBreaksHasNoSurf).
    // In the lit sea the factor is the fringes' (the ray energy's
    // coefficient); in a shadow the unbroken energy is the diffracted
    // wave's before this cell's cut (the breaking the rays met on their way
    // around the obstacle is not the lee's).
    for (std::size_t c = 0; c < n; ++c) {
        if (!march.reached[c])
            continue;
        double diffracted = energy[1][c];
        if (!rayTrusted[c]) {
            const glm::dvec2 k = march.wavenumber_radpm[c];
            const double turn =
                std::atan2(wave.direction.x * k.y - wave.direction.y * k.x, glm::dot(wave.direction, k));
            const double side = std::clamp(turn / kSideAngle_rad, -1.0, 1.0);
            const std::vector<double>& other = side < 0.0 ? energy[0] : energy[2];
            diffracted = (1.0 - std::abs(side)) * energy[1][c] + std::abs(side) * (other.empty() ? 0.0 : other[c]);
        }
        const double rays = march.energy[c];
        march.unbroken[c] = rayTrusted[c] && rays > 0.0 ? march.unbroken[c] * (diffracted / rays) : diffracted;
        march.energy[c] = std::min(diffracted, energyLimit[c]);
    }
}

} // namespace swell::coast
