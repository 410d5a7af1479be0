#include "geom/SurfaceProjector.h"

#include "geom/GeometryError.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <queue>

namespace geom {
namespace {

bool finite(const glm::dvec3& p) {
    return std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z);
}

}  // namespace

SurfaceProjector::SurfaceProjector(const Surface& surface) : tree_(surface) {
}

SurfacePoint SurfaceProjector::polish(const glm::dvec3& p, glm::dvec2 uv) const {
    // Newton on the gradient of |S - p|^2 / 2, with the Hessian shifted where it is not positive
    // definite, a backtracking step, and parameters held on the domain edges they run into.
    const double ua = tree_.domainStartU(), ub = tree_.domainEndU();
    const double va = tree_.domainStartV(), vb = tree_.domainEndV();
    uv = glm::dvec2(std::clamp(uv.x, ua, ub), std::clamp(uv.y, va, vb));
    BezierPatchTree::PatchPoint e = tree_.evaluate(uv.x, uv.y, 2);
    glm::dvec3 r = e.point - p;
    double f = glm::dot(r, r);
    for (int it = 0; it < 60; ++it) {
        const double gu = glm::dot(e.su, r), gv = glm::dot(e.sv, r);
        double huu = glm::dot(e.su, e.su) + glm::dot(e.suu, r);
        double huv = glm::dot(e.su, e.sv) + glm::dot(e.suv, r);
        double hvv = glm::dot(e.sv, e.sv) + glm::dot(e.svv, r);
        const bool holdU = (uv.x <= ua && gu > 0.0) || (uv.x >= ub && gu < 0.0);
        const bool holdV = (uv.y <= va && gv > 0.0) || (uv.y >= vb && gv < 0.0);
        double du = 0.0, dv = 0.0;
        const double trace = std::abs(huu) + std::abs(hvv) + 1e-300;
        if (!holdU && !holdV) {
            double det = huu * hvv - huv * huv;
            if (!(huu > 0.0 && det > 1e-14 * trace * trace)) {
                // Shift by more than the most negative eigenvalue.
                const double mean = 0.5 * (huu + hvv);
                const double rad = std::sqrt(0.25 * (huu - hvv) * (huu - hvv) + huv * huv);
                const double shift = std::max(0.0, -(mean - rad)) + 1e-6 * trace;
                huu += shift;
                hvv += shift;
                det = huu * hvv - huv * huv;
            }
            du = -(hvv * gu - huv * gv) / det;
            dv = -(-huv * gu + huu * gv) / det;
        } else if (!holdU) {
            du = -gu / (huu > 1e-14 * trace ? huu : std::abs(huu) + 1e-6 * trace);
        } else if (!holdV) {
            dv = -gv / (hvv > 1e-14 * trace ? hvv : std::abs(hvv) + 1e-6 * trace);
        }
        // Near the answer the full Newton step is taken even when rounding hides the decrease
        // of f; further away a backtracking search keeps f from growing.
        const bool small = std::abs(du) < 1e-6 * (ub - ua) && std::abs(dv) < 1e-6 * (vb - va);
        double step = 1.0;
        bool moved = false;
        for (int k = 0; k < 40; ++k, step *= 0.5) {
            const glm::dvec2 next(std::clamp(uv.x + step * du, ua, ub), std::clamp(uv.y + step * dv, va, vb));
            if (next == uv) break;
            const BezierPatchTree::PatchPoint en = tree_.evaluate(next.x, next.y, 2);
            const glm::dvec3 rn = en.point - p;
            const double fn = glm::dot(rn, rn);
            if (fn <= f || (small && k == 0 && fn <= f * (1.0 + 1e-12) + 1e-300)) {
                moved = std::abs(next.x - uv.x) > 1e-15 * (ub - ua) ||
                        std::abs(next.y - uv.y) > 1e-15 * (vb - va);
                uv = next;
                e = en;
                r = rn;
                f = fn;
                break;
            }
        }
        if (!moved) break;
    }
    SurfacePoint out;
    out.uv = uv;
    out.point = e.point;
    out.distance = std::sqrt(f);
    return out;
}

