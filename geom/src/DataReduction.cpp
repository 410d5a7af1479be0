#include "geom/DataReduction.h"

#include "KeptVector.h"
#include "RemovalDetail.h"
#include "SeamOrder.h"
#include "geom/Basis.h"
#include "geom/BoundingBox.h"
#include "geom/Evaluate.h"
#include "geom/FreeKnotFit.h"
#include "geom/GeometryError.h"
#include "geom/GridEvaluator.h"
#include "geom/Inversion.h"
#include "geom/KnotInsertion.h"
#include "geom/KnotSignificance.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <deque>
#include <limits>
#include <memory>
#include <optional>
#include <string>
#include <unordered_set>

namespace geom {
namespace detail {

/// CurveDeviationMeter on the original's power forms and, where given, its samples and points,
/// made by the reduction already (the same arrays the meter would make). The meter reads them
/// where they are: they must outlive it.
struct MeterFromSamples {
    static CurveDeviationMeter make(const Curve& original, int samplesPerSpan,
                                    const std::vector<glm::dvec3>& forms, const std::vector<double>* params,
                                    const std::vector<glm::dvec3>* points) {
        return CurveDeviationMeter(original, samplesPerSpan, borrowed(&forms), borrowed(params),
                                   borrowed(points));
    }

    /// meter.measure(reduced, {from, to}, reducedSamplesPerSpan) with the map read where it is
    /// (non-empty, ascending, of equal sizes), or with a proof only a proof.
    static CurveDeviation measureAlong(const CurveDeviationMeter& meter, const Curve& reduced,
                                       const std::vector<double>& from, const std::vector<double>& to,
                                       int reducedSamplesPerSpan, const MeasureProof& proof) {
        return meter.measureAlong(reduced, from, to, reducedSamplesPerSpan, proof);
    }
    /// meter.measure, or with a proof only a proof.
    static CurveDeviation measure(const CurveDeviationMeter& meter, const Curve& reduced,
                                  const ParameterMap& map, int reducedSamplesPerSpan,
                                  const MeasureProof& proof) {
        return meter.checkedMeasure(reduced, map, reducedSamplesPerSpan, proof);
    }

private:
    template <class T>
    static std::shared_ptr<const T> borrowed(const T* x) {
        return std::shared_ptr<const T>(std::shared_ptr<const T>(), x);  // aliasing: owns nothing
    }
};

}  // namespace detail
namespace {

/// Samples per span of the original for a final check: the loop's, but at least 4. A loop run at
/// 1 or 2 per span (for speed) misses peaks between its samples, and so would a check at its
/// density, passing a result that breaks the tolerance between them.
int finalCheckDensity(const ReductionOptions& options) {
    return std::max(options.samplesPerSpan, 4);
}

/// A measurement at `wanted` samples per span (a multiple of the loop's), within what
/// measureDeviation takes: past maxSamplesPerSpan it would throw for a valid samplesPerSpan.
int measureDensity(int wanted) {
    return std::min(wanted, maxSamplesPerSpan);
}

/// What a final check must find: with the report on, the deviation; with it off, only that the
/// tolerance holds (as CurveDeviationMeter::within).
detail::MeasureProof finalCheck(const ReductionOptions& options) {
    if (options.report) return {};
    return {0.9 * options.tolerance, options.tolerance};
}

// A spline with `sequences` coefficient sequences sharing one knot vector: a curve, or the
// isoparametric curves of a surface net along the direction being reduced.
struct Spline {
    int degree = 0;
    std::vector<double> knots;
    std::vector<glm::dvec3> points;
    std::size_t sequences = 1;
};

// The states a reduction accepted before its current one, newest last, for the final
// measurement's step back: the last kKeep only (a step back past them goes to the original),
// handed over by move so that a long curve's thousands of removals copy nothing.
class AcceptedStates {
public:
    static constexpr std::size_t kKeep = 16;

    /// `current` becomes `next`; what it was is kept.
    void accept(Spline& current, Spline next) {
        keep(std::move(current));
        current = std::move(next);
    }
    void keep(Spline previous) {
        states_.push_back(std::move(previous));
        if (states_.size() > kKeep) states_.pop_front();
    }
    /// The state before the last one stepped to, or nothing when no kept state is left.
    std::optional<Spline> stepBack() {
        if (states_.empty()) return std::nullopt;
        Spline previous = std::move(states_.back());
        states_.pop_back();
        return previous;
    }

private:
    std::deque<Spline> states_;
};

void checkOptions(const ReductionOptions& o, const char* where) {
    const std::string w = where;
    if (!(o.tolerance > 0.0))
        throw GeometryError(w + ": tolerance must be positive (infinity for count mode)");
    if (o.partitionSize < 1) throw GeometryError(w + ": partitionSize must be at least 1");
    if (o.rounds < 1 || o.lawsonSteps < 0)
        throw GeometryError(w + ": rounds must be at least 1 and lawsonSteps non-negative");
    if (o.margin < 0) throw GeometryError(w + ": margin must be non-negative");
    if (!(o.weightCutoff >= 0.0)) throw GeometryError(w + ": weightCutoff must be non-negative");
    if (o.samplesPerSpan < 1 || o.samplesPerSpan > maxSamplesPerSpan)
        throw GeometryError(w + ": samplesPerSpan must be from 1 to " + std::to_string(maxSamplesPerSpan));
    if (o.ends.fixedDerivatives < 0) throw GeometryError(w + ": fixedDerivatives must be non-negative");
    if (o.freeKnotIterations < 1 || o.freeKnotIterations > 1000)
        throw GeometryError(w + ": freeKnotIterations must be from 1 to 1000");
    if (o.rounds > 1000 || o.lawsonSteps > 1000)
        throw GeometryError(w + ": rounds and lawsonSteps must be at most 1000");
}

// A row of the refit's normal equations whose p + 1 columns are all free, added with weight w to
// the band and right side at its first column (the general loop's terms in the same order).
template <std::size_t P>
inline void addFreeRow(const double* row, double w, const glm::dvec3& target, double* band, glm::dvec3* rhs) {
    constexpr std::size_t wb = P + 1;
#pragma GCC unroll 8
    for (std::size_t a = 0; a <= P; ++a) {
        rhs[a] += (w * row[a]) * target;
#pragma GCC unroll 8
        for (std::size_t b = a; b <= P; ++b) band[a * wb + (b - a)] += w * row[a] * row[b];
    }
}

// refitToOriginal with the degree fixed at compile time where P > 0 (the loops over a row's p+1
// entries unroll; the same arithmetic in the same order), any degree where P = 0; likewise one
// coefficient sequence where S = 1 (a curve: the loops over sequences go), any number where S = 0.
// The rows' spans in tau are walked as t0 ascends (the span osloRow's search finds).
template <std::size_t P, std::size_t S>
bool refitToOriginalWith(int degree, const std::vector<double>& tau, std::vector<glm::dvec3>& points,
                         std::size_t sequenceCount, std::size_t cL, std::size_t cH,
                         const std::vector<double>& t0, const std::vector<glm::dvec3>& d0) {
    const std::size_t p = P > 0 ? P : static_cast<std::size_t>(degree);
    const std::size_t sequences = S > 0 ? S : sequenceCount;
    const std::size_t nt = points.size() / sequences;
    const std::size_t n0 = d0.size() / sequences;
    // The original coefficients whose rows can reach the free columns: their knot intervals
    // meet the free columns' support [tau[cL], tau[cH+p+1]].
    const double from = tau[cL], to = tau[cH + p + 1];
    const std::size_t jFirst = static_cast<std::size_t>(std::max<std::ptrdiff_t>(
        0, (std::lower_bound(t0.begin(), t0.end(), from) - t0.begin()) - static_cast<std::ptrdiff_t>(p) - 1));
    const std::size_t jLast =
        std::min(n0 - 1, static_cast<std::size_t>(std::upper_bound(t0.begin(), t0.end(), to) - t0.begin()));

    // Normal equations of the scaled rows: every row has p+1 neighbouring non-zeros, so the
    // matrix is banded and Cholesky solves it in O(rows p^2).
    const std::size_t freeCount = cH - cL + 1, wb = p + 1;
    std::vector<double> band(freeCount * wb, 0.0);
    std::vector<glm::dvec3> rhs(freeCount * sequences, glm::dvec3(0.0));
    // The row and the targets in locals where their sizes are fixed (they stay in registers).
    std::array<double, P + 1> fixedRow{};
    std::vector<double> anyRow(P > 0 ? 0 : p + 1);
    double* row = P > 0 ? fixedRow.data() : anyRow.data();
    glm::dvec3 oneTarget(0.0);
    std::vector<glm::dvec3> targets(S == 1 ? 0 : sequences);
    glm::dvec3* target = S == 1 ? &oneTarget : targets.data();
    std::size_t fitRows = 0;
    // tau[walk] <= t0[j] < tau[walk + 1] (or walk = nt - 1), from osloRow's search at the first row.
    std::size_t walk =
        static_cast<std::size_t>(std::upper_bound(tau.begin(), tau.end(), t0[jFirst]) - tau.begin());
    walk = std::clamp(walk == 0 ? 0 : walk - 1, p, nt - 1);
    std::vector<double> inverse(p * (p + 1) / 2);
    std::size_t inverseSpan = nt;  // the span inverse was made for
    for (std::size_t j = jFirst; j <= jLast; ++j) {
        while (walk + 1 < nt && !(t0[j] < tau[walk + 1])) ++walk;
        std::size_t mu = walk;
        while (mu > p && !(tau[mu] < tau[mu + 1])) --mu;
        if (mu != inverseSpan) detail::osloInverses(p, tau, inverseSpan = mu, inverse.data());
        detail::osloRowInverse<P>(p, tau, t0, j, mu, inverse.data(), row);
        const std::size_t c0 = mu - p;
        const double w = (t0[j + p + 1] - t0[j]) / static_cast<double>(p + 1);
        if (w == 0.0) continue;
        // Every column of the row free (most rows): no held terms, and no zero entries to skip
        // (they would add nothing: the rows are non-negative and sum to 1).
        if (P > 0 && S == 1 && c0 >= cL && c0 + p <= cH) {
            addFreeRow<P>(row, w, d0[j], &band[(c0 - cL) * wb], &rhs[c0 - cL]);
            ++fitRows;
            continue;
        }
        bool touchesFree = false;
#pragma GCC unroll 8
        for (std::size_t k = 0; k <= p; ++k)
            touchesFree = touchesFree || (row[k] != 0.0 && c0 + k >= cL && c0 + k <= cH);
        if (!touchesFree) continue;
        for (std::size_t s = 0; s < sequences; ++s) {
            target[s] = d0[j * sequences + s];
#pragma GCC unroll 8
            for (std::size_t k = 0; k <= p; ++k)
                if ((c0 + k < cL || c0 + k > cH) && row[k] != 0.0)
                    target[s] -= row[k] * points[(c0 + k) * sequences + s];
        }
#pragma GCC unroll 8
        for (std::size_t a = 0; a <= p; ++a) {
            const std::size_t ca = c0 + a;
            if (ca < cL || ca > cH || row[a] == 0.0) continue;
            const std::size_t fa = ca - cL;
            for (std::size_t s = 0; s < sequences; ++s) rhs[fa * sequences + s] += (w * row[a]) * target[s];
            for (std::size_t b = a; b <= p && c0 + b <= cH; ++b)
                band[fa * wb + (b - a)] += w * row[a] * row[b];
        }
        ++fitRows;
    }
    if (fitRows < freeCount) return false;
    if (!detail::solveBanded(band, freeCount, p, rhs, sequences))
        throw GeometryError("removeKnotsLeastSquares: the local fit is rank deficient");
    for (std::size_t c = cL; c <= cH; ++c)
        for (std::size_t s = 0; s < sequences; ++s) points[c * sequences + s] = rhs[(c - cL) * sequences + s];
    return true;
}

// Refits coefficients [cL, cH] of a reduced spline to the original one (knots t0, coefficients
// d0, same layout) in the original's discrete l2 norm, the other coefficients held. The original
// knots contain the reduced ones, so the original is the reduced spline with the missing knots
// inserted: the local insertion matrix gives the fit. Fitting the original rather than the
// previous approximation keeps the errors of successive removals from piling up. Returns false,
// leaving points alone, where the original has too few coefficients to determine the window.
bool refitToOriginal(int degree, const std::vector<double>& tau, std::vector<glm::dvec3>& points,
                     std::size_t sequences, std::size_t cL, std::size_t cH, const std::vector<double>& t0,
                     const std::vector<glm::dvec3>& d0) {
    bool ok = false;
    detail::withFixedDegree(static_cast<std::size_t>(degree), [&](auto fixed) {
        ok = sequences == 1 ? refitToOriginalWith<fixed(), 1>(degree, tau, points, 1, cL, cH, t0, d0)
                            : refitToOriginalWith<fixed(), 0>(degree, tau, points, sequences, cL, cH, t0, d0);
    });
    return ok;
}

// The linear stage's fit and bound: the best fit to the original (knots t0, coefficients d0) in
// its scaled discrete l2 norm on knots tau with the end points held, every interior coefficient
// free (refitToOriginal's normal equations), kept only if its coefficients refined onto t0 are
// within the tolerance of d0: then |C - C'| <= tolerance at every parameter (the B-splines are a
// partition of unity), a bound, not a sample. The Oslo rows from tau to t0 are made once per fit,
// their spans found by walking tau as t0 ascends, and serve both the fit and the bound.
class LinearFit {
public:
    explicit LinearFit(const Curve& original) : o_(original), p_(static_cast<std::size_t>(original.degree)) {}

    /// False where the fit is rank deficient or the bound fails; tau has at least two coefficients.
    bool run(const std::vector<double>& tau, std::vector<glm::dvec3>& c, double tolerance) {
        const std::size_t nt = tau.size() - p_ - 1;
        c.assign(nt, glm::dvec3(0.0));
        c.front() = o_.points.front();
        c.back() = o_.points.back();
        makeRows(tau, nt);
        return (nt < 3 || fit(nt, c)) && within(c, tolerance);
    }

    /// The fit alone (false where it is rank deficient), for a caller that judges it otherwise.
    bool fitOnly(const std::vector<double>& tau, std::vector<glm::dvec3>& c) {
        const std::size_t nt = tau.size() - p_ - 1;
        c.assign(nt, glm::dvec3(0.0));
        c.front() = o_.points.front();
        c.back() = o_.points.back();
        makeRows(tau, nt);
        return nt < 3 || fit(nt, c);
    }
    bool bounded(const std::vector<glm::dvec3>& c, double tolerance) const { return within(c, tolerance); }

    /// True when the spline (tau, c), whose knots are among the original's, is within the
    /// tolerance of the original by the coefficient bound.
    bool bounds(const std::vector<double>& tau, const std::vector<glm::dvec3>& c, double tolerance) {
        makeRows(tau, c.size());
        return within(c, tolerance);
    }

private:
    // A row reads tau[m + 1 - p .. m + p] around its span m (and the original's knots): where
    // those are the knots the last call read for the same row, the row is the one it made (the
    // stage's fits differ from one another by a few knots, so most rows are).
    void makeRows(const std::vector<double>& tau, std::size_t nt) {
        detail::withFixedDegree(p_, [&](auto fixed) { makeRowsWith<fixed()>(tau, nt); });
    }

