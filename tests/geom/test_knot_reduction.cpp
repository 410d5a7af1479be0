#include "GeomTestUtil.h"
#include "geom/Basis.h"
#include "geom/CurveProjector.h"
#include "geom/DataReduction.h"
#include "geom/Deviation.h"
#include "geom/Evaluate.h"
#include "geom/GeometryError.h"
#include "geom/GlobalInterpolation.h"
#include "geom/KnotInsertion.h"
#include "geom/KnotSignificance.h"
#include "geom/Primitives.h"
#include "geom/SurfaceProjector.h"

#include "Sanitized.h"

#include <catch2/catch.hpp>
#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>

namespace test_knot_reduction {

using namespace geom;

namespace {

using geomtest::noisyRefinedCurve;

Surface noisyRefinedSurface(std::mt19937& rng, int p, int q, std::size_t extra, double noise) {
    const Surface base = geomtest::bumpySurface(rng, p, q, static_cast<std::size_t>(p + 2),
                                                static_cast<std::size_t>(q + 2), false);
    std::uniform_real_distribution<double> unit(0.0, 1.0), jitter(-noise, noise);
    std::vector<double> iu, iv;
    for (std::size_t i = 0; i < extra; ++i) iu.push_back(0.02 + 0.96 * unit(rng));
    for (std::size_t i = 0; i < extra; ++i) iv.push_back(0.02 + 0.96 * unit(rng));
    Surface s = refineKnotsV(refineKnotsU(base, iu), iv);
    for (auto& pt : s.points) pt += glm::dvec3(jitter(rng), jitter(rng), jitter(rng));
    return s;
}

/// A rational surface of degrees p x q with weights over two decades, moved `away` from the origin.
Surface rationalBase(std::mt19937& rng, int p, int q, double away) {
    Surface base = geomtest::bumpySurface(rng, p, q, static_cast<std::size_t>(p + 3),
                                          static_cast<std::size_t>(q + 3), true);
    std::uniform_real_distribution<double> decade(-1.0, 1.0);
    for (double& w : base.weights) w = std::pow(10.0, decade(rng));
    for (glm::dvec3& q3 : base.points) q3 += glm::dvec3(away, -away, 0.5 * away);
    return base;
}

/// Inserts `rows` random knot rows each way into `base`, reduces the result at `tolerance` and
/// requires the simpler surface back: its knots, its control points (and weights), the error
/// measured within the tolerance.
void requireReducesBack(std::mt19937& rng, const Surface& base, int rows, double tolerance) {
    std::uniform_real_distribution<double> unit(0.05, 0.95);
    std::vector<double> iu, iv;
    for (int i = 0; i < rows; ++i) iu.push_back(unit(rng)), iv.push_back(unit(rng));
    const Surface refined = refineKnotsV(refineKnotsU(base, iu), iv);
    ReductionOptions o;
    o.tolerance = tolerance;
    const SurfaceReduction r = reduceSurface(refined, ReductionDirection::Both, o);
    REQUIRE(r.removedU == iu.size());
    REQUIRE(r.removedV == iv.size());
    REQUIRE(r.surface.knotsU == base.knotsU);
    REQUIRE(r.surface.knotsV == base.knotsV);
    REQUIRE(r.surface.weights.size() == base.weights.size());
    for (std::size_t k = 0; k < base.points.size(); ++k)
        REQUIRE(glm::length(r.surface.points[k] - base.points[k]) < tolerance);
    for (std::size_t k = 0; k < base.weights.size(); ++k)
        REQUIRE(std::abs(r.surface.weights[k] / base.weights[k] - 1.0) < 1e-9);
    REQUIRE(r.deviation.maxError <= tolerance);
}

}  // namespace

TEST_CASE("curve reduction keeps the measured distance within the tolerance, degrees 2 to 5",
          "[geom][knots][reduction]") {
    std::mt19937 rng(31);
    for (int p = 2; p <= 5; ++p)
        for (double tol : {1e-2, 1e-3}) {
            const Curve c = noisyRefinedCurve(rng, p, 40, 2e-4);
            ReductionOptions o;
            o.tolerance = tol;
            const CurveReduction r = reduceCurve(c, o);
            INFO("degree " << p << " tolerance " << tol);
            REQUIRE(r.removed > 20);
            REQUIRE(r.curve.points.size() == c.points.size() - r.removed);
            REQUIRE(r.curve.degree == p);
            REQUIRE(r.deviation.maxError <= tol);
            // An independent, denser measurement agrees.
            const CurveDeviation dense = measureDeviation(c, r.curve, 64);
            REQUIRE(dense.maxError <= tol * 1.001);
            REQUIRE(dense.maxError >= 0.5 * r.deviation.maxError);
            // Clamped ends stay where they were.
            REQUIRE(r.curve.points.front() == c.points.front());
            REQUIRE(r.curve.points.back() == c.points.back());
        }
}

TEST_CASE("a curve made by inserting knots reduces back to the simpler curve", "[geom][knots][reduction]") {
    std::mt19937 rng(32);
    for (int p = 2; p <= 5; ++p) {
        const Curve simple = geomtest::randomCurve(rng, p, static_cast<std::size_t>(p + 5), false, true);
        std::uniform_real_distribution<double> unit(0.05, 0.95);
        std::vector<double> inserted;
        for (int i = 0; i < 12; ++i) inserted.push_back(unit(rng));
        // Raise an original simple knot's multiplicity as well.
        for (std::size_t i = static_cast<std::size_t>(p) + 1; i < simple.points.size(); ++i)
            if (knotMultiplicity(simple.knots, simple.knots[i]) == 1) {
                inserted.push_back(simple.knots[i]);
                break;
            }
        const Curve refined = refineKnots(simple, inserted);
        ReductionOptions o;
        o.tolerance = 1e-9;
        const CurveReduction r = reduceCurve(refined, o);
        INFO("degree " << p);
        REQUIRE(r.removed == inserted.size());
        REQUIRE(r.curve.knots.size() == simple.knots.size());
        for (std::size_t i = 0; i < simple.knots.size(); ++i) REQUIRE(r.curve.knots[i] == simple.knots[i]);
        for (std::size_t i = 0; i < simple.points.size(); ++i)
            REQUIRE(glm::length(r.curve.points[i] - simple.points[i]) < 1e-10);
    }
}

TEST_CASE("a densely refined, jittered curve of degree 1 to 7 reduces to about its simpler curve",
          "[geom][knots][reduction]") {
    // 80 knots inserted into p + 8 poles, every pole moved by up to 1e-6: each inserted knot alone
    // moves the curve little, so the linear stage must not remove the simpler curve's knots
    // together with them; the removal loop goes on from its state. Where the free-knot search's
    // check does not find the curve refined, its fit stands alone and can keep more (26 points
    // on one curve of degree 5): only the count within tolerance is required there.
    std::mt19937 rng(35);
    int byLoop = 0;
    for (int p = 1; p <= 7; ++p)
        for (int trial = 0; trial < 3; ++trial) {
            const std::size_t baseCount = static_cast<std::size_t>(p + 8);
            const Curve simple = geomtest::randomCurve(rng, p, baseCount, false, true);
            std::uniform_real_distribution<double> unit(0.02, 0.98), jitter(-1e-6, 1e-6);
            std::vector<double> inserted;
            for (int i = 0; i < 80; ++i) inserted.push_back(unit(rng));
            Curve refined = refineKnots(simple, inserted);
            for (glm::dvec3& q : refined.points) q += glm::dvec3(jitter(rng), jitter(rng), jitter(rng));
            ReductionOptions o;
            o.tolerance = 1e-3;
            const CurveReduction r = reduceCurve(refined, o);
            INFO("degree " << p << ", trial " << trial << ": " << r.curve.points.size() << " points of "
                           << refined.points.size() << " (free-knot fit: " << r.freeKnotFit
                           << "), the simpler curve has " << baseCount);
            REQUIRE(measureDeviation(refined, r.curve, 64).maxError <= o.tolerance);
            REQUIRE(r.removed == refined.points.size() - r.curve.points.size());
            if (!r.freeKnotFit) {
                ++byLoop;
                REQUIRE(r.curve.points.size() <= baseCount + 2);
            }
        }
    REQUIRE(byLoop >= 15);  // of 21: the linear stage and the loop ran on most
}

TEST_CASE("a refined curve jittered by 1e-5 of degree 4 to 7 reduces to about its simpler curve",
          "[geom][knots][reduction]") {
    // Jitter near a hundredth of the tolerance hides the simpler curve's knots from the ranking
    // by weight, and the first moved-knot fit overshoots far below the tolerance: the removal
    // loop must still run and find the simpler curve, whichever way the result is made. At degree
    // 7 the first count can be the original's less one, too many knots for the significant-knot
    // fit's samples: a check that cannot be made must not leave the search alone.
    std::mt19937 rng(43);
    for (int p = 4; p <= 7; ++p)
        for (int trial = 0; trial < 3; ++trial) {
            const std::size_t baseCount = static_cast<std::size_t>(p + 8);
            const Curve simple = geomtest::randomCurve(rng, p, baseCount, false, true);
            std::uniform_real_distribution<double> unit(0.01, 0.99), jitter(-1e-5, 1e-5);
            std::vector<double> inserted;
            for (int i = 0; i < 80; ++i) inserted.push_back(unit(rng));
            Curve refined = refineKnots(simple, inserted);
            for (glm::dvec3& q : refined.points) q += glm::dvec3(jitter(rng), jitter(rng), jitter(rng));
            ReductionOptions o;
            o.tolerance = 1e-3;
            const CurveReduction r = reduceCurve(refined, o);
            INFO("degree " << p << ", trial " << trial << ": " << r.curve.points.size()
                           << " points (free-knot fit: " << r.freeKnotFit << "), the simpler curve has "
                           << baseCount);
            REQUIRE(measureDeviation(refined, r.curve, 64).maxError <= o.tolerance);
            REQUIRE(r.curve.points.size() <= baseCount + 3);
        }
}

TEST_CASE("a refined, jittered curve with C0 corners reduces to about its simpler curve, corners kept",
          "[geom][knots][reduction]") {
    // Interior knots of multiplicity p (corners) among 50 inserted ones: the original's own
    // significant knots fit, so the removal loop decides; it must keep every corner and the error.
    std::mt19937 rng(41);
    for (int p = 2; p <= 4; ++p)
        for (int trial = 0; trial < 3; ++trial) {
            const std::vector<double> corners{0.3, 0.65};
            std::vector<double> knots(static_cast<std::size_t>(p) + 1, 0.0);
            for (double c : corners) knots.insert(knots.end(), static_cast<std::size_t>(p), c);
            knots.insert(knots.end(), static_cast<std::size_t>(p) + 1, 1.0);
            std::vector<glm::dvec3> points;
            for (std::size_t i = 0; i + static_cast<std::size_t>(p) + 1 < knots.size(); ++i)
                points.push_back(geomtest::randomPoint(rng));
            const Curve simple(p, knots, points);
            std::uniform_real_distribution<double> unit(0.02, 0.98), jitter(-1e-6, 1e-6);
            std::vector<double> inserted;
            for (int i = 0; i < 50; ++i) inserted.push_back(unit(rng));
            Curve refined = refineKnots(simple, inserted);
            for (glm::dvec3& q : refined.points) q += glm::dvec3(jitter(rng), jitter(rng), jitter(rng));
            ReductionOptions o;
            o.tolerance = 1e-3;
            const CurveReduction r = reduceCurve(refined, o);
            INFO("degree " << p << ", trial " << trial << ": " << r.curve.points.size()
                           << " points, the simpler "
                           << "curve has " << simple.points.size());
            REQUIRE(measureDeviation(refined, r.curve, 64).maxError <= o.tolerance);
            REQUIRE(r.deviation.maxError <= o.tolerance);
            REQUIRE(r.removed == refined.points.size() - r.curve.points.size());
            REQUIRE(r.curve.points.size() <= simple.points.size() + 2);
            for (double c : corners) REQUIRE(std::count(r.curve.knots.begin(), r.curve.knots.end(), c) >= p);
        }
}

TEST_CASE(
    "with the report off, a result the coefficient bound proves skips the final check and keeps the "
    "tolerance",
    "[geom][knots][reduction]") {
    // Refined and jittered curves of degree 1 to 7, with and without corners, and noisy digitised
    // points interpolated by a cubic: with the report off the final measurement runs only where no
    // coefficient bound proves the result; the curve must be the one the report-on run returns,
    // and measured densely it must keep the tolerance.
    std::mt19937 rng(71);
    std::vector<Curve> curves;
    for (int p = 1; p <= 7; ++p)
        for (int trial = 0; trial < 4; ++trial) {
            Curve simple = geomtest::randomCurve(rng, p, static_cast<std::size_t>(p + 8), false, true);
            if (trial == 3 && p >= 2) {  // a corner: a knot of multiplicity p
                simple.knots = std::vector<double>(static_cast<std::size_t>(p) + 1, 0.0);
                simple.knots.insert(simple.knots.end(), static_cast<std::size_t>(p), 0.5);
                simple.knots.insert(simple.knots.end(), static_cast<std::size_t>(p) + 1, 1.0);
                simple.points.resize(simple.knots.size() - static_cast<std::size_t>(p) - 1);
            }
            std::uniform_real_distribution<double> unit(0.02, 0.98), jitter(-1e-5, 1e-5);
            std::vector<double> inserted;
            for (int i = 0; i < 60; ++i) inserted.push_back(unit(rng));
            Curve refined = refineKnots(simple, inserted);
            for (glm::dvec3& q : refined.points) q += glm::dvec3(jitter(rng), jitter(rng), jitter(rng));
            curves.push_back(std::move(refined));
        }
    for (int trial = 0; trial < 4; ++trial) {
        const Curve path = geomtest::randomCurve(rng, 3, 10, false, true);
        std::uniform_real_distribution<double> jitter(-1e-4, 1e-4);
        std::vector<glm::dvec3> data;
        for (int i = 0; i < 150; ++i)
            data.push_back(evaluate(path, i / 149.0) + glm::dvec3(jitter(rng), jitter(rng), jitter(rng)));
        curves.push_back(interpolateCurve(data, 3, Closure::Open));
    }
    int skipped = 0;
    for (std::size_t k = 0; k < curves.size(); ++k) {
        const Curve& c = curves[k];
        ReductionOptions on;
        on.tolerance = 1e-3;
        ReductionOptions off = on;
        off.report = false;
        const CurveReduction a = reduceCurve(c, on), b = reduceCurve(c, off);
        INFO("curve " << k << " of degree " << c.degree << ": " << b.curve.points.size() << " points");
        REQUIRE(a.deviation.samples > 0);
        REQUIRE(b.curve.knots == a.curve.knots);
        REQUIRE(b.curve.points == a.curve.points);
        REQUIRE(measureDeviation(c, b.curve, 64).maxError <= on.tolerance);
        if (b.deviation.samples == 0) ++skipped;
    }
    REQUIRE(skipped >= 16);  // of 32: most results here are the linear stage's states
}

TEST_CASE("count-driven reduction removes exactly the number asked for and reports its error",
          "[geom][knots][reduction]") {
    std::mt19937 rng(33);
    const Curve c = noisyRefinedCurve(rng, 3, 40, 1e-3);
    for (std::size_t n : {1u, 4u, 7u, 23u}) {
        ReductionOptions o;
        o.maxRemovals = n;
        const CurveReduction r = reduceCurve(c, o);
        REQUIRE(r.removed == n);
        REQUIRE(r.curve.points.size() == c.points.size() - n);
        REQUIRE(r.curve.knots.size() == c.knots.size() - n);
        // The report is filled: max is the larger direction, the mean is below the max.
        REQUIRE(r.deviation.samples > 0);
        REQUIRE(r.deviation.maxError ==
                std::max(r.deviation.maxOriginalToReduced, r.deviation.maxReducedToOriginal));
        REQUIRE(r.deviation.meanError <= r.deviation.maxError);
        REQUIRE(r.deviation.maxError > 0.0);
    }
    // Both limits: the count stops it first when the tolerance is loose.
    ReductionOptions both;
    both.maxRemovals = 5;
    both.tolerance = 1.0;
    REQUIRE(reduceCurve(c, both).removed == 5);
    // The partition size changes how often the weights are recomputed, not the count.
    ReductionOptions single;
    single.maxRemovals = 9;
    single.partitionSize = 1;
    REQUIRE(reduceCurve(c, single).removed == 9);
}

TEST_CASE("curve reduction with end derivatives fixed keeps them", "[geom][knots][reduction]") {
    std::mt19937 rng(34);
    const Curve c = noisyRefinedCurve(rng, 4, 30, 1e-4);
    ReductionOptions o;
    o.tolerance = 1e-2;
    o.ends.fixedDerivatives = 2;
    const CurveReduction r = reduceCurve(c, o);
    REQUIRE(r.removed > 0);
    REQUIRE(r.deviation.maxError <= o.tolerance);
    for (double u : {c.domainStart(), c.domainEnd()}) {
        const auto a = derivatives(c, u, 2), b = derivatives(r.curve, u, 2);
        for (int k = 0; k <= 2; ++k)
            REQUIRE(glm::length(a[static_cast<std::size_t>(k)] - b[static_cast<std::size_t>(k)]) <=
                    1e-8 * (1.0 + glm::length(a[static_cast<std::size_t>(k)])));
    }
}

TEST_CASE("rational curves reduce in homogeneous space within the Euclidean tolerance",
          "[geom][knots][reduction][rational]") {
    std::mt19937 rng(36);
    std::uniform_real_distribution<double> unit(0.0, 1.0), jitter(-1.0, 1.0);
    for (int trial = 0; trial < 24; ++trial) {
        const int p = 2 + trial % 4;
        // A random rational curve, weights spanning up to 1e-1..1e1, refined by 30 knots and
        // jittered a little, away from the origin so the weights' leverage matters.
        Curve base = geomtest::randomCurve(rng, p, std::size_t(p + 3), true, true);
        for (double& w : base.weights) w = std::pow(10.0, jitter(rng));
        for (glm::dvec3& q : base.points) q += glm::dvec3(50.0, -20.0, 5.0);
        std::vector<double> inserted;
        for (int i = 0; i < 30; ++i) inserted.push_back(0.02 + 0.96 * unit(rng));
        Curve c = refineKnots(base, inserted);
        for (glm::dvec3& q : c.points) q += 1e-5 * glm::dvec3(jitter(rng), jitter(rng), jitter(rng));
        for (double tol : {1e-2, 1e-3}) {
            ReductionOptions o;
            o.tolerance = tol;
            const CurveReduction r = reduceCurve(c, o);
            INFO("trial " << trial << " degree " << p << " tolerance " << tol);
            REQUIRE(r.curve.rational());
            REQUIRE(r.removed >= 30);  // every inserted knot
            REQUIRE(r.curve.points.size() == c.points.size() - r.removed);
            for (double w : r.curve.weights) REQUIRE(w > 0.0);
            CHECK(r.steppedBack == 0);  // the bound, not the final measurement, kept the tolerance
            // An independent, denser Euclidean measurement agrees.
            REQUIRE(measureDeviation(c, r.curve, 64).maxError <= tol);
            REQUIRE(r.curve.points.front() == c.points.front());
        }
    }
    // The exact circle, refined, goes back to few points; count mode removes what it is asked.
    const Curve circle = makeCircle({1, 2, 3}, {1, 0, 0}, {0, 1, 0}, 2.0);
    const Curve refined = refineKnots(circle, std::vector<double>{0.1, 0.2, 0.3, 0.45, 0.6, 0.7, 0.8, 0.9});
    ReductionOptions o;
    o.tolerance = 1e-9;
    const CurveReduction r = reduceCurve(refined, o);
    CHECK(r.curve.points.size() <= circle.points.size());
    CHECK(measureDeviation(refined, r.curve, 64).maxError <= 1e-9);
    ReductionOptions count;
    count.maxRemovals = 3;
    CHECK(reduceCurve(refined, count).removed == 3);
}

TEST_CASE("reduction rejects bad options", "[geom][knots][reduction]") {
    std::mt19937 rng(35);
    ReductionOptions o;
    o.tolerance = 1e-3;
    const Curve c = geomtest::randomCurve(rng, 3, 8, false, true);
    ReductionOptions bad = o;
    bad.tolerance = 0.0;
    REQUIRE_THROWS_WITH(reduceCurve(c, bad), Catch::Contains("tolerance"));
    bad = o;
    bad.partitionSize = 0;
    REQUIRE_THROWS_WITH(reduceCurve(c, bad), Catch::Contains("partitionSize"));
    bad = o;
    bad.samplesPerSpan = 0;
    REQUIRE_THROWS_WITH(reduceCurve(c, bad), Catch::Contains("samplesPerSpan"));
    const Surface rs = geomtest::randomSurface(rng, 2, 2, 5, 5, true, true);
    bad = o;
    bad.tolerance = -1.0;
    REQUIRE_THROWS_WITH(reduceSurface(rs, ReductionDirection::Both, bad), Catch::Contains("tolerance"));
}

TEST_CASE("surface reduction keeps the measured distance within the tolerance, degrees 2 to 5",
          "[geom][knots][reduction]") {
    std::mt19937 rng(36);
    const int degrees[][2] = {{2, 3}, {3, 3}, {4, 2}, {5, 4}};
    for (const auto& d : degrees) {
        const Surface s = noisyRefinedSurface(rng, d[0], d[1], 12, 2e-5);
        for (ReductionDirection dir :
             {ReductionDirection::U, ReductionDirection::V, ReductionDirection::Both}) {
            ReductionOptions o;
            o.tolerance = 1e-3;
            const SurfaceReduction r = reduceSurface(s, dir, o);
            INFO("degrees " << d[0] << "," << d[1] << " direction " << static_cast<int>(dir));
            REQUIRE(r.surface.countU == s.countU - r.removedU);
            REQUIRE(r.surface.countV == s.countV - r.removedV);
            if (dir != ReductionDirection::V) REQUIRE(r.removedU >= 6);
            if (dir != ReductionDirection::U) REQUIRE(r.removedV >= 6);
            if (dir == ReductionDirection::U) REQUIRE(r.removedV == 0);
            if (dir == ReductionDirection::V) REQUIRE(r.removedU == 0);
            REQUIRE(r.deviation.maxError <= o.tolerance);
            const SurfaceDeviation dense = measureDeviation(s, r.surface, 6);
            REQUIRE(dense.maxError <= o.tolerance * 1.001);
            // The error field: one value per grid vertex of the reduced surface; the maximum is at
            // least the field's (a peak between its vertices can be higher).
            REQUIRE(r.deviation.error.size() == r.deviation.u.size() * r.deviation.v.size());
            REQUIRE(*std::max_element(r.deviation.error.begin(), r.deviation.error.end()) <=
                    r.deviation.maxReducedToOriginal);
            REQUIRE(r.deviation.meanError <= r.deviation.maxReducedToOriginal);
        }
    }
}

TEST_CASE("surface row weights are the maximum over the isoparametric curves", "[geom][knots][reduction]") {
    std::mt19937 rng(37);
    const Surface base = geomtest::bumpySurface(rng, 3, 3, 6, 6, false);
    Surface s = insertKnotU(base, 0.37, 1);
    // The row weight of 0.37 equals the largest weight of the columns taken one by one.
    const auto rowRank = rankKnots(s.degreeU, s.knotsU, s.points, s.countV);
    const std::size_t r37 =
        static_cast<std::size_t>(std::find(s.knotsU.begin(), s.knotsU.end(), 0.37) - s.knotsU.begin());
    // Disturb one column near the knot: that column alone now needs it.
    s.point(r37 - 2, 3) += glm::dvec3(0, 0, 0.05);
    double worst = 0.0, sum = 0.0;
    for (std::size_t j = 0; j < s.countV; ++j) {
        std::vector<glm::dvec3> column;
        for (std::size_t i = 0; i < s.countU; ++i) column.push_back(s.point(i, j));
        const double w = knotRemovalWeight(s.degreeU, s.knotsU, column, 1, r37);
        worst = std::max(worst, w);
        sum += w;
    }
    REQUIRE(knotRemovalWeight(s.degreeU, s.knotsU, s.points, s.countV, r37) == worst);
    REQUIRE(worst > 2.0 * sum / static_cast<double>(s.countV));  // a mean would hide it
    REQUIRE(rowRank.front().value == 0.37);                      // before the disturbance it was free
    // The tolerance holds on the whole surface, so the row stays when one curve needs it.
    ReductionOptions o;
    o.tolerance = 1e-6;
    const SurfaceReduction r = reduceSurface(s, ReductionDirection::U, o);
    REQUIRE(std::find(r.surface.knotsU.begin(), r.surface.knotsU.end(), 0.37) != r.surface.knotsU.end());
    REQUIRE(r.deviation.maxError <= o.tolerance);
    // Undisturbed, the same row goes exactly.
    const SurfaceReduction clean = reduceSurface(insertKnotU(base, 0.37, 1), ReductionDirection::U, o);
    REQUIRE(clean.surface.knotsU == base.knotsU);
    REQUIRE(clean.deviation.maxError < 1e-10);
}

TEST_CASE("count-driven surface reduction removes that many rows in each direction",
          "[geom][knots][reduction]") {
    std::mt19937 rng(38);
    const Surface s = noisyRefinedSurface(rng, 3, 3, 10, 1e-3);
    ReductionOptions o;
    o.maxRemovals = 4;
    const SurfaceReduction r = reduceSurface(s, ReductionDirection::Both, o);
    REQUIRE(r.removedU == 4);
    REQUIRE(r.removedV == 4);
    REQUIRE(r.surface.countU == s.countU - 4);
    REQUIRE(r.surface.countV == s.countV - 4);
    REQUIRE(r.deviation.maxError > 0.0);
}

TEST_CASE("the final measurement steps back when coarse loop samples let the tolerance slip",
          "[geom][knots][reduction]") {
    // One sample per span in the loop misses the peaks between knots; the final measurement
    // (the result 8 times as dense, peaks followed) catches them and undoes accepted removals
    // until the tolerance holds.
    std::mt19937 rng(51);
    std::size_t steppedBack = 0;
    for (int trial = 0; trial < 6; ++trial) {
        const Curve c = noisyRefinedCurve(rng, 2 + trial % 4, 40, 3e-3);
        ReductionOptions o;
        o.tolerance = 1e-3;
        o.samplesPerSpan = 1;
        o.partitionSize = 1;
        o.freeKnots = false;  // the removal loop's step back
        const CurveReduction r = reduceCurve(c, o);
        steppedBack += r.steppedBack;
        REQUIRE(r.deviation.maxError <= o.tolerance);
        REQUIRE(r.removed == c.points.size() - r.curve.points.size());
        // The final check samples the original at least 4 times per span whatever the loop's
        // density (one per span misses peaks between samples): the result keeps the tolerance as a
        // plain measurement 64 times per span finds it, and the report, inverted from the loop's
        // witnesses, is its maximum to within 1%.
        const double dense = measureDeviation(c, r.curve, 64).maxError;
        REQUIRE(dense <= o.tolerance);
        REQUIRE(r.deviation.maxError == Approx(dense).epsilon(0.01));
    }
    REQUIRE(steppedBack > 0);
}

TEST_CASE("batch curve reduction keeps the measured distance within the tolerance, degrees 2 to 5",
          "[geom][knots][reduction]") {
    std::mt19937 rng(61);
    for (int p = 2; p <= 5; ++p)
        for (double tol : {1e-2, 1e-3}) {
            const Curve c = noisyRefinedCurve(rng, p, 40, 2e-4);
            ReductionOptions o;
            o.tolerance = tol;
            o.batch = true;
            o.freeKnots = false;
            const CurveReduction r = reduceCurve(c, o);
            INFO("degree " << p << " tolerance " << tol);
            REQUIRE(r.removed > 20);
            REQUIRE(r.curve.points.size() == c.points.size() - r.removed);
            REQUIRE(r.deviation.maxError <= tol);
            const CurveDeviation dense = measureDeviation(c, r.curve, 64);
            REQUIRE(dense.maxError <= tol * 1.001);
            REQUIRE(r.curve.points.front() == c.points.front());
            REQUIRE(r.curve.points.back() == c.points.back());
            // The batch loop does fewer fits than there are knots removed one at a time.
            REQUIRE(r.fits < r.removed);
        }
}

TEST_CASE("batch reduction recovers the simpler curve and keeps fixed end derivatives",
          "[geom][knots][reduction]") {
    std::mt19937 rng(62);
    for (int p = 2; p <= 5; ++p) {
        const Curve simple = geomtest::randomCurve(rng, p, static_cast<std::size_t>(p + 5), false, true);
        std::uniform_real_distribution<double> unit(0.05, 0.95);
        std::vector<double> inserted;
        for (int i = 0; i < 12; ++i) inserted.push_back(unit(rng));
        const Curve refined = refineKnots(simple, inserted);
        ReductionOptions o;
        o.tolerance = 1e-9;
        o.batch = true;
        o.freeKnots = false;
        const CurveReduction r = reduceCurve(refined, o);
        INFO("degree " << p);
        REQUIRE(r.removed == inserted.size());
        REQUIRE(r.curve.knots == simple.knots);
        for (std::size_t i = 0; i < simple.points.size(); ++i)
            REQUIRE(glm::length(r.curve.points[i] - simple.points[i]) < 1e-10);
    }
    const Curve c = noisyRefinedCurve(rng, 4, 30, 1e-4);
    ReductionOptions o;
    o.tolerance = 1e-2;
    o.batch = true;
    o.freeKnots = false;
    o.ends.fixedDerivatives = 2;
    const CurveReduction r = reduceCurve(c, o);
    REQUIRE(r.removed > 0);
    REQUIRE(r.deviation.maxError <= o.tolerance);
    for (double u : {c.domainStart(), c.domainEnd()}) {
        const std::vector<glm::dvec3> a = derivatives(c, u, 2), b = derivatives(r.curve, u, 2);
        for (std::size_t k = 0; k <= 2; ++k)
            REQUIRE(glm::length(a[k] - b[k]) <= 1e-8 * (1.0 + glm::length(a[k])));
    }
    ReductionOptions bad = o;
    bad.rounds = 0;
    REQUIRE_THROWS_WITH(reduceCurve(c, bad), Catch::Contains("rounds"));
}

TEST_CASE("the curve deviation's maximum is that of every sample's closest point and of the peaks",
          "[geom][knots][reduction]") {
    // measureDeviation inverts only the samples whose parametric distance could hold the
    // maximum, then follows the peaks near the largest between samples: at least the maxima of
    // inverting every sample globally, and no more than those of inverting 256 times as many.
    std::mt19937 rng(63);
    for (int p = 2; p <= 5; ++p) {
        const Curve c = noisyRefinedCurve(rng, p, 30, 1e-3);
        ReductionOptions o;
        o.maxRemovals = 20;
        o.report = false;
        const Curve reduced = reduceCurve(c, o).curve;
        const CurveDeviation d = measureDeviation(c, reduced, 8);
        auto bruteForce = [](const Curve& from, const Curve& to, int density) {
            const CurveProjector projector(to);
            double worst = 0.0;
            for (double u : spanSamples(from.knots, from.degree, from.points.size(), density))
                worst = std::max(worst, projector.closestPoint(evaluate(from, u)).distance);
            return worst;
        };
        INFO("degree " << p);
        REQUIRE(d.maxOriginalToReduced >= bruteForce(c, reduced, 8) * (1.0 - 1e-12));
        REQUIRE(d.maxReducedToOriginal >= bruteForce(reduced, c, 8) * (1.0 - 1e-12));
        // Never above the dense samples' largest by more than a hair (a peak between them): what
        // is reported is a real distance.
        REQUIRE(d.maxOriginalToReduced <= bruteForce(c, reduced, 2048) * (1.0 + 1e-4));
        REQUIRE(d.maxReducedToOriginal <= bruteForce(reduced, c, 2048) * (1.0 + 1e-4));
        REQUIRE(d.meanError <= d.maxError);
        REQUIRE(d.maxError > 0.0);
    }
}

TEST_CASE("a surface made by inserting knot rows reduces back to the simpler surface",
          "[geom][knots][reduction]") {
    // Every removal here is exact, so the coefficient bound on S - S' accepts it without the
    // grid; the result must be the simpler surface itself.
    std::mt19937 rng(64);
    for (int p = 2; p <= 4; ++p) {
        const Surface base = geomtest::bumpySurface(rng, p, p + 1, static_cast<std::size_t>(p + 3),
                                                    static_cast<std::size_t>(p + 4), false);
        INFO("degree " << p);
        requireReducesBack(rng, base, 8, 1e-9);
    }
}

TEST_CASE("a rational surface made by inserting knot rows reduces back to the simpler surface",
          "[geom][knots][reduction]") {
    // In homogeneous form every removal is exact: the result is the simpler surface itself,
    // wherever it lies and whatever its weights.
    std::mt19937 rng(65);
    for (int p = 1; p <= 4; ++p) {
        const Surface base = rationalBase(rng, p, 5 - p, p % 2 == 0 ? 1e3 : 0.0);
        INFO("degree " << p);
        requireReducesBack(rng, base, 6, 1e-7);
    }
}

TEST_CASE("rational surface reduction keeps the measured distance within the tolerance",
          "[geom][knots][reduction]") {
    std::mt19937 rng(66);
    const int degrees[][2] = {{2, 3}, {3, 3}, {4, 2}, {1, 3}};
    for (const auto& d : degrees) {
        const Surface base = rationalBase(rng, d[0], d[1], d[0] == 3 ? 1e3 : 0.0);
        std::uniform_real_distribution<double> unit(0.02, 0.98), jitter(-2e-5, 2e-5);
        std::vector<double> iu, iv;
        for (int i = 0; i < 10; ++i) iu.push_back(unit(rng)), iv.push_back(unit(rng));
        Surface s = refineKnotsV(refineKnotsU(base, iu), iv);
        for (glm::dvec3& q : s.points) q += glm::dvec3(jitter(rng), jitter(rng), jitter(rng));
        for (ReductionDirection dir : {ReductionDirection::U, ReductionDirection::Both}) {
            ReductionOptions o;
            o.tolerance = 1e-3;
            const SurfaceReduction r = reduceSurface(s, dir, o);
            INFO("degrees " << d[0] << "," << d[1] << " direction " << static_cast<int>(dir));
            REQUIRE(r.surface.rational());
            REQUIRE(r.surface.countU == s.countU - r.removedU);
            REQUIRE(r.surface.countV == s.countV - r.removedV);
            REQUIRE(r.removedU >= 5);
            if (dir == ReductionDirection::Both) REQUIRE(r.removedV >= 5);
            REQUIRE(r.deviation.maxError <= o.tolerance);
            REQUIRE(measureDeviation(s, r.surface, 6).maxError <= o.tolerance * 1.001);
        }
    }
}

TEST_CASE("the curve deviation follows a peak between its samples", "[geom][knots][reduction]") {
    // One control point moved: the two curves part in a bump over degree + 1 spans whose top
    // lies anywhere between the samples. The measured maxima must be at least those of sampling
    // 512 times per span, and not far above (where the nearest point switches from one piece to
    // another the peak is a ridge, which dense samples meet only to 1e-3 of it), by the plain
    // measurement and by the meter's.
    std::mt19937 rng(5122026);
    std::uniform_real_distribution<double> unit(-1.0, 1.0);
    for (int member = 0; member < 40; ++member) {
        const int p = 1 + member % 7;
        const Curve c =
            geomtest::randomCurve(rng, p, static_cast<std::size_t>(p) + 2 + rng() % 6, false, true);
        Curve moved = c;
        const std::size_t i = rng() % c.points.size();
        moved.points[i] += 1e-3 * glm::dvec3(unit(rng), unit(rng), unit(rng));
        auto dense = [](const Curve& from, const Curve& to) {
            const CurveProjector projector(to);
            double worst = 0.0;
            for (double u : spanSamples(from.knots, from.degree, from.points.size(), 512))
                worst = std::max(worst, projector.closestPoint(evaluate(from, u)).distance);
            return worst;
        };
        const double there = dense(c, moved), back = dense(moved, c);
        const std::size_t n = c.points.size();
        const ParameterMap identity{{c.knots[std::size_t(p)], c.knots[n]},
                                    {c.knots[std::size_t(p)], c.knots[n]}};
        INFO("member " << member << ", degree " << p << ", point " << i << " of " << n);
        for (const CurveDeviation& d :
             {measureDeviation(c, moved, 8), measureDeviation(c, moved, 8, identity)}) {
            CHECK(d.maxOriginalToReduced >= there * (1.0 - 1e-6));
            CHECK(d.maxOriginalToReduced <= there * (1.0 + 5e-3));
            CHECK(d.maxReducedToOriginal >= back * (1.0 - 1e-6));
            CHECK(d.maxReducedToOriginal <= back * (1.0 + 5e-3));
        }
    }
}

TEST_CASE("the surface deviation follows a peak between its grid vertices", "[geom][knots][reduction]") {
    // One control point moved: the surfaces part in a bump whose top lies anywhere between the
    // grid's vertices, where the grid alone reported up to a sixth less. The measured maxima must
    // reach those of a grid 8 times as dense (each vertex's global closest point) and not exceed
    // them by more than the dense grid misses (at a crease the peak is a ridge, which the dense
    // grid meets only to 3%).
    std::mt19937 rng(6122026);
    std::uniform_real_distribution<double> unit(-1.0, 1.0);
    for (int member = 0; member < membersForBuild(24); ++member) {
        const int p = 1 + member % 5, q = 1 + (member / 5) % 5;
        const Surface s = geomtest::bumpySurface(rng, p, q, std::size_t(p) + 2 + rng() % 4,
                                                 std::size_t(q) + 2 + rng() % 4, false);
        Surface moved = s;
        const std::size_t k = rng() % s.points.size();
        moved.points[k] += 1e-3 * glm::dvec3(unit(rng), unit(rng), unit(rng));
        auto dense = [](const Surface& from, const Surface& to) {
            const SurfaceProjector projector(to);
            double worst = 0.0;
            for (double u : spanSamples(from.knotsU, from.degreeU, from.countU, 32))
                for (double v : spanSamples(from.knotsV, from.degreeV, from.countV, 32))
                    worst = std::max(worst, projector.closestPoint(evaluate(from, u, v)).distance);
            return worst;
        };
        const double there = dense(s, moved), back = dense(moved, s);
        INFO("member " << member << ", degrees " << p << ", " << q << ", point " << k);
        const SurfaceDeviation d = measureDeviation(s, moved, 4);
        CHECK(d.maxOriginalToReduced >= there * (1.0 - 1e-4));
        CHECK(d.maxOriginalToReduced <= there * 1.05);
        CHECK(d.maxReducedToOriginal >= back * (1.0 - 1e-4));
        CHECK(d.maxReducedToOriginal <= back * 1.05);
    }
}

TEST_CASE("curve reduction and deviation above the power-form degree limit", "[geom][knots][reduction]") {
    // Degrees above 7 take Cox-de Boor instead of the span power form in sampling and Newton.
    std::mt19937 rng(65);
    for (int p : {7, 8}) {
        const Curve c = noisyRefinedCurve(rng, p, 30, 2e-4);
        for (int mode = 0; mode < 3; ++mode) {
            const bool batch = mode == 2;
            ReductionOptions o;
            o.tolerance = 1e-3;
            o.freeKnots = mode == 0;
            o.batch = batch;
            const CurveReduction r = reduceCurve(c, o);
            INFO("degree " << p << " mode " << mode);
            REQUIRE(r.removed > 10);
            REQUIRE(r.deviation.maxError <= o.tolerance);
            REQUIRE(measureDeviation(c, r.curve, 64).maxError <= o.tolerance * 1.001);
            const CurveProjector projector(c);
            double worst = 0.0;
            // The report samples a free-knot fit four times as densely as the original.
            const int density = r.freeKnotFit ? 64 : 16;
            for (double u : spanSamples(r.curve.knots, r.curve.degree, r.curve.points.size(), density))
                worst = std::max(worst, projector.closestPoint(evaluate(r.curve, u)).distance);
            // At least the samples' largest: the peaks between them are followed too.
            REQUIRE(r.deviation.maxReducedToOriginal >= worst * (1.0 - 1e-12));
        }
    }
}

TEST_CASE("a long, densely refined curve reduces to about its simpler curve", "[geom][knots][reduction]") {
    // A wandering cubic path of 100 poles with 2,400 knots inserted and every pole moved by up
    // to 1e-6: among so many neighbours the knots that matter weigh no more than the inserted
    // ones, so the significant-knot check cannot see that the curve is refined; the moved-knot
    // fit at the model's count then misses by far more than on a smooth curve, and the removal
    // loop must run too (the search alone kept about three times the simpler curve's points).
    // Not every member yet: of these six, trial 5 still keeps 280 points (the refined-curve test
    // misjudges it), so the claim is five of six.
    std::mt19937 rng(88);
    int nearSimple = 0;
    for (int trial = 0; trial < 6; ++trial) {
        std::normal_distribution<double> step(0.0, 1.0);
        std::vector<glm::dvec3> points{glm::dvec3(0.0)};
        glm::dvec3 v(1.0, 0.0, 0.0);
        while (points.size() < 100) {
            v = 0.7 * v + glm::dvec3{step(rng), step(rng), 0.3 * step(rng)};  // braces: drawn in order
            points.push_back(points.back() + v);
        }
        std::vector<double> knots(4, 0.0);
        for (int i = 1; i <= 96; ++i) knots.push_back(i / 97.0);
        knots.insert(knots.end(), 4, 1.0);
        const Curve simple(3, knots, points);
        std::uniform_real_distribution<double> unit(0.01, 0.99), jitter(-1e-6, 1e-6);
        std::vector<double> inserted;
        for (int i = 0; i < 2400; ++i) inserted.push_back(unit(rng));
        Curve refined = refineKnots(simple, inserted);
        for (glm::dvec3& q : refined.points) q += glm::dvec3{jitter(rng), jitter(rng), jitter(rng)};
        ReductionOptions o;
        o.tolerance = 1e-3;
        o.report = false;
        const CurveReduction r = reduceCurve(refined, o);
        INFO("trial " << trial << ": " << r.curve.points.size() << " points (free-knot fit: " << r.freeKnotFit
                      << ")");
        nearSimple += r.curve.points.size() <= 135 ? 1 : 0;
        REQUIRE(measureDeviation(refined, r.curve).maxError <= o.tolerance);
    }
    REQUIRE(nearSimple >= 5);
}

}  // namespace test_knot_reduction

