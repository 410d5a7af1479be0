#include "geom/curvemap/FacingDomain.h"

#include "geom/Evaluate.h"
#include "geom/Split.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <vector>

namespace geom::curvemap {

namespace {

/// Sample parameters of one direction: `perSpan` per distinct knot span, ends included.
std::vector<double> sampleParameters(const std::vector<double>& knots, int degree, std::size_t count,
                                     double lo, double hi, int perSpan) {
    std::vector<double> out;
    for (std::size_t i = static_cast<std::size_t>(degree); i < count; ++i) {
        const double a = std::max(knots[i], lo), b = std::min(knots[i + 1], hi);
        if (!(b > a)) continue;
        for (int k = 0; k < perSpan; ++k) out.push_back(a + (b - a) * k / perSpan);
    }
    out.push_back(hi);
    return out;
}

}  // namespace

std::optional<SurfaceDomain> facingDomain(const Surface& surface, const SurfaceDomain& domain,
                                          const glm::dvec2& reference, const glm::dvec3& direction,
                                          double minimumCosine) {
    const std::vector<double> us =
        sampleParameters(surface.knotsU, surface.degreeU, surface.countU, domain.u0, domain.u1, 8);
    const std::vector<double> ws =
        sampleParameters(surface.knotsV, surface.degreeV, surface.countV, domain.w0, domain.w1, 8);
    const glm::dvec3 d = glm::normalize(direction);
    const glm::dvec2 at = domain.wrap(reference);
    const double sign = glm::dot(normal(surface, at.x, at.y), d) >= 0.0 ? 1.0 : -1.0;
    const auto faces = [&](double u, double w) {
        return sign * glm::dot(normal(surface, u, w), d) >= minimumCosine;
    };
    if (!faces(at.x, at.y)) return std::nullopt;
    std::vector<char> grid(us.size() * ws.size());
    for (std::size_t i = 0; i < us.size(); ++i)
        for (std::size_t j = 0; j < ws.size(); ++j) grid[i * ws.size() + j] = faces(us[i], ws[j]) ? 1 : 0;
    // The samples just below and above the reference in each direction start the rectangle.
    const auto bracket = [](const std::vector<double>& t, double x) {
        std::size_t hi = static_cast<std::size_t>(std::upper_bound(t.begin(), t.end(), x) - t.begin());
        hi = std::clamp<std::size_t>(hi, 1, t.size() - 1);
        return std::pair<std::size_t, std::size_t>{hi - 1, hi};
    };
    auto [i0, i1] = bracket(us, at.x);
    auto [j0, j1] = bracket(ws, at.y);
    const auto rowFaces = [&](std::size_t i, std::size_t ja, std::size_t jb) {
        for (std::size_t j = ja; j <= jb; ++j)
            if (!grid[i * ws.size() + j]) return false;
        return true;
    };
    const auto columnFaces = [&](std::size_t j, std::size_t ia, std::size_t ib) {
        for (std::size_t i = ia; i <= ib; ++i)
            if (!grid[i * ws.size() + j]) return false;
        return true;
    };
    // Shrink the starting cell's corners that do not face (a reference right beside a fold).
    if (!rowFaces(i0, j0, j1) || !rowFaces(i1, j0, j1)) {
        // Keep at least the reference: a tiny cell around it.
        SurfaceDomain tiny = domain;
        tiny.closedU = tiny.closedW = false;
        const double du = 1e-3 * (domain.u1 - domain.u0), dw = 1e-3 * (domain.w1 - domain.w0);
        tiny.u0 = std::max(domain.u0, at.x - du);
        tiny.u1 = std::min(domain.u1, at.x + du);
        tiny.w0 = std::max(domain.w0, at.y - dw);
        tiny.w1 = std::min(domain.w1, at.y + dw);
        return tiny;
    }
    // Grow one sample row or column at a time, each side in turn, while the new one faces.
    bool grew = true;
    while (grew) {
        grew = false;
        if (i0 > 0 && rowFaces(i0 - 1, j0, j1)) --i0, grew = true;
        if (i1 + 1 < us.size() && rowFaces(i1 + 1, j0, j1)) ++i1, grew = true;
        if (j0 > 0 && columnFaces(j0 - 1, i0, i1)) --j0, grew = true;
        if (j1 + 1 < ws.size() && columnFaces(j1 + 1, i0, i1)) ++j1, grew = true;
    }
    SurfaceDomain out = domain;
    out.closedU = out.closedW = false;
    out.u0 = us[i0];
    out.u1 = us[i1];
    out.w0 = ws[j0];
    out.w1 = ws[j1];
    return out;
}

Surface subSurface(const Surface& surface, const SurfaceDomain& domain, const SurfaceDomain& part) {
    Surface s = surface;
    const double eu = 1e-12 * (domain.u1 - domain.u0), ew = 1e-12 * (domain.w1 - domain.w0);
    if (part.u0 > domain.u0 + eu) s = split(s, part.u0, false).second;
    if (part.u1 < domain.u1 - eu) s = split(s, part.u1, false).first;
    if (part.w0 > domain.w0 + ew) s = split(s, part.w0, true).second;
    if (part.w1 < domain.w1 - ew) s = split(s, part.w1, true).first;
    return s;
}

}  // namespace geom::curvemap