    // makeRows with the degree fixed at compile time where P > 0 (the Oslo rows' loops unroll;
    // the same arithmetic in the same order), any degree where P = 0.
    template <std::size_t P>
    void makeRowsWith(const std::vector<double>& tau, std::size_t nt) {
        const std::size_t n0 = o_.points.size(), p = P > 0 ? P : p_;
        rows_.resize(n0 * (p + 1));
        first_.resize(n0);
        const bool before = spans_.size() == n0;
        spans_.resize(n0);
        std::size_t mu = p, inverseSpan = nt;  // inverseSpan: the span inverse_ was made for
        inverse_.resize(p * (p + 1) / 2);
        for (std::size_t j = 0; j < n0; ++j) {
            while (mu + 1 < nt && !(o_.knots[j] < tau[mu + 1])) ++mu;
            std::size_t m = mu;
            while (m > p && !(tau[m] < tau[m + 1])) --m;
            first_[j] = m - p;
            if (before && std::equal(tau.begin() + static_cast<std::ptrdiff_t>(m + 1 - p),
                                     tau.begin() + static_cast<std::ptrdiff_t>(m + p + 1),
                                     readTau_.begin() + static_cast<std::ptrdiff_t>(spans_[j] + 1 - p))) {
                spans_[j] = m;
                continue;
            }
            spans_[j] = m;
            if (m != inverseSpan) detail::osloInverses(p, tau, inverseSpan = m, inverse_.data());
            detail::osloRowInverse<P>(p, tau, o_.knots, j, m, inverse_.data(), &rows_[j * (p + 1)]);
        }
        readTau_ = tau;
    }

    bool fit(std::size_t nt, std::vector<glm::dvec3>& c) {
        bool ok = false;
        detail::withFixedDegree(p_, [&](auto fixed) { ok = fitWith<fixed()>(nt, c); });
        return ok;
    }

    // The fit with the degree fixed at compile time where P > 0 (the loops over a row's p+1
    // entries unroll; the same arithmetic in the same order), any degree where P = 0.
    template <std::size_t P>
    bool fitWith(std::size_t nt, std::vector<glm::dvec3>& c) {
        const std::size_t p = P > 0 ? P : p_, n0 = o_.points.size(), wb = p + 1,
                          nf = nt - 2;  // free: 1 .. nt-2
        const std::vector<double>& t0 = o_.knots;
        band_.assign(nf * wb, 0.0);
        rhs_.assign(nf, glm::dvec3(0.0));
        std::size_t fitRows = 0;
        for (std::size_t j = 0; j < n0; ++j) {
            const double* row = &rows_[j * wb];
            const std::size_t c0 = first_[j];
            const double w = (t0[j + p + 1] - t0[j]) / static_cast<double>(p + 1);
            if (w == 0.0) continue;
            // A row clear of the held end points (most rows) adds its terms without the tests
            // (zero entries add nothing: the rows are non-negative).
            if (P > 0 && c0 >= 1 && c0 + p < nt - 1) {
                addFreeRow<P>(row, w, o_.points[j], &band_[(c0 - 1) * wb], &rhs_[c0 - 1]);
                ++fitRows;
                continue;
            }
            glm::dvec3 target = o_.points[j];
            bool touchesFree = false;
#pragma GCC unroll 8
            for (std::size_t k = 0; k <= p; ++k) {
                if (row[k] == 0.0) continue;
                if (c0 + k == 0 || c0 + k == nt - 1)
                    target -= row[k] * c[c0 + k];
                else
                    touchesFree = true;
            }
            if (!touchesFree) continue;
#pragma GCC unroll 8
            for (std::size_t a = 0; a <= p; ++a) {
                const std::size_t ca = c0 + a;
                if (ca == 0 || ca >= nt - 1 || row[a] == 0.0) continue;
                const std::size_t fa = ca - 1;
                rhs_[fa] += (w * row[a]) * target;
                for (std::size_t b = a; b <= p && c0 + b < nt - 1; ++b)
                    band_[fa * wb + (b - a)] += w * row[a] * row[b];
            }
            ++fitRows;
        }
        if (fitRows < nf || !detail::solveBanded(band_, nf, p, rhs_)) return false;
        for (std::size_t i = 0; i < nf; ++i) c[i + 1] = rhs_[i];
        return true;
    }

    bool within(const std::vector<glm::dvec3>& c, double tolerance) const {
        bool ok = false;
        detail::withFixedDegree(p_, [&](auto fixed) { ok = withinWith<fixed()>(c, tolerance); });
        return ok;
    }

    template <std::size_t P>
    bool withinWith(const std::vector<glm::dvec3>& c, double tolerance) const {
        const std::size_t p = P > 0 ? P : p_;
        const double tol2 = tolerance * tolerance;
        for (std::size_t j = 0; j < o_.points.size(); ++j) {
            const double* row = &rows_[j * (p + 1)];
            const glm::dvec3* cj = &c[first_[j]];
            glm::dvec3 v(0.0);
#pragma GCC unroll 8
            for (std::size_t a = 0; a <= p; ++a) v += row[a] * cj[a];
            const glm::dvec3 d = v - o_.points[j];
            if (glm::dot(d, d) > tol2) return false;
        }
        return true;
    }

    const Curve& o_;
    std::size_t p_;
    std::vector<double> rows_, band_, readTau_, inverse_;  // readTau_: the knots the rows were made on
    std::vector<std::size_t> first_, spans_;
    std::vector<glm::dvec3> rhs_;
};

// A linear stage after T. Lyche and K. Morken (A data reduction strategy for splines with
// applications to the approximation of functions and data, IMA J. Numer. Anal., 1988), as SISL's
// s1940 runs it: rank the knots once, remove the m least significant together, refit every free
// coefficient to the original by one banded least-squares solve, and halve m until the fit keeps
// the coefficient bound (LinearFit); then rank the result again, up to `passes` times. Every state
// it returns is within the tolerance by the bound. Ends: the end points only (fixedDerivatives 0). Unlike
// s1940, no two knots within kLinearSeparation places of each other go in the same pass: on densely spaced
// knots each one alone moves the curve little and together they move it much, and removing the simpler
// curve's knots among them leaves a state the removal loop cannot improve. Over 30 random members of
// each generated class, separation 2 kept the same points as 3 (within 1% on every class, after the
// loop) in 5-15% less time; 1 kept up to 4% more on degrees 2-5 and the long curve.
constexpr std::size_t kLinearSeparation = 2;

/// A knot of the linear stage's state whose own removal stays within the tolerance: its last
/// occurrence, its place among the distinct interior values, its removal weight.
struct LinearCandidate {
    std::size_t index, place;
    double weight;
};

/// The knots of s whose removal weight is within the tolerance, lightest first (ties in knot
/// order, as rankKnots has them), and the number of distinct interior values. Knots past the
/// tolerance are not sorted: every one of them ranks after every candidate, so they can neither
/// be taken nor keep a candidate out. ranking, where given, is rankKnots of s.
std::vector<LinearCandidate> linearCandidates(const Spline& s, double tolerance,
                                              const std::vector<KnotSignificance>* ranking,
                                              std::size_t& places) {
    const std::size_t p = static_cast<std::size_t>(s.degree), count = s.points.size();
    std::vector<LinearCandidate> out;
    std::vector<std::size_t> placeOf(ranking ? s.knots.size() : 0);
    places = 0;
    for (std::size_t i = p + 1; i < count; ++i) {
        if (s.knots[i] == s.knots[i + 1] || !(s.knots[i] > s.knots[p]) || !(s.knots[i] < s.knots[count]))
            continue;
        if (ranking) {
            placeOf[i] = places++;
            continue;
        }
        const double w = knotRemovalWeight(s.degree, s.knots, s.points, 1, i);
        if (w <= tolerance) out.push_back({i, places, w});
        ++places;
    }
    if (ranking) {
        for (const KnotSignificance& k : *ranking)
            if (k.weight <= tolerance) out.push_back({k.index, placeOf[k.index], k.weight});
        return out;  // rankKnots' order already
    }
    std::sort(out.begin(), out.end(), [](const LinearCandidate& a, const LinearCandidate& b) {
        return a.weight < b.weight || (a.weight == b.weight && a.place < b.place);
    });
    return out;
}

Spline linearRemoval(const Curve& curve, double tolerance, int passes,
                     const std::vector<KnotSignificance>& firstRanking) {
    const std::size_t p = static_cast<std::size_t>(curve.degree);
    Spline s{curve.degree, curve.knots, curve.points, 1};
    LinearFit fit(curve);
    std::vector<char> gone;
    // s without the knots at the first m candidates' indices (one copy of each value), refitted.
    auto without = [&](const std::vector<LinearCandidate>& ranked, std::size_t m, Spline& out) {
        gone.assign(s.knots.size(), 0);
        for (std::size_t i = 0; i < m; ++i) gone[ranked[i].index] = 1;
        out.degree = s.degree;
        out.sequences = 1;
        out.knots.clear();
        for (std::size_t i = 0; i < s.knots.size(); ++i)
            if (!gone[i]) out.knots.push_back(s.knots[i]);
        if (out.knots.size() < p + 3) return false;
        return fit.run(out.knots, out.points, tolerance);
    };
    Spline trial, best;
    for (int pass = 0; pass < passes; ++pass) {
        std::size_t places = 0;
        const std::vector<LinearCandidate> all = linearCandidates(
            s, tolerance, pass == 0 && !firstRanking.empty() ? &firstRanking : nullptr, places);
        // No two knots within kLinearSeparation places of each other; the ranking stays in order.
        std::vector<char> taken(places + 2 * kLinearSeparation, 0);
        std::vector<LinearCandidate> ranked;
        for (const LinearCandidate& k : all) {
            const std::size_t at = k.place + kLinearSeparation;
            bool free = true;
            for (std::size_t d = 1; d <= kLinearSeparation; ++d)
                free = free && !taken[at - d] && !taken[at + d];
            if (!free) continue;
            taken[at] = 1;
            ranked.push_back(k);
        }
        bool found = false;
        // Try all first (refined curves), then halve until one passes: the next pass ranks again
        // and takes what this one left (bisection upwards cost the smooth curves twice the
        // trials for the same counts).
        for (std::size_t m = ranked.size(); m > 0; m /= 2)
            if (without(ranked, m, trial)) {
                best = std::move(trial);
                found = true;
                break;
            }
        if (!found) break;
        s = std::move(best);
    }
    return s;
}

/// The rank / remove / approximate loop on s. accept(fit) measures a candidate and, when it keeps
/// the tolerance, updates the caller's measurement state and returns true.
template <class Accept, class Present>
class RemovalLoop {
public:
    RemovalLoop(Spline& s, const ReductionOptions& o, std::size_t& fits, Accept& accept,
                Present& presentError, AcceptedStates* history, const Spline* originalSpline,
                bool refitRounds)
        : s_(s),
          o_(o),
          fits_(fits),
          accept_(accept),
          presentError_(presentError),
          history_(history),
          original_(originalSpline ? *originalSpline : s),
          measuring_(std::isfinite(o.tolerance)),
          refitRounds_(refitRounds) {}

    /// Runs the loop's rounds; returns the number of knots removed.
    std::size_t run() {
        for (int round = 0;; ++round) {
            const std::size_t removedBefore = removed_;
            blocked_.clear();
            while (removed_ < o_.maxRemovals) {
                const std::vector<KnotSignificance> partition = nextPartition();
                if (partition.empty()) break;
                const std::size_t removedBeforePartition = removed_;
                removePartition(partition);
                // After a global refit every knot tried has failed once: where the best ranked of
                // them fail again, the others (ranked worse) do too (on noisy digitised curves a
                // second round removed none of 155 such knots), so the round ends there.
                if (round > 0 && removed_ == removedBeforePartition) break;
            }
            // Every knot left failed against the accumulated local fits. A global best fit to the
            // original on the knots now left usually lowers the error everywhere; if it keeps the
            // tolerance, the knots that failed get another chance. Not where the loop started from
            // the linear stage's state (refitRounds false), itself a global best fit: there a
            // second round almost never removes a knot (see geom/ALGORITHMS.md).
            if (!measuring_ || !refitRounds_ || removed_ == removedBefore || removed_ >= o_.maxRemovals ||
                round >= 4)
                break;
            if (!refitGlobally()) break;
        }
        return removed_;
    }

private:
    /// A knot's cached score, by value.
    struct Cached {
        double value, score;
    };

    /// The best ranked knots not blocked, up to the partition size and below the weight cutoff
    /// (ties in knot order). Only those few are sorted.
    std::vector<KnotSignificance> nextPartition() {
        const std::size_t want =
            std::min(static_cast<std::size_t>(o_.partitionSize), o_.maxRemovals - removed_);
        std::vector<KnotSignificance> partition;
        const bool cutoff = measuring_ && o_.weightCutoff > 0.0;
        for (const KnotSignificance& k : rank())
            if (!blocked_.contains(k.value) && !(cutoff && k.weight > o_.weightCutoff * o_.tolerance))
                partition.push_back(k);
        auto before = [](const KnotSignificance& a, const KnotSignificance& b) {
            return a.weight < b.weight || (a.weight == b.weight && a.index < b.index);
        };
        const std::size_t kept = std::min(want, partition.size());
        std::partial_sort(partition.begin(), partition.begin() + static_cast<std::ptrdiff_t>(kept),
                          partition.end(), before);
        partition.resize(kept);
        return partition;
    }

    /// Every knot with its score (in knot order), with the weights of knots whose local data no
    /// accepted fit touched kept from before (the same numbers, computed once): a knot's weight
    /// depends only on the knots and coefficients whose supports meet [knots[r-p-1], knots[r+p+1]].
    /// A knot's score is its weight plus, when measuring, the error already spent near it (vs
    /// the original): removing a knot moves the curve by about its weight on top of what is
    /// there, so this spreads the tolerance over the curve instead of exhausting it in one place.
    std::vector<KnotSignificance> rank() {
        const std::size_t p = static_cast<std::size_t>(s_.degree), count = s_.points.size() / s_.sequences;
        std::vector<KnotSignificance> out;
        std::vector<Cached> next;
        for (std::size_t i = p + 1; i < count; ++i) {
            if (s_.knots[i] == s_.knots[i + 1] || !(s_.knots[i] > s_.knots[p]) ||
                !(s_.knots[i] < s_.knots[count]))
                continue;
            const double score = scoreOf(i);
            std::size_t first = i;
            while (first > 0 && s_.knots[first - 1] == s_.knots[i]) --first;
            out.push_back({i, s_.knots[i], static_cast<int>(i - first + 1), score});
            next.push_back({s_.knots[i], score});
        }
        cache_ = std::move(next);
        return out;
    }

