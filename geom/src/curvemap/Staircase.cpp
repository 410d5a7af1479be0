#include "geom/curvemap/Staircase.h"
#include "../SegmentDistance.h"

#include "geom/GeometryError.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>

namespace geom::curvemap {

namespace {

using detail::segmentDistance;

/// Distance from p to the polyline points[first..last].
double distanceToPolyline(const glm::dvec2& p, const std::vector<glm::dvec2>& points, std::size_t first,
                          std::size_t last) {
    double best = glm::length(p - points[first]);
    for (std::size_t k = first; k < last; ++k)
        best = std::min(best, segmentDistance(p, points[k], points[k + 1]));
    return best;
}

/// Whether the step from points[i] to points[j] through `corner` and the loop between them
/// stay within tol of each other, both ways. (This subsumes the thesis's linear fit of the run:
/// a step fits exactly where a straight run would, and also around an iso-parametric corner.)
bool stepFits(const std::vector<glm::dvec2>& p, std::size_t i, std::size_t j, const glm::dvec2& corner,
              double tol) {
    for (std::size_t k = i + 1; k < j; ++k) {
        if (std::min(segmentDistance(p[k], p[i], corner), segmentDistance(p[k], corner, p[j])) > tol)
            return false;
    }
    return distanceToPolyline(corner, p, i, j) <= tol &&
           distanceToPolyline(0.5 * (p[i] + corner), p, i, j) <= tol &&
           distanceToPolyline(0.5 * (corner + p[j]), p, i, j) <= tol;
}

}  // namespace

std::vector<glm::dvec2> staircaseApproximation(const std::vector<glm::dvec2>& loop, double tolerance) {
    if (!(tolerance > 0.0) || !std::isfinite(tolerance))
        throw GeometryError("staircaseApproximation: the tolerance must be a positive number");
    // Densify so that every loop segment is at most one tolerance long: a single step then fits.
    for (std::size_t i = 0; i < loop.size(); ++i)
        if (!std::isfinite(loop[i].x) || !std::isfinite(loop[i].y))
            throw GeometryError("staircaseApproximation: loop point " + std::to_string(i) + " is not finite");
    // Bounded work: a loop longer than this many tolerances is refused, not densified.
    constexpr double kMaxPieces = 1e7;
    double pieceCount = 0.0;
    for (std::size_t i = 0; i + 1 < loop.size(); ++i)
        pieceCount += std::ceil(glm::length(loop[i + 1] - loop[i]) / tolerance);
    if (!(pieceCount <= kMaxPieces))
        throw GeometryError("staircaseApproximation: the loop is " + std::to_string(pieceCount) +
                            " tolerances long, more than " + std::to_string(kMaxPieces));
    std::vector<glm::dvec2> p;
    for (std::size_t i = 0; i + 1 < loop.size(); ++i) {
        const glm::dvec2 a = loop[i], b = loop[i + 1];
        const int pieces = std::max(1, static_cast<int>(std::ceil(glm::length(b - a) / tolerance)));
        for (int k = 0; k < pieces; ++k) p.push_back(a + (b - a) * (static_cast<double>(k) / pieces));
    }
    if (p.size() < 3)
        throw GeometryError("staircaseApproximation: the loop needs at least 3 distinct points");
    p.push_back(p.front());

    std::vector<glm::dvec2> out{p.front()};
    const std::size_t last = p.size() - 1;
    for (std::size_t i = 0; i < last;) {
        // Extend the step as far as it fits; j = i + 1 always fits after densifying.
        std::size_t j = i + 1;
        glm::dvec2 corner(p[j].x, p[i].y);
        for (std::size_t k = i + 2; k <= last; ++k) {
            const glm::dvec2 c1(p[k].x, p[i].y), c2(p[i].x, p[k].y);
            if (stepFits(p, i, k, c1, tolerance)) {
                j = k;
                corner = c1;
            } else if (stepFits(p, i, k, c2, tolerance)) {
                j = k;
                corner = c2;
            } else {
                break;
            }
        }
        if (j == i + 1) {
            const glm::dvec2 c2(p[i].x, p[j].y);
            if (segmentDistance(c2, p[i], p[j]) < segmentDistance(corner, p[i], p[j])) corner = c2;
        }
        out.push_back(corner);
        out.push_back(p[j]);
        i = j;
    }
    // Drop repeated points and the middle of three on one iso-line.
    std::vector<glm::dvec2> clean;
    for (const glm::dvec2& q : out) {
        if (!clean.empty() && clean.back() == q) continue;
        while (clean.size() >= 2) {
            const glm::dvec2 a = clean[clean.size() - 2], b = clean.back();
            if ((a.x == b.x && b.x == q.x) || (a.y == b.y && b.y == q.y))
                clean.pop_back();
            else
                break;
        }
        clean.push_back(q);
    }
    return clean;
}

}  // namespace geom::curvemap
