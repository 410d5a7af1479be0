// Bad input at every public entry point of geom: objects whose fields were set by hand (empty or
// decreasing knots, too few points, sizes that disagree, non-finite numbers, zero weights),
// non-finite and out-of-domain parameters. Each must give GeometryError, never a crash.

#include "geom/Basis.h"
#include "geom/Bezier.h"
#include "geom/BezierExtraction.h"
#include "geom/BezierPatchTree.h"
#include "geom/BezierSubdivision.h"
#include "geom/BoundingBox.h"
#include "geom/ControlNet.h"
#include "geom/Curvature.h"
#include "geom/CurveProjector.h"
#include "geom/DataReduction.h"
#include "geom/DegreeElevation.h"
#include "geom/Deviation.h"
#include "geom/Evaluate.h"
#include "geom/FreeKnotFit.h"
#include "geom/GeometryError.h"
#include "geom/GlobalInterpolation.h"
#include "geom/GridEvaluator.h"
#include "geom/Interpolate.h"
#include "geom/Intersect.h"
#include "geom/Inversion.h"
#include "geom/KnotInsertion.h"
#include "geom/KnotRemoval.h"
#include "geom/KnotSignificance.h"
#include "geom/Primitives.h"
#include "geom/ReferenceShapes.h"
#include "geom/Reparameterize.h"
#include "geom/Split.h"
#include "geom/SurfaceIntersector.h"
#include "geom/SurfaceProjector.h"
#include "geom/Tessellate.h"
#include "geom/curvemap/CurveMapper.h"
#include "geom/curvemap/Placement.h"
#include "geom/curvemap/Staircase.h"
#include "geom/curvemap/SurfaceDomain.h"

#include "GeomTestUtil.h"

#include <catch2/catch.hpp>
#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <random>
#include <string>
#include <vector>