    /// The score of knot i: cached, or its removal weight plus the error present near it.
    double scoreOf(std::size_t i) {
        const std::size_t p = static_cast<std::size_t>(s_.degree);
        const auto it = std::lower_bound(cache_.begin(), cache_.end(), s_.knots[i],
                                         [](const Cached& c, double v) { return c.value < v; });
        if (it != cache_.end() && it->value == s_.knots[i]) return it->score;
        double score = knotRemovalWeight(s_.degree, s_.knots, s_.points, s_.sequences, i);
        if (measuring_)
            score += presentError_(s_.knots[i > p + 1 ? i - p - 1 : 0],
                                   s_.knots[std::min(s_.knots.size() - 1, i + p + 1)]);
        return score;
    }

    /// Sub-partitions by locality: each knot not yet placed, in rank order, starts a group and
    /// takes the later ones whose local windows overlap its own. Knots are named by value, so
    /// the indices shifted by an earlier group's removal need no bookkeeping.
    void removePartition(const std::vector<KnotSignificance>& partition) {
        const std::size_t reach = static_cast<std::size_t>(s_.degree) + 1;
        std::vector<bool> placed(partition.size(), false);
        for (std::size_t i = 0; i < partition.size() && removed_ < o_.maxRemovals; ++i) {
            if (placed[i]) continue;
            std::vector<KnotSignificance> group{partition[i]};
            placed[i] = true;
            for (std::size_t j = i + 1; j < partition.size(); ++j) {
                const std::size_t a = partition[i].index, b = partition[j].index;
                if (!placed[j] && (a > b ? a - b : b - a) <= reach) {
                    group.push_back(partition[j]);
                    placed[j] = true;
                }
            }
            if (group.size() > o_.maxRemovals - removed_) group.resize(o_.maxRemovals - removed_);
            removeGroup(group);
        }
    }

    /// The group's knots together, or else one by one; a knot that fails alone is blocked. A
    /// curve in tolerance mode goes one by one at once: its group fits rarely keep the tolerance,
    /// and a failed one is a fit for nothing before the same knots are tried alone, in the same
    /// order (the counts come out the same either way).
    void removeGroup(const std::vector<KnotSignificance>& group) {
        if (group.size() > 1 && !(measuring_ && s_.sequences == 1)) {
            std::vector<double> values;
            for (const KnotSignificance& k : group) values.push_back(k.value);
            if (tryRemove(values)) {
                removed_ += group.size();
                return;
            }
        }
        for (const KnotSignificance& k : group) {
            if (removed_ >= o_.maxRemovals) break;
            if (tryRemove({k.value}))
                ++removed_;
            else
                blocked_.insert(k.value);
        }
    }

    /// Removes the knots of these values where the refitted window is accepted.
    bool tryRemove(std::vector<double> values) {
        std::sort(values.begin(), values.end());
        ++fits_;
        LeastSquaresRemoval fit;
        try {
            // The window is refitted to the original; only where the original has too few
            // coefficients there does the fit to the current approximation stand.
            fit = detail::removalWindow(s_.degree, s_.knots, s_.points, s_.sequences, values, o_.ends,
                                        o_.margin);
            if (!refitToOriginal(s_.degree, fit.knots, fit.points, s_.sequences, fit.firstChanged,
                                 fit.lastChanged, original_.knots, original_.points))
                fit = removeKnotsLeastSquares(s_.degree, s_.knots, s_.points, s_.sequences, values, o_.ends,
                                              o_.margin);
        } catch (const GeometryError&) {
            return false;  // the end conditions leave nothing to fit here
        }
        if (!accept_(fit)) return false;
        forget(fit.changedFrom, fit.changedTo);
        commit(fit);
        return true;
    }

    /// A global best fit to the original on the knots now left; true where it was accepted.
    bool refitGlobally() {
        const std::size_t nt = s_.points.size() / s_.sequences;
        const std::size_t fixedEnd = static_cast<std::size_t>(o_.ends.fixedDerivatives) + 1;
        if (nt < 2 * fixedEnd + 1) return false;
        LeastSquaresRemoval global;
        global.knots = s_.knots;
        global.points = s_.points;
        global.firstChanged = fixedEnd;
        global.lastChanged = nt - 1 - fixedEnd;
        refitToOriginal(s_.degree, global.knots, global.points, s_.sequences, global.firstChanged,
                        global.lastChanged, original_.knots, original_.points);
        global.changedFrom = global.knots.front();
        global.changedTo = global.knots.back();
        ++fits_;
        if (!accept_(global)) return false;
        cache_.clear();
        commit(global);
        return true;
    }

    /// The accepted fit becomes the current state (recorded in the history where there is one).
    void commit(LeastSquaresRemoval& fit) {
        Spline next{s_.degree, std::move(fit.knots), std::move(fit.points), s_.sequences};
        if (history_)
            history_->accept(s_, std::move(next));
        else
            s_ = std::move(next);
    }

    /// Where the spline changed on [from, to], the caller's errors changed up to about an original
    /// span further (its samples there are measured again); two spans of the original are safe.
    void widened(double& from, double& to) const {
        const std::size_t p = static_cast<std::size_t>(original_.degree);
        const std::size_t n = original_.points.size() / original_.sequences;
        const auto& t = original_.knots;
        std::size_t a = static_cast<std::size_t>(std::upper_bound(t.begin(), t.end(), from) - t.begin());
        std::size_t b = static_cast<std::size_t>(std::lower_bound(t.begin(), t.end(), to) - t.begin());
        a = a > p + 3 ? a - 3 : p;
        b = std::min(n, b + 2);
        from = std::min(from, t[a]);
        to = std::max(to, t[b]);
    }

    /// Drops the cached scores of the knots whose local data the change on [from, to] touched.
    void forget(double from, double to) {
        if (measuring_) widened(from, to);
        // The knots r whose [knots[r-p-1], knots[r+p+1]] meets [from, to] lie within p + 1 places
        // of the knots in [from, to]; the cache is sorted by value, so they go as one range.
        const std::size_t p = static_cast<std::size_t>(s_.degree), last = s_.knots.size() - 1;
        const std::size_t a = static_cast<std::size_t>(
            std::lower_bound(s_.knots.begin(), s_.knots.end(), from) - s_.knots.begin());
        const std::size_t b = static_cast<std::size_t>(
            std::upper_bound(s_.knots.begin(), s_.knots.end(), to) - s_.knots.begin());
        const double lo = s_.knots[a > p + 1 ? a - p - 1 : 0];
        const double hi = s_.knots[std::min(last, b + p)];
        cache_.erase(std::lower_bound(cache_.begin(), cache_.end(), lo,
                                      [](const Cached& c, double v) { return c.value < v; }),
                     std::upper_bound(cache_.begin(), cache_.end(), hi,
                                      [](double v, const Cached& c) { return v < c.value; }));
    }

    Spline& s_;
    const ReductionOptions& o_;
    std::size_t& fits_;
    Accept& accept_;
    Present& presentError_;
    AcceptedStates* history_;
    const Spline original_;  // the spline the fits approximate: s itself, or the original s was reduced from
    const bool measuring_, refitRounds_;
    std::unordered_set<double> blocked_;  // by value; a long curve blocks thousands
    std::vector<Cached> cache_;           // by value
    std::size_t removed_ = 0;
};

/// Runs the RemovalLoop on s; returns the number of knots removed.
template <class Accept, class Present>
std::size_t reduceLoop(Spline& s, const ReductionOptions& o, std::size_t& fits, Accept&& accept,
                       Present&& presentError, AcceptedStates* history = nullptr,
                       const Spline* originalSpline = nullptr, bool refitRounds = true) {
    using A = std::remove_reference_t<Accept>;
    using P = std::remove_reference_t<Present>;
    return RemovalLoop<A, P>(s, o, fits, accept, presentError, history, originalSpline, refitRounds).run();
}

Surface transposed(const Surface& s) {
    Surface t;
    t.degreeU = s.degreeV;
    t.degreeV = s.degreeU;
    t.knotsU = s.knotsV;
    t.knotsV = s.knotsU;
    t.countU = s.countV;
    t.countV = s.countU;
    t.points.resize(s.points.size());
    t.weights.resize(s.weights.size());
    for (std::size_t i = 0; i < s.countU; ++i)
        for (std::size_t j = 0; j < s.countV; ++j) {
            t.points[j * s.countU + i] = s.points[i * s.countV + j];
            if (s.rational()) t.weights[j * s.countU + i] = s.weights[i * s.countV + j];
        }
    return t;
}

// Measured parametric error of a surface being reduced along u against the original's values
// on a fixed grid (gridU x gridV, original parameters). The v direction does not change during
// the pass, so its basis values are computed once.
struct SurfaceGrid {
    std::vector<double> gridU, gridV;
    std::vector<glm::dvec3> values;  // original surface, gridU.size() x gridV.size()
    std::vector<std::size_t> spanV;
    std::vector<double> basisV;
    int degreeV = 0;
    const Surface* original = nullptr;  // the original in the same orientation
    // The current v knots' insertion rows into the original's: original v coefficient k is
    // sum_b rowsV[k * (q + 1) + b] * c[firstV[k] + b] of the current v coefficients c.
    std::vector<double> rowsV;
    std::vector<std::size_t> firstV;

    void prepareAcross(const Surface& current) {
        if (original) {
            const std::size_t q = static_cast<std::size_t>(current.degreeV);
            rowsV.resize(original->countV * (q + 1));
            firstV.resize(original->countV);
            for (std::size_t k = 0; k < original->countV; ++k)
                firstV[k] = detail::osloRow(current.degreeV, current.knotsV, current.countV, original->knotsV,
                                            k, rowsV.data() + k * (q + 1)) -
                            q;
        }
        degreeV = current.degreeV;
        const std::size_t w = static_cast<std::size_t>(degreeV) + 1;
        spanV.resize(gridV.size());
        basisV.resize(gridV.size() * w);
        for (std::size_t k = 0; k < gridV.size(); ++k) {
            spanV[k] = findSpan(degreeV, current.knotsV, current.countV, gridV[k]);
            basisFunctions(spanV[k], gridV[k], degreeV, current.knotsV, std::span(basisV).subspan(k * w, w));
        }
    }

    // True when the B-spline coefficients of S - S' on the original knots (S' refined by knot
    // insertion both ways) are within the tolerance for every original u coefficient whose
    // support meets (from, to): then |S - S'| <= tolerance everywhere on that strip (the
    // B-splines are a partition of unity), a bound, not a sample.
    bool coefficientsWithin(int degreeU, const std::vector<double>& knotsU,
                            const std::vector<glm::dvec3>& points, std::size_t countV, double from, double to,
                            double tolerance) const {
        if (!original) return false;
        const Surface& o = *original;
        const std::size_t p = static_cast<std::size_t>(degreeU), q = static_cast<std::size_t>(degreeV);
        const std::size_t countU = points.size() / countV;
        std::vector<double> row(p + 1);
        std::vector<glm::dvec3> refined(countV);
        for (std::size_t j = 0; j < o.countU; ++j) {
            if (!(o.knotsU[j + p + 1] > from && o.knotsU[j] < to)) continue;
            const std::size_t c0 = detail::osloRow(degreeU, knotsU, countU, o.knotsU, j, row.data()) - p;
            for (std::size_t k = 0; k < countV; ++k) {
                glm::dvec3 c(0.0);
                for (std::size_t a = 0; a <= p; ++a) c += row[a] * points[(c0 + a) * countV + k];
                refined[k] = c;
            }
            for (std::size_t k = 0; k < o.countV; ++k) {
                glm::dvec3 c(0.0);
                for (std::size_t b = 0; b <= q; ++b) c += rowsV[k * (q + 1) + b] * refined[firstV[k] + b];
                if (glm::length(c - o.points[j * o.countV + k]) > tolerance) return false;
            }
        }
        return true;
    }

    // True when |S(u, v) - S'(u, v)| <= tolerance at every grid vertex with u in [from, to].
    bool within(int degreeU, const std::vector<double>& knotsU, const std::vector<glm::dvec3>& points,
                std::size_t countV, double from, double to, double tolerance) const {
        if (coefficientsWithin(degreeU, knotsU, points, countV, from, to, tolerance)) return true;
        return everyVertex<glm::dvec3>(
            degreeU, knotsU, points.size() / countV, countV, from, to,
            [&](std::size_t row, std::size_t j) { return points[row * countV + j]; },
            [&](std::size_t at, const glm::dvec3& s) { return glm::length(s - values[at]) <= tolerance; });
    }

    // within() for a rational surface in homogeneous form: points[i * 2 countV + 2 j] = w P and
    // points[i * 2 countV + 2 j + 1] = (w, 0, 0); the weight must stay positive at every vertex.
    bool withinRational(int degreeU, const std::vector<double>& knotsU, const std::vector<glm::dvec3>& points,
                        std::size_t countV, double from, double to, double tolerance) const {
        return everyVertex<glm::dvec4>(
            degreeU, knotsU, points.size() / (2 * countV), countV, from, to,
            [&](std::size_t row, std::size_t j) {
                const std::size_t at = (row * countV + j) * 2;
                return glm::dvec4(points[at], points[at + 1].x);
            },
            [&](std::size_t at, const glm::dvec4& h) {
                return h.w > 0.0 && glm::length(glm::dvec3(h) / h.w - values[at]) <= tolerance;
            });
    }

