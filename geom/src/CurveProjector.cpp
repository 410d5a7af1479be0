#include "geom/CurveProjector.h"

#include "geom/Bezier.h"
#include "geom/BezierExtraction.h"
#include "geom/ControlNet.h"
#include "geom/GeometryError.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <limits>

namespace geom {

CurveProjector::CurveProjector(const Curve& curve) : degree_(curve.degree) {
    for (const BezierCurvePiece& piece : extractBezier(curve))
        pieces_.push_back(
            {homogeneousNet(piece.curve).data, boundingBox(piece.curve), piece.start, piece.end});
}

CurveProjector::Point CurveProjector::evaluate(double u) const {
    auto it = std::upper_bound(pieces_.begin(), pieces_.end(), u,
                               [](double x, const Piece& piece) { return x < piece.end; });
    if (it == pieces_.end()) --it;
    const Piece& piece = *it;
    const std::size_t n = static_cast<std::size_t>(degree_) + 1;
    thread_local std::vector<double> b, db, ddb;
    b.resize(n);
    db.resize(n);
    ddb.resize(n);
    const double scale = 1.0 / (piece.end - piece.start);
    bernsteinBasis(degree_, std::clamp((u - piece.start) * scale, 0.0, 1.0), b, db, ddb);
    glm::dvec4 h(0.0), h1(0.0), h2(0.0);
    for (std::size_t i = 0; i < n; ++i) {
        h += b[i] * piece.net[i];
        h1 += db[i] * piece.net[i];
        h2 += ddb[i] * piece.net[i];
    }
    h1 *= scale;
    h2 *= scale * scale;
    Point r;
    r.c = glm::dvec3(h) / h.w;
    r.d1 = (glm::dvec3(h1) - h1.w * r.c) / h.w;
    r.d2 = (glm::dvec3(h2) - 2.0 * h1.w * r.d1 - h2.w * r.c) / h.w;
    return r;
}

CurvePoint CurveProjector::closestPointFrom(const glm::dvec3& p, double u) const {
    if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z))
        throw GeometryError("closestPoint: the query point has a non-finite coordinate");
    if (!std::isfinite(u)) throw GeometryError("closestPoint: the start guess is not finite");
    const double a = pieces_.front().start, b = pieces_.back().end;
    u = std::clamp(u, a, b);
    Point e = evaluate(u);
    double f = glm::dot(e.c - p, e.c - p);
    for (int it = 0; it < 60; ++it) {
        const glm::dvec3 r = e.c - p;
        const double g = glm::dot(e.d1, r);
        if ((u <= a && g > 0.0) || (u >= b && g < 0.0) || g == 0.0) break;
        double h = glm::dot(e.d1, e.d1) + glm::dot(e.d2, r);
        const double floor = 1e-6 * glm::dot(e.d1, e.d1) + 1e-300;
        if (h < floor) h = std::abs(h) + floor;
        const double du = -g / h;
        bool moved = false;
        double step = 1.0;
        for (int k = 0; k < 40; ++k, step *= 0.5) {
            const double next = std::clamp(u + step * du, a, b);
            if (next == u) break;
            const Point en = evaluate(next);
            const double fn = glm::dot(en.c - p, en.c - p);
            if (fn <= f) {
                moved = std::abs(next - u) > 1e-16 * (b - a);
                u = next;
                e = en;
                f = fn;
                break;
            }
        }
        if (!moved) break;
    }
    return {u, e.c, std::sqrt(f)};
}

CurvePoint CurveProjector::closestPoint(const glm::dvec3& p) const {
    if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z))
        throw GeometryError("closestPoint: the query point has a non-finite coordinate");
    std::vector<std::pair<double, std::size_t>> order;
    order.reserve(pieces_.size());
    for (std::size_t i = 0; i < pieces_.size(); ++i) order.push_back({pieces_[i].box.distance(p), i});
    std::sort(order.begin(), order.end());
    CurvePoint best;
    best.distance = std::numeric_limits<double>::infinity();
    for (const auto& [boxDistance, i] : order) {
        if (boxDistance >= best.distance) break;
        const Piece& piece = pieces_[i];
        // Start at the nearest control point's Bézier abscissa, and at the piece's middle.
        std::size_t nearest = 0;
        double nearestDistance = std::numeric_limits<double>::infinity();
        for (std::size_t k = 0; k < piece.net.size(); ++k) {
            const glm::dvec3 c = glm::dvec3(piece.net[k]) / piece.net[k].w;
            const double d = glm::dot(c - p, c - p);
            if (d < nearestDistance) {
                nearestDistance = d;
                nearest = k;
            }
        }
        const double s = static_cast<double>(nearest) / static_cast<double>(degree_);
        for (double start : {piece.start + s * (piece.end - piece.start), 0.5 * (piece.start + piece.end)}) {
            const CurvePoint c = closestPointFrom(p, start);
            if (c.distance < best.distance) best = c;
        }
    }
    return best;
}

CurvePoint closestPoint(const Curve& curve, const glm::dvec3& p) {
    return CurveProjector(curve).closestPoint(p);
}

CurvePoint closestPoint(const Curve& curve, const glm::dvec3& p, double guess) {
    return CurveProjector(curve).closestPointFrom(p, guess);
}

}  // namespace geom
