// A NURBS curve with an interior knot of multiplicity order (degree + 1) jumps there: ISO 9592-4
// asks only for a non-decreasing knot sequence, so PHIGS programs may give one. It is drawn as
// one run per continuous piece, and no chord joins the two ends of a jump.
#include "phigs/Phigs.h"

#include "geom/Evaluate.h"
#include "geom/Inversion.h"
#include "geom/Split.h"

#include <catch2/catch.hpp>
#include <glm/geometric.hpp>

#include <random>

namespace test_curve_breaks {

using namespace phigs;

namespace {

/// A random curve of `degree` with `breaks` jumps: pieces of 1-3 spans, knots from 0 upward
/// (clamped at the ends or not), each piece's control points offset from the last by a jump.
geom::Curve curveWithBreaks(std::mt19937& rng, int degree, int breaks, bool rational, bool clamped) {
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    const std::size_t p = std::size_t(degree);
    std::vector<double> knots;
    double at = 0.0;
    if (clamped) {
        knots.assign(p + 1, 0.0);
    } else {
        for (std::size_t k = 0; k <= p; ++k) knots.push_back(at), at += 0.1 + unit(rng);
        at = knots.back();  // the domain starts at knots[p]
    }
    for (int piece = 0; piece <= breaks; ++piece) {
        const int spans = 1 + int(unit(rng) * 3);
        for (int s = 1; s < spans; ++s) at += 0.2 + unit(rng), knots.push_back(at);
        at += 0.2 + unit(rng);
        if (piece < breaks || clamped) {
            knots.insert(knots.end(), p + 1, at);  // a break, or the clamped end
        } else {
            knots.push_back(at);
            for (std::size_t k = 0; k < p; ++k) at += 0.1 + unit(rng), knots.push_back(at);
        }
    }
    const std::size_t points = knots.size() - p - 1;
    std::vector<glm::dvec3> cps;
    std::vector<double> weights;
    glm::dvec3 walk(0.0);
    for (std::size_t i = 0; i < points; ++i) {
        // A jump of 10 between pieces: the first point after a break knot starts a new piece.
        const bool afterBreak =
            i > p && knots[i] == knots[i + p] && knots[i] > knots[p] && knots[i] < knots[points];
        walk += glm::dvec3(unit(rng), unit(rng) - 0.5, unit(rng) - 0.5) +
                (afterBreak ? glm::dvec3(0, 10, 0) : glm::dvec3(0));
        cps.push_back(walk);
        if (rational) weights.push_back(0.3 + 2.0 * unit(rng));
    }
    return geom::Curve(degree, knots, cps, weights);
}

}  // namespace

TEST_CASE("splitAtBreaks gives each continuous piece, equal to the curve inside it", "[geom][curve]") {
    std::mt19937 rng(11);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    for (int trial = 0; trial < 120; ++trial) {
        const int degree = 1 + trial % 4, breaks = trial % 3;
        const geom::Curve c = curveWithBreaks(rng, degree, breaks, trial % 2 == 1, trial % 5 != 0);
        const std::vector<geom::Curve> pieces = geom::splitAtBreaks(c);
        INFO("trial " << trial << " degree " << degree << " breaks " << breaks);
        REQUIRE(pieces.size() == std::size_t(breaks) + 1);
        CHECK(pieces.front().domainStart() == c.domainStart());
        CHECK(pieces.back().domainEnd() == c.domainEnd());
        for (std::size_t k = 0; k < pieces.size(); ++k) {
            if (k > 0) CHECK(pieces[k].domainStart() == pieces[k - 1].domainEnd());
            for (int i = 0; i < 8; ++i) {
                const double u =
                    pieces[k].domainStart() +
                    (0.02 + 0.96 * unit(rng)) * (pieces[k].domainEnd() - pieces[k].domainStart());
                CHECK(glm::length(geom::evaluate(pieces[k], u) - geom::evaluate(c, u)) < 1e-9);
            }
        }
    }
}

TEST_CASE("the closest point on a curve that jumps is a point evaluate() gives", "[geom][curve]") {
    // Near the end of the piece before a jump, the answer's u lies just below the knot (evaluate
    // at the knot gives the piece after it); near the start of the piece after, at the knot.
    std::mt19937 rng(17);
    for (int trial = 0; trial < 60; ++trial) {
        const geom::Curve c = curveWithBreaks(rng, 1 + trial % 4, 1, trial % 2 == 1, true);
        const std::vector<geom::Curve> pieces = geom::splitAtBreaks(c);
        const double knot = pieces[0].domainEnd();
        for (const glm::dvec3 query : {geom::evaluate(pieces[0], knot) + glm::dvec3(0, -0.01, 0),
                                       geom::evaluate(pieces[1], knot) + glm::dvec3(0, 0.01, 0)}) {
            const geom::CurvePoint global = geom::closestPoint(c, query);
            const geom::CurvePoint local = geom::closestPoint(c, query, knot);
            INFO("trial " << trial);
            for (const geom::CurvePoint& found : {global, local})
                CHECK(glm::length(geom::evaluate(c, found.u) - found.point) < 1e-9);
        }
    }
}

TEST_CASE("a curve with jumps is drawn as one run per piece, no chord across a jump", "[traverse]") {
    std::mt19937 rng(5);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    for (int trial = 0; trial < 60; ++trial) {
        Phigs phigs;
        phigs.open();
        Workstation& ws = phigs.openWorkstation(1, WorkstationType::OffscreenImage);
        const int degree = 1 + trial % 4, breaks = 1 + trial % 2;
        const geom::Curve c = curveWithBreaks(rng, degree, breaks, trial % 2 == 1, trial % 3 != 0);
        // Half the curves drawn whole, half over a range starting inside the first piece.
        double start = 0.0, end = 0.0;
        if (trial % 2) {
            const geom::Curve first = geom::splitAtBreaks(c).front();
            start = first.domainStart() + 0.5 * (first.domainEnd() - first.domainStart());
            end = c.domainEnd();
        }
        const int criteria = trial % 4 == 0 ? 6 : 1;  // chordal in WC, or a constant count
        phigs.store().openStructure(1);
        phigs.store().insert(ApproximationAttribute{ElementType::CurveApproximationCriteria, criteria,
                                                    criteria == 6 ? 1e-3 : 6.0, 0});
        phigs.store().insert(NurbsCurveElement{c, start, end});
        phigs.store().closeStructure();
        ws.postStructure(1, 0);
        const DrawList& list = ws.display();
        INFO("trial " << trial << " degree " << degree << " breaks " << breaks);
        REQUIRE(list.items.size() == std::size_t(breaks) + 1);
        for (const DrawItem& item : list.items) {
            const DrawCurve& drawn = primitiveAs<DrawCurve>(item.primitive);
            REQUIRE(drawn.points.size() >= 2);
            // Inside a piece consecutive points are close; a jump is 10 across.
            for (std::size_t i = 0; i + 1 < drawn.points.size(); ++i)
                CHECK(glm::length(drawn.points[i + 1] - drawn.points[i]) < 5.0);
            // Each run's ends are its piece's own ends (the left limit before a jump).
            CHECK(glm::length(drawn.points[0] - geom::evaluate(*drawn.curve, drawn.rangeStart)) < 1e-9);
            CHECK(glm::length(drawn.points[drawn.points.size() - 1] -
                              geom::evaluate(*drawn.curve, drawn.rangeEnd)) < 1e-9);
        }
    }
}

}  // namespace test_curve_breaks