    // Whether check(vertex index, S'(u, v)) holds at every grid vertex with u in [from, to], the
    // reduced spline's coefficient (row, j) being coefficient(row, j), of type T.
    template <class T, class Coefficient, class Check>
    bool everyVertex(int degreeU, const std::vector<double>& knotsU, std::size_t countU, std::size_t countV,
                     double from, double to, Coefficient&& coefficient, Check&& check) const {
        const std::size_t p = static_cast<std::size_t>(degreeU);
        const std::size_t wv = static_cast<std::size_t>(degreeV) + 1;
        std::vector<double> nu(p + 1);
        std::vector<T> column(countV);
        const auto first = std::lower_bound(gridU.begin(), gridU.end(), from);
        const auto last = std::upper_bound(gridU.begin(), gridU.end(), to);
        for (auto it = first; it != last; ++it) {
            const std::size_t i = static_cast<std::size_t>(it - gridU.begin());
            const std::size_t span = findSpan(degreeU, knotsU, countU, *it);
            basisFunctions(span, *it, degreeU, knotsU, nu);
            for (std::size_t j = 0; j < countV; ++j) {
                T c(0.0);
                for (std::size_t k = 0; k <= p; ++k) c += nu[k] * coefficient(span - p + k, j);
                column[j] = c;
            }
            for (std::size_t k = 0; k < gridV.size(); ++k) {
                T sv(0.0);
                const std::size_t base = spanV[k] - static_cast<std::size_t>(degreeV);
                for (std::size_t l = 0; l < wv; ++l) sv += basisV[k * wv + l] * column[base + l];
                if (!check(i * gridV.size() + k, sv)) return false;
            }
        }
        return true;
    }
};

// A rational spline's frame for the removal loop: centred on its control box and with its
// largest weight 1 (neither changes the curve or surface), its homogeneous coefficients' removal
// weights are on the scale of the Euclidean error, which the ranking's weight cutoff compares
// with the tolerance.
struct RationalFrame {
    glm::dvec3 centre{0.0};
    double largest = 1.0;
};

RationalFrame rationalFrame(const std::vector<glm::dvec3>& points, const std::vector<double>& weights) {
    BoundingBox box;
    for (const glm::dvec3& q : points) box.add(q);
    return {box.center(), *std::max_element(weights.begin(), weights.end())};
}

// The sequences a rational spline's removal loop runs on: w P and (w, 0, 0) for each point.
std::vector<glm::dvec3> homogeneousPairs(const std::vector<glm::dvec3>& points,
                                         const std::vector<double>& weights) {
    std::vector<glm::dvec3> pairs(2 * points.size());
    for (std::size_t k = 0; k < points.size(); ++k) {
        pairs[2 * k] = weights[k] * points[k];
        pairs[2 * k + 1] = glm::dvec3(weights[k], 0.0, 0.0);
    }
    return pairs;
}

// Back from homogeneousPairs: the weights, and the points moved by `offset`.
void fromHomogeneousPairs(const std::vector<glm::dvec3>& pairs, const glm::dvec3& offset,
                          std::vector<glm::dvec3>& points, std::vector<double>& weights) {
    const std::size_t count = pairs.size() / 2;
    points.resize(count);
    weights.resize(count);
    for (std::size_t k = 0; k < count; ++k) {
        weights[k] = pairs[2 * k + 1].x;
        points[k] = pairs[2 * k] / weights[k] + offset;
    }
}

// One pass along u of a rational `current`: the loop on the homogeneous rows (w P and (w, 0, 0)
// per column, sharing the knots), a removal kept only where every weight it changed stays
// positive and the Euclidean surface keeps the tolerance on the grid.
std::size_t reduceRationalSurfaceAlongU(Surface& current, SurfaceGrid& grid, const ReductionOptions& o,
                                        double acceptance, std::size_t& fits) {
    const std::size_t nv = current.countV;
    Spline s{current.degreeU, current.knotsU, homogeneousPairs(current.points, current.weights), 2 * nv};
    grid.prepareAcross(current);
    const bool measuring = std::isfinite(o.tolerance);
    const std::size_t removed = reduceLoop(
        s, o, fits,
        [&](const LeastSquaresRemoval& fit) {
            for (std::size_t i = fit.firstChanged; i <= fit.lastChanged; ++i)
                for (std::size_t j = 0; j < nv; ++j)
                    if (!(fit.points[i * 2 * nv + 2 * j + 1].x > 0.0)) return false;
            return !measuring || grid.withinRational(s.degree, fit.knots, fit.points, nv, fit.changedFrom,
                                                     fit.changedTo, acceptance);
        },
        [](double, double) { return 0.0; });
    current.knotsU = std::move(s.knots);
    current.countU = s.points.size() / (2 * nv);
    fromHomogeneousPairs(s.points, glm::dvec3(0.0), current.points, current.weights);
    return removed;
}

// One pass along u of `current` (the original seen in the same orientation is `grid`).
std::size_t reduceSurfaceAlongU(Surface& current, SurfaceGrid& grid, const ReductionOptions& o,
                                double acceptance, std::size_t& fits) {
    if (current.rational()) return reduceRationalSurfaceAlongU(current, grid, o, acceptance, fits);
    Spline s{current.degreeU, current.knotsU, current.points, current.countV};
    grid.prepareAcross(current);
    const bool measuring = std::isfinite(o.tolerance);
    const std::size_t removed = reduceLoop(
        s, o, fits,
        [&](const LeastSquaresRemoval& fit) {
            return !measuring || grid.within(s.degree, fit.knots, fit.points, s.sequences, fit.changedFrom,
                                             fit.changedTo, acceptance);
        },
        [](double, double) { return 0.0; });
    current.knotsU = std::move(s.knots);
    current.points = std::move(s.points);
    current.countU = current.points.size() / current.countV;
    return removed;
}

// Tolerance-driven reduction of a curve in batches (the default): each pass ranks the knots,
// removes a whole set of low-weight, non-adjacent ones at once, refits every free coefficient to
// the original by one banded least-squares solve, and measures the result on the loop samples.
// A batch that fails puts back the knots next to the samples that broke the tolerance and is
// tried again; a single knot that fails is blocked until the next round. Accepted states go to
// history for the final measurement's step back.
// A batch takes the knots whose score (weight plus the error already there) is within
// batchShare of the tolerance, no two closer than batchSeparation knot indices (so that their
// errors hardly add up); a knot above it is tried alone. Measured on the reference curves: these
// values gave the fewest fits for about the same control point counts as 0.05-0.5 and 1-3.
constexpr double batchShare = 1.0;
constexpr std::size_t batchSeparation = 3;

class BatchReducer {
public:
    BatchReducer(const Curve& curve, const ReductionOptions& o, double tol)
        : p_(static_cast<std::size_t>(curve.degree)),
          degree_(curve.degree),
          t0_(curve.knots),
          d0_(curve.points),
          o_(o),
          tol_(tol),
          fixedEnd_(static_cast<std::size_t>(o.ends.fixedDerivatives) + 1),
          keep_(static_cast<std::size_t>(o.ends.fixedDerivatives)) {
        params_ = spanSamples(t0_, degree_, d0_.size(), o.samplesPerSpan);
        samples_.resize(params_.size());
        detail::evaluateAscending(degree_, t0_, d0_.data(), d0_.size(), params_, samples_.data());
        scale_.resize(d0_.size());
        for (std::size_t j = 0; j < d0_.size(); ++j)
            scale_[j] = (t0_[j + p_ + 1] - t0_[j]) / static_cast<double>(p_ + 1);
        error_.assign(params_.size(), 0.0);
        trialError_.resize(params_.size());
        values_.resize(params_.size());
        emphasis_.assign(d0_.size(), 1.0);
    }

    std::size_t run(std::vector<double>& knots, std::vector<glm::dvec3>& points, std::size_t& fits,
                    AcceptedStates& history) {
        std::size_t removed = 0;
        for (int round = 0; round < o_.rounds; ++round) {
            const std::size_t before = removed;
            blocked_.clear();
            while (removed < o_.maxRemovals) {
                std::vector<Candidate> batch = chooseBatch(knots, points, o_.maxRemovals - removed);
                if (batch.empty()) break;
                while (!batch.empty()) {
                    std::vector<double> tau;
                    std::vector<glm::dvec3> c;
                    ++fits;
                    const bool fitted = removeAndFit(knots, batch, tau, c);
                    std::vector<double> failures;
                    if (fitted && measure(tau, c, failures)) {
                        history.keep(Spline{degree_, knots, points, 1});
                        knots = std::move(tau);
                        points = std::move(c);
                        error_.swap(trialError_);
                        removed += batch.size();
                        break;
                    }
                    if (batch.size() == 1) {
                        blocked_.push_back(batch.front().value);
                        break;
                    }
                    putBack(batch, failures);
                }
            }
            if (removed == before && round > 0) break;
            if (!equalize(knots, points, fits, history) && removed == before) break;
        }
        return removed;
    }

private:
    // Lawson's iteration towards the best max-norm fit: the least-squares weights of the original
    // coefficients grow where the error is large, which evens the error out and leaves room for
    // more removals. Each reweighted fit is kept only if it keeps the tolerance.
    bool equalize(const std::vector<double>& knots, std::vector<glm::dvec3>& points, std::size_t& fits,
                  AcceptedStates& history) {
        bool changed = false;
        for (int step = 0; step < o_.lawsonSteps; ++step) {
            std::vector<double> local(d0_.size(), 0.0);
            double worst = 0.0;
            for (std::size_t j = 0, i = 0; j < d0_.size(); ++j) {
                while (i < params_.size() && params_[i] < t0_[j]) ++i;
                for (std::size_t k = i; k < params_.size() && params_[k] <= t0_[j + p_ + 1]; ++k)
                    local[j] = std::max(local[j], error_[k]);
                worst = std::max(worst, local[j]);
            }
            if (!(worst > 0.0)) break;
            const std::vector<double> saved = emphasis_;
            for (std::size_t j = 0; j < d0_.size(); ++j) emphasis_[j] *= std::max(local[j] / worst, 1e-3);
            std::vector<glm::dvec3> c;
            std::vector<double> failures;
            ++fits;
            if (!fitToOriginal(knots, c) || !measure(knots, c, failures)) {
                emphasis_ = saved;
                break;
            }
            history.keep(Spline{degree_, knots, points, 1});
            points = std::move(c);
            error_.swap(trialError_);
            changed = true;
        }
        return changed;
    }

    struct Candidate {
        std::size_t index;  // last occurrence in the current knots
        double value;
        double score;     // weight plus the error already spent near the knot
        double from, to;  // where removing it changes the curve
    };

    std::vector<Candidate> chooseBatch(const std::vector<double>& knots,
                                       const std::vector<glm::dvec3>& points, std::size_t most) const {
        const std::size_t count = points.size();
        std::vector<Candidate> ranked;
        for (const KnotSignificance& k : rankKnots(degree_, knots, points, 1)) {
            if (std::find(blocked_.begin(), blocked_.end(), k.value) != blocked_.end()) continue;
            if (k.index <= p_ + keep_ || k.index + keep_ >= count) continue;  // end conditions
            Candidate c{k.index, k.value, k.weight, knots[k.index - p_ - 1],
                        knots[std::min(knots.size() - 1, k.index + p_ + 1)]};
            c.score += presentError(c.from, c.to);
            if (o_.weightCutoff > 0.0 && c.score > o_.weightCutoff * tol_) continue;
            ranked.push_back(c);
        }
        std::stable_sort(ranked.begin(), ranked.end(),
                         [](const Candidate& a, const Candidate& b) { return a.score < b.score; });
        std::vector<Candidate> batch;
        std::vector<bool> taken(knots.size() + 1, false);
        for (const Candidate& c : ranked) {
            if (batch.size() >= most) break;
            if (!batch.empty() && c.score > batchShare * tol_) break;
            bool near = false;
            for (std::size_t d = 0; d <= batchSeparation; ++d)
                near = near || taken[std::min(c.index + d, knots.size())] || taken[c.index - d];
            if (near) continue;
            taken[c.index] = true;
            batch.push_back(c);
            if (c.score > batchShare * tol_) break;
        }
        return batch;
    }

    double presentError(double from, double to) const {
        const auto a = std::lower_bound(params_.begin(), params_.end(), from);
        const auto b = std::upper_bound(params_.begin(), params_.end(), to);
        double worst = 0.0;
        for (auto it = a; it < b; ++it)
            worst = std::max(worst, error_[static_cast<std::size_t>(it - params_.begin())]);
        return worst;
    }

    // The current knots without the batch, and the best fit to the original on them.
    bool removeAndFit(const std::vector<double>& knots, const std::vector<Candidate>& batch,
                      std::vector<double>& tau, std::vector<glm::dvec3>& c) const {
        std::vector<std::size_t> gone;
        for (const Candidate& k : batch) gone.push_back(k.index);
        std::sort(gone.begin(), gone.end());
        tau.reserve(knots.size() - gone.size());
        for (std::size_t i = 0, g = 0; i < knots.size(); ++i) {
            if (g < gone.size() && gone[g] == i) {
                ++g;
                continue;
            }
            tau.push_back(knots[i]);
        }
        return fitToOriginal(tau, c);
    }

    // Least squares in Lyche and Morken's scaled discrete l2 norm against the original's
    // coefficients (the original is the fit with the missing knots inserted): one row of the
    // insertion matrix per original coefficient (Oslo), banded normal equations, Cholesky.
    bool fitToOriginal(const std::vector<double>& tau, std::vector<glm::dvec3>& c) const {
        const std::size_t nt = tau.size() - p_ - 1, n0 = d0_.size();
        if (nt < 2 * fixedEnd_ + 1) return false;
        c.assign(nt, glm::dvec3(0.0));
        for (std::size_t i = 0; i < fixedEnd_; ++i) {
            c[i] = d0_[i];
            c[nt - 1 - i] = d0_[n0 - 1 - i];
        }
        const std::size_t nf = nt - 2 * fixedEnd_, wb = p_ + 1;
        std::vector<double> band(nf * wb, 0.0);
        std::vector<glm::dvec3> rhs(nf, glm::dvec3(0.0));
        std::vector<double> row(p_ + 1);
        for (std::size_t j = 0; j < n0; ++j) {
            const double w = scale_[j] * emphasis_[j];
            if (w == 0.0) continue;
            const std::size_t c0 = detail::osloRow(degree_, tau, nt, t0_, j, row.data()) - p_;
            glm::dvec3 target = d0_[j];
            for (std::size_t k = 0; k <= p_; ++k) {
                const std::size_t col = c0 + k;
                if (col < fixedEnd_ || col + fixedEnd_ >= nt) target -= row[k] * c[col];
            }
            for (std::size_t a = 0; a <= p_; ++a) {
                const std::size_t ca = c0 + a;
                if (ca < fixedEnd_ || ca + fixedEnd_ >= nt || row[a] == 0.0) continue;
                const std::size_t fa = ca - fixedEnd_;
                rhs[fa] += (w * row[a]) * target;
                for (std::size_t b = a; b <= p_; ++b) {
                    const std::size_t cb = c0 + b;
                    if (cb + fixedEnd_ >= nt) break;
                    band[fa * wb + (b - a)] += w * row[a] * row[b];
                }
            }
        }
        if (!detail::solveBanded(band, nf, p_, rhs)) return false;
        for (std::size_t i = 0; i < nf; ++i) c[fixedEnd_ + i] = rhs[i];
        return true;
    }

    // True when every loop sample is within the tolerance of the candidate, both ways: the
    // parametric distance |f(t) - g(t)| bounds both one-sided distances at the sample; where it
    // is too large, Newton from t on each curve measures them. Otherwise the parameters of the
    // samples that break the tolerance go to failures.
    bool measure(const std::vector<double>& tau, const std::vector<glm::dvec3>& c,
                 std::vector<double>& failures) {
        detail::SplineSampler candidate(degree_, tau, c.data(), c.size()),
            original(degree_, t0_, d0_.data(), d0_.size());
        for (std::size_t i = 0; i < params_.size(); ++i) values_[i] = candidate.value(params_[i]);
        bool ok = true;
        for (std::size_t i = 0; i < params_.size(); ++i) {
            const double parametric = glm::length(values_[i] - samples_[i]);
            trialError_[i] = parametric;
            if (parametric <= tol_) continue;
            if (ok) {
                const double there = detail::newtonDistance(candidate, samples_[i], params_[i], parametric);
                const double back =
                    there > tol_ ? there
                                 : detail::newtonDistance(original, values_[i], params_[i], parametric);
                trialError_[i] = std::max(there, back);
                if (trialError_[i] <= tol_) continue;
                ok = false;
            }
            failures.push_back(params_[i]);
        }
        return ok;
    }

    // Keeps the knots of the batch that no failing sample lies next to; when every knot is next
    // to one, keeps the better-ranked half.
    static void putBack(std::vector<Candidate>& batch, const std::vector<double>& failures) {
        std::vector<Candidate> kept;
        for (const Candidate& k : batch) {
            const auto it = std::lower_bound(failures.begin(), failures.end(), k.from);
            if (it == failures.end() || *it > k.to) kept.push_back(k);
        }
        if (kept.empty() || kept.size() == batch.size()) {
            batch.resize(batch.size() / 2);
            return;
        }
        batch = std::move(kept);
    }

