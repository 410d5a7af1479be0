#include "phigs/hardcopy/FacetOverlaps.h"

#include <glm/common.hpp>
#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>

namespace phigs::hardcopy {
namespace {

constexpr int kMaxOverlapCells = 1024;

double cross(glm::dvec2 o, glm::dvec2 a, glm::dvec2 b) {
    return (a.x - o.x) * (b.y - o.y) - (a.y - o.y) * (b.x - o.x);
}

/// The convex hull of a facet's points on the page (Andrew's monotone chain), counter-clockwise.
std::vector<glm::dvec2> hullOf(const ProjectedFacet& f) {
    std::vector<glm::dvec2> p;
    for (const auto& c : f.contours)
        for (const PagePoint& q : c) p.push_back(glm::dvec2(q));
    std::sort(p.begin(), p.end(),
              [](glm::dvec2 a, glm::dvec2 b) { return a.x < b.x || (a.x == b.x && a.y < b.y); });
    p.erase(std::unique(p.begin(), p.end()), p.end());
    if (p.size() < 3) return p;
    std::vector<glm::dvec2> hull(2 * p.size());
    std::size_t k = 0;
    for (std::size_t i = 0; i < p.size(); ++i) {
        while (k >= 2 && cross(hull[k - 2], hull[k - 1], p[i]) <= 0) --k;
        hull[k++] = p[i];
    }
    for (std::size_t i = p.size() - 1, lower = k + 1; i-- > 0;) {
        while (k >= lower && cross(hull[k - 2], hull[k - 1], p[i]) <= 0) --k;
        hull[k++] = p[i];
    }
    hull.resize(k - 1);
    return hull;
}

/// Whether some edge of `a` separates the two hulls (touching counts as separated).
bool separatedByEdgeOf(const std::vector<glm::dvec2>& a, const std::vector<glm::dvec2>& b, double epsilon) {
    for (std::size_t i = 0; i < a.size(); ++i) {
        const glm::dvec2 edge = a[(i + 1) % a.size()] - a[i];
        const glm::dvec2 axis(-edge.y, edge.x);
        double loA = 1e300, hiA = -1e300, loB = 1e300, hiB = -1e300;
        for (const glm::dvec2& p : a)
            loA = std::min(loA, glm::dot(axis, p)), hiA = std::max(hiA, glm::dot(axis, p));
        for (const glm::dvec2& p : b)
            loB = std::min(loB, glm::dot(axis, p)), hiB = std::max(hiB, glm::dot(axis, p));
        const double slack = epsilon * glm::length(axis);
        if (hiA <= loB + slack || hiB <= loA + slack) return true;
    }
    return false;
}

bool overlap(const std::vector<glm::dvec2>& a, const std::vector<glm::dvec2>& b, double epsilon) {
    if (a.size() < 3 || b.size() < 3) return false;  // no area: paints nothing another could cover
    return !separatedByEdgeOf(a, b, epsilon) && !separatedByEdgeOf(b, a, epsilon);
}

}  // namespace

FacetOverlaps facetOverlaps(const std::vector<ProjectedFacet>& facets, std::size_t maxPairs) {
    const std::size_t n = facets.size();
    FacetOverlaps out;
    out.hulls.resize(n);
    std::vector<glm::dvec2> lo(n, glm::dvec2(1e300)), hi(n, glm::dvec2(-1e300));
    glm::dvec2 low(1e300), high(-1e300);
    for (std::size_t i = 0; i < n; ++i) {
        out.hulls[i] = hullOf(facets[i]);
        for (const glm::dvec2& p : out.hulls[i]) lo[i] = glm::min(lo[i], p), hi[i] = glm::max(hi[i], p);
        low = glm::min(low, lo[i]), high = glm::max(high, hi[i]);
    }
    if (n < 2) return out;
    const double epsilon = 1e-9 * std::max(1.0, glm::length(high - low));
    const int cells = std::clamp(int(std::ceil(std::sqrt(double(n)))), 1, kMaxOverlapCells);
    const glm::dvec2 size = glm::max((high - low) / double(cells), glm::dvec2(1e-9));
    std::vector<std::vector<std::uint32_t>> grid(std::size_t(cells) * std::size_t(cells));
    std::vector<std::size_t> seen(n, ~std::size_t(0));
    auto cell = [&](double v, double origin, double step) {
        return std::clamp(int(std::floor((v - origin) / step)), 0, cells - 1);
    };
    for (std::size_t i = 0; i < n; ++i) {
        // Against every earlier facet in the cells its box covers, then into those cells.
        const int x0 = cell(lo[i].x, low.x, size.x), x1 = cell(hi[i].x, low.x, size.x);
        const int y0 = cell(lo[i].y, low.y, size.y), y1 = cell(hi[i].y, low.y, size.y);
        for (int y = y0; y <= y1; ++y)
            for (int x = x0; x <= x1; ++x) {
                auto& bucket = grid[std::size_t(y) * std::size_t(cells) + std::size_t(x)];
                for (std::uint32_t j : bucket) {
                    if (seen[j] == i) continue;
                    seen[j] = i;
                    if (lo[j].x >= hi[i].x || lo[i].x >= hi[j].x || lo[j].y >= hi[i].y || lo[i].y >= hi[j].y)
                        continue;
                    if (!overlap(out.hulls[i], out.hulls[j], epsilon)) continue;
                    if (out.pairs.size() == maxPairs) {
                        out.complete = false;
                        return out;
                    }
                    out.pairs.emplace_back(j, std::uint32_t(i));
                }
                bucket.push_back(std::uint32_t(i));
            }
    }
    return out;
}

std::vector<glm::dvec2> convexIntersection(const std::vector<glm::dvec2>& a,
                                           const std::vector<glm::dvec2>& b) {
    // Sutherland-Hodgman: a clipped by each edge of b in turn (both convex, so the result is).
    std::vector<glm::dvec2> part = a, next;
    for (std::size_t i = 0; i < b.size() && part.size() >= 3; ++i) {
        const glm::dvec2 from = b[i], to = b[(i + 1) % b.size()];
        next.clear();
        for (std::size_t k = 0; k < part.size(); ++k) {
            const glm::dvec2 p = part[k], q = part[(k + 1) % part.size()];
            const double dp = cross(from, to, p), dq = cross(from, to, q);
            if (dp >= 0.0) next.push_back(p);
            if ((dp > 0.0 && dq < 0.0) || (dp < 0.0 && dq > 0.0))
                next.push_back(p + (q - p) * (dp / (dp - dq)));
        }
        std::swap(part, next);
    }
    if (part.size() < 3) part.clear();
    return part;
}

}  // namespace phigs::hardcopy
