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

KnotLines::KnotLines(const Surface& surface, const SurfaceDomain& domain) {
    const auto degreeU = static_cast<std::size_t>(surface.degreeU);
    const auto degreeW = static_cast<std::size_t>(surface.degreeV);
    creaseU_.at =
        interiorKnots(surface.knotsU, surface.degreeU, surface.countU, std::max<std::size_t>(degreeU, 1));
    creaseW_.at =
        interiorKnots(surface.knotsV, surface.degreeV, surface.countV, std::max<std::size_t>(degreeW, 1));
    knotU_.at = interiorKnots(surface.knotsU, surface.degreeU, surface.countU, 1);
    knotW_.at = interiorKnots(surface.knotsV, surface.degreeV, surface.countV, 1);
    for (Lines* u : {&creaseU_, &knotU_}) {
        u->closed = domain.closedU;
        u->start = domain.u0;
        u->period = domain.periodU();
        // A closed direction meets itself at the seam, which need not be smooth.
        if (u->closed) u->at.insert(u->at.begin(), domain.u0);
    }
    for (Lines* w : {&creaseW_, &knotW_}) {
        w->closed = domain.closedW;
        w->start = domain.w0;
        w->period = domain.periodW();
        if (w->closed) w->at.insert(w->at.begin(), domain.w0);
    }
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
