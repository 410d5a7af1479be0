#include "geom/FreeKnotFit.h"

#include "RemovalDetail.h"
#include "geom/Basis.h"
#include "geom/Deviation.h"
#include "geom/GeometryError.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <utility>

namespace geom {

namespace {

// About the factor by which Lawson's rounds lower the error of a fit's first round on its final
// knots (FreeKnotStops; 0.77-0.93 on the reference curves).
constexpr double lawsonGain = 0.8;

// A fit this many times above its caller's giveUpAbove after three knot-moving rounds gives up
// there (FitRounds::keepGoing).
constexpr double kHopeless = 50.0;

// The p+1 non-zero B-splines at u in the span whose knots start at t[0] = t_span (Cox-de Boor,
// with the reciprocals of the knot differences it divides by made once per span: inverse holds
// them level by level). P > 0 fixes the degree at compile time, P = 0 takes it from degree.
template <std::size_t P>
inline void spanBasis(const double* t, const double* inverse, double u, double* n, std::size_t degree = P) {
    const std::size_t p = P > 0 ? P : degree;
    n[0] = 1.0;
#pragma GCC unroll 6
    for (std::size_t j = 1; j <= p; ++j) {
        double saved = 0.0;
#pragma GCC unroll 6
        for (std::size_t r = 0; r < j; ++r, ++inverse) {
            const double temp = n[r] * *inverse;
            n[r] = saved + (t[r + 1] - u) * temp;
            // 1 + r - j is negative for r < j - 1: t points inside the knot vector.
            saved = (u - t[static_cast<std::ptrdiff_t>(1 + r) - static_cast<std::ptrdiff_t>(j)]) * temp;
        }
        n[j] = saved;
    }
}

// What one fit (FreeKnotFitter::fit) starts from: the samples, the start knots and held points,
// the rounds and the stops.
struct FitInputs {
    const std::vector<double>& params;
    const std::vector<glm::dvec3>& targets;
    const std::vector<double>& spacing;
    std::vector<double> knots;
    std::vector<glm::dvec3> points;  // the end ones held
    int degree;
    std::size_t count, k;  // control points, interior knots held at each end
    double a, b, lo, hi;   // the domain, and the part of it the free knots take
    bool moveKnots;
    int iterations, movingRounds;
    double settledMove, lawsonSettled;
    double giveUpAbove, stopBelow, passAt;
    std::vector<char> pinned;  // by free knot: stays where it starts (empty: none)
};

// The rounds of one fit: P > 0 is the degree fixed at compile time, so that the loops over the
// p+1 basis functions unroll; P = 0 takes any degree (degree).
class FitRounds : public FitInputs {
public:
    explicit FitRounds(FitInputs inputs) : FitInputs(std::move(inputs)) {}

    /// Runs the rounds; the best round's fit goes to out.
    template <std::size_t P>
    void run(FreeKnotFit& out) {
        prepare<P>();
        detail::SplineSampler fitted(degree, knots, points.data(), count, true);
        for (int iteration = 0; iteration < iterations; ++iteration) {
            // Lawson's rounds on fixed knots barely move the parameters (the knot-moving rounds
            // have corrected them): only the first (after the last knot move; it is also the one
            // FreeKnotStops judges) and the last two correct them again, and the others, with the
            // samples' basis values unchanged, reuse them (the same counts on the reference curves).
            const bool lawsonRound = moveKnots && iteration >= movingRounds;
            const bool stepParams = !lawsonRound || iteration == movingRounds || iteration + 2 >= iterations;
            if (nf_ > 0) {
                assemble<P>();
                if (!solveFree()) break;
            }
            double worst = 0.0;
            if constexpr (P > 0)
                worst = correctFixed<P>(stepParams);
            else
                worst = correctAny(fitted, stepParams);
            basisKept_ = P > 0 && nf_ > 0 && !stepParams && lawsonRound;
            if (!keepGoing(out, iteration, lawsonRound, worst)) break;
            // The first half moves the knots on plain least squares (Lawson weights made for other
            // knots would mislead it); the second half keeps the knots and runs Lawson's iteration:
            // weights grow where the error is large, towards the equioscillating best max-norm fit.
            if (!(moveKnots && iteration < movingRounds)) {
                reweight();
                continue;
            }
            std::fill(lawson_.begin(), lawson_.end(), 1.0);
            gapErrors();
            if (free_ == 0) continue;
            spreadKnots(worst);
            settle(iteration);
        }
    }

private:
    /// The sizes and the working arrays of the rounds.
    template <std::size_t P>
    void prepare() {
        p_ = P > 0 ? P : static_cast<std::size_t>(degree);
        fixed_ = k + 1;
        m_ = params.size();
        free_ = count - p_ - 1 - 2 * k;
        gaps_ = free_ + 1;
        nf_ = count - 2 * fixed_;
        wb_ = p_ + 1;
        triangle_ = p_ * (p_ + 1) / 2;
        s_ = params;
        lawson_.assign(m_, 1.0);
        error_.assign(m_, 0.0);
        basis_.resize(P > 0 ? 0 : p_ + 1);
        gapError_.resize(gaps_);
        h_.resize(gaps_);
        forms_.resize(P > 0 ? count * (P + 1) : 0);
        reciprocal_.resize(P > 0 ? count : 0);
        spanOf_.resize(P > 0 ? m_ : 0);
        basisOf_.resize(P > 0 ? m_ * (P + 1) : 0);
    }