    std::size_t p_;
    int degree_;
    const std::vector<double>& t0_;
    const std::vector<glm::dvec3>& d0_;
    const ReductionOptions& o_;
    double tol_;
    std::size_t fixedEnd_, keep_;
    std::vector<double> params_, scale_, emphasis_, error_, trialError_, blocked_;
    std::vector<glm::dvec3> samples_, values_;
};

// Removes, by The NURBS Book's A5.8, every knot that can go while the curve moves by at most
// `tolerance` each time (knots inserted into a simpler curve), outside the knots the end
// conditions keep and up to `most` of them, in rank order, ranking again at most `passes` times
// (the first ranking, of the curve given, goes to firstRanking).
Curve removeKnotsInRankOrder(const Curve& curve, const EndConditions& ends, double tolerance,
                             std::size_t most, int passes, std::vector<KnotSignificance>* firstRanking) {
    Curve c = curve;
    const std::size_t p = static_cast<std::size_t>(c.degree),
                      k = static_cast<std::size_t>(ends.fixedDerivatives);
    std::size_t removed = 0;
    for (bool again = true; again && removed < most && passes-- > 0;) {
        again = false;
        const std::vector<KnotSignificance> ranking = rankKnots(c);
        if (firstRanking && firstRanking->empty()) *firstRanking = ranking;
        for (const KnotSignificance& s : ranking) {
            if (s.weight > tolerance || removed >= most) break;
            const std::size_t first = s.index + 1 - static_cast<std::size_t>(s.multiplicity);
            if (first <= p + k || s.index + k >= c.points.size()) continue;
            ExactKnotRemoval r = removeKnot(c, s.value, 1, tolerance);
            if (r.removed == 0) continue;
            c = std::move(r.curve);
            ++removed;
            again = true;
        }
    }
    return c;
}

/// The number of nonempty spans of c (at least one).
std::size_t spanCount(const Curve& c) {
    std::size_t spans = 0;
    for (std::size_t j = static_cast<std::size_t>(c.degree); j < c.points.size(); ++j)
        spans += c.knots[j + 1] > c.knots[j] ? 1 : 0;
    return std::max<std::size_t>(spans, 1);
}

/// The exact removals (within a rounding-sized tolerance) in rank order, kept where the
/// measurement confirms them; ranked gets the original's knots by weight.
CurveReduction exactRemovals(const Curve& curve, const ReductionOptions& o,
                             std::vector<KnotSignificance>& ranked) {
    const std::size_t n0 = curve.points.size();
    double size = 0.0;
    for (const glm::dvec3& q : curve.points) size = std::max(size, glm::length(q));
    CurveReduction out;
    out.curve = removeKnotsInRankOrder(curve, o.ends, std::max(1e-6 * o.tolerance, 1e-13 * size),
                                       o.maxRemovals, std::numeric_limits<int>::max(), &ranked);
    if (out.curve.points.size() < n0) {
        out.deviation = measureDeviation(curve, out.curve, measureDensity(2 * o.samplesPerSpan));
        if (out.deviation.maxError > o.tolerance) out.curve = curve;
    }
    if (out.curve.points.size() == n0) out.deviation = CurveDeviation{};  // the original: no error
    return out;
}

/// True where some interior knot of the spline (degree, knots, points) has a removal weight within
/// limit: the first one found ends the search (no ranking, no sort).
bool someKnotWithin(int degree, const std::vector<double>& knots, const std::vector<glm::dvec3>& points,
                    double limit) {
    const std::size_t p = static_cast<std::size_t>(degree), count = points.size();
    for (std::size_t i = p + 1; i < count; ++i) {
        if (knots[i] == knots[i + 1] || !(knots[i] > knots[p]) || !(knots[i] < knots[count])) continue;
        if (knotRemovalWeight(degree, knots, points, 1, i) <= limit) return true;
    }
    return false;
}

/// True where every knot left would move the curve by more than weightCutoff times the tolerance
/// (the cutoff the removal loop trusts): no fit with fewer points keeps it either, and the search
/// would only confirm that, probe by probe.
bool everyKnotPastCutoff(const Curve& original, const Curve& left, const ReductionOptions& o,
                         const std::vector<KnotSignificance>& ranked) {
    const double limit = o.weightCutoff * o.tolerance;
    if (left.points.size() != original.points.size())
        return !someKnotWithin(left.degree, left.knots, left.points, limit);
    double smallest = std::numeric_limits<double>::infinity();
    for (const KnotSignificance& s : ranked) smallest = std::min(smallest, s.weight);
    return smallest > limit;
}

/// The smallest control point count the end conditions and maxRemovals allow.
std::size_t lowestCount(const ReductionOptions& o, std::size_t n0, std::size_t p) {
    const std::size_t k = static_cast<std::size_t>(o.ends.fixedDerivatives);
    std::size_t lowest = std::max({p + 1, 2 * (k + 1), p + 1 + 2 * k});
    if (o.maxRemovals < n0) lowest = std::max(lowest, n0 - o.maxRemovals);
    return lowest;
}

/// The knot vector with n control points whose interior knots are the original's most
/// significant ones (byWeight: heaviest first), with their multiplicities.
std::vector<double> significantKnots(const Curve& curve, const std::vector<KnotSignificance>& byWeight,
                                     std::size_t k, std::size_t n) {
    const std::size_t n0 = curve.points.size(), p = static_cast<std::size_t>(curve.degree);
    const double lo = curve.knots[p + k], hi = curve.knots[n0 - k];
    std::vector<double> knots(curve.knots.begin(),
                              curve.knots.begin() + static_cast<std::ptrdiff_t>(p + 1 + k));
    std::vector<double> chosen;
    const std::size_t want = n - p - 1 - 2 * k;
    for (const KnotSignificance& r : byWeight) {
        if (!(r.value > lo && r.value < hi)) continue;
        for (int m = 0; m < r.multiplicity && chosen.size() < want; ++m) chosen.push_back(r.value);
        if (chosen.size() == want) break;
    }
    std::sort(chosen.begin(), chosen.end());
    knots.insert(knots.end(), chosen.begin(), chosen.end());
    knots.insert(knots.end(), curve.knots.end() - static_cast<std::ptrdiff_t>(p + 1 + k), curve.knots.end());
    return knots;
}

/// The original's loop samples (spanSamples at samplesPerSpan) and its points there, made once
/// when first needed and shared by the significant-knot check and the removal loop.
class OriginalSamples {
public:
    OriginalSamples(const Curve& curve, int samplesPerSpan)
        : curve_(curve), samplesPerSpan_(samplesPerSpan) {}

    const std::vector<double>& params() {
        if (!paramsMade_)
            detail::spanSamplesInto(params_, curve_.knots, curve_.degree, curve_.points.size(),
                                    samplesPerSpan_);
        paramsMade_ = true;
        return params_;
    }
    const std::vector<glm::dvec3>& values() { return valuesBefore(params().size()); }
    int samplesPerSpan() const { return samplesPerSpan_; }
    /// The values, made up to sample `end` at least (a caller that may stop early makes no more).
    const std::vector<glm::dvec3>& valuesBefore(std::size_t end) {
        const std::vector<double>& at = params();
        end = std::min(end, at.size());
        if (valuesMade_ < end) {
            values_.resize(at.size());
            detail::evaluateAscending(curve_.degree, curve_.knots, curve_.points.data(), curve_.points.size(),
                                      std::span(at).subspan(valuesMade_, end - valuesMade_),
                                      values_.data() + valuesMade_, &forms());
            valuesMade_ = end;
        }
        return values_;
    }
    /// The original's span power forms (detail::powerForms), made when first needed: the samples
    /// are evaluated from them, and a free-knot fitter shares them.
    const std::vector<glm::dvec3>& forms() {
        if (!formsMade_)
            detail::powerFormsInto(forms_, curve_.degree, curve_.knots, curve_.points.data(),
                                   curve_.points.size());
        formsMade_ = true;
        return forms_;
    }

private:
    const Curve& curve_;
    int samplesPerSpan_;
    bool paramsMade_ = false, formsMade_ = false;
    std::size_t valuesMade_ = 0;  // values_[0, valuesMade_) are made
    detail::KeptVector<double> params_;
    detail::KeptVector<glm::dvec3> values_, forms_;
};

/// True where the least-squares fit to the coefficients on `knots` (LinearFit: one banded solve)
/// keeps the pass by the coefficient bound (a bound on the whole curve), or else by its distance
/// from the original at every loop sample. The samples go in blocks: a fit that fails usually
/// fails in the first, and the rest are not evaluated.
bool linearFitPasses(const Curve& curve, const ReductionOptions& o, const std::vector<double>& knots,
                     OriginalSamples& samples) {
    std::vector<glm::dvec3> coefficients;
    LinearFit linearFit(curve);
    if (!linearFit.fitOnly(knots, coefficients)) return false;
    if (linearFit.bounded(coefficients, 0.99 * o.tolerance)) return true;
    constexpr std::size_t kBlock = 64;
    const std::vector<double>& at = samples.params();
    std::vector<glm::dvec3> b(std::min(kBlock, at.size()));
    const double pass2 = 0.99 * 0.99 * o.tolerance * o.tolerance;
    for (std::size_t start = 0; start < at.size(); start += kBlock) {
        const std::size_t end = std::min(at.size(), start + kBlock);
        const std::vector<glm::dvec3>& a = samples.valuesBefore(end);
        detail::evaluateAscending(curve.degree, knots, coefficients.data(), coefficients.size(),
                                  std::span(at).subspan(start, end - start), b.data());
        for (std::size_t i = start; i < end; ++i)
            if (!(glm::dot(a[i] - b[i - start], a[i] - b[i - start]) <= pass2)) return false;
    }
    return true;
}

/// A probe expected to pass so easily that the model has the count two below it pass too stops
/// early (FreeKnotFit::overshot): it will not be the one the search ends on. That needs the count
/// two below to be still open (above the largest failure, fail); 0 means no such stop.
double overshootBelow(const ReductionOptions& o, std::size_t p, std::size_t n, std::size_t fail) {
    if (n < p + 3 || n - 2 <= fail) return 0.0;
    return 0.97 * o.tolerance * std::pow(double(n - 2 - p) / double(n - p), double(p + 1));
}

/// The error model's first count, from the density integral (with the constant measured on the
/// reference curves) before any fit, within [lowest, ceiling - 1].
std::size_t modelFirstCount(const ReductionOptions& o, std::size_t p, const FreeKnotFitter& fitter,
                            std::size_t lowest, std::size_t ceiling) {
    const double want = double(p) + std::pow(1e-3 / (0.97 * o.tolerance), 1.0 / double(p + 1)) *
                                        std::pow(fitter.predictedError(p + 1), 1.0 / double(p + 1));
    const double n = std::isfinite(want) ? std::ceil(want) : double(ceiling - 1);
    return static_cast<std::size_t>(std::clamp(n, double(lowest), double(ceiling - 1)));
}

/// The free-knot fitter's options for a reduction with options o.
FreeKnotOptions freeKnotOptions(const ReductionOptions& o) {
    FreeKnotOptions fo;
    fo.iterations = o.freeKnotIterations;
    fo.warmIterations = std::max(1, o.freeKnotIterations / 2);
    fo.ends = o.ends;
    return fo;
}

/// True where the error model, calibrated on the first moved fit (at count first), has the
/// largest count left to search (one below the ceiling, the loop's) miss the tolerance twice
/// over: every probe below it would give up (on refined degree-1 curves the moved knots miss by
/// 100 to 1000 times at the first count, which the model puts near the original's).
bool searchIsFutile(const FreeKnotFit& moved, std::size_t p, std::size_t first, std::size_t ceiling,
                    double tolerance) {
    const double reached = moved.gaveUp || moved.overshot ? moved.expectedError : moved.sampleError;
    return ceiling > first + 1 && std::isfinite(reached) &&
           reached * std::pow(double(first - p) / double(ceiling - 1 - p), double(p + 1)) > 2.0 * tolerance;
}

/// One search over the control point count: the error model E(n) = C (n - p)^-(p+1) guesses the
/// next count, C from the density integral before any fit, then from the last fit (a secant
/// through the last two follows their noise: the fits are not monotone in n); the bracket lies
/// between the smallest count that passed and the largest that failed (or that the model,
/// calibrated on the pass above it, rules out). A count passes when its sample error is within
/// 0.99 of the tolerance and, for the one the search ends on, the meter (the final check) finds
/// the Hausdorff distance within it. A probe that cannot come within 1.2 times the pass gives up
/// early (FreeKnotFit::gaveUp).
class CountSearch {
public:
    /// Counts from `ceiling` up are left to the removal loop; a result found goes to out.
    CountSearch(const Curve& curve, const ReductionOptions& o, const FreeKnotFitter& fitter,
                OriginalSamples& samples, std::size_t lowest, std::size_t ceiling, CurveReduction& out)
        : curve_(curve),
          o_(o),
          fitter_(fitter),
          samples_(samples),
          out_(out),
          p_(static_cast<std::size_t>(curve.degree)),
          lowest_(lowest),
          none_(ceiling),
          measureDensity_(2 * finalCheckDensity(o)),
          target_(std::log(0.97 * o.tolerance)),
          giveUp_(1.2 * 0.99 * o.tolerance),
          passAt_(0.95 * o.tolerance),
          pass_(none_),
          fail_(lowest - 1),
          logC_(std::log(1e-3 * fitter.predictedError(p_ + 1))),
          passed_(none_ + 1),
          failed_(none_ + 1, false),
          overshot_(none_ + 1, false) {}

    /// Searches from count first, whose fit firstFit (if made) is used for its first probe.
    void run(std::size_t first, FreeKnotFit firstFit) {
        first_ = first;
        firstFit_ = std::move(firstFit);
        for (std::size_t n = first < pass_ ? first : next();;) {
            closeBracket(n);
            // The smallest count that passed on samples gets the final check (the meter); the
            // larger ones are measured only where it fails, so most searches measure once.
            if (pass_ == none_ || finalCheckPasses()) return;
            reopenBracket();
            n = next();
        }
    }

private:
    enum class Probe { passes, fails, overshoots };

    /// Probes from count n on until no count lies between the largest failure and the smallest pass.
    void closeBracket(std::size_t n) {
        for (; pass_ > fail_ + 1; n = next()) {
            const Probe result = probe(n);
            afterOvershoot_ = result == Probe::overshoots;
            if (afterOvershoot_) continue;
            const bool ok = result == Probe::passes;
            (ok ? pass_ : fail_) = n;
            failed_[n] = !ok;
            // The error model, calibrated on this fit, predicts the count below fails too:
            // it is not tried (a fit that beat the model by that much is rare).
            if (ok && n > p_ + 1 &&
                passed_[n]->sampleError * std::pow(double(n - p_) / double(n - 1 - p_), double(p_ + 1)) >
                    0.99 * o_.tolerance)
                fail_ = std::max(fail_, n - 1);
        }
    }

