#include "GeomTestUtil.h"
#include "geom/Basis.h"
#include "geom/Deviation.h"
#include "geom/Evaluate.h"
#include "geom/GeometryError.h"
#include "geom/KnotInsertion.h"
#include "geom/KnotRemoval.h"
#include "geom/KnotSignificance.h"

#include <catch2/catch.hpp>
#include <glm/geometric.hpp>

#include <algorithm>

namespace test_knot_removal {

using namespace geom;
using geomtest::randomCurve;

namespace {

double maxPointDistance(const std::vector<glm::dvec3>& a, const std::vector<glm::dvec3>& b) {
    REQUIRE(a.size() == b.size());
    double worst = 0.0;
    for (std::size_t i = 0; i < a.size(); ++i) worst = std::max(worst, glm::length(a[i] - b[i]));
    return worst;
}

double maxKnotDifference(const std::vector<double>& a, const std::vector<double>& b) {
    REQUIRE(a.size() == b.size());
    double worst = 0.0;
    for (std::size_t i = 0; i < a.size(); ++i) worst = std::max(worst, std::abs(a[i] - b[i]));
    return worst;
}

// A value strictly between two distinct interior breakpoints, away from every knot.
double freshKnot(std::mt19937& rng, const Curve& c) {
    std::uniform_real_distribution<double> unit(0.1, 0.9);
    for (;;) {
        const double u = c.domainStart() + unit(rng) * (c.domainEnd() - c.domainStart());
        bool clear = true;
        for (double k : c.knots) clear = clear && std::abs(k - u) > 1e-3;
        if (clear) return u;
    }
}

}  // namespace

TEST_CASE("knot weights: an inserted knot weighs nothing, original knots weigh something",
          "[geom][knots][removal]") {
    std::mt19937 rng(21);
    for (int p = 2; p <= 5; ++p) {
        const Curve c = randomCurve(rng, p, static_cast<std::size_t>(p + 6), false, true);
        const double u = freshKnot(rng, c);
        const Curve d = insertKnot(c, u, 1);
        const std::vector<KnotSignificance> ranked = rankKnots(d);
        // Every distinct interior value is ranked once, in ascending weight.
        std::vector<double> interior;
        for (std::size_t i = static_cast<std::size_t>(p) + 1; i < d.points.size(); ++i)
            if (interior.empty() || interior.back() != d.knots[i]) interior.push_back(d.knots[i]);
        REQUIRE(ranked.size() == interior.size());
        for (std::size_t i = 1; i < ranked.size(); ++i) REQUIRE(ranked[i - 1].weight <= ranked[i].weight);
        REQUIRE(ranked.front().value == u);
        REQUIRE(ranked.front().weight < 1e-12);
        REQUIRE(ranked.front().multiplicity == 1);
        REQUIRE(ranked[1].weight > 1e-6);
        REQUIRE(d.knots[ranked.front().index] == u);
        REQUIRE(knotRemovalWeight(d, ranked.front().index) == ranked.front().weight);
    }
}

TEST_CASE("knot weights handle multiple knots and any degree", "[geom][knots][removal]") {
    std::mt19937 rng(22);
    for (int p = 2; p <= 5; ++p) {
        const Curve c = randomCurve(rng, p, static_cast<std::size_t>(p + 5), false, true);
        const double u = freshKnot(rng, c);
        // A double knot made by insertion: removing one occurrence is free.
        const Curve d = insertKnot(c, u, 2);
        const auto ranked = rankKnots(d);
        const auto it = std::find_if(ranked.begin(), ranked.end(),
                                     [&](const KnotSignificance& k) { return k.value == u; });
        REQUIRE(it != ranked.end());
        REQUIRE(it->multiplicity == 2);
        REQUIRE(it->weight < 1e-12);
        // An original knot raised to multiplicity 2: the extra occurrence is free, and asking by
        // the index of either occurrence gives the same answer.
        const double original = c.knots[static_cast<std::size_t>(p) + 3];
        REQUIRE(knotMultiplicity(c.knots, original) == 1);
        const Curve e = insertKnot(c, original, 1);
        const std::size_t last =
            static_cast<std::size_t>(std::upper_bound(e.knots.begin(), e.knots.end(), original) -
                                     e.knots.begin()) -
            1;
        REQUIRE(knotRemovalWeight(e, last - 1) == knotRemovalWeight(e, last));
        REQUIRE(knotRemovalWeight(e, last) < 1e-12);
    }
}

TEST_CASE("knot weights are the l-infinity error, no larger than a least-squares fit gives",
          "[geom][knots][removal]") {
    std::mt19937 rng(23);
    for (int p = 2; p <= 5; ++p) {
        const Curve c = randomCurve(rng, p, static_cast<std::size_t>(p + 7), false, true);
        for (const KnotSignificance& k : rankKnots(c)) {
            // Removing the knot with the smallest window (margin 0) is a best l2 fit on the same
            // coefficients; its max coefficient error cannot beat the best max-norm fit.
            const Curve r = removeKnotsLeastSquares(c, std::vector<double>{k.value}, {}, 0);
            const Curve back = insertKnot(r, k.value, 1);
            REQUIRE(k.weight <= maxPointDistance(back.points, c.points) * (1.0 + 1e-9) + 1e-12);
            REQUIRE(k.weight > 0.0);
        }
        // Scaling the curve scales the weights.
        Curve scaled = c;
        for (auto& q : scaled.points) q *= 3.0;
        const auto a = rankKnots(c), b = rankKnots(scaled);
        for (std::size_t i = 0; i < a.size(); ++i)
            REQUIRE(b[i].weight == Approx(3.0 * a[i].weight).epsilon(1e-9));
    }
}

TEST_CASE("knot weights reject knots that are not interior", "[geom][knots][removal]") {
    std::mt19937 rng(24);
    const Curve c = randomCurve(rng, 3, 8, false, true);
    REQUIRE_THROWS_AS(knotRemovalWeight(c, 0), GeometryError);
    REQUIRE_THROWS_AS(knotRemovalWeight(c, c.knots.size() - 1), GeometryError);
    REQUIRE_THROWS_AS(knotRemovalWeight(c, c.knots.size()), GeometryError);
    REQUIRE_THROWS_WITH(knotRemovalWeight(c, 1), Catch::Contains("not an interior knot"));
}

TEST_CASE("exact knot removal (A5.8) undoes knot insertion, rational too", "[geom][knots][removal]") {
    std::mt19937 rng(25);
    for (int trial = 0; trial < 24; ++trial) {
        const int p = 2 + trial % 4;
        const bool rational = trial % 2 == 1;
        const Curve c = randomCurve(rng, p, static_cast<std::size_t>(p + 4 + trial % 3), rational, true);
        const double u = freshKnot(rng, c);
        const int times = 1 + trial % p;
        const Curve d = insertKnot(c, u, times);
        const ExactKnotRemoval r = removeKnot(d, u, times, 1e-9);
        REQUIRE(r.removed == times);
        REQUIRE(r.curve.rational() == rational);
        REQUIRE(maxKnotDifference(r.curve.knots, c.knots) == 0.0);
        REQUIRE(maxPointDistance(r.curve.points, c.points) < 1e-10);
        if (rational)
            for (std::size_t i = 0; i < c.weights.size(); ++i)
                REQUIRE(r.curve.weights[i] == Approx(c.weights[i]).margin(1e-10));
    }
}

TEST_CASE("exact knot removal keeps a knot the curve needs and stops at the first that fails",
          "[geom][knots][removal]") {
    std::mt19937 rng(26);
    const Curve c = randomCurve(rng, 3, 9, false, true);
    const double original = c.knots[5];
    const ExactKnotRemoval none = removeKnot(c, original, 1, 1e-9);
    REQUIRE(none.removed == 0);
    REQUIRE(none.curve.knots == c.knots);
    // Inserted once on top of an original simple knot: one of the two goes, not both.
    const Curve d = insertKnot(c, original, 1);
    const ExactKnotRemoval one = removeKnot(d, original, 2, 1e-9);
    REQUIRE(one.removed == 1);
    REQUIRE(maxPointDistance(one.curve.points, c.points) < 1e-10);
    // With a generous tolerance the knot goes and the curve moves by no more than it.
    const double tol = 0.5;
    const ExactKnotRemoval loose = removeKnot(c, original, 1, tol);
    if (loose.removed == 1) REQUIRE(measureDeviation(c, loose.curve).maxError <= tol);
    REQUIRE_THROWS_AS(removeKnot(c, 0.0, 1), GeometryError);
    REQUIRE_THROWS_AS(removeKnot(c, original, 0), GeometryError);
    REQUIRE_THROWS_AS(removeKnot(c, 0.5 * (c.knots[4] + c.knots[5]) + 1e-7, 1), GeometryError);
}

TEST_CASE(
    "exact removal from a rational curve answers alike wherever the curve is placed, scaled or "
    "reweighted, and keeps its tolerance",
    "[geom][knots][removal]") {
    // The bound on a rational curve's homogeneous points once held 1 + |P|max and weights below
    // 1 side by side: a curve moved away from the origin, scaled, or with its weights multiplied
    // (the same curve) kept knots the same curve elsewhere lost. Random rational curves of
    // degrees 2-5 with weights over two decades, a knot inserted up to p times and the points
    // then disturbed, removed at tolerances over five decades of their size: the count must not
    // change under moving up to 1e4 sizes, scaling by 1e-3..1e3 and weights times 1e-2..1e2, and
    // the curve must move by no more than the tolerance.
    std::mt19937 rng(29);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    int removals = 0;
    for (int trial = 0; trial < 60; ++trial) {
        const int p = 2 + trial % 4;
        Curve c = randomCurve(rng, p, static_cast<std::size_t>(p + 4 + trial % 3), true, true);
        for (double& w : c.weights) w = std::pow(10.0, -1.0 + 2.0 * unit(rng));
        const double u = freshKnot(rng, c);
        const int times = 1 + trial % p;
        Curve d = insertKnot(c, u, times);
        const double noise = std::pow(10.0, -6.0 + 4.0 * unit(rng));
        for (glm::dvec3& q : d.points) q += noise * glm::dvec3(unit(rng), unit(rng), unit(rng));
        const double tolerance = std::pow(10.0, -5.0 + 4.0 * unit(rng));
        const ExactKnotRemoval plain = removeKnot(d, u, times, tolerance);
        INFO("trial " << trial << ", degree " << p << ", " << times << " times, noise " << noise
                      << ", tolerance " << tolerance << ": " << plain.removed << " removed");
        if (plain.removed > 0) REQUIRE(measureDeviation(d, plain.curve, 32).maxError <= tolerance);
        removals += plain.removed;
        const double scale = std::pow(10.0, -3.0 + 6.0 * unit(rng)),
                     weight = std::pow(10.0, -2.0 + 4.0 * unit(rng));
        const glm::dvec3 shift = 1e4 * glm::dvec3(unit(rng), unit(rng), unit(rng));
        Curve moved = d, scaled = d, reweighted = d;
        for (glm::dvec3& q : moved.points) q += shift;
        for (glm::dvec3& q : scaled.points) q *= scale;
        for (double& w : reweighted.weights) w *= weight;
        REQUIRE(removeKnot(moved, u, times, tolerance).removed == plain.removed);
        REQUIRE(removeKnot(scaled, u, times, scale * tolerance).removed == plain.removed);
        REQUIRE(removeKnot(reweighted, u, times, tolerance).removed == plain.removed);
    }
    REQUIRE(removals >= 40);
}

TEST_CASE("insert-then-remove gives the curve back wherever the knot lies, next to the ends too",
          "[geom][knots][removal][roundtrip]") {
    // A5.8 met its two recurrences in the middle: with a knot near a clamped end every alpha is
    // near 1 (or 0) and one side divided by tiny numbers, so an exact removal was refused (u =
    // 0.99876 on a degree-7 curve, at every tolerance up to 1e-8 of its size). Random curves of
    // degree 1..7, clamped or not, half rational with weights over six decades, scaled by
    // 1e-6..1e6; the knot anywhere, or within 1e-4 of the domain's width from either end. Each
    // must come off at 1e-9 of the curve's size and give the curve back within 1e-14 of it
    // (polynomial; measured: 4.4e-16) or 1e-11 (rational, where evaluating with weights six
    // decades apart rounds at 1e-16 x 1e6 already; measured: 1.7e-12).
    std::mt19937 rng(20261210);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    int tried = 0, refused = 0, moved = 0;
    for (int member = 0; member < 6000; ++member) {
        const int p = 1 + member % 7;
        const bool rational = member % 2 == 1, clamped = member % 4 != 3;
        const std::size_t count = static_cast<std::size_t>(p) + 1 + std::size_t(unit(rng) * 9.0);
        Curve c = randomCurve(rng, p, count, rational, clamped);
        const double scale = std::pow(10.0, -6.0 + 12.0 * unit(rng));
        for (glm::dvec3& q : c.points) q *= scale;
        for (double& w : c.weights) w = std::pow(10.0, -3.0 + 6.0 * unit(rng));
        const double a = c.domainStart(), b = c.domainEnd(), width = b - a;
        const double where = unit(rng), offset = 1e-4 * width * unit(rng);
        const double u = member % 3 == 0 ? a + offset : member % 3 == 1 ? b - offset : a + where * width;
        if (!(u > a && u < b) || knotMultiplicity(c.knots, u) > 0) continue;
        ++tried;
        double size = 0.0;
        for (const glm::dvec3& q : c.points)
            size = std::max({size, std::abs(q.x), std::abs(q.y), std::abs(q.z)});
        const ExactKnotRemoval r = removeKnot(insertKnot(c, u, 1), u, 1, 1e-9 * size);
        if (r.removed != 1) {
            ++refused;
            continue;
        }
        REQUIRE(r.curve.knots == c.knots);
        double error = 0.0;
        for (int k = 0; k <= 64; ++k) {
            const double x = a + width * k / 64.0;
            error = std::max(error, glm::length(evaluate(r.curve, x) - evaluate(c, x)));
        }
        moved += error > (rational ? 1e-11 : 1e-14) * size;
    }
    INFO(tried << " curves: " << refused << " refused, " << moved << " moved too far");
    REQUIRE(tried > 5000);
    REQUIRE(refused == 0);
    REQUIRE(moved == 0);
}

TEST_CASE("asking to remove a knot several times never removes fewer than asking once",
          "[geom][knots][removal][roundtrip]") {
    // A5.8 removes several occurrences together, its first step the solve that divides by numbers
    // near 0 next to a clamped end; where it stops short, one occurrence after another takes
    // over. Random curves of degree 2..7, polynomial and rational, a knot inserted 2..degree times
    // anywhere or within 1e-4 of the width from either end, then removed as often at 1e-9 of the
    // size: all of them come off, and the curve comes back within 1e-9 of its size.
    std::mt19937 rng(20261207);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    int tried = 0;
    for (int member = 0; member < 1200; ++member) {
        const int p = 2 + member % 6;
        const bool rational = member % 2 == 1;
        Curve c = randomCurve(rng, p, static_cast<std::size_t>(p) + 2 + std::size_t(unit(rng) * 6.0),
                              rational, true);
        const double a = c.domainStart(), b = c.domainEnd(), width = b - a;
        const double offset = 1e-4 * width * (0.1 + unit(rng));
        const double u = member % 3 == 0 ? a + offset : member % 3 == 1 ? b - offset : a + unit(rng) * width;
        if (!(u > a && u < b) || knotMultiplicity(c.knots, u) > 0) continue;
        ++tried;
        const int times = 2 + static_cast<int>(rng() % static_cast<unsigned>(p - 1));
        double size = 0.0;
        for (const glm::dvec3& q : c.points)
            size = std::max({size, std::abs(q.x), std::abs(q.y), std::abs(q.z)});
        const Curve d = insertKnot(c, u, times);
        const ExactKnotRemoval once = removeKnot(d, u, 1, 1e-9 * size);
        const ExactKnotRemoval all = removeKnot(d, u, times, 1e-9 * size);
        CAPTURE(member, p, rational, times, u);
        CHECK(all.removed >= once.removed);
        REQUIRE(all.removed == times);
        for (int k = 0; k <= 32; ++k) {
            const double x = a + width * k / 32.0;
            CHECK(glm::length(evaluate(all.curve, x) - evaluate(c, x)) <= 1e-9 * size);
        }
    }
    REQUIRE(tried > 1000);
}

TEST_CASE("least-squares removal of several nearby knots recovers the simpler curve",
          "[geom][knots][removal]") {
    std::mt19937 rng(27);
    for (int p = 2; p <= 5; ++p) {
        const Curve c = randomCurve(rng, p, static_cast<std::size_t>(p + 8), false, true);
        // Three new knots in one span and its neighbours.
        const double a = c.knots[static_cast<std::size_t>(p) + 3],
                     b = c.knots[static_cast<std::size_t>(p) + 4];
        const std::vector<double> inserted{a + 0.2 * (b - a), a + 0.5 * (b - a), a + 0.7 * (b - a)};
        const Curve d = refineKnots(c, inserted);
        for (int margin = 0; margin <= 2; ++margin) {
            const Curve r = removeKnotsLeastSquares(d, inserted, {}, margin);
            REQUIRE(maxKnotDifference(r.knots, c.knots) == 0.0);
            REQUIRE(maxPointDistance(r.points, c.points) < 1e-10);
        }
    }
}

TEST_CASE("least-squares removal keeps end conditions and reports its window", "[geom][knots][removal]") {
    std::mt19937 rng(28);
    const Curve r0 = randomCurve(rng, 3, 12, false, true);
    std::vector<double> uniform{0, 0, 0, 0};
    for (int i = 1; i <= 8; ++i) uniform.push_back(i / 9.0);
    for (int i = 0; i < 4; ++i) uniform.push_back(1.0);
    const Curve c(3, uniform, r0.points);
    const double near = c.knots[6];  // the third interior knot: its removal reaches the end points
    for (int fixed = 0; fixed <= 2; ++fixed) {
        EndConditions ends;
        ends.fixedDerivatives = fixed;
        const LeastSquaresRemoval r =
            removeKnotsLeastSquares(3, c.knots, c.points, 1, std::vector<double>{near}, ends);
        REQUIRE(r.points.size() == c.points.size() - 1);
        for (int k = 0; k <= fixed; ++k) {
            REQUIRE(r.points[static_cast<std::size_t>(k)] == c.points[static_cast<std::size_t>(k)]);
            REQUIRE(r.points[r.points.size() - 1 - static_cast<std::size_t>(k)] ==
                    c.points[c.points.size() - 1 - static_cast<std::size_t>(k)]);
        }
        REQUIRE(r.firstChanged > static_cast<std::size_t>(fixed));
        // Outside [changedFrom, changedTo] the curve is untouched.
        const Curve g(3, r.knots, r.points);
        for (double u = c.domainStart(); u <= c.domainEnd(); u += 0.01)
            if (u < r.changedFrom || u > r.changedTo)
                REQUIRE(glm::length(evaluate(g, u) - evaluate(c, u)) < 1e-12);
        // End derivatives held: the curve's derivatives at the ends agree up to `fixed`.
        const auto d0 = derivatives(c, c.domainStart(), fixed), e0 = derivatives(g, g.domainStart(), fixed);
        for (int k = 0; k <= fixed; ++k)
            REQUIRE(glm::length(d0[static_cast<std::size_t>(k)] - e0[static_cast<std::size_t>(k)]) < 1e-9);
    }
    EndConditions tangents;
    tangents.fixedDerivatives = 1;
    REQUIRE_THROWS_WITH(removeKnotsLeastSquares(c, std::vector<double>{c.knots[4]}, tangents),
                        Catch::Contains("end derivatives"));
    REQUIRE_THROWS_WITH(
        removeKnotsLeastSquares(c, std::vector<double>{c.knots[c.points.size() - 1]}, tangents),
        Catch::Contains("end derivatives"));
    REQUIRE_NOTHROW(removeKnotsLeastSquares(c, std::vector<double>{c.knots[5]}, tangents));
    REQUIRE_THROWS_WITH(removeKnotsLeastSquares(c, std::vector<double>{0.123456}),
                        Catch::Contains("not a knot"));
    REQUIRE_THROWS_WITH(removeKnotsLeastSquares(c, std::vector<double>{0.0}),
                        Catch::Contains("not an interior knot"));
    REQUIRE_THROWS_WITH(removeKnotsLeastSquares(c, std::vector<double>{c.knots[5], c.knots[5]}),
                        Catch::Contains("twice"));
    Curve rational = c;
    rational.weights.assign(c.points.size(), 1.0);
    REQUIRE_THROWS_WITH(removeKnotsLeastSquares(rational, std::vector<double>{c.knots[5]}),
                        Catch::Contains("rational"));
}

}  // namespace test_knot_removal