    /// Cox-de Boor's knot differences do not depend on the parameter: their reciprocals are made
    /// once per span, level by level.
    void makeInverses() {
        inverse_.assign(count * triangle_, 0.0);
        for (std::size_t span = p_; span < count; ++span)
            for (std::size_t j = 1, at = span * triangle_; j <= p_; ++j)
                for (std::size_t r = 0; r < j; ++r, ++at) {
                    const double d = knots[span + r + 1] - knots[span + 1 + r - j];
                    inverse_[at] = d > 0.0 ? 1.0 / d : 0.0;
                }
    }

    /// The normal equations of least squares on the samples at their current parameters, for
    /// every column, the held ones too (each sample adds to p+1 neighbouring rows, no end cases).
    /// The (ascending) parameters walk the spans forward.
    template <std::size_t P>
    void assemble() {
        band_.assign(count * wb_, 0.0);
        rhs_.assign(count, glm::dvec3(0.0));
        const bool kept = P > 0 && basisKept_;
        if (!kept) makeInverses();
        std::size_t span = p_;
        for (std::size_t i = 0; i < m_; ++i) {
            const double w = spacing[i] * lawson_[i];
            if (kept) {
                span = spanOf_[i];
            } else {
                while (span + 1 < count && !(s_[i] < knots[span + 1])) ++span;
                while (span > p_ && s_[i] < knots[span]) --span;
                if constexpr (P > 0) spanOf_[i] = span;
            }
            if (w != 0.0) addSample<P>(i, span, w);
        }
    }

    /// Sample i's terms of the normal equations, with weight w, in span.
    template <std::size_t P>
    void addSample(std::size_t i, std::size_t span, double w) {
        double* row = band_.data() + (span - p_) * wb_;
        glm::dvec3* right = rhs_.data() + (span - p_);
        if constexpr (P > 0) {
            // In locals, which the band's stores cannot alias: the loops over the p+1 basis
            // functions then stay in registers (P fixed at compile time; -O2 does not unroll them
            // by itself). A round that reuses the basis values reads them back.
            std::array<double, P + 1> n;
            double* kept = &basisOf_[i * (P + 1)];
            if (basisKept_) {
#pragma GCC unroll 6
                for (std::size_t x = 0; x <= P; ++x) n[x] = kept[x];
            } else {
                spanBasis<P>(knots.data() + span, inverse_.data() + span * triangle_, s_[i], n.data());
#pragma GCC unroll 6
                for (std::size_t x = 0; x <= P; ++x) kept[x] = n[x];
            }
            const glm::dvec3 q = targets[i];
#pragma GCC unroll 6
            for (std::size_t x = 0; x <= P; ++x, row += wb_) {
                const double wx = w * n[x];
                right[x] += wx * q;
#pragma GCC unroll 6
                for (std::size_t y = x; y <= P; ++y) row[y - x] += wx * n[y];
            }
        } else {
            double* basis = basis_.data();
            spanBasis<0>(knots.data() + span, inverse_.data() + span * triangle_, s_[i], basis, p_);
            for (std::size_t x = 0; x <= p_; ++x, row += wb_) {
                const double wx = w * basis[x];
                right[x] += wx * targets[i];
                for (std::size_t y = x; y <= p_; ++y) row[y - x] += wx * basis[y];
            }
        }
    }

    /// Moves the held columns' terms to the right and solves for the free coefficients; false
    /// where the system is singular.
    bool solveFree() {
        const std::size_t fixed = fixed_, wb = wb_, p = p_;
        for (std::size_t r = fixed; r < count - fixed; ++r)
            for (std::size_t c = 0; c < fixed; ++c) {
                if (r <= c + p) rhs_[r] -= band_[c * wb + (r - c)] * points[c];
                const std::size_t e = count - 1 - c;  // the held column at the far end
                if (e <= r + p) rhs_[r] -= band_[r * wb + (e - r)] * points[e];
            }
        band_.erase(band_.begin(), band_.begin() + static_cast<std::ptrdiff_t>(fixed * wb));
        rhs_.erase(rhs_.begin(), rhs_.begin() + static_cast<std::ptrdiff_t>(fixed));
        if (!detail::solveBanded(band_, nf_, p, rhs_)) return false;
        for (std::size_t i = 0; i < nf_; ++i) points[fixed + i] = rhs_[i];
        return true;
    }

    /// The local parameter of u in its span (span: the last sample's, walked to u's); most
    /// samples stay in their span (then the walks would not move).
    double locate(double u, std::size_t& span) const {
        if (!(knots[span] <= u && u < knots[span + 1])) {
            while (span + 1 < count && !(u < knots[span + 1])) ++span;
            while (span > p_ && (u < knots[span] || !(knots[span + 1] > knots[span]))) --span;
        }
        return (u - knots[span]) * reciprocal_[span];
    }