namespace test_knot_reduction {

/// The largest relative difference of the derivatives 1 .. order at the two ends of a curve.
double seamJump(const Curve& c, int order) {
    if (order < 1) return 0.0;
    const std::vector<glm::dvec3> a = derivatives(c, c.domainStart(), order),
                                  b = derivatives(c, c.domainEnd(), order);
    double jump = 0.0;
    for (int k = 1; k <= order; ++k) {
        const double scale = std::max(glm::length(a[std::size_t(k)]), glm::length(b[std::size_t(k)]));
        if (scale > 0.0) jump = std::max(jump, glm::length(a[std::size_t(k)] - b[std::size_t(k)]) / scale);
    }
    return jump;
}

/// The angle in degrees between the tangents at the two ends of a curve.
double seamAngle(const Curve& c) {
    const glm::dvec3 a = derivatives(c, c.domainStart(), 1)[1], b = derivatives(c, c.domainEnd(), 1)[1];
    return std::atan2(glm::length(glm::cross(a, b)), glm::dot(a, b)) * 180.0 / M_PI;
}

TEST_CASE("reduceCurve keeps the end points of unclamped and closed curves, closed ones stay closed",
          "[geom][reduction]") {
    // Unclamped and periodic curves were reduced as they were: ends moved by up to the tolerance
    // and a closed curve came back open by more than it (a tester's 5 of 40 periodic curves).
    std::mt19937 rng(99);
    std::uniform_real_distribution<double> unit(-1.0, 1.0);
    for (int member = 0; member < 60; ++member) {
        const int p = 1 + member % 5;
        const bool rational = member % 3 == 0, closed = member % 2 == 0;
        const std::size_t n = 20 + rng() % 20;
        std::vector<glm::dvec3> points;
        std::vector<double> weights;
        for (std::size_t i = 0; i < n; ++i) {
            const double a = 2.0 * M_PI * double(i) / double(n),
                         r = 1.0 + 0.2 * std::sin(5.0 * a) + 0.02 * unit(rng);
            points.push_back({r * std::cos(a), r * std::sin(a), 0.1 * std::cos(3.0 * a)});
            if (rational) weights.push_back(std::pow(10.0, 0.5 * unit(rng)));
        }
        Curve c = closed ? makePeriodicCurve(p, points, weights) : Curve{};
        if (!closed) {
            std::vector<double> knots(n + std::size_t(p) + 1);
            for (std::size_t k = 0; k < knots.size(); ++k) knots[k] = double(k);  // uniform, unclamped
            c = Curve(p, knots, points, weights);
        }
        ReductionOptions o;
        o.tolerance = 0.02;
        const CurveReduction r = reduceCurve(c, o);
        INFO("member " << member << ": degree " << p << (rational ? ", rational" : "")
                       << (closed ? ", closed" : ""));
        const glm::dvec3 a = evaluate(c, c.domainStart()), b = evaluate(c, c.domainEnd());
        CHECK(glm::length(evaluate(r.curve, r.curve.domainStart()) - a) <= 1e-12);
        CHECK(glm::length(evaluate(r.curve, r.curve.domainEnd()) - b) <= 1e-12);
        CHECK(r.curve.points.size() <= c.points.size());
        CHECK(r.removed == c.points.size() - r.curve.points.size());
        CHECK(measureDeviation(c, r.curve).maxError <= o.tolerance);
        // A closed curve stays smooth across its seam: C^(p-1), as periodic (the ends were
        // reduced apart: 1-6 degree kinks).
        if (closed) {
            CHECK(seamJump(c, p - 1) <= 1e-9);
            CHECK(seamJump(r.curve, p - 1) <= 1e-8);
        }
    }
}

TEST_CASE("reduceCurve keeps a closed curve's seam as smooth as it was, and only a closed one's",
          "[geom][reduction]") {
    // Random closed curves of degrees 2-7 meeting C^(p-1), G1 only (clamped, tangents of different
    // lengths) or at a corner, and open ones, up to 300 points, up to 1e6 of their size from the
    // origin (there the derivatives' rounding once hid the seam's order): the seam keeps what it
    // had; where it had nothing to keep (a corner, an open curve) the result is the one
    // keepSeams = false gives.
    std::mt19937 rng(2027);
    std::uniform_real_distribution<double> unit(-1.0, 1.0);
    for (int member = 0; member < 48; ++member) {
        const int p = 2 + member % 6, kind = (member / 6) % 4;  // periodic, G1, corner, open
        const std::size_t n = member % 3 == 0 ? 250 + rng() % 50 : 40 + rng() % 40;
        const glm::dvec3 offset =
            std::pow(10.0, 3.0 * (1.0 + unit(rng))) * glm::dvec3(unit(rng), unit(rng), 0.0);
        std::vector<glm::dvec3> ring;
        const double lobes = 2.0 + double(rng() % 4), noise = 5e-5 * (1.0 + unit(rng));
        for (std::size_t i = 0; i < n; ++i) {
            const double a = 2.0 * M_PI * double(i) / double(n), r = 1.0 + 0.25 * std::cos(lobes * a);
            ring.push_back(offset + glm::dvec3(r * std::cos(a), r * std::sin(a), 0.2 * std::sin(a)) +
                           noise * glm::dvec3(unit(rng), unit(rng), unit(rng)));
        }
        Curve c = clampEnds(makePeriodicCurve(p, ring));
        if (kind == 1) {  // G1: the tangent at the start three times as long (points 1 and n - 2 moved)
            const glm::dvec3 joint = c.points.front();
            c.points[1] = joint + 3.0 * (c.points[1] - joint);
        } else if (kind == 2) {  // a corner: the first leg turned
            c.points[1] += 0.2 * glm::dvec3(unit(rng), unit(rng), 0.3);
        } else if (kind == 3) {  // open: the last point moved off the first
            c.points.back() += glm::dvec3(0.05, 0.0, 0.0);
        }
        ReductionOptions o;
        o.tolerance = 1e-3 * std::pow(10.0, 1.0 + unit(rng));
        const CurveReduction r = reduceCurve(c, o);
        INFO("member " << member << ": degree " << p << ", kind " << kind << ", offset " << offset.x << " "
                       << offset.y << ", " << c.points.size() << " -> " << r.curve.points.size());
        CHECK(r.curve.points.size() < c.points.size());
        CHECK(measureDeviation(c, r.curve).maxError <= o.tolerance);
        // As smooth as it was: the original's own seam jump (rounding, from 1e-16 at the origin to
        // about 1e-5 in the fourth derivative 1e6 away) and no more.
        if (kind == 0) CHECK(seamJump(r.curve, p - 1) <= 1e-8 + 2.0 * seamJump(c, p - 1));
        if (kind == 1) {
            CHECK(seamAngle(c) <= 1e-6);
            CHECK(seamAngle(r.curve) <= 1e-6);
        }
        if (kind >= 2) {
            ReductionOptions apart = o;
            apart.keepSeams = false;
            const CurveReduction plain = reduceCurve(c, apart);
            CHECK(plain.curve.knots == r.curve.knots);
            CHECK(plain.curve.points == r.curve.points);
        }
    }
}

TEST_CASE("reduceSurface keeps the edges of periodic surfaces and a closed seam closed",
          "[geom][reduction]") {
    // A surface periodic in one direction was reduced as it was: a V reduction moved its corners
    // and opened its seam by up to 0.7 of the tolerance (a tester's 5 of 18).
    std::mt19937 rng(1234);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    const ReductionDirection directions[] = {ReductionDirection::U, ReductionDirection::V,
                                             ReductionDirection::Both};
    for (int member = 0; member < 36; ++member) {
        const bool periodicU = member % 2 == 1;
        const std::size_t along = 6 + rng() % 12, around = 8 + rng() % 12;
        const int p = 1 + int(rng() % 5), q = 1 + 2 * int(rng() % 3);  // q odd: a periodic degree
        std::vector<glm::dvec3> grid;
        for (std::size_t i = 0; i < along; ++i)
            for (std::size_t j = 0; j < around; ++j) {
                const double a = 2.0 * M_PI * double(j) / double(around),
                             r = 1.0 + 0.3 * std::sin(0.8 * double(i)) + 1e-3 * unit(rng);
                grid.push_back({r * std::cos(a), r * std::sin(a), 0.5 * double(i)});
            }
        Surface s = interpolateSurface(grid, along, around, p, q, Closure::Open, Closure::Periodic);
        if (periodicU)
            s = Surface(s.degreeV, s.degreeU, s.knotsV, s.knotsU, s.countV, s.countU, [&] {
                std::vector<glm::dvec3> t;
                for (std::size_t j = 0; j < s.countV; ++j)
                    for (std::size_t i = 0; i < s.countU; ++i) t.push_back(s.point(i, j));
                return t;
            }());
        ReductionOptions o;
        o.tolerance = 0.002 * std::pow(10.0, 1.5 * unit(rng));
        const ReductionDirection direction = directions[member % 3];
        const SurfaceReduction r = reduceSurface(s, direction, o);
        INFO("member " << member << ": degrees " << s.degreeU << ", " << s.degreeV << ", periodic in "
                       << (periodicU ? "u" : "v") << ", direction " << int(direction));
        CHECK(r.surface.points.size() <= s.points.size());
        CHECK(r.removedU == s.countU - r.surface.countU);
        CHECK(r.removedV == s.countV - r.surface.countV);
        CHECK(measureDeviation(s, r.surface).maxError <= o.tolerance);
        double seam = 0.0, corner = 0.0;
        for (int k = 0; k <= 40; ++k) {
            const double t = double(k) / 40.0;
            const auto at = [&](const Surface& x, double w, bool end) {
                return periodicU ? evaluate(x, end ? x.domainEndU() : x.domainStartU(),
                                            x.domainStartV() + w * (x.domainEndV() - x.domainStartV()))
                                 : evaluate(x, x.domainStartU() + w * (x.domainEndU() - x.domainStartU()),
                                            end ? x.domainEndV() : x.domainStartV());
            };
            seam = std::max(seam, glm::length(at(r.surface, t, false) - at(r.surface, t, true)));
            for (const bool end : {false, true})
                corner = std::max(
                    corner, glm::length(at(r.surface, t, end) - at(s, t, end)) * double(k == 0 || k == 40));
        }
        CHECK(seam <= 1e-12);
        CHECK(corner <= 1e-12);
        // Smooth across the seam as well (C^(q-1), as periodic): every row across it.
        const bool acrossSeamReduced =
            direction == ReductionDirection::Both || (direction == ReductionDirection::U) == periodicU;
        for (std::size_t row = 0;
             acrossSeamReduced && row < (periodicU ? r.surface.countV : r.surface.countU); ++row) {
            Curve line;
            line.degree = periodicU ? r.surface.degreeU : r.surface.degreeV;
            line.knots = periodicU ? r.surface.knotsU : r.surface.knotsV;
            for (std::size_t k = 0; k < (periodicU ? r.surface.countU : r.surface.countV); ++k)
                line.points.push_back(periodicU ? r.surface.point(k, row) : r.surface.point(row, k));
            CHECK(seamJump(line, line.degree - 1) <= 1e-8);
        }
    }
}

}  // namespace test_knot_reduction
