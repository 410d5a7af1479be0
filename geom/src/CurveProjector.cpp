#include "geom/CurveProjector.h"

#include "Checked.h"
#include "ProjectionBounds.h"
#include "geom/Bezier.h"
#include "geom/BezierExtraction.h"
#include "geom/ControlNet.h"
#include "geom/GeometryError.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>
#include <queue>

namespace geom {
namespace {

/// One part of a piece in the global search: fractions [s0, s1] of the piece's parameters, its
/// Bézier polygon (an offset into a pool) and its subdivision depth.
struct Segment {
    std::size_t piece = 0;
    double s0 = 0.0, s1 = 1.0;
    std::size_t polygon = 0;
    int depth = 0;
};

/// Segments are halved at most this often (1/1024 of a piece, where no bound settles them):
/// below it a Newton basin is smaller than a segment. Weights spanning decades can squeeze much
/// of a piece's shape into a tiny end of its parameters; there a segment still larger than
/// kLargeSegment of the curve goes on being halved, down to kHardDepth.
constexpr int kMaxSegmentDepth = 10;
constexpr int kHardDepth = 40;
constexpr double kLargeSegment = 1e-3;

}  // namespace

CurveProjector::CurveProjector(const Curve& curve) : degree_(curve.degree), rational_(curve.rational()) {
    validate(curve, "CurveProjector");
    BoundingBox whole;  // the pieces' boxes together
    for (const BezierCurvePiece& piece : extractBezier(curve)) {
        pieces_.push_back(
            {homogeneousNet(piece.curve).data, boundingBox(piece.curve), piece.start, piece.end});
        scale_ = std::max(scale_, pieces_.back().box.diagonal());
        whole.add(pieces_.back().box);
    }
    detail::checkProjectedExtent(whole.hi - whole.lo, "CurveProjector");
}

CurveProjector::Point CurveProjector::evaluate(std::size_t index, double u) const {
    const Piece& piece = pieces_[index];
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

CurvePoint CurveProjector::polishOnPiece(std::size_t index, const glm::dvec3& p, double u) const {
    return polishIn(index, p, u, pieces_[index].start, pieces_[index].end);
}

CurvePoint CurveProjector::polishIn(std::size_t index, const glm::dvec3& p, double u, double a,
                                    double b) const {
    u = std::clamp(u, a, b);
    Point e = evaluate(index, u);
    double f = glm::dot(e.c - p, e.c - p);
    for (int it = 0; it < 60; ++it) {
        const glm::dvec3 r = e.c - p;
        const double g = glm::dot(e.d1, r);
        if ((u <= a && g > 0.0) || (u >= b && g < 0.0) || g == 0.0) break;
        double h = glm::dot(e.d1, e.d1) + glm::dot(e.d2, r);
        const double floor = 1e-6 * glm::dot(e.d1, e.d1) + 1e-300;
        if (h < floor) h = std::abs(h) + floor;
        const double du = -g / h;
        // A step this small that rounding lets grow f ends the search: halving it further only
        // spends evaluations on the last bits. Small in the parameter is not enough: with weights
        // decades apart most of the curve lies in a sliver of it, so the gain Newton predicts
        // must be at rounding's level too.
        const bool small = std::abs(du) < 1e-6 * (b - a) && std::abs(g * du) <= 1e-12 * f;
        bool moved = false;
        double step = 1.0;
        for (int k = 0; k < 40; ++k, step *= 0.5) {
            const double next = std::clamp(u + step * du, a, b);
            if (next == u) break;
            const Point en = evaluate(index, next);
            const double fn = glm::dot(en.c - p, en.c - p);
            if (fn <= f) {
                moved = std::abs(next - u) > 1e-16 * (b - a);
                u = next;
                e = en;
                f = fn;
                break;
            }
            if (small) break;
        }
        if (!moved || std::abs(du) < 1e-14 * (b - a)) break;
    }
    return {u, e.c, std::sqrt(f)};
}

CurvePoint CurveProjector::closestPointFrom(const glm::dvec3& p, double u) const {
    detail::checkQueryPoint(p, "closestPoint");
    if (!std::isfinite(u)) throw GeometryError("closestPoint: the start guess is not finite");
    u = std::clamp(u, pieces_.front().start, pieces_.back().end);
    auto it = std::upper_bound(pieces_.begin(), pieces_.end(), u,
                               [](double x, const Piece& piece) { return x < piece.end; });
    std::size_t index =
        it == pieces_.end() ? pieces_.size() - 1 : static_cast<std::size_t>(it - pieces_.begin());
    CurvePoint best = polishOnPiece(index, p, u);
    // Across a piece end (a corner, say) the search goes on in the neighbour while that lowers
    // the distance; each step strictly lowers it, the count only bounds the work.
    for (std::size_t round = 0; round < pieces_.size() + 2; ++round) {
        std::size_t next = index;
        if (best.u <= pieces_[index].start && index > 0)
            next = index - 1;
        else if (best.u >= pieces_[index].end && index + 1 < pieces_.size())
            next = index + 1;
        if (next == index) break;
        const CurvePoint there = polishOnPiece(next, p, best.u);
        if (!(there.distance < best.distance * (1.0 - 1e-14))) break;
        best = there;
        index = next;
    }
    // Near a control point of 1e300 the squared distance overflows and Newton has nothing to go
    // by: the global search, whose bounds still hold, answers instead.
    if (!std::isfinite(best.distance)) return closestPoint(p);
    return beforeJump(best, index);
}

CurvePoint CurveProjector::beforeJump(CurvePoint best, std::size_t piece) const {
    // At a knot of multiplicity degree + 1 the curve jumps, and evaluate() gives the point after
    // it: the end of the piece before is reached from just below the knot.
    if (piece + 1 < pieces_.size() && best.u >= pieces_[piece].end &&
        glm::length(evaluate(piece + 1, best.u).c - best.point) > 1e-9 * scale_)
        best.u = std::nextafter(pieces_[piece].end, -std::numeric_limits<double>::infinity());
    return best;
}

bool CurveProjector::mayHalve(int depth, const std::vector<glm::dvec3>& polygon) const {
    if (depth < kMaxSegmentDepth) return true;
    if (depth >= kHardDepth) return false;
    BoundingBox box;
    for (const glm::dvec3& q : polygon) box.add(q);
    return box.diagonal() > kLargeSegment * scale_;
}

CurvePoint CurveProjector::closestPoint(const glm::dvec3& p) const {
    detail::checkQueryPoint(p, "closestPoint");
    const std::size_t n = static_cast<std::size_t>(degree_) + 1;
    thread_local std::vector<Segment> segments;
    thread_local std::vector<glm::dvec4> pool, work;
    thread_local std::vector<glm::dvec3> points;
    segments.clear();
    pool.clear();
    CurvePoint best;
    best.distance = std::numeric_limits<double>::infinity();
    std::size_t bestPiece = 0;
    glm::dvec3 toward(0.0);
    const double tolerance = 1e-13 * scale_;
    using Entry = std::pair<double, std::size_t>;
    std::priority_queue<Entry, std::vector<Entry>, std::greater<Entry>> queue;
    for (std::size_t i = 0; i < pieces_.size(); ++i) {
        segments.push_back({i, 0.0, 1.0, pool.size(), 0});
        pool.insert(pool.end(), pieces_[i].net.begin(), pieces_[i].net.end());
        queue.push({pieces_[i].box.distance(p), i});
    }
    auto take = [&](const CurvePoint& candidate, std::size_t piece) {
        if (!(candidate.distance < best.distance)) return;
        best = candidate;
        bestPiece = piece;
        if (best.distance > 0.0) toward = (best.point - p) / best.distance;
    };
    auto split = [&](const Segment& segment) {
        const std::size_t base = pool.size();
        pool.resize(base + 2 * n);
        detail::halveLine(pool.data() + segment.polygon, 1, n, pool.data() + base, pool.data() + base + n,
                          work);
        const double mid = 0.5 * (segment.s0 + segment.s1);
        for (std::size_t k = 0; k < 2; ++k) {
            const Segment child{segment.piece, k == 0 ? segment.s0 : mid, k == 0 ? mid : segment.s1,
                                base + k * n, segment.depth + 1};
            const glm::dvec4* polygon = pool.data() + child.polygon;
            detail::project(polygon, n, points);
            const double bound =
                detail::lowerBound(points, p, std::isfinite(best.distance) ? &toward : nullptr);
            if (bound >= best.distance - tolerance) continue;
            // Where the distance provably grows along the segment towards an end inside the
            // piece, the segment's nearest point is that end, which its neighbour holds.
            const int sign = detail::gradientSign(polygon, points, n, 1, rational_, false, p);
            if ((sign > 0 && child.s0 > 0.0) || (sign < 0 && child.s1 < 1.0)) continue;
            segments.push_back(child);
            queue.push({bound, segments.size() - 1});
        }
    };
    while (!queue.empty()) {
        const auto [bound, id] = queue.top();
        queue.pop();
        if (bound >= best.distance - tolerance) break;
        const Segment segment = segments[id];
        const Piece& piece = pieces_[segment.piece];
        const double width = piece.end - piece.start;
        // A segment at the piece's end ends exactly there (start + 1.0 * width can round past it).
        const double ua = piece.start + segment.s0 * width;
        const double ub = segment.s1 >= 1.0 ? piece.end : piece.start + segment.s1 * width;
        const bool holdsBest =
            std::isfinite(best.distance) && bestPiece == segment.piece && best.u >= ua && best.u <= ub;
        const glm::dvec4* polygon = pool.data() + segment.polygon;
        detail::project(polygon, n, points);
        // Start at the best point or at the segment's control point nearest to p.
        double start = best.u;
        if (!holdsBest)
            start = ua + (ub - ua) * static_cast<double>(detail::nearestPoint(points, p)) /
                             static_cast<double>(degree_);
        if (detail::provablyConvex(polygon, points, n, 1, p)) {
            // Convex on the segment: Newton held inside it finds the segment's minimum.
            take(polishIn(segment.piece, p, start, ua, ub), segment.piece);
            continue;
        }
        if (!holdsBest) {
            take(polishOnPiece(segment.piece, p, start), segment.piece);
            if (segment.depth == 0) take(polishOnPiece(segment.piece, p, 0.5 * (ua + ub)), segment.piece);
        }
        if (!(bound < best.distance - tolerance)) continue;
        if (mayHalve(segment.depth, points)) {
            split(segment);
        } else if (!detail::provablyFarther(polygon, n, 1, p, best.distance - tolerance)) {
            // A leaf that may still hold a nearer point (wide weights can fold a local maximum
            // into a segment below the halving size): Newton from its Bezier abscissae.
            for (int k = 0; k <= degree_; ++k)
                take(polishIn(segment.piece, p, ua + (ub - ua) * k / std::max(degree_, 1), ua, ub),
                     segment.piece);
        }
    }
    detail::checkDistance(best.distance, "closestPoint");
    return beforeJump(best, bestPiece);
}

CurvePoint closestPoint(const Curve& curve, const glm::dvec3& p) {
    return CurveProjector(curve).closestPoint(p);
}

CurvePoint closestPoint(const Curve& curve, const glm::dvec3& p, double guess) {
    return CurveProjector(curve).closestPointFrom(p, guess);
}

}  // namespace geom