    /// Parameter correction (P > 0): one Newton step per sample towards its foot point on the fit
    /// where stepParams (the rounds repeat it), kept in order, so that the parameters stay a
    /// monotone map of the samples'; then each sample's error at its parameter. Returns the
    /// largest. Every span's power form is made first, and the ascending parameters walk them.
    template <std::size_t P>
    double correctFixed(bool stepParams) {
        for (std::size_t span = p_; span < count; ++span)
            if (knots[span + 1] > knots[span]) {
                detail::spanPowerForm<P>(span, P, knots.data(), points.data(), &forms_[span * (P + 1)]);
                reciprocal_[span] = 1.0 / (knots[span + 1] - knots[span]);
            }
        double worst = 0.0;
        std::size_t span = p_;
        for (std::size_t i = 0; i < m_ && !stepParams; ++i) {
            const double x = locate(s_[i], span);
            const glm::dvec3* form = &forms_[span * (P + 1)];
            glm::dvec3 c = form[P];
#pragma GCC unroll 6
            for (std::size_t e = P; e > 0; --e) c = c * x + form[e - 1];
            error_[i] = glm::length(c - targets[i]);
            worst = std::max(worst, error_[i]);
        }
        for (std::size_t i = 0; i < m_ && stepParams; ++i) {
            error_[i] = stepSample<P>(i, span);
            worst = std::max(worst, error_[i]);
        }
        return worst;
    }

    /// One sample's Newton step (not at the ends) and its error after it. The span's polynomial
    /// in its local parameter is re-expanded about the sample's (Taylor coefficients taylor[e] =
    /// C^(e) / e!, by repeated synthetic division): the step needs the first three, and the
    /// point after the step, while it stays in the span, is their polynomial in the step.
    template <std::size_t P>
    double stepSample(std::size_t i, std::size_t& span) {
        const double x = locate(s_[i], span);
        glm::dvec3 taylor[P + 1];
        const glm::dvec3* form = &forms_[span * (P + 1)];
#pragma GCC unroll 6
        for (std::size_t e = 0; e <= P; ++e) taylor[e] = form[e];
#pragma GCC unroll 6
        for (std::size_t level = 0; level < P; ++level)
#pragma GCC unroll 6
            for (std::size_t e = P - 1; e + 1 > level; --e) taylor[e] += x * taylor[e + 1];
        double step = 0.0;  // in the local parameter
        if (i > 0 && i + 1 < m_) {
            const glm::dvec3 r = taylor[0] - targets[i];
            const double speed = glm::dot(taylor[1], taylor[1]);
            double hess = speed + 2.0 * glm::dot(r, taylor[2 <= P ? 2 : P]);
            if (hess <= 0.1 * speed) hess = speed;
            if (hess > 0.0) {
                const double length = knots[span + 1] - knots[span];
                const double u = std::clamp(s_[i] - length * glm::dot(r, taylor[1]) / hess,
                                            std::max(a, s_[i - 1]), std::min(b, s_[i + 1]));
                step = (u - s_[i]) * reciprocal_[span];
                s_[i] = u;
            }
        }
        glm::dvec3 c;
        if (x + step >= 0.0 && x + step <= 1.0) {
            c = taylor[P];
#pragma GCC unroll 6
            for (std::size_t e = P; e > 0; --e) c = c * step + taylor[e - 1];
        } else {
            const double moved = locate(s_[i], span);
            form = &forms_[span * (P + 1)];
            c = form[P];
#pragma GCC unroll 6
            for (std::size_t e = P; e > 0; --e) c = c * moved + form[e - 1];
        }
        return glm::length(c - targets[i]);
    }

    /// correctFixed for any degree, by the sampler's derivatives.
    double correctAny(detail::SplineSampler& fitted, bool stepParams) {
        double worst = 0.0;
        fitted.restart();
        for (std::size_t i = 0; i < m_; ++i) {
            glm::dvec3 c, d1, d2;
            if (stepParams && i > 0 && i + 1 < m_) {
                fitted.derivatives(s_[i], c, d1, d2);
                const glm::dvec3 r = c - targets[i];
                double hess = glm::dot(d1, d1) + glm::dot(r, d2);
                if (hess <= 0.1 * glm::dot(d1, d1)) hess = glm::dot(d1, d1);
                if (hess > 0.0)
                    s_[i] = std::clamp(s_[i] - glm::dot(r, d1) / hess, std::max(a, s_[i - 1]),
                                       std::min(b, s_[i + 1]));
            }
            error_[i] = glm::length(fitted.value(s_[i]) - targets[i]);
            worst = std::max(worst, error_[i]);
        }
        return worst;
    }