namespace test_bad_input {

using namespace geom;
using namespace geom::curvemap;

namespace {

const double kNaN = std::numeric_limits<double>::quiet_NaN();
const double kInf = std::numeric_limits<double>::infinity();

Curve validCurve(bool rational) {
    std::vector<glm::dvec3> pts;
    for (int i = 0; i < 7; ++i) pts.emplace_back(i, std::sin(i), 0.1 * i * i);
    return Curve(3, {0, 0, 0, 0, 0.25, 0.5, 0.75, 1, 1, 1, 1}, pts,
                 rational ? std::vector<double>(7, 1.0) : std::vector<double>{});
}

/// Hand-made breakages of a valid curve; each touches the span around u = 0.3 (span 4, points
/// 1..4), so that per-point evaluation there reads it too.
std::vector<std::pair<std::string, Curve>> brokenCurves() {
    std::vector<std::pair<std::string, Curve>> out;
    auto add = [&](const char* name, bool rational, const std::function<void(Curve&)>& breakIt) {
        Curve c = validCurve(rational);
        breakIt(c);
        out.emplace_back(name, c);
    };
    add("empty knots", false, [](Curve& c) { c.knots.clear(); });
    add("no points", false, [](Curve& c) { c.points.clear(); });
    add("too few points", false, [](Curve& c) { c.points.resize(2); });
    add("degree 0", false, [](Curve& c) { c.degree = 0; });
    add("negative degree", false, [](Curve& c) { c.degree = -2; });
    add("huge degree", false, [](Curve& c) { c.degree = 1 << 30; });
    add("a knot missing", false, [](Curve& c) { c.knots.pop_back(); });
    add("decreasing knots", false, [](Curve& c) { c.knots[5] = 0.1; });
    add("NaN knot", false, [](Curve& c) { c.knots[5] = kNaN; });
    add("empty domain", false, [](Curve& c) { c.knots.assign(c.knots.size(), 0.0); });
    add("NaN point", false, [](Curve& c) { c.points[3].x = kNaN; });
    add("infinite point", false, [](Curve& c) { c.points[2].y = kInf; });
    add("zero weight", true, [](Curve& c) { c.weights[3] = 0.0; });
    add("negative weight", true, [](Curve& c) { c.weights[2] = -1.0; });
    add("subnormal weight", true, [](Curve& c) { c.weights[3] = 1e-310; });
    add("weights for too few points", true, [](Curve& c) { c.weights.resize(3); });
    add("NaN weight", true, [](Curve& c) { c.weights[2] = kNaN; });
    add("infinite weight", true, [](Curve& c) { c.weights[3] = kInf; });
    add("infinite knots", false, [](Curve& c) { std::fill(c.knots.begin() + 6, c.knots.end(), kInf); });
    add("knot above degree + 1 times", false, [](Curve& c) {
        for (std::size_t i = 3; i <= 7; ++i) c.knots[i] = 0.3;
        c.knots[8] = 0.3;
    });
    add("degree above the points", false, [](Curve& c) { c.degree = 8; });
    return out;
}

Surface validSurface(bool rational) {
    std::vector<glm::dvec3> pts;
    for (int i = 0; i < 5; ++i)
        for (int j = 0; j < 4; ++j) pts.emplace_back(i, j, 0.1 * std::sin(i + j));
    return Surface(3, 2, {0, 0, 0, 0, 0.5, 1, 1, 1, 1}, {0, 0, 0, 0.5, 1, 1, 1}, 5, 4, pts,
                   rational ? std::vector<double>(20, 1.0) : std::vector<double>{});
}

/// Breakages of a valid surface; each touches the patch around (0.3, 0.3) (points i 1..4, j 0..2).
std::vector<std::pair<std::string, Surface>> brokenSurfaces() {
    std::vector<std::pair<std::string, Surface>> out;
    auto add = [&](const char* name, bool rational, const std::function<void(Surface&)>& breakIt) {
        Surface s = validSurface(rational);
        breakIt(s);
        out.emplace_back(name, s);
    };
    add("empty u knots", false, [](Surface& s) { s.knotsU.clear(); });
    add("empty v knots", false, [](Surface& s) { s.knotsV.clear(); });
    add("too few points", false, [](Surface& s) { s.points.resize(7); });
    add("net size disagrees", false, [](Surface& s) { s.countU = 6; });
    add("zero columns", false, [](Surface& s) { s.countV = 0; });
    add("degree 0", false, [](Surface& s) { s.degreeV = 0; });
    add("decreasing v knots", false, [](Surface& s) { s.knotsV[3] = -0.5; });
    add("NaN u knot", false, [](Surface& s) { s.knotsU[4] = kNaN; });
    add("NaN point", false, [](Surface& s) { s.points[2 * 4 + 1].z = kNaN; });
    add("zero weight", true, [](Surface& s) { s.weights[2 * 4 + 1] = 0.0; });
    add("subnormal weight", true, [](Surface& s) { s.weights[2 * 4 + 1] = 1e-310; });
    add("weights for too few points", true, [](Surface& s) { s.weights.resize(5); });
    add("NaN weight", true, [](Surface& s) { s.weights[2 * 4 + 1] = kNaN; });
    add("infinite v knots", false, [](Surface& s) { std::fill(s.knotsV.begin() + 4, s.knotsV.end(), kInf); });
    add("empty v domain", false, [](Surface& s) { s.knotsV.assign(s.knotsV.size(), 0.5); });
    add("u degree above the points", false, [](Surface& s) { s.degreeU = 6; });
    return out;
}

void requireAllThrow(const std::string& entry, const std::function<void(const Curve&)>& call) {
    for (const auto& [name, curve] : brokenCurves()) {
        INFO(entry << " with " << name);
        REQUIRE_THROWS_AS(call(curve), GeometryError);
    }
}

void requireAllThrow(const std::string& entry, const std::function<void(const Surface&)>& call) {
    for (const auto& [name, surface] : brokenSurfaces()) {
        INFO(entry << " with " << name);
        REQUIRE_THROWS_AS(call(surface), GeometryError);
    }
}

}  // namespace

TEST_CASE("every curve entry point refuses a hand-broken curve", "[geom][bad-input]") {
    const Curve good = validCurve(false);
    const glm::dvec3 p(1.0, 0.5, 0.2);
    requireAllThrow("evaluate", [](const Curve& c) { evaluate(c, 0.3); });
    requireAllThrow("derivatives", [](const Curve& c) { derivatives(c, 0.3, 2); });
    requireAllThrow("evaluateMany", [](const Curve& c) { evaluateMany(c, std::vector<double>{0.3, 0.6}); });
    requireAllThrow("extractBezier", [](const Curve& c) { extractBezier(c); });
    requireAllThrow("isBezier", [](const Curve& c) { isBezier(c); });
    requireAllThrow("insertKnot", [](const Curve& c) { insertKnot(c, 0.3); });
    requireAllThrow("refineKnots", [](const Curve& c) { refineKnots(c, std::vector<double>{0.3, 0.6}); });
    requireAllThrow("split", [](const Curve& c) { split(c, 0.3); });
    requireAllThrow("elevateDegree", [](const Curve& c) { elevateDegree(c, 1); });
    requireAllThrow("reverse", [](const Curve& c) { reverse(c); });
    requireAllThrow("reparameterize", [](const Curve& c) { reparameterize(c, 0.0, 2.0); });
    requireAllThrow("tessellate", [](const Curve& c) { tessellate(c, 1e-3); });
    requireAllThrow("CurveProjector", [](const Curve& c) { CurveProjector projector(c); });
    requireAllThrow("closestPoint", [&](const Curve& c) { closestPoint(c, p); });
    requireAllThrow("closestPoint from a guess", [&](const Curve& c) { closestPoint(c, p, 0.3); });
    requireAllThrow("rankKnots", [](const Curve& c) { rankKnots(c); });
    requireAllThrow("knotRemovalWeight", [](const Curve& c) { knotRemovalWeight(c, 5); });
    requireAllThrow("removeKnot", [](const Curve& c) { removeKnot(c, 0.5); });
    requireAllThrow("removeKnotsLeastSquares",
                    [](const Curve& c) { removeKnotsLeastSquares(c, std::vector<double>{0.5}); });
    requireAllThrow("reduceCurve", [](const Curve& c) {
        ReductionOptions options;
        options.tolerance = 1e-3;
        reduceCurve(c, options);
    });
    requireAllThrow("measureDeviation original", [&](const Curve& c) { measureDeviation(c, good); });
    requireAllThrow("measureDeviation reduced", [&](const Curve& c) { measureDeviation(good, c); });
    requireAllThrow("FreeKnotFitter", [](const Curve& c) { FreeKnotFitter fitter(c, FreeKnotOptions{}); });
    requireAllThrow("makeRevolution", [](const Curve& c) { makeRevolution(c); });
    requireAllThrow("boundingBox", [](const Curve& c) { boundingBox(c); });
}

TEST_CASE("every surface entry point refuses a hand-broken surface", "[geom][bad-input]") {
    const Surface good = validSurface(false);
    const glm::dvec3 p(1.0, 1.0, 0.5);
    requireAllThrow("evaluate", [](const Surface& s) { evaluate(s, 0.3, 0.3); });
    requireAllThrow("derivatives", [](const Surface& s) { derivatives(s, 0.3, 0.3, 2); });
    requireAllThrow("normal", [](const Surface& s) { normal(s, 0.3, 0.3); });
    requireAllThrow("curvature", [](const Surface& s) { curvature(s, 0.3, 0.3); });
    requireAllThrow("GridEvaluator", [](const Surface& s) { GridEvaluator grid(s); });
    requireAllThrow("extractBezier", [](const Surface& s) { extractBezier(s); });
    requireAllThrow("isBezier", [](const Surface& s) { isBezier(s); });
    requireAllThrow("BezierPatchTree", [](const Surface& s) { BezierPatchTree tree(s); });
    requireAllThrow("SurfaceProjector", [](const Surface& s) { SurfaceProjector projector(s); });
    requireAllThrow("closestPoint", [&](const Surface& s) { closestPoint(s, p); });
    requireAllThrow("closestPoint from a guess", [&](const Surface& s) { closestPoint(s, p, {0.3, 0.3}); });
    requireAllThrow("SurfaceIntersector", [](const Surface& s) { SurfaceIntersector intersector(s); });
    requireAllThrow("intersectLine", [](const Surface& s) { intersectLine(s, {1, 1, 5}, {0, 0, -1}); });
    requireAllThrow("tessellateUniform", [](const Surface& s) { tessellateUniform(s, 4, 4); });
    requireAllThrow("tessellateAdaptive", [](const Surface& s) { tessellateAdaptive(s, 1e-3); });
    requireAllThrow("insertKnotU", [](const Surface& s) { insertKnotU(s, 0.3); });
    requireAllThrow("insertKnotV", [](const Surface& s) { insertKnotV(s, 0.3); });
    requireAllThrow("refineKnotsU", [](const Surface& s) { refineKnotsU(s, std::vector<double>{0.3}); });
    requireAllThrow("split", [](const Surface& s) { split(s, 0.3, false); });
    requireAllThrow("reverse", [](const Surface& s) { reverse(s, true); });
    requireAllThrow("reparameterize", [](const Surface& s) { reparameterize(s, 0, 2, 0, 2); });
    requireAllThrow("elevateDegree", [](const Surface& s) { elevateDegree(s, 1, false); });
    requireAllThrow("boundingBox", [](const Surface& s) { boundingBox(s); });
    requireAllThrow("reduceSurface", [](const Surface& s) {
        ReductionOptions options;
        options.tolerance = 1e-3;
        reduceSurface(s, ReductionDirection::Both, options);
    });
    requireAllThrow("measureDeviation original", [&](const Surface& s) { measureDeviation(s, good); });
    requireAllThrow("measureDeviation reduced", [&](const Surface& s) { measureDeviation(good, s); });
    requireAllThrow("surfaceDomain", [](const Surface& s) { surfaceDomain(s); });
    requireAllThrow("closesInU", [](const Surface& s) { closesInU(s); });
    requireAllThrow("placementFrame", [](const Surface& s) { placementFrame(s, Placement{{0.3, 0.3}}); });
    requireAllThrow("CurveMapper", [](const Surface& s) { CurveMapper mapper(s); });
    requireAllThrow("homogeneousNet", [](const Surface& s) {
        // Only the sizes matter to the net itself; a content breakage is left to the users above.
        if (s.points.size() == s.countU * s.countV &&
            (s.weights.empty() || s.weights.size() == s.points.size()))
            throw GeometryError("sizes agree");
        homogeneousNet(s, false);
    });
}

TEST_CASE("parameters that are not finite or lie outside the domain are refused by name",
          "[geom][bad-input]") {
    const Curve c = validCurve(false);
    const Surface s = validSurface(false);
    for (double bad : {kNaN, kInf, -kInf, 1.5, -0.01}) {
        INFO("parameter " << bad);
        REQUIRE_THROWS_WITH(evaluate(c, bad), Catch::Contains("evaluate") && Catch::Contains("parameter u"));
        REQUIRE_THROWS_WITH(derivatives(c, bad, 1), Catch::Contains("derivatives") && Catch::Contains("u"));
        REQUIRE_THROWS_WITH(evaluate(s, 0.5, bad), Catch::Contains("parameter v"));
        REQUIRE_THROWS_WITH(derivatives(s, bad, 0.5, 1), Catch::Contains("parameter u"));
        REQUIRE_THROWS_WITH(normal(s, bad, 0.5), Catch::Contains("normal"));
        REQUIRE_THROWS_AS(curvature(s, 0.5, bad), GeometryError);
        REQUIRE_THROWS_AS(insertKnot(c, bad), GeometryError);
        REQUIRE_THROWS_AS(split(c, bad), GeometryError);
        REQUIRE_THROWS_AS(insertKnotV(s, bad), GeometryError);
    }
    // Rounding just past an end is clamped, not refused.
    REQUIRE(evaluate(c, 1.0 + 1e-12) == evaluate(c, 1.0));
    REQUIRE(evaluate(s, -1e-12, 0.5) == evaluate(s, 0.0, 0.5));
    // Batches name the position of the bad parameter.
    REQUIRE_THROWS_WITH(evaluateMany(c, std::vector<double>{0.1, kNaN}), Catch::Contains("us[1]"));
    const GridEvaluator grid(s);
    REQUIRE_THROWS_WITH(grid.evaluate(std::vector<double>{0.5}, std::vector<double>{0.2, 0.3, kInf}),
                        Catch::Contains("vs[2]"));
    REQUIRE_THROWS_WITH(derivatives(c, 0.5, -1), Catch::Contains("order"));
    REQUIRE_THROWS_AS(closestPoint(s, {kNaN, 0, 0}), GeometryError);
    REQUIRE_THROWS_AS(intersectLine(s, {0, 0, kNaN}, {0, 0, 1}), GeometryError);
}

TEST_CASE("huge counts, far query points and degenerate axes are refused by name, in bounded time",
          "[geom][bad-input]") {
    const Curve c = validCurve(false);
    const Surface s = validSurface(true);
    // Counts whose + 1 or + degree overflowed an int passed the size checks.
    REQUIRE_THROWS_WITH(tessellateUniform(s, std::numeric_limits<int>::max(), 1),
                        Catch::Contains("too many"));
    for (int times : {65, 1 << 20, std::numeric_limits<int>::max()}) {
        REQUIRE_THROWS_WITH(elevateDegree(c, times),
                            Catch::Contains("elevateDegree") && Catch::Contains("64"));
        REQUIRE_THROWS_AS(elevateDegree(s, times, true), GeometryError);
    }
    REQUIRE(elevateDegree(c, 64 - c.degree).degree == 64);
    // A query so far out that its squared distance overflows: refused, not a wrong answer.
    for (double far : {1e151, 1e200, -1e300}) {
        REQUIRE_THROWS_WITH(closestPoint(c, {far, 0, 0}), Catch::Contains("1e150"));
        REQUIRE_THROWS_WITH(closestPoint(s, {0, far, 0}), Catch::Contains("1e150"));
        REQUIRE_THROWS_AS(closestPoint(c, {0, 0, far}, 0.5), GeometryError);
        REQUIRE_THROWS_AS(closestPoint(s, {0, 0, far}, {0.5, 0.5}), GeometryError);
    }
    // An object so small that its squared distances underflow: refused, not distance 0 at (0, 0).
    for (double tiny : {1e-160, 1e-200, 1e-300}) {
        Curve small = c;
        for (glm::dvec3& p : small.points) p *= tiny;
        Surface flat = s;
        for (glm::dvec3& p : flat.points) p *= tiny;
        REQUIRE_THROWS_WITH(closestPoint(small, glm::dvec3(tiny)), Catch::Contains("1e-140"));
        REQUIRE_THROWS_WITH(closestPoint(flat, glm::dvec3(tiny)), Catch::Contains("1e-140"));
        REQUIRE_THROWS_AS(closestPoint(small, glm::dvec3(tiny), 0.5), GeometryError);
    }
    // Above it the answer scales with the object.
    {
        const Curve segment(1, {0, 0, 1, 1}, {{0, 0, 0}, {1e-130, 0, 0}});
        const CurvePoint near = closestPoint(segment, {0.25e-130, 3e-130, 0});
        REQUIRE(near.u == Approx(0.25));
        REQUIRE(near.distance == Approx(3e-130));
    }
    // Up to it, the answer is right: the nearest end of a segment, at the full distance.
    const Curve segment(1, {0, 0, 1, 1}, {{0, 0, 0}, {1, 0, 0}});
    const CurvePoint end = closestPoint(segment, {1e149, 0, 0});
    REQUIRE(end.u == 1.0);
    REQUIRE(end.distance == Approx(1e149));
    // A count so large that count + degree + 1 wraps: an empty knot list matched it (a crash).
    for (int degree : {1, 2, 3}) {
        Surface wrapped = validSurface(false);
        wrapped.degreeU = degree;
        wrapped.countU = std::numeric_limits<std::size_t>::max() - std::size_t(degree);
        wrapped.knotsU.clear();
        REQUIRE_THROWS_WITH(validate(wrapped), Catch::Contains("too many"));
    }
    // Knots mapped past the largest double.
    REQUIRE_THROWS_WITH(reparameterize(c, -1e308, 1e308), Catch::Contains("reparameterize"));
    REQUIRE_THROWS_AS(reparameterize(s, -1e308, 1e308, 0, 1), GeometryError);
    // Options and generated shapes whose size would exhaust memory.
    ReductionOptions options;
    options.tolerance = 1e-3;
    options.samplesPerSpan = 1000000000;
    REQUIRE_THROWS_WITH(reduceCurve(c, options), Catch::Contains("samplesPerSpan"));
    options.samplesPerSpan = 8;
    options.freeKnotIterations = 1 << 30;
    REQUIRE_THROWS_WITH(reduceCurve(c, options), Catch::Contains("freeKnotIterations"));
    options.freeKnotIterations = 16;
    REQUIRE_THROWS_WITH(reduceSurface(validSurface(false), static_cast<ReductionDirection>(7), options),
                        Catch::Contains("direction 7"));
    REQUIRE_THROWS_AS(uniformParameters(std::size_t{1} << 62), GeometryError);
    REQUIRE_THROWS_AS(iBeamCurve(std::size_t{1} << 40), GeometryError);
    REQUIRE_THROWS_AS(paraboloidSurface(std::size_t{1} << 33), GeometryError);
    REQUIRE_THROWS_AS(wingSurface(std::size_t{1} << 32, std::size_t{1} << 32), GeometryError);
    // A circle or arc needs two axes that span a plane.
    for (const auto& [x, y] : std::vector<std::pair<glm::dvec3, glm::dvec3>>{
             {{0, 0, 0}, {0, 1, 0}}, {{1, 0, 0}, {2, 0, 0}}, {{1, 0, 0}, {kNaN, 1, 0}}}) {
        REQUIRE_THROWS_WITH(makeCircle({0, 0, 0}, x, y, 1.0), Catch::Contains("axes"));
        REQUIRE_THROWS_AS(makeArc({0, 0, 0}, x, y, 1.0, 0.0, 1.0), GeometryError);
    }
    // A profile crossing the axis of revolution would sweep a surface through itself.
    REQUIRE_THROWS_WITH(makeRevolution(Curve(1, {0, 0, 1, 1}, {{-1, 0, 0}, {1, 0, 1}})),
                        Catch::Contains("profile point 0 has x -1"));
    REQUIRE_NOTHROW(makeRevolution(Curve(1, {0, 0, 1, 1}, {{-1e-17, 0, 0}, {1, 0, 1}})));
}

TEST_CASE("grid counts whose product wraps to the point count are refused, naming the counts",
          "[geom][bad-input]") {
    std::mt19937 rng(3003);
    std::uniform_real_distribution<double> unit(-1.0, 1.0);
    for (int k = 1; k <= 6; ++k)
        for (std::size_t m = 2; m <= 4; ++m) {
            // countU * countV == 2^64 + countU * m, which wraps to the point count countU * m.
            const std::size_t small = std::size_t{1} << k, huge = (std::size_t{1} << (64 - k)) + m;
            std::vector<glm::dvec3> grid(small * m);
            for (auto& p : grid) p = {unit(rng), unit(rng), unit(rng)};
            for (const auto& [countU, countV] : {std::pair{small, huge}, std::pair{huge, small}}) {
                // Matchers hold references to their parts, so each assertion builds its own.
                const std::string u = std::to_string(countU), v = std::to_string(countV);
                REQUIRE_THROWS_WITH(
                    chordLengthGridParameters(grid, countU, countV, Closure::Open, Closure::Open),
                    Catch::Contains(u) && Catch::Contains(v));
                REQUIRE_THROWS_WITH(
                    interpolateSurface(grid, countU, countV, 1, 1, Closure::Open, Closure::Open),
                    Catch::Contains(u) && Catch::Contains(v));
                REQUIRE_THROWS_WITH(interpolateSurface(grid, countU, countV, GridParameters{{0, 1}, {0, 1}},
                                                       1, 1, Closure::Open, Closure::Open),
                                    Catch::Contains(u) && Catch::Contains(v));
                REQUIRE_THROWS_WITH(subdivideAdaptive(grid, countU, countV, SubdivisionOptions{}),
                                    Catch::Contains(u) && Catch::Contains(v));
                Surface s = validSurface(false);
                s.points = grid;
                s.countU = countU;
                s.countV = countV;
                REQUIRE_THROWS_WITH(homogeneousNet(s, false), Catch::Contains(u) && Catch::Contains(v));
                REQUIRE_THROWS_WITH(homogeneousNet(s, true), Catch::Contains(u) && Catch::Contains(v));
            }
        }
}

TEST_CASE("overflowing knot spans and lengths, NaN knots and NaN net points are named as such",
          "[geom][bad-input]") {
    std::mt19937 rng(5005);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    const double big = std::numeric_limits<double>::max();
    for (int trial = 0; trial < 50; ++trial) {
        const int degree = 1 + trial % 4;
        const std::size_t count = static_cast<std::size_t>(degree) + 2 + rng() % 5;
        // Knots over [-h, h] with 2 h past the largest double: each is finite, the span is not.
        const double h = big * (0.51 + 0.49 * unit(rng));
        Curve c = geomtest::randomCurve(rng, degree, count, trial % 2 == 1, true);
        std::vector<double> wide = c.knots;
        for (double& k : wide) k = h * k - h * (1.0 - k);
        wide.front() = -h;
        wide.back() = h;
        CHECK_THROWS_WITH(Curve(degree, wide, c.points, c.weights), Catch::Contains("knot span"));
        c.knots = wide;  // set by hand, past the constructor
        CHECK_THROWS_WITH(evaluate(c, 0.0), Catch::Contains("evaluate") && Catch::Contains("knot span"));
        Surface s = geomtest::randomSurface(rng, degree, 2, count, 3, false, true);
        for (double& k : s.knotsU) k = h * k - h * (1.0 - k);
        CHECK_THROWS_WITH(validate(s), Catch::Contains("knot span"));
        CHECK_THROWS_WITH(evaluate(s, 0.0, 0.5), Catch::Contains("knot span"));

        // Points a whole double range apart: the polyline's length overflows, it is not zero.
        std::vector<glm::dvec3> far(count);
        for (std::size_t i = 0; i < count; ++i)
            far[i] = {(i % 2 == 0 ? -h : h), unit(rng), static_cast<double>(i)};
        CHECK_THROWS_WITH(chordLengthParameters(far, Closure::Open), Catch::Contains("not finite"));
        CHECK_THROWS_WITH(interpolateCurve(far, 1, Closure::Open), Catch::Contains("not finite"));
        std::vector<glm::dvec3> grid;
        for (std::size_t i = 0; i < 3; ++i)
            for (const glm::dvec3& p : far) grid.push_back(p + glm::dvec3(0, 0, static_cast<double>(10 * i)));
        CHECK_THROWS_WITH(chordLengthGridParameters(grid, 3, count, Closure::Open, Closure::Open),
                          Catch::Contains("row 0") && Catch::Contains("not finite"));
        // Chords whose squares overflow but whose lengths do not still give parameters.
        for (glm::dvec3& p : far) p.x *= 1e-150;
        CHECK_NOTHROW(chordLengthParameters(far, Closure::Open));

        // A NaN knot at a random index is named, not reported as a missing interior knot.
        const Curve plain = geomtest::randomCurve(rng, degree, count + 2, false, true);
        std::vector<double> knots = plain.knots;
        const double removable = knots[static_cast<std::size_t>(degree) + 1];
        const std::size_t nanAt = rng() % knots.size();
        knots[nanAt] = kNaN;
        CHECK_THROWS_WITH(
            removeKnotsLeastSquares(degree, knots, plain.points, 1, std::vector<double>{removable}),
            Catch::Contains("knot " + std::to_string(nanAt) + " is not a finite"));

        // A net point that is not finite is refused, not returned as a flat leaf.
        const std::size_t nu = 2 + rng() % 3, nv = 2 + rng() % 3;
        std::vector<glm::dvec3> net(nu * nv);
        for (auto& p : net) p = geomtest::randomPoint(rng);
        const std::size_t badAt = rng() % net.size();
        net[badAt][static_cast<int>(rng() % 3)] = trial % 3 == 0 ? kNaN : (trial % 3 == 1 ? kInf : -kInf);
        CHECK_THROWS_WITH(subdivideAdaptive(net, nu, nv, SubdivisionOptions{}),
                          Catch::Contains("net point " + std::to_string(badAt)));
    }
}

TEST_CASE("circles and arcs keep their radius whatever the length and angle of the axes",
          "[geom][primitives]") {
    // The axes were used as given: (2, 0, 0) and (0, 2, 0) made a circle of twice the radius, and
    // axes 60 degrees apart an ellipse. The plane is xAxis's direction and yAxis's perpendicular
    // part; the circle starts along xAxis and turns towards yAxis.
    std::mt19937 rng(612);
    std::uniform_real_distribution<double> unit(-1.0, 1.0), scale(-3.0, 3.0);
    for (int member = 0; member < 200; ++member) {
        const glm::dvec3 centre(unit(rng), unit(rng), unit(rng));
        const glm::dvec3 x = std::pow(10.0, scale(rng)) * glm::dvec3(unit(rng), unit(rng), unit(rng));
        const glm::dvec3 y = std::pow(10.0, scale(rng)) * glm::dvec3(unit(rng), unit(rng), unit(rng));
        if (glm::length(glm::cross(glm::normalize(x), glm::normalize(y))) < 0.05) continue;
        const double r = std::pow(10.0, scale(rng));
        const glm::dvec3 normal = glm::normalize(glm::cross(x, y));
        INFO("member " << member);
        for (const Curve& c : {makeCircle(centre, x, y, r), makeArc(centre, x, y, r, 0.0, 2.5)}) {
            REQUIRE(glm::length(evaluate(c, 0.0) - (centre + r * glm::normalize(x))) <= 1e-12 * (1 + r));
            for (int k = 0; k <= 16; ++k) {
                const glm::dvec3 p = evaluate(c, k / 16.0) - centre;
                REQUIRE(std::abs(glm::length(p) - r) <= 1e-12 * r);
                REQUIRE(std::abs(glm::dot(p, normal)) <= 1e-12 * r);
            }
            // A quarter of the way round the full circle it is on yAxis's side of xAxis.
            REQUIRE(glm::dot(evaluate(c, 0.25 * (c.knots.back() - c.knots.front())) - centre,
                             glm::cross(normal, glm::normalize(x))) > 0.0);
        }
    }
}

TEST_CASE("a rational control point whose homogeneous coordinates overflow is refused", "[geom][bad-input]") {
    // (1e308, 0, 0) with weight 2 is (2e308, 0, 0, 2) in homogeneous space: knot insertion gave
    // back infinite control points from a curve that had passed validation.
    const std::vector<glm::dvec3> points{
        {0, 0, 0}, {1e308, 0, 0}, {1e308, 1e308, 0}, {0, 1e308, 0}, {0, 0, 0}};
    REQUIRE_THROWS_WITH(Curve(3, {0, 0, 0, 0, 0.5, 1, 1, 1, 1}, points, {1, 2, 2, 2, 1}),
                        Catch::Contains("control point 1 times its weight 2 overflows"));
    REQUIRE_NOTHROW(Curve(3, {0, 0, 0, 0, 0.5, 1, 1, 1, 1}, points, {1, 1, 1, 1, 1}));
    Curve c(3, {0, 0, 0, 0, 0.5, 1, 1, 1, 1}, points);
    c.weights = {1, 1, 1, 2, 1};  // set by hand: no constructor checked it
    REQUIRE_THROWS_WITH(insertKnot(c, 0.25, 1), Catch::Contains("overflows"));
}

TEST_CASE("control points near 1e300 and subnormal knot spacing: an answer or a named refusal",
          "[geom][bad-input]") {
    // A control point so far out that squared distances near it overflow: a search started there
    // has nothing to go by. The answer is finite, or a refusal that says why, never infinite.
    const glm::dvec3 query(1, 2, 3);
    auto answersOrRefuses = [](auto&& search) {
        try {
            return std::isfinite(search().distance);
        } catch (const GeometryError& e) {
            return std::string(e.what()).find("overflows") != std::string::npos;
        }
    };
    for (std::size_t far = 1; far < 6; ++far) {
        Curve c = validCurve(true);
        c.points[far] = {1e300, -1e300, 1e300};
        REQUIRE(answersOrRefuses([&] { return closestPoint(c, query); }));
        for (double guess : {0.0, 0.3, 0.5, 0.7, 1.0})
            REQUIRE(answersOrRefuses([&] { return closestPoint(c, query, guess); }));
        Surface s = validSurface(true);
        s.points[far * 3] = {1e300, 1e300, -1e300};
        REQUIRE(answersOrRefuses([&] { return closestPoint(s, query); }));
        for (const glm::dvec2 guess : {glm::dvec2(0.5, 0.5), glm::dvec2(0.3, 0.6), glm::dvec2(0, 1)})
            REQUIRE(answersOrRefuses([&] { return closestPoint(s, query, guess); }));
    }
    // Near the start, where the curve stays in range, a search from far out falls back
    // on the global one, which answers: the start point.
    Curve c = validCurve(true);
    c.points[1] = {1e300, -1e300, 1e300};
    const CurvePoint fromMiddle = closestPoint(c, query, 0.2);
    REQUIRE(fromMiddle.u == 0.0);
    REQUIRE(fromMiddle.distance == Approx(std::sqrt(14.0)));
    // Knots a subnormal amount apart: the basis functions would divide by it and overflow.
    const double tiny = std::numeric_limits<double>::denorm_min();
    REQUIRE_THROWS_WITH(Curve(3, {0, 0, 0, 0, tiny, 2 * tiny, 2 * tiny, 2 * tiny, 2 * tiny},
                              std::vector<glm::dvec3>(5, glm::dvec3(1, 2, 3))),
                        Catch::Contains("smallest normal"));
    REQUIRE_THROWS_WITH(Curve(1, {0, 0, 1e-310, 1e-310}, {{0, 0, 0}, {1, 0, 0}}),
                        Catch::Contains("knots 1 and 2"));
    REQUIRE(Curve(1, {0, 0, 1e-300, 1e-300}, {{0, 0, 0}, {1, 0, 0}}).domainEnd() == 1e-300);
    Surface narrow = validSurface(false);
    narrow.knotsV = {0, 0, 0, tiny, 2 * tiny, 2 * tiny, 2 * tiny};
    REQUIRE_THROWS_WITH(validate(narrow),
                        Catch::Contains("v direction") && Catch::Contains("smallest normal"));
    // A batch refuses a parameter outside the domain by its place, as evaluate() refuses it.
    const Curve plain = validCurve(false);
    REQUIRE_THROWS_WITH(evaluateMany(plain, std::vector<double>{0.5, 1.5}), Catch::Contains("us[1]"));
    REQUIRE_THROWS_WITH(evaluateMany(plain, std::vector<double>{-0.25}),
                        Catch::Contains("outside the domain"));
    REQUIRE(evaluateMany(plain, std::vector<double>{1.0 + 1e-12})[0] == evaluate(plain, 1.0));
}

TEST_CASE("a broken object's message names the entry point and the rule", "[geom][bad-input]") {
    Curve c = validCurve(false);
    c.knots.clear();
    REQUIRE_THROWS_WITH(evaluate(c, 0.5), Catch::Contains("evaluate") && Catch::Contains("knots"));
    REQUIRE_THROWS_WITH(extractBezier(c), Catch::Contains("extractBezier") && Catch::Contains("knots"));
    Surface s = validSurface(false);
    s.knotsV[3] = -0.5;
    REQUIRE_THROWS_WITH(GridEvaluator(s), Catch::Contains("GridEvaluator") && Catch::Contains("decrease"));
    REQUIRE_THROWS_WITH(evaluate(s, 0.3, 0.3), Catch::Contains("evaluate") && Catch::Contains("knots"));
    // Numbers are quoted with the digits that tell them apart, whatever their scale.
    Curve small = validCurve(true);
    small.knots = {0, 0, 0, 0, 2e-7, 1e-7, 3e-7, 4e-7, 4e-7, 4e-7, 4e-7};
    REQUIRE_THROWS_WITH(validate(small), Catch::Contains("(2e-07 then 1e-07)"));
    Curve light = validCurve(true);
    light.weights[4] = 1e-310;
    REQUIRE_THROWS_WITH(validate(light), Catch::Contains("weight 4 is 1e-310"));
    REQUIRE_THROWS_WITH(evaluate(light, 0.6), Catch::Contains("weight 4"));
    REQUIRE_THROWS_WITH(insertKnot(validCurve(false), 1.0 + 1e-15),
                        Catch::Contains("1.000000000000001") && Catch::Contains("[0, 1]"));
}

TEST_CASE("a staircase refuses non-finite loop points and unbounded work", "[geom][bad-input]") {
    const std::vector<glm::dvec2> square{{0, 0}, {1, 0}, {1, 1}, {0, 1}, {0, 0}};
    REQUIRE_FALSE(staircaseApproximation(square, 0.1).empty());
    std::vector<glm::dvec2> lastNaN = square;
    lastNaN.back().x = kNaN;
    REQUIRE_THROWS_WITH(staircaseApproximation(lastNaN, 0.1), Catch::Contains("loop point 4"));
    REQUIRE_THROWS_WITH(staircaseApproximation(square, 1e-12), Catch::Contains("tolerances long"));
}

TEST_CASE("low-level basis functions refuse knots and outputs too small for the degree",
          "[geom][bad-input][basis]") {
    // Every degree 0..7 on a clamped knot vector: one value short (or one knot short) is refused
    // by name, the exact size is accepted.
    for (int degree = 0; degree <= 7; ++degree) {
        CAPTURE(degree);
        const std::size_t p = static_cast<std::size_t>(degree), count = p + 3;
        std::vector<double> knots(p + 1, 0.0);
        knots.push_back(0.3), knots.push_back(0.6);
        knots.insert(knots.end(), p + 1, 1.0);
        const std::size_t span = findSpan(degree, knots, count, 0.5);
        std::vector<double> out(p + 1), firsts(p + 1), derivatives(2 * (p + 1));
        REQUIRE_NOTHROW(basisFunctions(span, 0.5, degree, knots, out));
        REQUIRE_NOTHROW(bernsteinBasis(degree, 0.5, out, firsts, firsts));
        REQUIRE_NOTHROW(basisDerivatives(span, 0.5, degree, knots, 1, derivatives));
        // Degree 0 jumps at every interior knot: the double below each is sampled too.
        REQUIRE(spanSamples(knots, degree, count, 4).size() == 3 * 4 + 1 + (degree == 0 ? 2 : 0));
        const std::span<double> short1(out.data(), p), shortD(derivatives.data(), 2 * p + 1);
        REQUIRE_THROWS_WITH(basisFunctions(span, 0.5, degree, knots, short1),
                            Catch::Contains("basisFunctions") && Catch::Contains("too small"));
        REQUIRE_THROWS_WITH(basisDerivatives(span, 0.5, degree, knots, 1, shortD),
                            Catch::Contains("basisDerivatives") && Catch::Contains("too small"));
        REQUIRE_THROWS_WITH(bernsteinBasis(degree, 0.5, short1), Catch::Contains("bernsteinBasis"));
        if (degree >= 1)  // an empty derivative output means "skip it"
            REQUIRE_THROWS_WITH(bernsteinBasis(degree, 0.5, out, firsts, short1),
                                Catch::Contains("bernsteinBasis"));
        REQUIRE_THROWS_WITH(basisFunctions(knots.size(), 0.5, degree, knots, out),
                            Catch::Contains("reads past"));
        if (degree >= 1) {
            REQUIRE_NOTHROW(basisWithFirstDerivatives(span, 0.5, degree, knots, out, firsts));
            REQUIRE_THROWS_WITH(basisWithFirstDerivatives(span, 0.5, degree, knots, out, short1),
                                Catch::Contains("basisWithFirstDerivatives"));
        }
        const std::span<const double> fewerKnots(knots.data(), count);
        REQUIRE_THROWS_WITH(findSpan(degree, fewerKnots, count, 0.5), Catch::Contains("findSpan"));
        REQUIRE_THROWS_WITH(findSpan(degree, {}, count, 0.5), Catch::Contains("findSpan"));
        REQUIRE_THROWS_WITH(findSpan(degree, knots, p, 0.5), Catch::Contains("findSpan"));
        REQUIRE_THROWS_WITH(findSpan(-1 - degree, knots, count, 0.5), Catch::Contains("findSpan"));
        REQUIRE_THROWS_WITH(spanSamples({0, 1}, degree, count, 4),
                            Catch::Contains("spanSamples") && Catch::Contains("2 knots"));
        REQUIRE_THROWS_WITH(bernsteinBasis(-1 - degree, 0.5, out), Catch::Contains("bernsteinBasis"));
        // A parameter that is not finite (a NaN passed findSpan's comparisons and came back as a
        // span; the basis values came back NaN) and a negative derivative order.
        for (double u : {kNaN, kInf, -kInf}) {
            CAPTURE(u);
            REQUIRE_THROWS_WITH(findSpan(degree, knots, count, u),
                                Catch::Contains("findSpan") && Catch::Contains("not finite"));
            REQUIRE_THROWS_WITH(basisFunctions(span, u, degree, knots, out), Catch::Contains("not finite"));
            REQUIRE_THROWS_WITH(basisDerivatives(span, u, degree, knots, 1, derivatives),
                                Catch::Contains("basisDerivatives") && Catch::Contains("not finite"));
            if (degree >= 1)
                REQUIRE_THROWS_WITH(basisWithFirstDerivatives(span, u, degree, knots, out, firsts),
                                    Catch::Contains("not finite"));
        }
        REQUIRE_THROWS_WITH(basisDerivatives(span, 0.5, degree, knots, -1, derivatives),
                            Catch::Contains("order -1"));
        REQUIRE(findSpan(degree, knots, count, -5.0) == p);  // finite parameters are clamped, as before
    }
    for (int order : {-5, -1, 65})
        REQUIRE_THROWS_WITH(SurfaceDerivatives(order), Catch::Contains("outside 0..64"));
    REQUIRE(SurfaceDerivatives(64).order() == 64);
}

TEST_CASE("interpolation refuses an out-of-range parameterization, closure or degree",
          "[geom][bad-input][interpolation]") {
    InterpolationData data;
    data.points = {{0, 0, 0}, {1, 1, 0}, {2, 0, 0}, {3, 1, 1}};
    for (int kind : {0, 4, 9, -1}) {
        data.parameterization = static_cast<Parameterization>(kind);
        REQUIRE_THROWS_WITH(interpolateCubic(data),
                            Catch::Contains("parameterization " + std::to_string(kind)));
    }
    data.parameterization = Parameterization::Centripetal;
    REQUIRE_NOTHROW(interpolateCubic(data));
    const std::vector<double> t{0, 0.25, 0.5, 1};
    for (int degree : {0, -1, -7})
        for (Closure closure : {Closure::Open, Closure::Periodic})
            REQUIRE_THROWS_WITH(interpolationKnots(t, degree, closure),
                                Catch::Contains("degree " + std::to_string(degree)));
    REQUIRE_THROWS_WITH(interpolationKnots(t, 1, static_cast<Closure>(7)), Catch::Contains("closure 7"));
    REQUIRE(interpolationKnots(t, 1, Closure::Open).size() == 6);
    // A break (multiplicity degree + 1) is refused as DegreeElevation.h says.
    const Curve broken(2, {0, 0, 0, 0.5, 0.5, 0.5, 1, 1, 1},
                       {{0, 0, 0}, {1, 1, 0}, {2, 0, 0}, {3, 0, 0}, {4, 1, 0}, {5, 0, 0}});
    REQUIRE_THROWS_WITH(elevateDegree(broken), Catch::Contains("a break"));
}

}  // namespace test_bad_input

