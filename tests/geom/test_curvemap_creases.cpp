#include "CurveMapTestUtil.h"

#include "geom/Primitives.h"
#include "geom/SurfaceIntersector.h"

#include "Sanitized.h"

#include <numbers>
#include <random>

namespace test_curvemap_creases {

using namespace geom;
using namespace geom::curvemap;
using namespace curvemap_test;

namespace {

double distanceToSegment(const glm::dvec3& p, const glm::dvec3& a, const glm::dvec3& b) {
    const glm::dvec3 ab = b - a;
    const double len2 = glm::dot(ab, ab);
    const double t = len2 > 0.0 ? std::clamp(glm::dot(p - a, ab) / len2, 0.0, 1.0) : 0.0;
    return glm::length(p - (a + t * ab));
}

/// Clamped knots for `count` poles of degree p over [0, count - p], interior knots jittered and
/// the middle one repeated `fold` times (fold = p leaves a crease there).
std::vector<double> knotVector(std::mt19937& rng, int p, int count, int fold) {
    std::uniform_real_distribution<double> jitter(-0.3, 0.3);
    const int spans = count - p - (fold > 1 ? fold - 1 : 0);
    std::vector<double> knots(static_cast<std::size_t>(p) + 1, 0.0);
    for (int i = 1; i < spans; ++i) {
        const double at = i + (i == spans / 2 ? 0.0 : jitter(rng));
        for (int k = 0; k < (i == spans / 2 ? std::max(fold, 1) : 1); ++k) knots.push_back(at);
    }
    knots.insert(knots.end(), static_cast<std::size_t>(p) + 1, static_cast<double>(spans));
    return knots;
}

/// A height field over [-5, 5]^2 of one of three classes: degree 1 (a crease at every knot line),
/// degree 2 or 3 with a crease in each direction, or rational with weights spanning 1e-2..1e2.
Surface randomSurface(std::mt19937& rng, int kind) {
    std::uniform_real_distribution<double> height(-0.6, 0.6), unit(0.0, 1.0);
    const int p = kind == 0 ? 1 : 2 + static_cast<int>(rng() % 2);
    const int n = p + 4 + static_cast<int>(rng() % 4);
    const int fold = kind == 1 ? p : 1;
    std::vector<glm::dvec3> points;
    std::vector<double> weights;
    for (int i = 0; i < n; ++i)
        for (int j = 0; j < n; ++j) {
            points.push_back({i * 10.0 / (n - 1) - 5.0, j * 10.0 / (n - 1) - 5.0, height(rng)});
            if (kind == 2) weights.push_back(std::pow(10.0, -2.0 + 4.0 * unit(rng)));
        }
    return Surface(p, p, knotVector(rng, p, n, fold), knotVector(rng, p, n, fold), std::size_t(n),
                   std::size_t(n), points, weights);
}

Curve randomCurve(std::mt19937& rng) {
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    const double radius = 0.3 + 4.0 * unit(rng);
    const unsigned kind = rng() % 3;
    if (kind == 0) return makeCircle({0.0, 0.0, 0.0}, {1.0, 0.0, 0.0}, {0.0, 1.0, 0.0}, radius);
    const int sides = 3 + static_cast<int>(rng() % 6);
    std::vector<glm::dvec3> corners;
    for (int k = 0; k < sides; ++k) {
        const double angle = (k + 0.3 * unit(rng)) * 2.0 * std::numbers::pi / sides;
        const double r = radius * (0.5 + 0.5 * unit(rng));
        corners.push_back({r * std::cos(angle), r * std::sin(angle), 0.0});
    }
    if (kind == 1) return polygonCurve(corners);
    // A closed spline of degree 2..5 through the corners' control polygon.
    const int degree = 2 + static_cast<int>(rng() % 4);
    corners.push_back(corners.front());
    while (corners.size() < std::size_t(degree) + 2)
        corners.insert(corners.end() - 1, corners[corners.size() - 2]);
    const int count = static_cast<int>(corners.size());
    std::vector<double> knots(std::size_t(degree) + 1, 0.0);
    for (int i = 1; i < count - degree; ++i) knots.push_back(double(i) / (count - degree));
    knots.insert(knots.end(), std::size_t(degree) + 1, 1.0);
    return Curve(degree, knots, corners);
}

/// The mapped point of curve parameter s: the hit nearest the curve point along the projection line.
struct Truth {
    bool hit = false;
    glm::dvec3 point{0.0};
};

Truth trueMapping(const SurfaceIntersector& intersector, const MapResult& r, const Curve& curve, double s) {
    const std::vector<LineSurfaceHit> hits =
        intersector.intersect(r.frame.toModel(evaluate(curve, s)), r.frame.z);
    if (hits.empty()) return {};
    const auto nearest = std::min_element(
        hits.begin(), hits.end(), [](const auto& x, const auto& y) { return std::abs(x.t) < std::abs(y.t); });
    return {true, nearest->point};
}

/// The largest distances, over the loops' segments between two projected curve points: of a true
/// mapped point from its chord, and of the surface image of the straight (u, w) segment from the
/// true mapped polyline.
std::pair<double, double> worstDeviations(const CurveMapper& mapper, const SurfaceIntersector& intersector,
                                          const MapResult& r, const Curve& curve) {
    const SurfaceDomain& d = mapper.domain();
    double chord = 0.0, image = 0.0;
    for (const MappedLoop& loop : r.parts[0].loops)
        for (std::size_t i = 0; i + 1 < loop.uv.size(); ++i) {
            const double s0 = loop.curveParameters[i], s1 = loop.curveParameters[i + 1];
            // Boundary vertices have no curve point; a jump between sheets (where the nearest hit
            // switches surfaces) joins two mapped points of one curve point.
            const double span = curve.domainEnd() - curve.domainStart();
            if (std::isnan(s0) || std::isnan(s1) || std::abs(s1 - s0) > 0.5 * span ||
                std::abs(s1 - s0) < 1e-9 * span)
                continue;
            std::vector<glm::dvec3> truePolyline{loop.points[i]};
            constexpr int kInner = 8;
            for (int k = 1; k < kInner; ++k) {
                const Truth t = trueMapping(intersector, r, curve, s0 + (s1 - s0) * k / kInner);
                if (!t.hit) continue;
                truePolyline.push_back(t.point);
                chord = std::max(chord, distanceToSegment(t.point, loop.points[i], loop.points[i + 1]));
            }
            truePolyline.push_back(loop.points[i + 1]);
            const glm::dvec2 a = loop.uv[i], b = d.unwrapNear(loop.uv[i + 1], a);
            for (int k = 1; k < kInner; ++k) {
                const glm::dvec2 uv = d.wrap(a + (b - a) * (double(k) / kInner));
                const glm::dvec3 q = evaluate(mapper.surface(), uv.x, uv.y);
                double nearest = 1e300;
                for (std::size_t j = 0; j + 1 < truePolyline.size(); ++j)
                    nearest = std::min(nearest, distanceToSegment(q, truePolyline[j], truePolyline[j + 1]));
                image = std::max(image, nearest);
            }
        }
    return {chord, image};
}

}  // namespace

TEST_CASE("mapped curves stay within the tolerance across creases and steep rational knot lines",
          "[geom][curvemap]") {
    // Degree-1 surfaces fold at every knot line and p-fold knots fold too: the mapped curve kinks
    // there, between any two samples. With weights spanning 1e-2..1e2 the image of a straight
    // (u, w) segment bends away from the mapped curve across a knot line. Every emitted segment and
    // its image must still keep to the tolerance, measured at points the mapper never sampled.
    std::mt19937 rng(20261205);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    const char* kinds[] = {"degree 1", "p-fold knot", "rational 1e-2..1e2"};
    int checked = 0;
    const int members = membersForBuild(300);
    for (int member = 0; member < members; ++member) {
        const int kind = member % 3;
        const Surface surface = randomSurface(rng, kind);
        const CurveMapper mapper(surface);
        const SurfaceIntersector intersector(surface);
        const SurfaceDomain& d = mapper.domain();
        Placement placement;
        placement.reference = {d.u0 + (d.u1 - d.u0) * unit(rng), d.w0 + (d.w1 - d.w0) * unit(rng)};
        placement.quarterTurns = static_cast<int>(rng() % 4);
        placement.flipped = rng() % 2 == 1;
        const Curve curve = randomCurve(rng);
        const double tolerance = rng() % 2 == 0 ? 1e-2 : 1e-3;
        const MapResult r = mapper.map({curve}, placement, {tolerance});
        INFO("member " << member << ", " << kinds[kind] << ", curve degree " << curve.degree << ", tolerance "
                       << tolerance);
        checkMapping(mapper, r, {curve});
        CHECK(r.parts[0].issues.empty());
        const auto [chord, image] = worstDeviations(mapper, intersector, r, curve);
        CHECK(chord <= 1.01 * tolerance);
        CHECK(image <= 1.01 * tolerance);
        if (!r.parts[0].loops.empty()) ++checked;
    }
    CHECK(checked >= members / 10);
}

}  // namespace test_curvemap_creases