    /// Keeps the round's fit where it is the best so far; false where the rounds end here.
    bool keepGoing(FreeKnotFit& out, int iteration, bool lawsonRound, double worst) {
        out.rounds = iteration + 1;
        if (worst < out.sampleError) {
            out.sampleError = worst;
            out.curve.degree = degree;
            out.curve.knots = knots;
            out.curve.points = points;
            out.map.to = s_;
        }
        if (!(worst > 0.0) || iteration + 1 == iterations || worst <= passAt) return false;
        // Measure before searching on: a fit still kHopeless times above giveUpAbove after its
        // third knot-moving round will not come down to it (over the geom tests' fits and the
        // generated classes, the rounds after the third lowered the error by at most 12 times).
        if (moveKnots && iteration >= 2 && iteration < movingRounds && worst > kHopeless * giveUpAbove) {
            out.gaveUp = true;
            out.expectedError = lawsonGain * out.sampleError;
            return false;
        }
        // Lawson's rounds end where one no longer pays (it lowered the error by less than
        // lawsonSettled): the rest, the last two's parameter correction included, would gain
        // as little.
        if (lawsonRound) {
            if (lawsonSettled > 0.0 && iteration > movingRounds && iteration + 2 < iterations &&
                worst > (1.0 - lawsonSettled) * previousWorst_)
                return false;
            previousWorst_ = worst;
        }
        // The first round on the final knots: Lawson's rounds will lower its error by about a
        // fifth (lawsonGain). A fit expected to come below stopBelow (a smaller count would do) stops
        // there too; Lawson's gain is that of all its rounds, so only the first is judged by it.
        if (moveKnots && iteration >= movingRounds) {
            const double expected = std::min(out.sampleError, lawsonGain * worst);
            const bool first = iteration == movingRounds;
            if (expected > giveUpAbove || (first && expected < stopBelow)) {
                (expected > giveUpAbove ? out.gaveUp : out.overshot) = true;
                out.expectedError = expected;
                return false;
            }
        }
        return true;
    }

    /// Lawson's reweighting: each sample's weight grows with its error.
    void reweight() {
        double sum = 0.0;
        for (std::size_t i = 0; i < m_; ++i) sum += lawson_[i] * error_[i];
        for (std::size_t i = 0; i < m_; ++i)
            lawson_[i] = std::max(lawson_[i] * error_[i] * double(m_) / sum, 1e-6);
    }

    /// The largest sample error of each gap between free knots (gap g lies between free knots g
    /// and g+1; the ascending parameters walk them).
    void gapErrors() {
        std::fill(gapError_.begin(), gapError_.end(), 0.0);
        std::size_t g = 0;
        for (std::size_t i = 0; i < m_; ++i) {
            if (s_[i] < lo || s_[i] > hi) continue;
            while (g < free_ && knots[p_ + k + 1 + g] <= s_[i]) ++g;
            const std::size_t gap = std::min(g, gaps_ - 1);
            gapError_[gap] = std::max(gapError_[gap], error_[i]);
        }
    }

    /// Equidistribution: each gap scaled by its error^(-1/(p+1)); each run of knots between two
    /// that stay (or the domain's ends) spreads over its interval by its own gaps' steps.
    void spreadKnots(double worst) {
        const std::size_t p = p_, free = free_;
        for (std::size_t gap = 0; gap < gaps_; ++gap) {
            const double width = knots[p + k + gap + 1] - knots[p + k + gap];
            const double e = std::max(gapError_[gap], 1e-3 * worst);
            // Half the full step, at most 1.5 times wider: the full step overshoots and oscillates.
            h_[gap] = width * std::clamp(std::pow(worst / e, 0.5 / double(p + 1)), 1.0, 1.5);
        }
        before_.assign(knots.begin() + static_cast<std::ptrdiff_t>(p + k),
                       knots.begin() + static_cast<std::ptrdiff_t>(p + k + free + 2));
        auto knotAt = [&](std::size_t i) { return i == 0 ? lo : i > free ? hi : knots[p + k + i]; };
        for (std::size_t from = 0, to = 1; to <= free + 1; ++to) {
            if (to <= free && (pinned.empty() || !pinned[to - 1])) continue;
            // Free knots from + 1 .. to - 1 (1-based, lo and hi at 0 and free + 1), gaps from .. to - 1.
            const double start = knotAt(from), length = knotAt(to) - start;
            double sum = 0.0;
            for (std::size_t gap = from; gap < to; ++gap) sum += h_[gap];
            const double minimum = 0.05 * length / double(to - from);
            double at = start;
            for (std::size_t gap = from; gap + 1 < to; ++gap) {
                at += std::max(h_[gap] * length / sum, minimum);
                knots[p + k + 1 + gap] = std::min(at, start + length - minimum * double(to - 1 - gap));
            }
            from = to;
        }
    }

    /// Knots that have settled (on average the round moved them by less than settledMove of
    /// their nearer neighbour's distance) end the knot-moving rounds; Lawson's rounds follow.
    void settle(int iteration) {
        double moved = 0.0;
        std::size_t moving = 0;
        for (std::size_t i = 1; i <= free_; ++i) {
            const double near = std::min(before_[i] - before_[i - 1], before_[i + 1] - before_[i]);
            if ((pinned.empty() || !pinned[i - 1]) && near > 0.0)
                moved += std::abs(knots[p_ + k + i] - before_[i]) / near, ++moving;
        }
        if (moved < settledMove * double(moving) && iteration + 1 < movingRounds) {
            iterations -= movingRounds - (iteration + 1);
            movingRounds = iteration + 1;
        }
    }

