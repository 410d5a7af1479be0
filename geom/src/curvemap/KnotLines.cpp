#include "KnotLines.h"

#include <algorithm>
#include <cmath>

namespace geom::curvemap {
namespace {

/// The distinct interior knots (knots[degree + 1 .. count - 1]) that occur at least `least` times.
std::vector<double> interiorKnots(const std::vector<double>& knots, int degree, std::size_t count,
                                  std::size_t least) {
    std::vector<double> lines;
    for (std::size_t i = static_cast<std::size_t>(degree) + 1; i < count;) {
        std::size_t j = i;
        while (j + 1 < count && knots[j + 1] == knots[i]) ++j;
        if (j - i + 1 >= least) lines.push_back(knots[i]);
        i = j + 1;
    }
    return lines;
}

}  // namespace

KnotLines::Lines KnotLines::Lines::of(const std::vector<double>& knots, int degree, std::size_t count,
                                      std::size_t least, bool closed, double start, double period) {
    Lines lines{interiorKnots(knots, degree, count, least), closed, start, period};
    // A closed direction meets itself at the seam, which need not be smooth.
    if (closed) lines.at.insert(lines.at.begin(), start);
    return lines;
}

KnotLines::KnotLines(const Surface& surface, const SurfaceDomain& domain) {
    const auto foldU = static_cast<std::size_t>(std::max(surface.degreeU, 1));
    const auto foldW = static_cast<std::size_t>(std::max(surface.degreeV, 1));
    creaseU_ = Lines::of(surface.knotsU, surface.degreeU, surface.countU, foldU, domain.closedU, domain.u0,
                         domain.periodU());
    creaseW_ = Lines::of(surface.knotsV, surface.degreeV, surface.countV, foldW, domain.closedW, domain.w0,
                         domain.periodW());
    knotU_ = Lines::of(surface.knotsU, surface.degreeU, surface.countU, 1, domain.closedU, domain.u0,
                       domain.periodU());
    knotW_ = Lines::of(surface.knotsV, surface.degreeV, surface.countV, 1, domain.closedW, domain.w0,
                       domain.periodW());
}

bool KnotLines::crossesCrease(const glm::dvec2& a, const glm::dvec2& b) const {
    return creaseU_.crossed(a.x, b.x) || creaseW_.crossed(a.y, b.y);
}

bool KnotLines::crossesKnot(const glm::dvec2& a, const glm::dvec2& b) const {
    return knotU_.crossed(a.x, b.x) || knotW_.crossed(a.y, b.y);
}

bool KnotLines::Lines::crossed(double a, double b) const {
    if (at.empty()) return false;
    const double lo = std::min(a, b), hi = std::max(a, b);
    // Unwrapped coordinates of a closed direction may lie a period or more outside the domain.
    const double shift = closed ? period * std::floor((lo - start) / period) : 0.0;
    // The first line above lo lies in lo's period or the next.
    for (int k = 0; k < 2; ++k) {
        const double turn = shift + k * period;
        const auto next = std::upper_bound(at.begin(), at.end(), lo - turn);
        if (next != at.end()) return *next + turn < hi;
        if (!closed || !(period > 0.0)) return false;
    }
    return false;
}

}  // namespace geom::curvemap
