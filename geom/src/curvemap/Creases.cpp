#include "Creases.h"

#include <algorithm>
#include <cmath>

namespace geom::curvemap {
namespace {

std::vector<double> foldingKnots(const std::vector<double>& knots, int degree, std::size_t count) {
    // Interior knots are knots[degree + 1 .. count - 1]; a run of `degree` equal ones leaves only
    // C0 continuity there.
    std::vector<double> lines;
    const auto p = static_cast<std::size_t>(degree);
    for (std::size_t i = p + 1; i < count;) {
        std::size_t j = i;
        while (j + 1 < count && knots[j + 1] == knots[i]) ++j;
        if (j - i + 1 >= p) lines.push_back(knots[i]);
        i = j + 1;
    }
    return lines;
}

}  // namespace

Creases::Creases(const Surface& surface, const SurfaceDomain& domain) {
    u_.at = foldingKnots(surface.knotsU, surface.degreeU, surface.countU);
    w_.at = foldingKnots(surface.knotsV, surface.degreeV, surface.countV);
    u_.closed = domain.closedU;
    u_.start = domain.u0;
    u_.period = domain.periodU();
    w_.closed = domain.closedW;
    w_.start = domain.w0;
    w_.period = domain.periodW();
    // A closed direction meets itself at the seam, which need not be smooth.
    if (u_.closed) u_.at.insert(u_.at.begin(), domain.u0);
    if (w_.closed) w_.at.insert(w_.at.begin(), domain.w0);
}

bool Creases::crossed(const glm::dvec2& a, const glm::dvec2& b) const {
    return u_.crossed(a.x, b.x) || w_.crossed(a.y, b.y);
}

bool Creases::Lines::crossed(double a, double b) const {
    if (at.empty()) return false;
    const double lo = std::min(a, b), hi = std::max(a, b);
    // Unwrapped coordinates of a closed direction may lie a period or more outside the domain.
    const double shift = closed ? period * std::floor((lo - start) / period) : 0.0;
    for (double turn = shift;; turn += period) {
        const auto next = std::upper_bound(at.begin(), at.end(), lo - turn);
        if (next != at.end()) return *next + turn < hi;
        if (!closed || !(period > 0.0)) return false;
    }
}

}  // namespace geom::curvemap