    /// One fit at count n, judged on samples; it calibrates the error model.
    Probe probe(std::size_t n) {
        FreeKnotFit f;
        if (n == first_ && !firstUsed_) {
            f = std::move(firstFit_);
            firstUsed_ = true;
        } else {
            ++out_.fits;
            // A probe just above the largest failure ends the search if it passes: it stops at its
            // first round within 0.95 of the tolerance (FreeKnotStops::passAt), the margin for the
            // meter (within 0.99 it missed the meter on the I-beam at 1e-4 and cost a point). A
            // count that overshot once is fitted in full if probed again.
            f = fitter_.fit(n, previousKnots_, true, 0,
                            FreeKnotStops{giveUp_, overshot_[n] ? 0.0 : overshootBelow(o_, p_, n, fail_),
                                          n == fail_ + 1 ? passAt_ : 0.0});
        }
        if (!f.curve.knots.empty()) previousKnots_ = f.curve.knots;
        // A fit that stopped early calibrates the model with the error it would have reached.
        const double reached = f.gaveUp || f.overshot ? f.expectedError : f.sampleError;
        if (std::isfinite(reached) && reached > 0.0)
            logC_ = std::log(reached) + double(p_ + 1) * std::log(double(n - p_));
        if (f.overshot) {
            overshot_[n] = true;
            return Probe::overshoots;
        }
        if (!(f.sampleError <= 0.99 * o_.tolerance)) return Probe::fails;
        passed_[n] = std::move(f);
        return Probe::passes;
    }

    /// The model's count rounded to the nearest (rounded up, it leaned a count high: I-beam at
    /// 1.2e-3 and 1e-4 and the airfoil at 1.2e-3 took a probe more), inside the bracket. The count
    /// after an overshoot is one above the model's: calibrated on an expected error (Lawson's
    /// gain, 0.8, taken from fits run in full), the model lands a count low there (I-beam at 1e-2
    /// to 1e-4: 20/32/33/55 points in 0.73-1.12 of the instructions).
    std::size_t next() const {
        const double want = double(p_) + std::exp((logC_ - target_) / double(p_ + 1));
        const double n =
            std::isfinite(want) ? std::round(want) + (afterOvershoot_ ? 1.0 : 0.0) : double(pass_ - 1);
        return static_cast<std::size_t>(std::clamp(n, double(fail_ + 1), double(pass_ - 1)));
    }

    /// The meter's Hausdorff check of the smallest count that passed; true (the result in out)
    /// where it keeps the tolerance.
    bool finalCheckPasses() {
        FreeKnotFit& f = *passed_[pass_];
        Curve candidate(f.curve.degree, f.curve.knots, f.curve.points);
        const CurveDeviation d = detail::MeterFromSamples::measure(meterFor(candidate), candidate, f.map,
                                                                   4 * measureDensity_, finalCheck(o_));
        if (!(d.maxError <= o_.tolerance)) return false;
        out_.curve = std::move(candidate);
        out_.deviation = o_.report ? d : CurveDeviation{};
        out_.freeKnotFit = true;
        return true;
    }

    /// The meter, made for the first candidate measured: the fit's few spans are sampled
    /// 4 * measureDensity times each (a fit may turn sharply between samples where the original
    /// does not), and the original as densely in parameter (at least twice per span, at most
    /// measureDensity times): many more original samples (an original of many spans reduced to
    /// few) would only repeat what the candidate's samples already pin down.
    CurveDeviationMeter& meterFor(const Curve& candidate) {
        if (!meter_) {
            const std::size_t wanted = 4 * static_cast<std::size_t>(measureDensity_) * spanCount(candidate);
            const std::size_t spans = spanCount(curve_);
            const int density = static_cast<int>(
                std::clamp<std::size_t>((wanted + spans - 1) / spans, 2, std::size_t(measureDensity_)));
            // The original's power forms, and at the loop's density its samples and points, are
            // the ones the reduction made already.
            const bool same = density == samples_.samplesPerSpan();
            meter_.emplace(detail::MeterFromSamples::make(curve_, density, samples_.forms(),
                                                          same ? &samples_.params() : nullptr,
                                                          same ? &samples_.values() : nullptr));
        }
        return *meter_;
    }

    /// The bracket after a failed final check: the next count that passed above, the largest
    /// failure below it.
    void reopenBracket() {
        passed_[pass_].reset();
        failed_[pass_] = true;
        while (pass_ < none_ && !passed_[pass_]) ++pass_;
        for (fail_ = pass_ - 1; fail_ >= lowest_ && !failed_[fail_];) --fail_;
    }

    const Curve& curve_;
    const ReductionOptions& o_;
    const FreeKnotFitter& fitter_;
    OriginalSamples& samples_;
    CurveReduction& out_;
    const std::size_t p_, lowest_, none_;  // none_: no fit at or above it is needed
    const int measureDensity_;
    const double target_, giveUp_, passAt_;
    std::size_t pass_, fail_;
    double logC_;
    std::vector<double> previousKnots_;               // the last fit's, whose knot density starts the next
    std::vector<std::optional<FreeKnotFit>> passed_;  // by count, on samples
    std::vector<bool> failed_, overshot_;
    std::size_t first_ = 0;
    FreeKnotFit firstFit_;
    bool firstUsed_ = false, afterOvershoot_ = false;
    std::optional<CurveDeviationMeter> meter_;
};

// Tolerance mode with free knots: the exact removals first, then a search over the control
// point count n (CountSearch). Each probe is a free-knot fit; the smallest count whose fit passes
// on samples must also pass measureDeviation (the final check itself). loopCurve() runs the
// removal loop (once) and gives its result before the final measurement: on a refined curve the
// search looks only below its count, and not at all where every knot it left is past the cutoff.
//
// The original's most significant knots (by removal weight), kept, fit a refined curve whose
// few knots that matter are where the p-th derivative jumps (equidistribution cannot hit
// those exactly); on a smooth curve they fit far worse than moved knots (on the reference
// curves 50 to 10^5 times the error after three rounds; two rounds, the best kept, can only
// be worse). Where they come within 45 times (on random refined test curves they do, from
// 0.01 to 10 times), the caller runs the removal loop too, which finds such knots. One round
// is too few: 2 of 72 refined test curves then kept more points than the loop. Where the moved
// knots come far below the tolerance (the first count overshoots), the comparison is with the
// tolerance instead: a refined degree-5 curve whose significant knots missed 3000 times the
// moved fit's error but only 17 times the tolerance kept 16 points by the search, 13 by the loop.
constexpr double kModelMissed = 1.5;
template <class LoopCurve>
CurveReduction reduceCurveByFreeKnots(const Curve& curve, const ReductionOptions& o, OriginalSamples& samples,
                                      LoopCurve&& loopCurve, bool& refined, bool& settled,
                                      std::vector<KnotSignificance>& originalRanking) {
    const std::size_t n0 = curve.points.size(), p = static_cast<std::size_t>(curve.degree);
    const std::size_t k = static_cast<std::size_t>(o.ends.fixedDerivatives);
    std::vector<KnotSignificance> ranked;  // the original's knots by weight
    CurveReduction out = exactRemovals(curve, o, ranked);
    originalRanking = ranked;  // for the linear stage's first pass
    // Measure before searching (see everyKnotPastCutoff).
    if (o.weightCutoff > 0.0 && everyKnotPastCutoff(curve, out.curve, o, ranked)) {
        out.removed = n0 - out.curve.points.size();
        settled = true;
        return out;
    }
    const std::size_t lowest = lowestCount(o, n0, p);
    refined = false;
    // Counts from `ceiling` up are left to the removal loop.
    std::size_t ceiling = out.curve.points.size();
    if (ceiling <= lowest) {
        out.removed = n0 - out.curve.points.size();
        return out;
    }
    const FreeKnotOptions fo = freeKnotOptions(o);
    FreeKnotFitter fitter(curve, fo);
    fitter.shareForms([&samples]() -> const std::vector<glm::dvec3>& { return samples.forms(); });
    std::stable_sort(ranked.begin(), ranked.end(), [](const KnotSignificance& x, const KnotSignificance& y) {
        return x.weight > y.weight;
    });
    const std::size_t first = modelFirstCount(o, p, fitter, lowest, ceiling);
    // The significant knots' linear fit first: where it passes, the sampled fit below (a free-knot
    // fit's rounds, whose pass is judged on samples too) is not needed.
    if (k == 0 && linearFitPasses(curve, o, significantKnots(curve, ranked, k, first), samples)) {
        refined = true;
        out.removed = n0 - out.curve.points.size();
        return out;
    }
    ++out.fits;
    // Half the samples do for the check (the same counts on the reference and test curves; a
    // third of them misjudge one of 72 refined curves).
    const double significantError = fitter
                                        .fit(first, significantKnots(curve, ranked, k, first), false, 2, {},
                                             std::max(1, fo.samplesPerFitSpan / 2))
                                        .sampleError;
    // Where the original's own most significant knots at the model's count already fit, the
    // curve is a refined one whose knots that matter are among its own: the removal loop finds
    // those, and the moved-knot fit and search (on the generated refined classes of degrees 2,
    // 3, 6, 7 and with corners they never beat the loop, at 1.5-4 times its cost) are not run.
    if (significantError <= 0.99 * o.tolerance) {
        refined = true;
        out.removed = n0 - out.curve.points.size();
        return out;
    }
    // Where the model's first count is the original's less one (it knows nothing of the curve)
    // and the significant-knot fit could not be made there (too few samples for its knots), the
    // check tells nothing: both run. Where the significant knots come within 45 times the
    // tolerance, the loop runs whatever the moved-knot fit gives (see above).
    refined =
        (!std::isfinite(significantError) && first + 1 >= ceiling) || significantError <= 45.0 * o.tolerance;
    // On a refined curve the removal loop runs too (from the linear stage's state) and runs
    // first: the search looks only below the count it reached, where on refined curves it
    // rarely has anything to find (probes above it were fits and measurements for nothing).
    // Where every knot the loop left weighs more than the cutoff, the search below it is not run
    // (see everyKnotPastCutoff): on refined curves the loop recovers the simpler curve's knots,
    // and a probe below them is a fit and a measurement that rarely finds anything. This trades
    // a rare point for time; the error bound is unchanged (geom/ALGORITHMS.md).
    auto belowLoop = [&] {
        const Curve& left = loopCurve();
        ceiling = std::min(ceiling, left.points.size());
        if (o.weightCutoff > 0.0 && everyKnotPastCutoff(curve, left, o, ranked)) ceiling = lowest;
    };
    if (refined) belowLoop();
    // A first fit at or above the ceiling is never probed (the search starts from the model):
    // it is made only below it.
    FreeKnotFit moved;
    if (first < ceiling) {
        ++out.fits;
        moved = fitter.fit(first, {}, true, 0,
                           FreeKnotStops{1.2 * 0.99 * o.tolerance, overshootBelow(o, p, first, lowest - 1)});
        // A moved-knot fit that misses by half the tolerance again at the model's count (on smooth
        // curves it comes within 0.6-1.25 of it there) says the model, made from the density of
        // the original, does not describe the curve: a densely refined one whose jitter inflates
        // the density, and whose knots that matter hide from the ranking among their many
        // neighbours (the significant-knot check above cannot see them). Such a curve goes to the
        // loop as well, which finds its knots by removing the inserted ones.
        refined = refined || significantError <= 45.0 * moved.sampleError ||
                  moved.sampleError > kModelMissed * o.tolerance;
        if (refined) belowLoop();
        // Measure before searching (see searchIsFutile).
        if (refined && searchIsFutile(moved, p, first, ceiling, o.tolerance)) ceiling = lowest;
    }
    if (ceiling > lowest)
        CountSearch(curve, o, fitter, samples, lowest, ceiling, out).run(first, std::move(moved));
    out.removed = n0 - out.curve.points.size();
    return out;
}

// The Euclidean bound of a rational removal. The reduced homogeneous spline (X' = w' P', w') is
// refined onto the original knots by Oslo rows; then C - C' = (dX - C dw) / w' at every t, where
// dX, dw are the refined differences. C(t) lies in the hull of the original points whose
// B-splines reach t, so with e_j = max |dX_j - P_i dw_j| over those points (i within p of j),
// |C - C'| <= max e_j / min w'_k over the coefficients j, k that reach t: a bound, not a sample.
class RationalBound {
public:
    explicit RationalBound(const Curve& original) : original_(original) {}