SurfacePoint SurfaceProjector::closestPointFrom(const glm::dvec3& p, const glm::dvec2& guess) const {
    if (!finite(p)) throw GeometryError("closestPoint: the query point has a non-finite coordinate");
    if (!std::isfinite(guess.x) || !std::isfinite(guess.y))
        throw GeometryError("closestPoint: the start guess is not finite");
    return polish(p, guess);
}

SurfacePoint SurfaceProjector::closestPoint(const glm::dvec3& p) const {
    if (!finite(p)) throw GeometryError("closestPoint: the query point has a non-finite coordinate");
    const auto& nodes = tree_.nodes();
    const auto& patches = tree_.patches();
    const std::size_t pu = static_cast<std::size_t>(tree_.degreeU()) + 1;
    const std::size_t qv = static_cast<std::size_t>(tree_.degreeV()) + 1;
    SurfacePoint best;
    best.distance = std::numeric_limits<double>::infinity();
    using Entry = std::pair<double, int>;
    std::priority_queue<Entry, std::vector<Entry>, std::greater<Entry>> queue;
    queue.push({nodes[0].box.distance(p), 0});
    while (!queue.empty()) {
        const auto [boxDistance, index] = queue.top();
        queue.pop();
        if (boxDistance >= best.distance) break;
        const BezierPatchTree::Node& node = nodes[static_cast<std::size_t>(index)];
        if (node.patch < 0) {
            queue.push({nodes[static_cast<std::size_t>(node.first)].box.distance(p), node.first});
            queue.push({nodes[static_cast<std::size_t>(node.second)].box.distance(p), node.second});
            continue;
        }
        // Start at the best of the nearest control point's Bézier abscissae and a small grid.
        const BezierPatchTree::Patch& patch = patches[static_cast<std::size_t>(node.patch)];
        std::size_t nearest = 0;
        double nearestDistance = std::numeric_limits<double>::infinity();
        for (std::size_t k = 0; k < patch.net.size(); ++k) {
            const glm::dvec3 c = glm::dvec3(patch.net[k]) / patch.net[k].w;
            const double d = glm::dot(c - p, c - p);
            if (d < nearestDistance) {
                nearestDistance = d;
                nearest = k;
            }
        }
        const double s = pu > 1 ? static_cast<double>(nearest / qv) / static_cast<double>(pu - 1) : 0.5;
        const double t = qv > 1 ? static_cast<double>(nearest % qv) / static_cast<double>(qv - 1) : 0.5;
        auto at = [&](double a, double b) {
            return glm::dvec2(patch.u0 + a * (patch.u1 - patch.u0), patch.v0 + b * (patch.v1 - patch.v0));
        };
        glm::dvec2 start = at(s, t);
        glm::dvec3 sp = tree_.evaluate(static_cast<std::size_t>(node.patch), start.x, start.y, 0).point;
        double startDistance = glm::dot(sp - p, sp - p);
        constexpr int kGrid = 4;
        for (int a = 0; a <= kGrid; ++a)
            for (int b = 0; b <= kGrid; ++b) {
                const glm::dvec2 g = at(static_cast<double>(a) / kGrid, static_cast<double>(b) / kGrid);
                const glm::dvec3 gp = tree_.evaluate(static_cast<std::size_t>(node.patch), g.x, g.y, 0).point;
                const double d = glm::dot(gp - p, gp - p);
                if (d < startDistance) {
                    startDistance = d;
                    start = g;
                }
            }
        const SurfacePoint candidate = polish(p, start);
        if (candidate.distance < best.distance) best = candidate;
    }
    return best;
}

SurfacePoint closestPoint(const Surface& surface, const glm::dvec3& p) {
    return SurfaceProjector(surface).closestPoint(p);
}

SurfacePoint closestPoint(const Surface& surface, const glm::dvec3& p, const glm::dvec2& guess) {
    return SurfaceProjector(surface).closestPointFrom(p, guess);
}

}  // namespace geom
