// The inverse of the Gerstner surface: the rest point whose displaced image
// lies over a world point, and the height there (swell::restPointUnder,
// swell::heightAt). Newton's method on the horizontal displacement, in double.
#include "ocean/gerstner/gerstner_terms.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <vector>

namespace swell {

using namespace gerstner;

namespace {

// The inverse of the horizontal displacement, shared by heightAt and
// restPointUnder. The unknown is the offset of the rest point from the world
// point, so that far from the origin nothing large is ever subtracted.
struct Inverse {
    glm::dvec2 restPoint_m;
    double height_m;
};

Inverse solveInverse(const WaveSet& set, glm::dvec2 worldPoint_m, double time_s)
{
    const std::size_t n = set.waves.size();
    std::vector<WaveTerms> terms(n);
    std::vector<double> theta0(n); // phase at the world point, rad
    const WaveReach reach = waveReach(set);
    const double amplitudeSum = reach.vertical_m; // sum(A), m
    const double radius = reach.horizontal_m;     // sum(Q*A) >= |Dxz| >= |offset of the answer|, m
    for (std::size_t i = 0; i < n; ++i) {
        terms[i] = termsOf(set.waves[i], set.depth_m);
        theta0[i] = phaseAt(terms[i], set.waves[i].phase_rad, worldPoint_m, time_s);
    }

    // Residual r(offset) = offset + Dxz(worldPoint + offset). Its Jacobian
    // J = I + dDxz/dx0 is symmetric, and positive semi-definite for fold-free
    // sets: x0 + Dxz(x0) is the gradient of the convex |x0|^2/2 +
    // sum(Q*A/k*cos(theta)). So a short enough step against r always shrinks
    // it, which is what makes the halving below safe.
    struct State {
        glm::dvec2 residual;
        double jxx, jxz, jzz;
        double height;
    };
    auto stateAt = [&](glm::dvec2 offset) {
        Evaluation e;
        for (std::size_t i = 0; i < n; ++i)
            accumulate(set.waves[i], terms[i], theta0[i] + glm::dot(terms[i].kd, offset), e);
        return State{offset + glm::dvec2(e.displacement.x, e.displacement.z),
                     e.partials.alongX.x, e.partials.alongX.z, e.partials.alongZ.z, e.displacement.y};
    };
    auto norm2 = [](glm::dvec2 v) { return glm::dot(v, v); };
    auto clampToRadius = [radius](glm::dvec2 offset) {
        const double length = std::sqrt(glm::dot(offset, offset));
        return length > radius ? offset * (radius / length) : offset;
    };

    // 1e-10 m is far below any use; the relative floor keeps huge sets from
    // chasing a residual below their own rounding.
    const double tolerance = std::max(1e-10, 1e-15 * amplitudeSum);
    constexpr int kMaxSteps = 100;
    glm::dvec2 offset(0.0);
    State state = stateAt(offset);
    for (int step = 0; step < kMaxSteps && norm2(state.residual) > tolerance * tolerance; ++step) {
        // Newton step. At a cusp of a set at the fold limit J is singular, and
        // 1 - sum(...) cancels to exactly 0 near it; a small ridge keeps the
        // step finite and pointing against r, and the halving finds its length.
        double jxx = state.jxx;
        double jzz = state.jzz;
        double det = jxx * jzz - state.jxz * state.jxz;
        if (!(det > 1e-12)) {
            jxx += 1e-6;
            jzz += 1e-6;
            det = jxx * jzz - state.jxz * state.jxz;
        }
        glm::dvec2 delta = -state.residual; // the fixed-point step, if J is not even semi-definite
        if (det > 0.0) {
            delta = glm::dvec2(state.jxz * state.residual.y - jzz * state.residual.x,
                               state.jxz * state.residual.x - jxx * state.residual.y)
                  / det;
        }
        // Halve the step until the residual shrinks: near a cusp the full
        // Newton step overshoots along the nearly singular direction.
        bool improved = false;
        for (int halving = 0; halving < 60 && !improved; ++halving) {
            const glm::dvec2 candidate = clampToRadius(offset + delta);
            const State next = stateAt(candidate);
            if (norm2(next.residual) < norm2(state.residual)) {
                offset = candidate;
                state = next;
                improved = true;
            }
            delta *= 0.5;
        }
        if (!improved)
            break; // at the rounding floor: no step helps any more
    }
    return {worldPoint_m + offset, state.height};
}

} // namespace

double heightAt(const WaveSet& set, glm::dvec2 worldPoint_m, double time_s)
{
    return solveInverse(set, worldPoint_m, time_s).height_m;
}

glm::dvec2 restPointUnder(const WaveSet& set, glm::dvec2 worldPoint_m, double time_s)
{
    return solveInverse(set, worldPoint_m, time_s).restPoint_m;
}

} // namespace swell