    /// True when the candidate keeps every weight positive and, if tolerance is finite, the
    /// bound within it wherever the spline changed.
    bool holds(const LeastSquaresRemoval& fit, double tolerance) const {
        const std::size_t p = static_cast<std::size_t>(original_.degree), n = original_.points.size();
        for (std::size_t i = fit.firstChanged; i <= fit.lastChanged; ++i)
            if (!(fit.points[2 * i + 1].x > 0.0)) return false;
        // Original coefficients that changed, p more each side whose neighbours changed, p more
        // for those neighbours' weights.
        std::size_t lo = n, hi = 0;
        for (std::size_t j = 0; j < n; ++j)
            if (original_.knots[j + p + 1] > fit.changedFrom && original_.knots[j] < fit.changedTo)
                lo = std::min(lo, j), hi = std::max(hi, j);
        if (lo > hi) return true;
        const std::size_t first = lo > 2 * p ? lo - 2 * p : 0, last = std::min(n - 1, hi + 2 * p);
        const std::size_t count = fit.points.size() / 2;
        std::vector<double> row(p + 1), refinedW(last - first + 1);
        std::vector<glm::dvec3> dX(last - first + 1);
        std::vector<double> dW(last - first + 1);
        for (std::size_t j = first; j <= last; ++j) {
            const std::size_t c0 =
                detail::osloRow(original_.degree, fit.knots, count, original_.knots, j, row.data()) - p;
            glm::dvec3 x(0.0);
            double w = 0.0;
            for (std::size_t a = 0; a <= p; ++a) {
                x += row[a] * fit.points[2 * (c0 + a)];
                w += row[a] * fit.points[2 * (c0 + a) + 1].x;
            }
            if (!(w > 0.0)) return false;
            refinedW[j - first] = w;
            dX[j - first] = original_.weights[j] * original_.points[j] - x;
            dW[j - first] = original_.weights[j] - w;
        }
        if (!std::isfinite(tolerance)) return true;
        const std::size_t checkFirst = lo > p ? lo - p : 0, checkLast = std::min(n - 1, hi + p);
        for (std::size_t j = checkFirst; j <= checkLast; ++j) {
            const std::size_t from = j > p ? j - p : 0, to = std::min(n - 1, j + p);
            double e = 0.0, wMin = std::numeric_limits<double>::infinity();
            for (std::size_t i = from; i <= to; ++i) {
                e = std::max(e, glm::length(dX[j - first] - original_.points[i] * dW[j - first]));
                if (i >= first && i <= last) wMin = std::min(wMin, refinedW[i - first]);
            }
            if (e > tolerance * wMin) return false;
        }
        return true;
    }

private:
    const Curve& original_;
};

// Rational curves: the removal loop on the homogeneous coefficient sequences X_i = w_i P_i and
// (w_i, 0, 0), sharing the knots, each removal kept only under RationalBound; measureDeviation
// (point inversion, Euclidean) checks the result and steps back should it ever disagree.
CurveReduction reduceRationalCurve(const Curve& curve, const ReductionOptions& options) {
    const std::size_t n = curve.points.size();
    const RationalFrame frame = rationalFrame(curve.points, curve.weights);
    const glm::dvec3 centre = frame.centre;
    Curve centred = curve;
    for (glm::dvec3& q : centred.points) q -= centre;
    for (double& w : centred.weights) w /= frame.largest;
    Spline s{curve.degree, curve.knots, homogeneousPairs(centred.points, centred.weights), 2};
    const RationalBound bound(centred);
    const bool measuring = std::isfinite(options.tolerance);
    auto toCurve = [&centre](const Spline& h) {
        std::vector<glm::dvec3> points;
        std::vector<double> weights;
        fromHomogeneousPairs(h.points, centre, points, weights);
        return Curve(h.degree, h.knots, std::move(points), std::move(weights));
    };
    CurveReduction out;
    AcceptedStates history;
    out.removed = reduceLoop(
        s, options, out.fits,
        [&](const LeastSquaresRemoval& fit) { return bound.holds(fit, options.tolerance); },
        [](double, double) { return 0.0; }, &history);
    out.curve = toCurve(s);
    if (measuring || options.report)
        out.deviation = measureDeviation(curve, out.curve, measureDensity(2 * finalCheckDensity(options)));
    while (measuring && out.deviation.maxError > options.tolerance) {
        ++out.steppedBack;
        const std::optional<Spline> previous = history.stepBack();
        out.curve = previous ? toCurve(*previous) : curve;
        out.removed = n - out.curve.points.size();
        out.deviation = measureDeviation(curve, out.curve, measureDensity(2 * finalCheckDensity(options)));
        if (!previous) break;
    }
    return out;
}

/// The removal loop's dense samples of the original and the current result's error at each.
/// witness[i] is the parameter of the point of the current reduced curve nearest to sample i (it
/// drifts from params[i] as knots go).
class LoopSamples {
public:
    /// original: the original's samples, or null for none (the loop then measures nothing).
    LoopSamples(const Curve& curve, int samplesPerSpan, double tol, OriginalSamples* original)
        : params_(original ? original->params() : noParams()),
          samples_(original ? original->values() : noValues()),
          witness_(params_),
          trial_(params_.size()),
          error_(params_.size(), 0.0),
          trialError_(params_.size()),
          blockError_(params_.size() / kErrorBlock + 1, 0.0),
          pad_(static_cast<std::size_t>(samplesPerSpan)),
          tol_(tol),
          originalSampler_(curve.degree, curve.knots, curve.points.data(), curve.points.size()) {}

    const std::vector<double>& params() const { return params_; }

    /// The loop's witnesses kept ascending: with params(), a parameter map onto the result.
    detail::KeptVector<double> ascendingWitnesses() const {
        detail::KeptVector<double> to(witness_);
        for (std::size_t i = 1; i < to.size(); ++i) to[i] = std::max(to[i], to[i - 1]);
        return to;
    }

    /// True where the fit keeps the tolerance at every sample near its change; then records it.
    bool accept(int degree, const LeastSquaresRemoval& fit) {
        // The candidate is read where the fit left it (no copy of its knots and points).
        const std::vector<double>& knots = fit.knots;
        const std::vector<glm::dvec3>& points = fit.points;
        // The curve changed on [changedFrom, changedTo]; a sample just outside may have its
        // nearest point inside, so one original span more is measured on each side.
        const std::size_t lo = static_cast<std::size_t>(
            std::lower_bound(params_.begin(), params_.end(), fit.changedFrom) - params_.begin());
        const std::size_t hi = static_cast<std::size_t>(
            std::upper_bound(params_.begin(), params_.end(), fit.changedTo) - params_.begin());
        const std::size_t first = lo > pad_ ? lo - pad_ : 0;
        const std::size_t last = std::min(params_.size(), hi + pad_);
        detail::SplineSampler candidate(degree, knots, points.data(), points.size());
        if ((lastFailed_ || failures_ > accepted_) &&
            !sparseSampleKeeps(degree, knots, points, candidate, first, last))
            return rejected();
        std::vector<glm::dvec3>& onCandidate = window_;
        onCandidate.resize(last - first);
        detail::evaluateAscending(degree, knots, points.data(), points.size(),
                                  std::span(params_).subspan(first, last - first), onCandidate.data());
        // The sample farthest from the candidate in parameter first: most candidates that fail,
        // fail there, before any other sample is inverted.
        const std::size_t farthest = first + farthestOf(onCandidate, first, 1);
        if (first < last && !sampleKeeps(candidate, onCandidate[farthest - first], farthest))
            return rejected();
        for (std::size_t i = first; i < last; ++i)
            if (i != farthest && !sampleKeeps(candidate, onCandidate[i - first], i)) return rejected();
        commitTrial(first, last);
        ++accepted_;
        lastFailed_ = false;
        return true;
    }

    /// The largest recorded error among the samples with parameters in [from, to].
    double presentError(double from, double to) const {
        std::size_t a = static_cast<std::size_t>(std::lower_bound(params_.begin(), params_.end(), from) -
                                                 params_.begin());
        const std::size_t b =
            static_cast<std::size_t>(std::upper_bound(params_.begin(), params_.end(), to) - params_.begin());
        double worst = 0.0;
        for (; a < b && a % kErrorBlock != 0; ++a) worst = std::max(worst, error_[a]);
        for (; a + kErrorBlock <= b; a += kErrorBlock) worst = std::max(worst, blockError_[a / kErrorBlock]);
        for (; a < b; ++a) worst = std::max(worst, error_[a]);
        return worst;
    }

private:
    /// The largest error of each block of kErrorBlock samples, for the ranking's many range maxima.
    static constexpr std::size_t kErrorBlock = 16;
    /// A candidate turned away, counted.
    bool rejected() {
        ++failures_;
        lastFailed_ = true;
        return false;
    }

    /// The sparse first check's stride over the window's samples.
    static constexpr std::size_t kSparseStride = 4;

    /// Every kSparseStride-th sample of [first, last) first: where the one of them farthest from
    /// the candidate in parameter fails, the candidate fails (the full check below tries every
    /// sample, that one too), and most candidates that fail are turned away at a quarter of the
    /// evaluations. The full check makes its own verdict and witnesses where this one passes, so
    /// the results are the same either way; accept runs it once more candidates have failed than
    /// passed (noisy data: three of four fail), or after a candidate that failed (the loop ranks
    /// the lightest knots first, so its failures come in runs once the easy ones are gone), not
    /// where most pass (higher degrees: most do, and it would cost them a quarter of the
    /// evaluations more).
    bool sparseSampleKeeps(int degree, const std::vector<double>& knots,
                           const std::vector<glm::dvec3>& points, detail::SplineSampler& candidate,
                           std::size_t first, std::size_t last) {
        if (last - first < 8 * kSparseStride) return true;
        sparseParams_.clear();
        for (std::size_t i = first; i < last; i += kSparseStride) sparseParams_.push_back(params_[i]);
        sparseValues_.resize(sparseParams_.size());
        detail::evaluateAscending(degree, knots, points.data(), points.size(), sparseParams_,
                                  sparseValues_.data());
        const std::size_t farthest = farthestOf(sparseValues_, first, kSparseStride);
        return sampleKeeps(candidate, sparseValues_[farthest], first + farthest * kSparseStride);
    }

    /// The k for which onCandidate[k], the candidate at sample first + k * stride, is farthest
    /// from that sample.
    std::size_t farthestOf(const std::vector<glm::dvec3>& onCandidate, std::size_t first,
                           std::size_t stride) const {
        std::size_t farthest = 0;
        double farthestDistance = -1.0;
        for (std::size_t k = 0; k < onCandidate.size(); ++k) {
            const glm::dvec3 d = onCandidate[k] - samples_[first + k * stride];
            const double e = glm::dot(d, d);
            if (e > farthestDistance) farthestDistance = e, farthest = k;
        }
        return farthest;
    }

    /// Newton from a known point: a distance to a real point of the candidate, so an upper bound
    /// of the closest one. The loop needs to know only that a sample is within the tolerance, so
    /// Newton stops there.
    CurvePoint newton(detail::SplineSampler& candidate, const glm::dvec3& target, double from) const {
        CurvePoint c;
        c.u = from;
        c.distance = detail::newtonDistance(candidate, target, from, std::numeric_limits<double>::infinity(),
                                            &c.u, tol_);
        return c;
    }

    /// One sample: true where it keeps the tolerance both ways (its witness and error go to the
    /// trial arrays).
    bool sampleKeeps(detail::SplineSampler& candidate, const glm::dvec3& q, std::size_t i) {
        // |f(u) - g(u)| bounds the distance both ways, so where it is small enough no
        // projection is needed.
        const double parametric = glm::length(q - samples_[i]);
        if (parametric <= tol_) {
            trial_[i] = witness_[i];
            trialError_[i] = parametric;
            return true;
        }
        // Original to reduced, by Newton from the witness (geom's projector, local mode).
        CurvePoint pr = newton(candidate, samples_[i], witness_[i]);
        if (pr.distance > tol_) {
            const CurvePoint again = newton(candidate, samples_[i], params_[i]);
            if (again.distance < pr.distance) pr = again;
        }
        if (pr.distance > tol_) return false;
        trial_[i] = pr.u;
        const double d = reducedToOriginal(q, i, parametric);
        if (d > tol_) return false;
        trialError_[i] = std::max(d, pr.distance);
        return true;
    }

    /// Reduced to original, seeded where the witnesses say g(params[i]) lies on the original.
    double reducedToOriginal(const glm::dvec3& q, std::size_t i, double parametric) {
        auto toOriginal = [&](double from) {
            return detail::newtonDistance(originalSampler_, q, from, parametric, nullptr, tol_);
        };
        double d = toOriginal(params_[i]);
        if (d > tol_) {
            const auto it = std::upper_bound(witness_.begin(), witness_.end(), params_[i]);
            const std::size_t k =
                static_cast<std::size_t>(std::max<std::ptrdiff_t>(it - witness_.begin(), 1)) - 1;
            d = std::min(d, toOriginal(params_[k]));
        }
        return d;
    }

    /// The trial witnesses and errors of [first, last) become the current ones.
    void commitTrial(std::size_t first, std::size_t last) {
        for (std::size_t i = first; i < last; ++i) witness_[i] = trial_[i], error_[i] = trialError_[i];
        for (std::size_t k = first / kErrorBlock; k * kErrorBlock < last; ++k) {
            blockError_[k] = 0.0;
            for (std::size_t i = k * kErrorBlock; i < std::min(params_.size(), (k + 1) * kErrorBlock); ++i)
                blockError_[k] = std::max(blockError_[k], error_[i]);
        }
    }

    static const std::vector<double>& noParams() {
        static const std::vector<double> none;
        return none;
    }
    static const std::vector<glm::dvec3>& noValues() {
        static const std::vector<glm::dvec3> none;
        return none;
    }

    const std::vector<double>& params_;  // the original's (OriginalSamples, which outlives the loop)
    const std::vector<glm::dvec3>& samples_;
    detail::KeptVector<double> witness_, trial_, error_, trialError_, blockError_, sparseParams_;
    detail::KeptVector<glm::dvec3> sparseValues_, window_;  // window_: the candidate at accept's samples
    std::size_t accepted_ = 0, failures_ = 0;               // the candidates judged so far
    bool lastFailed_ = false;                               // the last candidate judged failed
    std::size_t pad_;
    double tol_;
    detail::SplineSampler originalSampler_;
};

/// True where every knot of the linear stage's state s weighs more than the cutoff: the loop
/// would try none, so that state stands (within the tolerance by the coefficient bound).
bool loopTriesNone(const ReductionOptions& options, const Spline& s, std::size_t n) {
    const bool measuring = std::isfinite(options.tolerance);
    if (!(measuring && !options.batch && options.weightCutoff > 0.0 && s.points.size() < n)) return false;
    return !someKnotWithin(s.degree, s.knots, s.points, options.weightCutoff * options.tolerance);
}

/// The loop result's final measurement, seeded by the loop's witnesses where it has samples.
/// With the report off, a result the coefficient bound proves (the linear stage's state, or one
/// whose coefficients refined onto the original's knots stay within the tolerance) needs no
/// final check and gets none.
void measureLoopResult(const Curve& curve, const ReductionOptions& options, double tol,
                       const LoopSamples& samples, OriginalSamples& original, CurveReduction& out) {
    const bool measuring = std::isfinite(options.tolerance);
    const bool proved =
        measuring && !options.report && LinearFit(curve).bounds(out.curve.knots, out.curve.points, tol);
    const bool measure = (measuring || options.report) && !proved;
    if (measure && samples.params().size() >= 2) {
        // The loop's witnesses map the original's parameters to their nearest points on the
        // result: as bounds and seeds they spare most inversions (the maxima stay those of
        // inverting every sample). The original is measured at the loop's own samples (made
        // once, read where they are), the result 8 times as densely per span (it can turn between
        // the original's samples, where the loop did not look), and each direction's peaks are
        // followed between samples.
        const int density = finalCheckDensity(options);
        const bool shared = density == options.samplesPerSpan;
        const CurveDeviationMeter meter = detail::MeterFromSamples::make(
            curve, density, original.forms(), shared ? &original.params() : nullptr,
            shared ? &original.values() : nullptr);
        out.deviation = detail::MeterFromSamples::measureAlong(meter, out.curve, samples.params(),
                                                               samples.ascendingWitnesses(), 8 * density,
                                                               finalCheck(options));
    } else if (measure) {
        // No loop samples (the linear stage's state stands, or batch mode): the map is the
        // identity, whose bounds are the plain measurement's; the meter's global step (span
        // boxes) needs no projector built on the original.
        const std::size_t p = static_cast<std::size_t>(curve.degree), n = curve.points.size();
        const double a = curve.knots[p], b = curve.knots[n];
        const CurveDeviationMeter meter = detail::MeterFromSamples::make(
            curve, 2 * finalCheckDensity(options), original.forms(), nullptr, nullptr);
        out.deviation = detail::MeterFromSamples::measure(meter, out.curve, ParameterMap{{a, b}, {a, b}}, 0,
                                                          finalCheck(options));
    }
}

/// The guarantee: if the denser final measurement finds the tolerance broken, step back through
/// the accepted states until it holds (the original always does).
void stepBackToTolerance(const Curve& curve, const ReductionOptions& options, AcceptedStates& history,
                         CurveReduction& out) {
    while (std::isfinite(options.tolerance) && out.deviation.maxError > options.tolerance) {
        ++out.steppedBack;
        const std::optional<Spline> previous = history.stepBack();
        out.curve = previous ? Curve(previous->degree, previous->knots, previous->points) : curve;
        out.removed = curve.points.size() - out.curve.points.size();
        out.deviation = measureDeviation(curve, out.curve, measureDensity(2 * finalCheckDensity(options)));
        if (!previous) break;
    }
}

// The removal loop from state s (the original, or the linear stage's), run at construction; its
// final measurement and step back (the result then keeps the tolerance as measured by
// measureDeviation) wait until the result is asked for: where the free-knot search beats the
// loop's count (noisy data: about half the members), the loop's result is never measured.
class LoopReduction {
public:
    LoopReduction(const Curve& curve, const ReductionOptions& options, Spline s, double tol,
                  const Spline& originalSpline, OriginalSamples& originalSamples)
        : curve_(curve),
          options_(options),
          tol_(tol),
          triesNone_(loopTriesNone(options, s, curve.points.size())),
          originalSamples_(originalSamples),
          samples_(curve, options.samplesPerSpan, tol,
                   (std::isfinite(options.tolerance) && options.batch) || triesNone_ ? nullptr
                                                                                     : &originalSamples) {
        const bool measuring = std::isfinite(options.tolerance);
        const std::size_t n = curve.points.size();
        auto accept = [&](const LeastSquaresRemoval& fit) {
            return !measuring || samples_.accept(s.degree, fit);
        };
        auto presentError = [&](double from, double to) { return samples_.presentError(from, to); };
        if (measuring && options.batch) {
            BatchReducer reducer(curve, options, tol);
            out_.removed = reducer.run(s.knots, s.points, out_.fits, history_);
        } else {
            const std::size_t before = n - s.points.size();
            out_.removed = before + (triesNone_ ? 0
                                                : reduceLoop(s, options, out_.fits, accept, presentError,
                                                             &history_, &originalSpline, before == 0));
        }
        out_.curve = Curve(s.degree, std::move(s.knots), std::move(s.points));
    }