namespace test_bad_input {

TEST_CASE("sampling counts past maxSamplesPerSpan are refused by name before any allocation",
          "[geom][bad-input][deviation]") {
    // 1 << 30 samples per span asked for gigabytes per span and died in the allocation.
    const Curve c(2, {0, 0, 0, 0.5, 1, 1, 1}, {{0, 0, 0}, {1, 1, 0}, {2, 0, 0}, {3, 1, 0}});
    const Surface s(1, 1, {0, 0, 1, 1}, {0, 0, 1, 1}, 2, 2, {{0, 0, 0}, {0, 1, 0}, {1, 0, 0}, {1, 1, 1}});
    const ParameterMap identity{{0.0, 1.0}, {0.0, 1.0}};
    REQUIRE(maxSamplesPerSpan == 4096);
    for (int huge : {1 << 30, maxSamplesPerSpan + 1}) {
        CAPTURE(huge);
        REQUIRE_THROWS_WITH(spanSamples(c.knots, 2, 4, huge), Catch::Contains("spanSamples: samplesPerSpan"));
        REQUIRE_THROWS_WITH(measureDeviation(c, c, huge),
                            Catch::Contains("measureDeviation: samplesPerSpan"));
        REQUIRE_THROWS_WITH(measureDeviation(s, s, huge),
                            Catch::Contains("measureDeviation: samplesPerSpan"));
        REQUIRE_THROWS_WITH(measureDeviation(c, c, huge, identity), Catch::Contains("samplesPerSpan"));
        REQUIRE_THROWS_WITH(measureDeviation(c, c, 4, identity, huge),
                            Catch::Contains("reducedSamplesPerSpan"));
        REQUIRE_THROWS_WITH(CurveDeviationMeter(c, huge), Catch::Contains("samplesPerSpan"));
        REQUIRE_THROWS_WITH(CurveDeviationMeter(c, 4).within(c, identity, 1.0, huge),
                            Catch::Contains("reducedSamplesPerSpan"));
    }
    REQUIRE_THROWS_WITH(measureDeviation(c, c, 1 << 30),
                        Catch::Contains("from 1 to 4096") && Catch::Contains("1073741824"));
    REQUIRE_THROWS_WITH(measureDeviation(s, s, 0), Catch::Contains("from 1 to 4096"));
    // The limit itself is taken, and a reduction at it still measures (its final checks at
    // multiples of samplesPerSpan stay within the limit).
    REQUIRE(spanSamples(c.knots, 2, 4, maxSamplesPerSpan).size() == 2 * 4096 + 1);
    REQUIRE(measureDeviation(c, c, maxSamplesPerSpan).maxError == 0.0);
    ReductionOptions o;
    o.tolerance = 1e-3;
    o.samplesPerSpan = maxSamplesPerSpan;
    REQUIRE(reduceCurve(c, o).deviation.maxError <= o.tolerance);
}

}  // namespace test_bad_input
