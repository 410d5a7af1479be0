#include "GeomTestUtil.h"
#include "geom/Basis.h"
#include "geom/BezierExtraction.h"
#include "geom/Evaluate.h"
#include "geom/GeometryError.h"
#include "geom/KnotInsertion.h"

#include <catch2/catch.hpp>
#include <glm/geometric.hpp>

#include <limits>

namespace test_knot_insertion {

using namespace geom;
using geomtest::randomCurve;
using geomtest::randomSurface;

namespace {

double maxCurveDistance(const Curve& a, const Curve& b, int samples = 97) {
    double worst = 0.0;
    const double lo = a.domainStart(), hi = a.domainEnd();
    for (int i = 0; i <= samples; ++i) {
        const double u = lo + (hi - lo) * i / samples;
        worst = std::max(worst, glm::length(evaluate(a, u) - evaluate(b, u)));
    }
    return worst;
}

double maxSurfaceDistance(const Surface& a, const Surface& b, int samples = 13) {
    double worst = 0.0;
    for (int i = 0; i <= samples; ++i)
        for (int j = 0; j <= samples; ++j) {
            const double u = a.domainStartU() + (a.domainEndU() - a.domainStartU()) * i / samples;
            const double v = a.domainStartV() + (a.domainEndV() - a.domainStartV()) * j / samples;
            worst = std::max(worst, glm::length(evaluate(a, u, v) - evaluate(b, u, v)));
        }
    return worst;
}

}  // namespace

TEST_CASE("knot insertion keeps the curve's shape", "[geom][knots]") {
    std::mt19937 rng(11);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    for (int trial = 0; trial < 60; ++trial) {
        const int p = 1 + trial % 6;
        const bool clamped = trial % 3 != 0;
        const Curve c =
            randomCurve(rng, p, static_cast<std::size_t>(p + 1 + trial % 5), trial % 2 == 0, clamped);
        const double u = c.domainStart() + unit(rng) * (c.domainEnd() - c.domainStart());
        const int times = 1 + trial % p;
        const Curve d = insertKnot(c, u, times);
        REQUIRE(d.knots.size() == c.knots.size() + static_cast<std::size_t>(times));
        REQUIRE(d.points.size() == c.points.size() + static_cast<std::size_t>(times));
        REQUIRE(knotMultiplicity(d.knots, u) == times);
        REQUIRE(d.rational() == c.rational());
        REQUIRE_NOTHROW(validate(d));
        REQUIRE(maxCurveDistance(c, d) < 1e-12);
    }
}

TEST_CASE("knot insertion at an existing knot and at an unclamped domain end", "[geom][knots]") {
    std::mt19937 rng(5);
    const Curve c = randomCurve(rng, 3, 7, true, false);
    const Curve atEnd = insertKnot(c, c.domainEnd(), 2);
    REQUIRE(maxCurveDistance(c, atEnd) < 1e-12);
    const Curve atStart = insertKnot(c, c.domainStart(), 2);
    REQUIRE(maxCurveDistance(c, atStart) < 1e-12);
    // Multiplicity 3 at the start of a cubic: the curve starts at a control point.
    REQUIRE(glm::length(evaluate(atStart, atStart.domainStart()) - atStart.points[2]) < 1e-12);
    const Curve twice = insertKnot(insertKnot(c, c.knots[4], 1), c.knots[4], 1);
    REQUIRE(knotMultiplicity(twice.knots, c.knots[4]) == 3);
    REQUIRE(maxCurveDistance(c, twice) < 1e-12);
}

TEST_CASE("refinement of many knots equals repeated insertion", "[geom][knots]") {
    std::mt19937 rng(23);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    for (int trial = 0; trial < 40; ++trial) {
        const int p = 1 + trial % 5;
        const Curve c = randomCurve(rng, p, static_cast<std::size_t>(p + 3), trial % 2 == 1, trial % 4 != 0);
        std::vector<double> extra;
        for (int i = 0; i < 6; ++i)
            extra.push_back(c.domainStart() + unit(rng) * (c.domainEnd() - c.domainStart()));
        if (p >= 2) extra.push_back(extra[0]);                           // a repeated value
        if (trial % 4 == 0 && p >= 2) extra.push_back(c.domainEnd());    // unclamped end
        if (trial % 4 == 0 && p >= 2) extra.push_back(c.domainStart());  // unclamped start
        const Curve refined = refineKnots(c, extra);
        Curve repeated = c;
        for (double x : extra) repeated = insertKnot(repeated, x, 1);
        REQUIRE(refined.knots.size() == c.knots.size() + extra.size());
        REQUIRE(refined.knots == repeated.knots);
        REQUIRE_NOTHROW(validate(refined));
        for (std::size_t i = 0; i < refined.points.size(); ++i)
            REQUIRE(glm::length(refined.points[i] - repeated.points[i]) < 1e-12);
        REQUIRE(maxCurveDistance(c, refined) < 1e-12);
    }
}

TEST_CASE("surface knot insertion and refinement keep the shape", "[geom][knots]") {
    std::mt19937 rng(31);
    for (int trial = 0; trial < 8; ++trial) {
        const Surface s =
            randomSurface(rng, 2 + trial % 3, 1 + trial % 4, 6, 5, trial % 2 == 0, trial % 3 != 0);
        const double um = 0.5 * (s.domainStartU() + s.domainEndU());
        const double vm = 0.3 * s.domainStartV() + 0.7 * s.domainEndV();
        const Surface a = insertKnotU(s, um, 1);
        REQUIRE(a.countU == s.countU + 1);
        REQUIRE(a.countV == s.countV);
        REQUIRE(maxSurfaceDistance(s, a) < 1e-12);
        const Surface b = insertKnotV(s, vm, 1);
        REQUIRE(b.countV == s.countV + 1);
        REQUIRE(maxSurfaceDistance(s, b) < 1e-12);
        const std::vector<double> ku{um, um * 0.9 + 0.1 * s.domainStartU(), s.domainEndU() * 0.8 + 0.2 * um};
        const std::vector<double> kv{vm, 0.5 * (s.domainStartV() + vm)};
        const Surface c = refineKnotsV(refineKnotsU(s, ku), kv);
        REQUIRE(c.countU == s.countU + 3);
        REQUIRE(c.countV == s.countV + 2);
        REQUIRE_NOTHROW(validate(c));
        REQUIRE(maxSurfaceDistance(s, c) < 1e-12);
    }
}

TEST_CASE("Bezier extraction of curves gives one exact piece per span", "[geom][bezier]") {
    std::mt19937 rng(41);
    for (int trial = 0; trial < 30; ++trial) {
        const int p = 1 + trial % 7;
        const Curve c =
            randomCurve(rng, p, static_cast<std::size_t>(p + 1 + trial % 6), trial % 2 == 0, trial % 3 != 0);
        const auto pieces = extractBezier(c);
        std::size_t spans = 0;
        for (std::size_t k = static_cast<std::size_t>(p); k < c.points.size(); ++k)
            if (c.knots[k] < c.knots[k + 1]) ++spans;
        REQUIRE(pieces.size() == spans);
        REQUIRE(pieces.front().start == c.domainStart());
        REQUIRE(pieces.back().end == c.domainEnd());
        for (std::size_t i = 0; i < pieces.size(); ++i) {
            const BezierCurvePiece& piece = pieces[i];
            REQUIRE(piece.curve.points.size() == static_cast<std::size_t>(p + 1));
            REQUIRE(piece.curve.rational() == c.rational());
            REQUIRE_NOTHROW(validate(piece.curve));
            if (i > 0) REQUIRE(piece.start == pieces[i - 1].end);
            REQUIRE(c.knots[piece.span] == piece.start);
            REQUIRE(c.knots[piece.span + 1] == piece.end);
            for (int s = 0; s <= 10; ++s) {
                const double u = piece.start + (piece.end - piece.start) * s / 10.0;
                INFO("trial " << trial << " piece " << i << " u " << u << " p " << p);
                REQUIRE(glm::length(evaluate(piece.curve, u) - evaluate(c, u)) < 1e-12);
            }
        }
    }
}

TEST_CASE("Bezier extraction of a high degree curve and of a surface", "[geom][bezier]") {
    std::mt19937 rng(43);
    const Curve high = randomCurve(rng, 25, 40, true, true);
    const auto pieces = extractBezier(high);
    for (const auto& piece : pieces)
        for (int s = 0; s <= 4; ++s) {
            const double u = piece.start + (piece.end - piece.start) * s / 4.0;
            REQUIRE(glm::length(evaluate(piece.curve, u) - evaluate(high, u)) < 1e-12);
        }

    for (int trial = 0; trial < 4; ++trial) {
        const Surface s = randomSurface(rng, 3, 2, 7, 5, trial % 2 == 0, trial != 1);
        const auto patches = extractBezier(s);
        REQUIRE(patches.size() >= 2);
        for (std::size_t i = 0; i < patches.size(); ++i) {
            const BezierSurfacePiece& patch = patches[i];
            REQUIRE(patch.surface.countU == 4);
            REQUIRE(patch.surface.countV == 3);
            REQUIRE(s.knotsU[patch.spanU] == patch.u0);
            REQUIRE(s.knotsV[patch.spanV] == patch.v0);
            if (i > 0) {
                const auto& prev = patches[i - 1];
                REQUIRE(
                    (prev.spanU < patch.spanU || (prev.spanU == patch.spanU && prev.spanV < patch.spanV)));
            }
            for (int a = 0; a <= 4; ++a)
                for (int b = 0; b <= 4; ++b) {
                    const double u = patch.u0 + (patch.u1 - patch.u0) * a / 4.0;
                    const double v = patch.v0 + (patch.v1 - patch.v0) * b / 4.0;
                    REQUIRE(glm::length(evaluate(patch.surface, u, v) - evaluate(s, u, v)) < 1e-12);
                }
        }
    }
}

TEST_CASE("bad knot insertions are refused", "[geom][knots]") {
    std::mt19937 rng(3);
    const Curve c = randomCurve(rng, 3, 6, false, true);
    REQUIRE_THROWS_WITH(insertKnot(c, 1.5), Catch::Contains("outside the domain"));
    REQUIRE_THROWS_WITH(insertKnot(c, std::nan("")), Catch::Contains("outside the domain"));
    REQUIRE_THROWS_WITH(insertKnot(c, 0.5, 4), Catch::Contains("above the degree"));
    REQUIRE_THROWS_WITH(insertKnot(c, 0.0, 1), Catch::Contains("above the degree"));
    REQUIRE_THROWS_WITH(insertKnot(c, 0.5, -1), Catch::Contains("-1 times"));
    const std::vector<double> tooMany{0.5, 0.5, 0.5, 0.5};
    REQUIRE_THROWS_WITH(refineKnots(c, tooMany), Catch::Contains("multiplicity"));
    const std::vector<double> outside{0.2, -0.1};
    REQUIRE_THROWS_AS(refineKnots(c, outside), GeometryError);
    const Surface s = randomSurface(rng, 2, 2, 4, 4, false, true);
    REQUIRE_THROWS_WITH(insertKnotV(s, 2.0), Catch::Contains("insertKnotV"));
    // The largest count at a knot already there: multiplicity + times must not wrap to a
    // negative int (it passed the check and asked for INT_MAX more control points).
    constexpr int most = std::numeric_limits<int>::max();
    for (double u : {c.knots[4], 0.0, 1.0})
        REQUIRE_THROWS_WITH(insertKnot(c, u, most), Catch::Contains("above the degree"));
    REQUIRE_THROWS_WITH(insertKnot(c, 0.5, most), Catch::Contains("above the degree"));
    REQUIRE_THROWS_WITH(insertKnotU(s, s.knotsU[3], most), Catch::Contains("insertKnotU"));
    REQUIRE_THROWS_WITH(insertKnotV(s, 0.0, most), Catch::Contains("above the degree"));
}

}  // namespace test_knot_insertion