    /// The curve the loop left, before the final measurement (which rarely steps back).
    const Curve& curve() const { return out_.curve; }
    std::size_t count() const { return out_.curve.points.size(); }
    std::size_t fits() const { return out_.fits; }

    /// The result, measured and stepped back until it keeps the tolerance (once).
    const CurveReduction& result() {
        if (!measured_) {
            measureLoopResult(curve_, options_, tol_, samples_, originalSamples_, out_);
            stepBackToTolerance(curve_, options_, history_, out_);
            // With the report off the check proved the tolerance and reports nothing.
            if (!options_.report) out_.deviation = CurveDeviation{};
            measured_ = true;
        }
        return out_;
    }

private:
    const Curve& curve_;
    const ReductionOptions& options_;
    double tol_;
    bool triesNone_, measured_ = false;
    OriginalSamples& originalSamples_;
    LoopSamples samples_;
    AcceptedStates history_;
    CurveReduction out_;
};

/// o, with the ends' derivatives kept up to a closed shape's seam order (ReductionOptions::keepSeams):
/// each end keeps its derivatives, so the seam keeps the continuity it had.
ReductionOptions keepingSeam(const ReductionOptions& o, int seamOrder) {
    ReductionOptions kept = o;
    if (o.keepSeams && seamOrder > o.ends.fixedDerivatives) kept.ends.fixedDerivatives = seamOrder;
    return kept;
}

/// Whether the knots repeat p + 1 times at each end (n poles).
bool hasClampedEnds(const std::vector<double>& knots, int degree, std::size_t n) {
    const auto p = static_cast<std::ptrdiff_t>(degree), last = static_cast<std::ptrdiff_t>(n);
    return std::equal(knots.begin(), knots.begin() + p, knots.begin() + 1) &&
           std::equal(knots.begin() + last, knots.end() - 1, knots.begin() + last + 1);
}

}  // namespace

namespace {

/// reduceCurve of a clamped curve whose ends' conditions are options.ends.
CurveReduction reduceClampedCurve(const Curve& curve, const ReductionOptions& options) {
    const bool measuring = std::isfinite(options.tolerance);
    const std::size_t p = static_cast<std::size_t>(curve.degree), n = curve.points.size();
    if (curve.rational()) return reduceRationalCurve(curve, options);
    // Samples can miss a peak between them by a little; the loop keeps 1% in hand, and the
    // final measurement below has the last word.
    const double tol = options.tolerance * 0.99;
    const bool batch = measuring && options.batch;
    // The removal loop starts from the linear stage's state where the ends allow it (one banded
    // solve per bisection step removes most of a refined or oversampled curve's knots at once).
    // Run when first needed: by the free-knot search on a refined curve (the loop's count bounds
    // the search), else before the loop; not where the search's result stands alone (the reference
    // curves: it would cost them a third more time for nothing). With freeKnots off the loop runs
    // from the original as before (on the reference curves the linear stage's state costs it
    // 0-9 points: I-beam 27 / 50 / 48 / 92 against 25 / 43 / 44 / 83).
    const bool linear = measuring && options.freeKnots && !batch && options.ends.fixedDerivatives == 0 &&
                        n > p + 1 && options.maxRemovals >= n;
    const Spline originalSpline{curve.degree, curve.knots, curve.points, 1};
    OriginalSamples originalSamples(curve, options.samplesPerSpan);
    std::optional<Spline> linearState;
    std::vector<KnotSignificance> originalRanking;  // rankKnots(curve), once the search has made it
    auto runLinear = [&]() -> const Spline& {
        if (!linearState)
            linearState = linear ? linearRemoval(curve, tol, 30, originalRanking) : originalSpline;
        return *linearState;
    };
    std::optional<LoopReduction> loop;
    auto runLoop = [&]() -> LoopReduction& {
        if (!loop) loop.emplace(curve, options, runLinear(), tol, originalSpline, originalSamples);
        return *loop;
    };
    std::optional<CurveReduction> fitted;
    if (measuring && options.freeKnots) {
        bool refined = false, settled = false;
        fitted = reduceCurveByFreeKnots(
            curve, options, originalSamples, [&]() -> const Curve& { return runLoop().curve(); }, refined,
            settled, originalRanking);
        // The removal loop runs too where nothing fitted below the original or the original
        // looks like a refined curve (see reduceCurveByFreeKnots); the fewer points win. Where
        // every knot's weight is past the cutoff (settled), the loop would try none.
        if ((fitted->removed > 0 && !refined) || n <= p + 1 || settled) return *fitted;
    }
    runLoop();
    // The loop's measurement can only add points (by stepping back): a fit with no more than the
    // loop's count before it wins without it.
    if (fitted && fitted->curve.points.size() <= loop->count()) {
        fitted->fits += loop->fits();
        return *fitted;
    }
    CurveReduction out = loop->result();
    if (fitted && fitted->curve.points.size() <= out.curve.points.size()) {
        fitted->fits += out.fits;
        return *fitted;
    }
    if (fitted) out.fits += fitted->fits;
    return out;
}

/// reduceCurve of a clamped closed curve whose seam is continuous to order seam (seamOrder): both
/// ends keep their derivatives up to it, and with them the first and last `seam` interior knots
/// (EndConditions). Knots that go exactly (within rounding of the curve's size, so the seam stays
/// as it was) go first wherever they are: a refined circle goes back to its own points. Their
/// measured error comes off the tolerance, and the result is measured against the curve given.
CurveReduction reduceClosedCurve(const Curve& curve, const ReductionOptions& given, int seam) {
    const std::size_t n = curve.points.size();
    const bool measuring = std::isfinite(given.tolerance);
    double size = 0.0;
    for (const glm::dvec3& q : curve.points) size = std::max(size, glm::length(q));
    const Curve exact = removeKnotsInRankOrder(curve, given.ends, 1e-13 * size, given.maxRemovals,
                                               std::numeric_limits<int>::max(), nullptr);
    const std::size_t gone = n - exact.points.size();
    const double exactError =
        gone > 0 && measuring
            ? measureDeviation(curve, exact, measureDensity(2 * finalCheckDensity(given))).maxError
            : 0.0;
    auto fromGiven = [&] { return reduceClampedCurve(curve, keepingSeam(given, seam)); };
    if (gone == 0 || detail::seamOrder(exact) < seam || !(exactError < 0.5 * given.tolerance))
        return fromGiven();
    ReductionOptions rest = keepingSeam(given, seam);
    rest.maxRemovals -= gone;
    rest.tolerance -= exactError;
    CurveReduction r = reduceClampedCurve(exact, rest);
    r.removed += gone;
    if (!measuring && !given.report) return r;
    // Against the curve given; a free-knot fit as its own report samples it (four times denser).
    const CurveDeviation d =
        measureDeviation(curve, r.curve, measureDensity((r.freeKnotFit ? 4 : 2) * finalCheckDensity(given)));
    if (measuring && !(d.maxError <= given.tolerance)) return fromGiven();
    r.deviation = given.report ? d : CurveDeviation{};
    return r;
}

}  // namespace

CurveReduction reduceCurve(const Curve& curve, const ReductionOptions& given) {
    checkOptions(given, "reduceCurve");
    validate(curve, "reduceCurve");
    const std::size_t n = curve.points.size();
    // The ends stay where the curve has them: an unclamped one (a periodic, closed one too) is
    // reduced as its clamped form, the same curve, so it keeps its end points (a closed curve
    // stays closed). Where that keeps more points than the original had, the original stands.
    if (!hasClampedEnds(curve.knots, curve.degree, n)) {
        CurveReduction r = reduceCurve(clampEnds(curve), given);
        if (r.curve.points.size() >= n) {
            CurveReduction unchanged;
            unchanged.curve = curve;
            unchanged.fits = r.fits;
            return unchanged;
        }
        r.removed = n - r.curve.points.size();
        return r;
    }
    // A closed curve keeps its seam as smooth as it was (ReductionOptions::keepSeams).
    const int seam = given.keepSeams ? detail::seamOrder(curve) : -1;
    return seam > given.ends.fixedDerivatives ? reduceClosedCurve(curve, given, seam)
                                              : reduceClampedCurve(curve, given);
}

namespace {

SurfaceReduction reduceClampedSurface(const Surface& surface, ReductionDirection direction,
                                      const ReductionOptions& options) {
    SurfaceReduction out;
    const Surface across = transposed(surface);
    SurfaceGrid grid;
    grid.original = &surface;
    grid.gridU = spanSamples(surface.knotsU, surface.degreeU, surface.countU, options.samplesPerSpan);
    grid.gridV = spanSamples(surface.knotsV, surface.degreeV, surface.countV, options.samplesPerSpan);
    if (std::isfinite(options.tolerance)) {
        const std::vector<GridSample> samples = GridEvaluator(surface).evaluate(grid.gridU, grid.gridV);
        grid.values.resize(samples.size());
        for (std::size_t k = 0; k < samples.size(); ++k) grid.values[k] = samples[k].point;
    }
    // The grid keeps 1% of the tolerance in hand for what it misses between its vertices; if
    // the final measurement still finds the tolerance broken, the reduction runs again with
    // less (the original, with nothing removed, always passes).
    const bool measuring = std::isfinite(options.tolerance);
    // A closed direction keeps the continuity of its seam (ReductionOptions::keepSeams).
    const ReductionOptions alongU = keepingSeam(
        options,
        options.keepSeams && direction != ReductionDirection::V ? detail::seamOrder(surface, true) : -1);
    const ReductionOptions alongV = keepingSeam(
        options,
        options.keepSeams && direction != ReductionDirection::U ? detail::seamOrder(surface, false) : -1);
    for (double share : {0.99, 0.9, 0.7, 0.0}) {
        out = SurfaceReduction{};
        Surface current = surface;
        const double acceptance = share * options.tolerance;
        if (share > 0.0 || !measuring) {
            if (direction != ReductionDirection::V)
                out.removedU = reduceSurfaceAlongU(current, grid, alongU, acceptance, out.fits);
            if (direction != ReductionDirection::U) {
                // Along v by transposition (the thesis's swap_uw), the grid transposed with it.
                Surface t = transposed(current);
                SurfaceGrid tg;
                tg.original = &across;
                tg.gridU = grid.gridV;
                tg.gridV = grid.gridU;
                if (!grid.values.empty()) {
                    tg.values.resize(grid.values.size());
                    for (std::size_t i = 0; i < grid.gridU.size(); ++i)
                        for (std::size_t j = 0; j < grid.gridV.size(); ++j)
                            tg.values[j * grid.gridU.size() + i] = grid.values[i * grid.gridV.size() + j];
                }
                out.removedV = reduceSurfaceAlongU(t, tg, alongV, acceptance, out.fits);
                current = transposed(t);
            }
        }
        validate(current);
        out.surface = std::move(current);
        if (options.report || measuring)
            out.deviation = measureDeviation(surface, out.surface, std::max(2, options.samplesPerSpan / 2));
        if (!measuring || out.deviation.maxError <= options.tolerance) break;
    }
    return out;
}

// A checked surface, clamped or not.
SurfaceReduction reduceAnySurface(const Surface& surface, ReductionDirection direction,
                                  const ReductionOptions& options) {
    // As for curves: unclamped edges (a periodic direction's seam too) are reduced on the clamped
    // form, the same surface, whose edge curves knot removal keeps, so a closed seam stays closed.
    if (!hasClampedEnds(surface.knotsU, surface.degreeU, surface.countU) ||
        !hasClampedEnds(surface.knotsV, surface.degreeV, surface.countV)) {
        SurfaceReduction r = reduceClampedSurface(clampEnds(surface), direction, options);
        if (r.surface.points.size() >= surface.points.size()) {
            SurfaceReduction unchanged;
            unchanged.surface = surface;
            unchanged.fits = r.fits;
            if (options.report || std::isfinite(options.tolerance))
                unchanged.deviation =
                    measureDeviation(surface, surface, std::max(2, options.samplesPerSpan / 2));
            return unchanged;
        }
        r.removedU = surface.countU - r.surface.countU;  // counted from the original's rows
        r.removedV = surface.countV - r.surface.countV;
        return r;
    }
    return reduceClampedSurface(surface, direction, options);
}

// A rational surface, reduced in its RationalFrame.
SurfaceReduction reduceRationalSurface(const Surface& surface, ReductionDirection direction,
                                       const ReductionOptions& options) {
    const RationalFrame frame = rationalFrame(surface.points, surface.weights);
    Surface centred = surface;
    for (glm::dvec3& q : centred.points) q -= frame.centre;
    for (double& w : centred.weights) w /= frame.largest;
    SurfaceReduction r = reduceAnySurface(centred, direction, options);
    for (glm::dvec3& q : r.surface.points) q += frame.centre;
    for (double& w : r.surface.weights) w *= frame.largest;
    return r;
}

}  // namespace

SurfaceReduction reduceSurface(const Surface& surface, ReductionDirection direction,
                               const ReductionOptions& options) {
    checkOptions(options, "reduceSurface");
    validate(surface, "reduceSurface");
    if (direction != ReductionDirection::U && direction != ReductionDirection::V &&
        direction != ReductionDirection::Both)
        throw GeometryError("reduceSurface: direction " + std::to_string(static_cast<int>(direction)) +
                            " is not U, V or Both");
    return surface.rational() ? reduceRationalSurface(surface, direction, options)
                              : reduceAnySurface(surface, direction, options);
}

}  // namespace geom