    std::size_t p_ = 0, fixed_ = 0, m_ = 0, free_ = 0, gaps_ = 0, nf_ = 0, wb_ = 0, triangle_ = 0;
    std::vector<double> s_, lawson_, error_, basis_, band_, inverse_, gapError_, h_, before_;
    std::vector<glm::dvec3> rhs_, forms_;
    std::vector<double> reciprocal_;  // of each span's length (P > 0)
    // Every sample's span and basis values, kept from a round that moved neither the knots nor
    // the parameters for the next (P > 0).
    std::vector<std::size_t> spanOf_;
    std::vector<double> basisOf_;
    bool basisKept_ = false;
    double previousWorst_ = std::numeric_limits<double>::infinity();
};

/// The original's corners inside (lo, hi), or none where their knots are more than free.
std::vector<double> cornersThatFit(const std::vector<double>& allCorners, const std::vector<double>& t,
                                   double lo, double hi, std::size_t free) {
    std::vector<double> corners;
    std::size_t cornerKnots = 0;
    for (double v : allCorners)
        if (v > lo && v < hi)
            corners.push_back(v),
                cornerKnots += static_cast<std::size_t>(std::upper_bound(t.begin(), t.end(), v) -
                                                        std::lower_bound(t.begin(), t.end(), v));
    if (cornerKnots > free) corners.clear();
    return corners;
}

/// Whether anchors a, a + 1 bound a pinned (hot) span of the original, whose knots are t.
bool boundsPinnedSpan(const std::vector<double>& t, const std::vector<char>& hot,
                      const std::vector<double>& anchors, std::size_t a) {
    const std::size_t n0 = hot.size();
    const std::size_t j =
        static_cast<std::size_t>(std::upper_bound(t.begin(), t.end(), anchors[a]) - t.begin()) - 1;
    return j < n0 && hot[j] && t[j + 1] == anchors[a + 1];
}

/// An interval between pinned knots that gets free knots by its share of the density's integral.
struct Interval {
    double from, to, weight;
    std::size_t knots = 0;
    double remainder = 0.0;
};

/// Shares movable knots among the intervals by weight (largest remainders).
void shareKnots(std::vector<Interval>& intervals, std::size_t movable) {
    double weights = 0.0;
    for (const Interval& in : intervals) weights += in.weight;
    std::size_t given = 0;
    for (Interval& in : intervals) {
        // A weight that is not finite would cast to a wild count: the knots go one at a time below.
        const double exact =
            weights > 0.0 && std::isfinite(weights) ? double(movable) * in.weight / weights : 0.0;
        in.knots = static_cast<std::size_t>(exact);
        in.remainder = exact - double(in.knots);
        given += in.knots;
    }
    // (With every span pinned no interval is left, but then no knot is movable either: the fit
    // has the original's count.)
    for (; given < movable && !intervals.empty(); ++given) {
        Interval& most =
            *std::max_element(intervals.begin(), intervals.end(),
                              [](const Interval& x, const Interval& y) { return x.remainder < y.remainder; });
        ++most.knots, most.remainder = -1.0;
    }
}

/// Whether start knots have every pin and no knot inside a pinned span.
template <class PinnedSpan>
bool startFitsPins(std::span<const double> startKnots, const std::vector<double>& pins,
                   const std::vector<double>& anchors, PinnedSpan&& pinnedSpan) {
    bool compatible = true;
    for (double v : pins)
        compatible = compatible && std::binary_search(startKnots.begin(), startKnots.end(), v);
    for (std::size_t a = 0; compatible && a + 1 < anchors.size(); ++a)
        if (pinnedSpan(a)) {
            const auto inside = std::upper_bound(startKnots.begin(), startKnots.end(), anchors[a]);
            compatible = inside == startKnots.end() || !(*inside < anchors[a + 1]);
        }
    return compatible;
}

/// Differences the control points of a degree-p spline p times, as its p-th derivative's
/// coefficients (level k: (p-k+1) (Q_i - Q_{i-1}) / (t_{i+p-k+1} - t_i)), leaving one per span in
/// top[p..]. Each level multiplies by up to p over the shortest span, so at high degree the product
/// can pass the largest double (degree 48 on 352 uniform spans does), and a density built on it
/// would be infinite. A level whose largest coefficient leaves [1e-100, 1e100] is divided by it;
/// returns the logarithm of the product of those divisors (0 where none was needed: ordinary
/// curves get exactly the unscaled coefficients).
double pthDerivativeCoefficients(int degree, const std::vector<double>& t, std::vector<glm::dvec3>& top) {
    const std::size_t p = static_cast<std::size_t>(degree), n0 = top.size();
    double logScale = 0.0;
    for (std::size_t level = 1; level <= p; ++level) {
        double largest = 0.0;
        for (std::size_t i = n0 - 1; i >= level; --i) {
            const double d = t[i + p - level + 1] - t[i];
            top[i] = d > 0.0 ? (double(p - level + 1) / d) * (top[i] - top[i - 1]) : glm::dvec3(0.0);
            largest = std::max({largest, std::abs(top[i].x), std::abs(top[i].y), std::abs(top[i].z)});
        }
        if (std::isfinite(largest) && (largest > 1e100 || (largest > 0.0 && largest < 1e-100))) {
            for (std::size_t i = level; i < n0; ++i) top[i] /= largest;
            logScale += std::log(largest);
        }
    }
    return logScale;
}

}  // namespace

FreeKnotFitter::FreeKnotFitter(const Curve& original, const FreeKnotOptions& options)
    : original_(original), options_(options) {
    validate(original, "FreeKnotFitter");
    if (original.rational()) throw GeometryError("FreeKnotFitter: rational curves are not supported");
    const std::size_t p = static_cast<std::size_t>(original.degree), n0 = original.points.size();
    for (std::size_t i = 0; i < p; ++i)
        if (original.knots[i] != original.knots[p] || original.knots[n0 + 1 + i] != original.knots[n0])
            throw GeometryError("FreeKnotFitter: the curve must have clamped ends");
    if (options.samplesPerFitSpan < 1)
        throw GeometryError("FreeKnotFitter: samplesPerFitSpan must be at least 1");
    if (options.iterations < 1 || options.warmIterations < 1)
        throw GeometryError("FreeKnotFitter: iterations and warmIterations must be at least 1");
    if (options.ends.fixedDerivatives < 0)
        throw GeometryError("FreeKnotFitter: fixedDerivatives must be non-negative");
    if (!(options.pinShare >= 0.0) || !(options.settledMove >= 0.0) || !(options.lawsonSettled >= 0.0))
        throw GeometryError("FreeKnotFitter: pinShare, settledMove and lawsonSettled must be non-negative");

    // The best knots for an l-infinity spline fit put h_i proportional to |f^(p+1)|^(-1/(p+1)).
    // The original's p-th derivative is constant on each span: the control points differenced p
    // times leave one coefficient per span, O(n p) for the curve, scaled where they would overflow
    // (the density takes the scale back as its (p+1)-th root). Its jumps over the neighbouring
    // spans' mean length estimate f^(p+1) at the knots.
    const std::vector<double>& t = original.knots;
    std::vector<glm::dvec3> top(original.points);
    const double logScale = pthDerivativeCoefficients(original.degree, t, top);
    const double scale = std::exp(logScale / double(p + 1));  // 1 where nothing was scaled
    density_.assign(n0, 0.0);
    std::size_t previous = n0;
    for (std::size_t j = p; j < n0; ++j) {
        if (!(t[j + 1] > t[j])) continue;
        if (previous != n0) {
            const double mean = 0.5 * (t[j + 1] - t[j] + t[previous + 1] - t[previous]);
            const double jump =
                scale * std::pow(glm::length(top[j] - top[previous]) / mean, 1.0 / double(p + 1));
            density_[j] = std::max(density_[j], jump);
            density_[previous] = std::max(density_[previous], jump);
        }
        previous = j;
    }
    for (std::size_t j = p; j < n0; ++j) densityIntegral_ += density_[j] * (t[j + 1] - t[j]);
    // What scaling cannot keep finite (control points near the largest double, spans near the
    // smallest) gets a uniform density: knots spread evenly rather than shares of infinity.
    if (!std::isfinite(densityIntegral_)) {
        std::fill(density_.begin() + static_cast<std::ptrdiff_t>(p), density_.end(), 1.0);
        densityIntegral_ = t[n0] - t[p];
    }
    // A floor, so that straight parts still get knots and no span is empty of samples.
    const double mean = densityIntegral_ / (t[n0] - t[p]);
    for (std::size_t j = p; j < n0; ++j) density_[j] = mean > 0.0 ? std::max(density_[j], 0.2 * mean) : 1.0;

    // The original's corners: interior knots of multiplicity p or more where the first derivative
    // jumps. The p-th derivative's jumps do not see them, and moved knots cannot make one.
    std::vector<double> first(2 * (p + 1));
    auto slope = [&](std::size_t span, double u) {
        basisDerivatives(span, u, original.degree, t, 1, first);
        glm::dvec3 d(0.0);
        for (std::size_t b = 0; b <= p; ++b) d += first[p + 1 + b] * original.points[span - p + b];
        return d;
    };
    for (std::size_t i = p + 1; i < n0;) {
        std::size_t last = i;
        while (last + 1 < n0 && t[last + 1] == t[i]) ++last;
        if (last + 1 - i >= p) {
            const glm::dvec3 left = slope(i - 1, t[i]), right = slope(last, t[i]);
            if (glm::length(left - right) > 1e-9 * (glm::length(left) + glm::length(right)))
                corners_.push_back(t[i]);
        }
        i = last + 1;
    }
}

const std::vector<glm::dvec3>& FreeKnotFitter::originalForms() const {
    if (formsSource_) return formsSource_();
    if (forms_.empty())
        forms_ = detail::powerForms(original_.degree, original_.knots, original_.points.data(),
                                    original_.points.size());
    return forms_;
}

const FreeKnotFitter::Samples& FreeKnotFitter::samplesFor(std::size_t count, int samplesPerFitSpan) const {
    const std::size_t wanted =
        static_cast<std::size_t>(samplesPerFitSpan > 0 ? samplesPerFitSpan : options_.samplesPerFitSpan) *
        count;
    Samples& out = samples_[wanted];
    if (!out.params.empty()) return out;
    // The original's parameters at equal steps of the density's integral, as the starting knots
    // are spread (initialKnots): each span of the fit gets about samplesPerFitSpan of them, a short
    // span where the curve turns as many as a long flat one. Spread evenly in the parameter, the
    // airfoil's leading edge (short in chord-length parameter, its spans short too) got few, and
    // the fits there needed more samples in all (10 per fit span now do better than 12 did).
    const std::vector<double>& t = original_.knots;
    const std::size_t p = static_cast<std::size_t>(original_.degree), n0 = original_.points.size();
    std::vector<double> steps;
    densitySteps(t[p], t[n0], wanted - 1, steps);
    out.params.push_back(t[p]);
    for (double u : steps)
        if (u > out.params.back() && u < t[n0]) out.params.push_back(u);
    out.params.push_back(t[n0]);
    out.points.resize(out.params.size());
    detail::evaluateAscending(original_.degree, original_.knots, original_.points.data(), n0, out.params,
                              out.points.data(), &originalForms());
    out.spacing = spacingOf(out.params);
    return out;
}

std::vector<double> FreeKnotFitter::spacingOf(const std::vector<double>& params) {
    // Each sample stands for the parameter interval half way to its neighbours.
    std::vector<double> spacing(params.size());
    for (std::size_t k = 0; k < params.size(); ++k) {
        const double left = k > 0 ? params[k - 1] : params[k];
        const double right = k + 1 < params.size() ? params[k + 1] : params[k];
        spacing[k] = 0.5 * (right - left);
    }
    return spacing;
}

double FreeKnotFitter::clippedLength(std::size_t span, double from, double to) const {
    const std::vector<double>& t = original_.knots;
    return std::max(0.0, std::min(to, t[span + 1]) - std::max(from, t[span]));
}

double FreeKnotFitter::densityIntegral(double from, double to) const {
    const std::size_t p = static_cast<std::size_t>(original_.degree), n0 = original_.points.size();
    double sum = 0.0;
    for (std::size_t j = p; j < n0; ++j) sum += density_[j] * clippedLength(j, from, to);
    return sum;
}

void FreeKnotFitter::densitySteps(double from, double to, std::size_t count, std::vector<double>& out) const {
    const std::vector<double>& t = original_.knots;
    const std::size_t p = static_cast<std::size_t>(original_.degree), n0 = original_.points.size();
    const double total = densityIntegral(from, to);
    double below = 0.0;
    std::size_t j = p;
    for (std::size_t i = 1; i <= count; ++i) {
        const double goal = total * double(i) / double(count + 1);
        while (j + 1 < n0 && below + density_[j] * clippedLength(j, from, to) < goal)
            below += density_[j] * clippedLength(j, from, to), ++j;
        const double along = density_[j] > 0.0 ? (goal - below) / density_[j] : 0.0;
        out.push_back(std::clamp(std::max(from, t[j]) + along, from, to));
    }
}

double FreeKnotFitter::predictedError(std::size_t count) const {
    const std::size_t p = static_cast<std::size_t>(original_.degree);
    if (count <= p) return std::numeric_limits<double>::infinity();
    return std::pow(densityIntegral_ / double(count - p), double(p + 1));
}

FreeKnotFitter::KnotLayout FreeKnotFitter::initialKnots(std::size_t count, std::span<const double> startKnots,
                                                        bool pin) const {
    const std::size_t p = static_cast<std::size_t>(original_.degree), n0 = original_.points.size();
    const std::size_t k = static_cast<std::size_t>(options_.ends.fixedDerivatives);
    const std::vector<double>& t = original_.knots;
    KnotLayout out;
    std::vector<double>& knots = out.knots;
    knots.resize(count + p + 1);
    for (std::size_t i = 0; i <= p; ++i) knots[i] = t[p], knots[count + i] = t[n0];
    for (std::size_t i = 0; i < k; ++i) knots[p + 1 + i] = t[p + 1 + i], knots[count - k + i] = t[n0 - k + i];
    const double lo = t[p + k], hi = t[n0 - k];
    const std::size_t free = count - p - 1 - 2 * k;
    const double total = densityIntegral(lo, hi);

    // The original's corners (where the fit has knots enough for them all), and the end knots
    // of its spans that the density gives at least pinShare of a knot each (raised where their
    // knots would be more than the fit has) stay, with their multiplicity.
    auto interior = [&](double v) { return v > lo && v < hi; };
    const std::vector<double> corners = cornersThatFit(corners_, t, lo, hi, free);
    std::vector<char> hot(n0, 0);
    std::vector<double> pins;
    for (double share = options_.pinShare; pin && share > 0.0 && total > 0.0; share *= 1.25) {
        pins.clear();
        std::vector<double> ends = corners;
        for (std::size_t j = p; j < n0; ++j) {
            const double length = clippedLength(j, lo, hi);
            hot[j] = length > 0.0 && double(free + 1) * density_[j] * length / total >= share;
            if (hot[j]) ends.push_back(t[j]), ends.push_back(t[j + 1]);
        }
        std::sort(ends.begin(), ends.end());
        for (std::size_t i = p + 1; i < n0; ++i)
            if (interior(t[i]) && std::binary_search(ends.begin(), ends.end(), t[i])) pins.push_back(t[i]);
        if (pins.size() <= free) break;
    }
    if (pins.empty()) std::fill(hot.begin(), hot.end(), 0);

    // The free knots go to the intervals between pinned knots (and lo, hi), except the pinned
    // spans, by the density's share (largest remainders), each spread like the start knots
    // inside it where there are any, else at equal steps of the density's integral.
    std::vector<double> anchors{lo};
    for (double v : pins)
        if (v != anchors.back()) anchors.push_back(v);
    if (anchors.back() != hi) anchors.push_back(hi);
    auto pinnedSpan = [&](std::size_t a) { return boundsPinnedSpan(t, hot, anchors, a); };
    std::vector<Interval> intervals;
    for (std::size_t a = 0; a + 1 < anchors.size(); ++a)
        if (!pinnedSpan(a))
            intervals.push_back({anchors[a], anchors[a + 1], densityIntegral(anchors[a], anchors[a + 1])});
    shareKnots(intervals, free - pins.size());

    // Start knots from a count whose pins differ (they change with the count) would spread wrongly
    // around these (the bump curve from 31 points' knots fit 42 points to 2.0e-4, from the
    // density's to 4.8e-5): with pins, the start is kept only where it has every pin and no knot
    // inside a pinned span.
    if (!pins.empty() && !startFitsPins(startKnots, pins, anchors, pinnedSpan)) startKnots = {};
    std::vector<double> placed;
    std::size_t nextPin = 0;
    for (const Interval& in : intervals) {
        while (nextPin < pins.size() && pins[nextPin] <= in.from)
            placed.push_back(pins[nextPin++]), out.pinned.push_back(1);
        // Start knots inside: quantiles of a knot density, knot j of m at fraction j / (m + 1);
        // the new ones are read off at i / (knots + 1), linearly.
        std::vector<double> q{in.from};
        for (double v : startKnots)
            if (v > in.from && v < in.to) q.push_back(v);
        q.push_back(in.to);
        const std::size_t inside = q.size() - 2;
        if (inside == 0) densitySteps(in.from, in.to, in.knots, placed);
        for (std::size_t i = 1; i <= in.knots && inside > 0; ++i) {
            const double at = double(i) * double(inside + 1) / double(in.knots + 1);
            const std::size_t m = std::min(static_cast<std::size_t>(at), inside);
            placed.push_back(q[m] + (at - double(m)) * (q[m + 1] - q[m]));
        }
        out.pinned.insert(out.pinned.end(), in.knots, 0);
    }
    while (nextPin < pins.size()) placed.push_back(pins[nextPin++]), out.pinned.push_back(1);
    std::copy(placed.begin(), placed.end(), knots.begin() + static_cast<std::ptrdiff_t>(p + k + 1));
    if (pins.empty()) out.pinned.clear();
    return out;
}

FreeKnotFit FreeKnotFitter::fit(std::size_t count, std::span<const double> startKnots, bool moveKnots,
                                int rounds, const FreeKnotStops& stops, int samplesPerFitSpan) const {
    const int degree = original_.degree;
    const std::size_t p = static_cast<std::size_t>(degree), n0 = original_.points.size();
    const std::size_t k = static_cast<std::size_t>(options_.ends.fixedDerivatives), fixed = k + 1;
    FreeKnotFit out;
    if (samplesPerFitSpan < 0)
        throw GeometryError("FreeKnotFitter::fit: samplesPerFitSpan must not be negative");
    if (count < p + 1 || count < 2 * fixed || count - p - 1 < 2 * k || count > n0) return out;
    if (k > 0 && !(original_.knots[p + k] < original_.knots[n0 - k])) return out;
    const bool warm = startKnots.size() > 2 * (p + 1 + k);
    // Knots that do not move are taken as given (resampled to the count); moving ones may pin.
    KnotLayout layout = initialKnots(count, warm ? startKnots : std::span<const double>{}, moveKnots);
    out.pinnedKnots = static_cast<std::size_t>(std::count(layout.pinned.begin(), layout.pinned.end(), 1));
    const Samples& data = samplesFor(count, samplesPerFitSpan);
    FitRounds run(FitInputs{data.params,
                            data.points,
                            data.spacing,
                            std::move(layout.knots),
                            std::vector<glm::dvec3>(count),
                            degree,
                            count,
                            k,
                            original_.knots[p],
                            original_.knots[n0],
                            original_.knots[p + k],
                            original_.knots[n0 - k],
                            moveKnots,
                            rounds > 0 ? rounds
                            : warm     ? options_.warmIterations
                                       : options_.iterations,
                            0,
                            options_.settledMove,
                            options_.lawsonSettled,
                            stops.giveUpAbove,
                            stops.stopBelow,
                            stops.passAt,
                            std::move(layout.pinned)});
    run.movingRounds = (run.iterations + 1) / 2;
    for (std::size_t i = 0; i < fixed; ++i) {
        run.points[i] = original_.points[i];
        run.points[count - 1 - i] = original_.points[n0 - 1 - i];
    }
    detail::withFixedDegree(p, [&](auto compiled) { run.run<compiled()>(out); });
    if (out.curve.points.empty()) out.sampleError = std::numeric_limits<double>::infinity();
    out.map.from = data.params;
    return out;
}

}  // namespace geom
