#include "geom/SurfaceProjector.h"

#include "Checked.h"
#include "ProjectionBounds.h"
#include "UnitScale.h"
#include "geom/BoundingBox.h"
#include "geom/GeometryError.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <queue>
#include <vector>

namespace geom {
namespace {

/// Newton on the gradient of |S - p|^2 / 2 over [ua,ub] x [va,vb], with the Hessian shifted where
/// it is not positive definite, a backtracking step, and parameters held on the domain edges they
/// run into. eval(u, v) gives a BezierPatchTree::PatchPoint with derivatives up to order 2.
template <class Eval>
SurfacePoint polishWith(Eval&& eval, double ua, double ub, double va, double vb, const glm::dvec3& p,
                        glm::dvec2 uv) {
    uv = glm::dvec2(std::clamp(uv.x, ua, ub), std::clamp(uv.y, va, vb));
    BezierPatchTree::PatchPoint e = eval(uv.x, uv.y);
    glm::dvec3 r = e.point - p;
    double f = glm::dot(r, r);
    int stalls = 0;
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
            // Positive definite by the scaled Hessian (unit diagonal): next to a pole hvv is as small as
            // the squared distance to it, and a test against the trace would shift away the step in v.
            if (!(huu > 0.0 && hvv > 0.0 && det > 1e-14 * huu * hvv)) {
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
        const double before = f;
        // Where the full step leaves the region, its crossing of the border is tried next (then
        // halvings below it): Newton lands on the border, held there from the next step on,
        // instead of halving towards it a step at a time (a region far narrower than the step,
        // deep in a patch: 27 steps and 640 evaluations where 5 do).
        double border = 1.0;
        if (du < 0.0 && uv.x > ua) border = std::min(border, (ua - uv.x) / du);
        if (du > 0.0 && uv.x < ub) border = std::min(border, (ub - uv.x) / du);
        if (dv < 0.0 && uv.y > va) border = std::min(border, (va - uv.y) / dv);
        if (dv > 0.0 && uv.y < vb) border = std::min(border, (vb - uv.y) / dv);
        double step = 1.0;
        bool moved = false;
        for (int k = 0; k < 40; ++k, step *= (k == 1 && border < 0.5 ? border : 0.5)) {
            const glm::dvec2 next(std::clamp(uv.x + step * du, ua, ub), std::clamp(uv.y + step * dv, va, vb));
            if (next == uv) break;
            const BezierPatchTree::PatchPoint en = eval(next.x, next.y);
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
            // A step that small which rounding lets grow f ends the search: halving it further
            // only spends evaluations on the last bits.
            if (small) break;
        }
        const bool converged = std::abs(du) < 1e-13 * (ub - ua) && std::abs(dv) < 1e-13 * (vb - va);
        // Three steps in a row that lowered the squared distance by less than 1e-14 of it end the
        // search too: along a nearly flat valley Newton creeps on for every iteration it has, while
        // next to a minimum two such steps bring (u, v) in.
        stalls = before - f <= 1e-14 * before ? stalls + 1 : 0;
        if (!moved || converged || stalls == 3) break;
    }
    SurfacePoint out;
    out.uv = uv;
    out.point = e.point;
    out.distance = std::sqrt(f);
    return out;
}

/// Regions are halved at most this often in each direction (1/256 of a patch a side, and only
/// where no bound settles them): below it a Newton basin is smaller than a region. Small weights
/// can squeeze much of a patch's shape into a tiny corner of its parameters; there a region
/// still larger than kLargeRegion of the surface goes on being halved, down to kHardDepth.
constexpr int kMaxProjectionDepth = 8;
constexpr int kHardDepth = 24;
constexpr double kLargeRegion = 1e-3;
/// Halvings one query may make. Near a pole or a collapsed edge every region touching it holds
/// points at the best distance, which no bound separates: each halving there quadruples them.
/// Past the budget regions are settled as leaves.
constexpr std::size_t kSplitBudget = std::size_t(1) << 13;

}  // namespace

SurfaceProjector::SurfaceProjector(const Surface& surface) : tree_(surface), rational_(surface.rational()) {
    if (tree_.root() < 0) return;
    const BoundingBox& box = tree_.nodes()[std::size_t(tree_.root())].box;  // the whole surface's
    detail::checkProjectedExtent(box.hi - box.lo, "SurfaceProjector");
}

SurfacePoint SurfaceProjector::polishIn(std::size_t index, const glm::dvec3& p, glm::dvec2 uv, double ua,
                                        double ub, double va, double vb) const {
    return polishWith([this, index](double u, double v) { return tree_.evaluate(index, u, v, 2); }, ua, ub,
                      va, vb, p, uv);
}

SurfacePoint SurfaceProjector::polishOnPatch(std::size_t index, const glm::dvec3& p, glm::dvec2 uv) const {
    const BezierPatchTree::Patch& patch = tree_.patches()[index];
    return polishIn(index, p, uv, patch.u0, patch.u1, patch.v0, patch.v1);
}

SurfacePoint SurfaceProjector::polish(const glm::dvec3& p, glm::dvec2 uv) const {
    uv = glm::dvec2(std::clamp(uv.x, tree_.domainStartU(), tree_.domainEndU()),
                    std::clamp(uv.y, tree_.domainStartV(), tree_.domainEndV()));
    std::size_t index = tree_.patchAt(uv.x, uv.y);
    SurfacePoint best = polishOnPatch(index, p, uv);
    const std::vector<double>& bu = tree_.breaksU();
    const std::vector<double>& bv = tree_.breaksV();
    const std::size_t spansU = bu.size() - 1, spansV = bv.size() - 1;
    // Each round strictly lowers the distance, so no patch is left and re-entered for nothing;
    // the count only bounds the work.
    const std::size_t rounds = 2 * tree_.patches().size() + 8;
    for (std::size_t round = 0; round < rounds; ++round) {
        const std::size_t iu = index / spansV, iv = index % spansV;
        bool moved = false;
        for (std::size_t a = iu > 0 ? iu - 1 : 0; a <= std::min(iu + 1, spansU - 1) && !moved; ++a)
            for (std::size_t b = iv > 0 ? iv - 1 : 0; b <= std::min(iv + 1, spansV - 1) && !moved; ++b) {
                if (a == iu && b == iv) continue;
                if (best.uv.x < bu[a] || best.uv.x > bu[a + 1] || best.uv.y < bv[b] || best.uv.y > bv[b + 1])
                    continue;
                const SurfacePoint next = polishOnPatch(a * spansV + b, p, best.uv);
                if (next.distance < best.distance * (1.0 - 1e-14)) {
                    best = next;
                    index = a * spansV + b;
                    moved = true;
                }
            }
        if (!moved) break;
    }
    return best;
}

SurfacePoint SurfaceProjector::closestPointFrom(const glm::dvec3& p, const glm::dvec2& guess) const {
    detail::checkQueryPoint(p, "closestPoint");
    if (!std::isfinite(guess.x) || !std::isfinite(guess.y))
        throw GeometryError("closestPoint: the start guess is not finite");
    const SurfacePoint local = polish(p, guess);
    // An overflowing distance (control points near 1e300) gives Newton nothing to go by.
    if (!std::isfinite(local.distance)) return closestPoint(p);
    // Weights decades apart squeeze most of a patch into a sliver of its parameters, where Newton
    // crawls and can stop on a slope: a point that is not stationary is replaced by the global
    // answer, which is never farther.
    if (!stationary(p, local)) {
        const SurfacePoint global = closestPoint(p);
        if (global.distance < local.distance) return global;
    }
    return beforeJump(local);
}

bool SurfaceProjector::stationary(const glm::dvec3& p, const SurfacePoint& at) const {
    const BezierPatchTree::PatchPoint e = tree_.evaluate(at.uv.x, at.uv.y, 1);
    const glm::dvec3 r = e.point - p;
    const double distance = glm::length(r);
    if (distance <= 1e-12 * tree_.scale()) return true;  // on the surface
    // A component of the gradient may point out of the domain at its border, and take any value
    // on a knot line (a crease's kink: the derivative there is one side's); elsewhere each must
    // be a rounding's worth of the derivative and the distance.
    auto flat = [&](double g, const glm::dvec3& d, double t, const std::vector<double>& breaks) {
        if ((t <= breaks.front() && g >= 0.0) || (t >= breaks.back() && g <= 0.0)) return true;
        if (std::binary_search(breaks.begin() + 1, breaks.end() - 1, t)) return true;
        return std::abs(g) <= 1e-6 * glm::length(d) * distance;
    };
    return flat(glm::dot(e.su, r), e.su, at.uv.x, tree_.breaksU()) &&
           flat(glm::dot(e.sv, r), e.sv, at.uv.y, tree_.breaksV());
}

SurfacePoint SurfaceProjector::beforeJump(SurfacePoint best) const {
    // Only a point on a patch's upper edge can be one evaluate() does not give back: where the
    // knot line is a jump, the parameter just below it reaches the patch before.
    const double tolerance = 1e-9 * tree_.scale();
    auto givesBack = [&](const glm::dvec2& uv) {
        return glm::length(tree_.evaluate(uv.x, uv.y, 0).point - best.point) <= tolerance;
    };
    if (givesBack(best.uv)) return best;
    const double below = -std::numeric_limits<double>::infinity();
    const double u = std::nextafter(best.uv.x, below), v = std::nextafter(best.uv.y, below);
    for (const glm::dvec2 uv : {glm::dvec2(u, best.uv.y), glm::dvec2(best.uv.x, v), glm::dvec2(u, v)})
        if (uv.x >= tree_.domainStartU() && uv.y >= tree_.domainStartV() && givesBack(uv)) {
            best.uv = uv;
            break;
        }
    return best;
}

glm::dvec2 SurfaceProjector::patchStart(std::size_t index, const glm::dvec3& p, glm::dvec2 start) const {
    const BezierPatchTree::Patch& patch = tree_.patches()[index];
    auto at = [&](double a, double b) {
        return glm::dvec2(patch.u0 + a * (patch.u1 - patch.u0), patch.v0 + b * (patch.v1 - patch.v0));
    };
    const glm::dvec3 sp = tree_.evaluate(index, start.x, start.y, 0).point;
    double startDistance = glm::dot(sp - p, sp - p);
    constexpr int kGrid = 2;
    for (int a = 0; a <= kGrid; ++a)
        for (int b = 0; b <= kGrid; ++b) {
            const glm::dvec2 g = at(static_cast<double>(a) / kGrid, static_cast<double>(b) / kGrid);
            const glm::dvec3 gp = tree_.evaluate(index, g.x, g.y, 0).point;
            const double d = glm::dot(gp - p, gp - p);
            if (d < startDistance) {
                startDistance = d;
                start = g;
            }
        }
    return start;
}

/// One global closest-point query: a branch and bound over the patches and the regions they are
/// cut into, nearest bound first.
class SurfaceProjector::Search {
public:
    Search(const SurfaceProjector& projector, const glm::dvec3& p)
        : projector_(projector),
          tree_(projector.tree_),
          p_(p),
          pu_(static_cast<std::size_t>(tree_.degreeU()) + 1),
          qv_(static_cast<std::size_t>(tree_.degreeV()) + 1),
          netSize_(pu_ * qv_),
          tolerance_(1e-13 * tree_.scale()) {
        regions_.clear();
        pool_.clear();
        best_.distance = std::numeric_limits<double>::infinity();
    }

    SurfacePoint run() {
        const auto& nodes = tree_.nodes();
        // Queue entries: a tree node (index >= 0) or a region (index -1 - r).
        queue_.push({nodes[0].box.distance(p_), 0});
        while (!queue_.empty()) {
            const auto [bound, id] = queue_.top();
            queue_.pop();
            if (bound >= best_.distance - tolerance_) break;
            if (id < 0) {
                visit(regions_[static_cast<std::size_t>(-1 - id)], bound);
                continue;
            }
            const BezierPatchTree::Node& node = nodes[static_cast<std::size_t>(id)];
            if (node.patch >= 0) {
                pushPatch(static_cast<std::size_t>(node.patch));
                continue;
            }
            queue_.push({nodes[static_cast<std::size_t>(node.first)].box.distance(p_), node.first});
            queue_.push({nodes[static_cast<std::size_t>(node.second)].box.distance(p_), node.second});
        }
        return best_;
    }

private:
    /// Where a region's surface does not change along v (alongV) or u: collapsed to a curve there.
    enum class Flat : std::uint8_t { none, alongU, alongV };

    /// A part of a patch: fractions [s0, s1] x [t0, t1] of the patch's own parameters, its Bézier
    /// net (an offset into the pool) and its subdivision depth. A flat region keeps only its edge
    /// curve's net (at t0 alongV, at s0 alongU), halved along that curve alone: every point of
    /// the region lies within tolerance_ of the curve, where a search of the whole region would
    /// find a continuum of nearest points that no bound tells apart.
    struct Region {
        std::size_t patch = 0;
        double s0 = 0.0, s1 = 1.0, t0 = 0.0, t1 = 1.0;
        std::size_t net = 0;
        int depth = 0;
        Flat flat = Flat::none;
    };

    const glm::dvec3* toward() const { return std::isfinite(best_.distance) ? &toward_ : nullptr; }

    void take(const SurfacePoint& candidate, std::size_t patch) {
        if (!(candidate.distance < best_.distance)) return;
        best_ = candidate;
        bestPatch_ = patch;
        if (best_.distance > 0.0) toward_ = (best_.point - p_) / best_.distance;
    }

    void push(const Region& region, double bound) {
        regions_.push_back(region);
        queue_.push({bound, -1 - static_cast<std::ptrdiff_t>(regions_.size() - 1)});
    }

    void pushPatch(std::size_t patch) {
        Region whole;
        whole.patch = patch;
        whole.net = pool_.size();
        const std::vector<glm::dvec4>& net = tree_.patches()[patch].net;
        whole.flat = flatness(net.data());
        if (whole.flat == Flat::alongV) {
            for (std::size_t i = 0; i < pu_; ++i) pool_.push_back(net[i * qv_]);
        } else if (whole.flat == Flat::alongU) {
            pool_.insert(pool_.end(), net.begin(), net.begin() + static_cast<std::ptrdiff_t>(qv_));
        } else {
            pool_.insert(pool_.end(), net.begin(), net.end());
        }
        detail::project(pool_.data() + whole.net, netCount(whole), points_);
        const double bound = detail::lowerBound(points_, p_, toward());
        if (bound < best_.distance - tolerance_ && !fartherThanBest(whole)) push(whole, bound);
    }

    /// Where the distance provably grows across the region towards one of its edges inside the
    /// patch, the region's nearest point lies on that edge, which a neighbour holds.
    bool settledByNeighbour(const Region& region) const {
        const glm::dvec4* net = pool_.data() + region.net;
        if (region.flat != Flat::none) {
            const int sign =
                detail::gradientSign(net, points_, netCount(region), 1, projector_.rational_, false, p_);
            const bool alongV = region.flat == Flat::alongV;
            return (sign > 0 && (alongV ? region.s0 : region.t0) > 0.0) ||
                   (sign < 0 && (alongV ? region.s1 : region.t1) < 1.0);
        }
        const int signU = detail::gradientSign(net, points_, pu_, qv_, projector_.rational_, false, p_);
        if ((signU > 0 && region.s0 > 0.0) || (signU < 0 && region.s1 < 1.0)) return true;
        const int signV = detail::gradientSign(net, points_, pu_, qv_, projector_.rational_, true, p_);
        return (signV > 0 && region.t0 > 0.0) || (signV < 0 && region.t1 < 1.0);
    }

    /// The weights-aware test for rational nets, whose hull bounds small weights loosen.
    bool fartherThanBest(const Region& region) const {
        return projector_.rational_ && std::isfinite(best_.distance) &&
               detail::provablyFarther(pool_.data() + region.net, rows(region), columns(region), p_,
                                       best_.distance - tolerance_);
    }

    /// How far apart the points of a collapsed row or column may lie, their coordinates up to
    /// `magnitude`: the search's tolerance, and the rounding by which the points a collapsed row
    /// became under knot insertion and subdivision differ.
    double collapseTolerance(double magnitude) const {
        return tolerance_ + 64.0 * std::numeric_limits<double>::epsilon() * magnitude;
    }

    /// Whether a patch's net is flat along v or u: within collapseTolerance of its edge curve.
    Flat flatness(const glm::dvec4* net) const {
        detail::project(net, netSize_, points_);
        double magnitude = 0.0;
        for (const glm::dvec3& q : points_) magnitude = std::max(magnitude, detail::largestCoordinate(q));
        const double allowed = collapseTolerance(magnitude);
        if (detail::departureFromEdge(net, points_, pu_, qv_, true) <= allowed) return Flat::alongV;
        if (detail::departureFromEdge(net, points_, pu_, qv_, false) <= allowed) return Flat::alongU;
        return Flat::none;
    }

    /// The points a region keeps in the pool, and how its net is laid out (a flat one's is a curve's).
    std::size_t netCount(const Region& region) const {
        return region.flat == Flat::none ? netSize_ : (region.flat == Flat::alongV ? pu_ : qv_);
    }
    std::size_t rows(const Region& region) const {
        return region.flat == Flat::none ? pu_ : netCount(region);
    }
    std::size_t columns(const Region& region) const { return region.flat == Flat::none ? qv_ : 1; }

    /// A flat region halved along its curve.
    void splitFlat(const Region& region) {
        ++splits_;
        const std::size_t count = netCount(region), base = pool_.size();
        pool_.resize(base + 2 * count);
        detail::halveLine(pool_.data() + region.net, 1, count, pool_.data() + base,
                          pool_.data() + base + count, work_);
        const bool alongV = region.flat == Flat::alongV;
        const double middle = alongV ? 0.5 * (region.s0 + region.s1) : 0.5 * (region.t0 + region.t1);
        for (std::size_t k = 0; k < 2; ++k) {
            Region child = region;
            child.depth = region.depth + 1;
            child.net = base + k * count;
            (alongV ? (k == 0 ? child.s1 : child.s0) : (k == 0 ? child.t1 : child.t0)) = middle;
            consider(child);
        }
    }

    /// Queues a region just halved off unless its bound, its gradient or its weights settle it.
    void consider(const Region& child) {
        detail::project(pool_.data() + child.net, netCount(child), points_);
        const double bound = detail::lowerBound(points_, p_, toward());
        if (bound < best_.distance - tolerance_ && !settledByNeighbour(child) && !fartherThanBest(child))
            push(child, bound);
    }

    /// visit() for a flat region: Newton along its edge curve, from [lo, hi] in the patch's parameters.
    void visitFlat(const Region& region, double bound, glm::dvec2 lo, glm::dvec2 hi) {
        const glm::dvec4* net = pool_.data() + region.net;
        const std::size_t count = netCount(region);
        detail::project(net, count, points_);
        auto along = [&](double f) { return lo + f * (hi - lo); };
        auto polish = [&](glm::dvec2 start) {
            take(projector_.polishIn(region.patch, p_, start, lo.x, hi.x, lo.y, hi.y), region.patch);
        };
        const bool holdsBest = std::isfinite(best_.distance) && bestIn(region, lo.x, hi.x, lo.y, hi.y);
        const glm::dvec2 start = holdsBest ? glm::clamp(best_.uv, lo, hi)
                                           : along(static_cast<double>(detail::nearestPoint(points_, p_)) /
                                                   static_cast<double>(count - 1));
        if (detail::provablyConvex(net, points_, count, 1, p_)) return polish(start);
        if (!holdsBest) polish(start);
        if (!(bound < best_.distance - tolerance_)) return;
        if (mayHalve(region)) return splitFlat(region);
        if (detail::provablyFarther(net, count, 1, p_, best_.distance - tolerance_)) return;
        // Too small to halve: from the nearest of a few points along it too, and from its ends and
        // middle where the best so far sits on one of its ends.
        polish(nearestSample(region.patch, lo.x, hi.x, lo.y, hi.y));
        if (bestIn(region, lo.x, hi.x, lo.y, hi.y) && (best_.uv == lo || best_.uv == hi))
            for (double f : {0.0, 0.5, 1.0}) polish(along(f));
    }

    /// Whether row i (alongV: column i) of the region's net is one point (points_ holds them).
    bool collapsedLine(std::size_t i, bool alongV) const {
        const std::size_t count = alongV ? pu_ : qv_;
        const glm::dvec3& first = alongV ? points_[i] : points_[i * qv_];
        const double allowed = collapseTolerance(detail::largestCoordinate(first));
        for (std::size_t k = 1; k < count; ++k)
            if (glm::distance(alongV ? points_[k * qv_ + i] : points_[i * qv_ + k], first) > allowed)
                return false;
        return true;
    }

    /// Whether a region is best halved across a pole in its first or last row (alongV: column) alone:
    /// where the pole is farther than the best so far by more than 1e-3 of the region's size, a few
    /// such halvings bring the bound of the part that touches it past the best. Nearer, the best
    /// may lie just beside the pole, and the region is halved both ways.
    bool acrossPole(bool alongV) const {
        const std::size_t last = alongV ? qv_ - 1 : pu_ - 1;
        const bool first = collapsedLine(0, alongV);
        if (!first && !collapsedLine(last, alongV)) return false;
        const glm::dvec3& pole = points_[first ? 0 : (alongV ? last : last * qv_)];
        BoundingBox box;
        for (const glm::dvec3& q : points_) box.add(q);
        return glm::distance(pole, p_) - best_.distance > 1e-3 * box.diagonal();
    }

    /// Halves a region (points_ holds its net's points) into four, or into two across a pole: a
    /// region whose first or last row is one point is halved in u only (a column: in v only).
    /// Halving it along the pole too would double the regions touching the pole at every level,
    /// none of which a bound settles before it is smaller than the pole's distance from the best.
    void split(const Region& region) {
        ++splits_;
        const bool poleRow = acrossPole(false), poleColumn = acrossPole(true);
        const bool halveU = poleRow || !poleColumn, halveV = poleColumn || !poleRow;
        // The halves along u into the pool, then each along v (or the region's net along v).
        const std::size_t base = pool_.size();
        pool_.resize(base + (halveU && halveV ? 6 : 2) * netSize_);
        glm::dvec4* const lowU = pool_.data() + base;
        const glm::dvec4* net = pool_.data() + region.net;
        if (halveU)
            for (std::size_t j = 0; j < qv_; ++j)
                detail::halveLine(net + j, qv_, pu_, lowU + j, lowU + netSize_ + j, work_);
        const std::size_t halves = halveU ? 2 : 1;
        glm::dvec4* const quarters = halveU ? lowU + 2 * netSize_ : lowU;
        if (halveV)
            for (std::size_t h = 0; h < halves; ++h)
                for (std::size_t i = 0; i < pu_; ++i)
                    detail::halveLine((halveU ? lowU + h * netSize_ : net) + i * qv_, 1, qv_,
                                      quarters + (2 * h) * netSize_ + i * qv_,
                                      quarters + (2 * h + 1) * netSize_ + i * qv_, work_);
        const double sm = 0.5 * (region.s0 + region.s1), tm = 0.5 * (region.t0 + region.t1);
        const std::size_t children = halveU && halveV ? 4 : 2;
        for (std::size_t k = 0; k < children; ++k) {
            Region child = region;
            child.depth = region.depth + 1;
            child.net = base + (children == 4 ? 2 + k : k) * netSize_;
            if (halveU) (k < children / 2 ? child.s1 : child.s0) = sm;
            if (halveV) (k % 2 == 0 ? child.t1 : child.t0) = tm;
            consider(child);
        }
    }

    /// Whether a region may be halved again (points_ holds its net's points).
    bool mayHalve(const Region& region) const {
        if (splits_ >= kSplitBudget) return false;
        if (region.depth < kMaxProjectionDepth) return true;
        if (region.depth >= kHardDepth) return false;
        BoundingBox box;
        for (const glm::dvec3& q : points_) box.add(q);
        return box.diagonal() > kLargeRegion * tree_.scale();
    }

    void visit(Region region, double bound) {
        // The best may have improved since the region was queued.
        if (region.depth > 0 && fartherThanBest(region)) return;
        const BezierPatchTree::Patch& patch = tree_.patches()[region.patch];
        // A region at the patch's far edge ends exactly there (u0 + 1.0 * width can round past it).
        const double ua = patch.u0 + region.s0 * (patch.u1 - patch.u0);
        const double ub = region.s1 >= 1.0 ? patch.u1 : patch.u0 + region.s1 * (patch.u1 - patch.u0);
        const double va = patch.v0 + region.t0 * (patch.v1 - patch.v0);
        const double vb = region.t1 >= 1.0 ? patch.v1 : patch.v0 + region.t1 * (patch.v1 - patch.v0);
        if (region.flat == Flat::alongV) return visitFlat(region, bound, {ua, va}, {ub, va});
        if (region.flat == Flat::alongU) return visitFlat(region, bound, {ua, va}, {ua, vb});
        const bool holdsBest = std::isfinite(best_.distance) && bestIn(region, ua, ub, va, vb);
        const glm::dvec4* net = pool_.data() + region.net;
        detail::project(net, netSize_, points_);
        glm::dvec2 start = best_.uv;
        if (!holdsBest) {
            start = nearestAbscissa(ua, ub, va, vb);
            if (region.depth == 0) start = projector_.patchStart(region.patch, p_, start);
        }
        if (detail::provablyConvex(net, points_, pu_, qv_, p_)) {
            // Convex on the region: Newton held inside it finds the region's minimum.
            take(projector_.polishIn(region.patch, p_, start, ua, ub, va, vb), region.patch);
            return;
        }
        if (!holdsBest)
            take(projector_.polishIn(region.patch, p_, start, patch.u0, patch.u1, patch.v0, patch.v1),
                 region.patch);
        if (!(bound < best_.distance - tolerance_)) return;
        if (mayHalve(region))
            split(region);
        else if (!detail::provablyFarther(net, pu_, qv_, p_, best_.distance - tolerance_))
            settleLeaf(region, ua, ub, va, vb);
    }

    /// A region too small to halve that may still hold a nearer point (wide weights can fold a
    /// local maximum into it): Newton held inside it from its net's point nearest to p (points_
    /// holds the region's net), and where the best so far sits on the region's edge (Newton stopped
    /// there, the minimum just inside), also from its corners, edge middles and centre.
    void settleLeaf(const Region& region, double ua, double ub, double va, double vb) {
        take(projector_.polishIn(region.patch, p_, nearestAbscissa(ua, ub, va, vb), ua, ub, va, vb),
             region.patch);
        const glm::dvec2 sample = nearestSample(region.patch, ua, ub, va, vb);
        take(projector_.polishIn(region.patch, p_, sample, ua, ub, va, vb), region.patch);
        settleBorders(region, ua, ub, va, vb);
        const glm::dvec2 uv = best_.uv;
        if (!bestIn(region, ua, ub, va, vb) || !(uv.x == ua || uv.x == ub || uv.y == va || uv.y == vb))
            return;
        for (int i = 0; i <= 2; ++i)
            for (int j = 0; j <= 2; ++j)
                take(
                    projector_.polishIn(region.patch, p_,
                                        {ua + 0.5 * i * (ub - ua), va + 0.5 * j * (vb - va)}, ua, ub, va, vb),
                    region.patch);
    }

    /// A leaf on its patch's border: Newton along each border edge it holds, from the edge's
    /// middle. Near a pole or a collapsed edge the distance is nearly flat and Newton over the
    /// region (its Hessian nearly singular there) can stop short of a minimum on the border,
    /// which the edge's own curve, regular there, finds.
    void settleBorders(const Region& region, double ua, double ub, double va, double vb) {
        const double um = 0.5 * (ua + ub), vm = 0.5 * (va + vb);
        if (region.t0 == 0.0)
            take(projector_.polishIn(region.patch, p_, {um, va}, ua, ub, va, va), region.patch);
        if (region.t1 == 1.0)
            take(projector_.polishIn(region.patch, p_, {um, vb}, ua, ub, vb, vb), region.patch);
        if (region.s0 == 0.0)
            take(projector_.polishIn(region.patch, p_, {ua, vm}, ua, ua, va, vb), region.patch);
        if (region.s1 == 1.0)
            take(projector_.polishIn(region.patch, p_, {ub, vm}, ub, ub, va, vb), region.patch);
    }

    /// The point of a kLeafGrid x kLeafGrid grid over [ua, ub] x [va, vb] nearest to p: near a
    /// pole the net's nearest point is the pole itself, where the distance's gradient along the
    /// collapsed edge vanishes and Newton cannot choose a direction.
    glm::dvec2 nearestSample(std::size_t patch, double ua, double ub, double va, double vb) const {
        constexpr int kLeafGrid = 5;
        glm::dvec2 best{ua, va};
        double bestDistance = std::numeric_limits<double>::infinity();
        // A flat region's line ([ua, ua] or [va, va]) takes one sample across it.
        const int acrossU = ub > ua ? kLeafGrid : 1, acrossV = vb > va ? kLeafGrid : 1;
        for (int i = 0; i < acrossU; ++i)
            for (int j = 0; j < acrossV; ++j) {
                const glm::dvec2 uv{ua + (ub - ua) * i / (kLeafGrid - 1),
                                    va + (vb - va) * j / (kLeafGrid - 1)};
                const glm::dvec3 d = tree_.evaluate(patch, uv.x, uv.y, 0).point - p_;
                const double e = glm::dot(d, d);
                if (e < bestDistance) bestDistance = e, best = uv;
            }
        return best;
    }

    /// Whether the best so far lies in the region's parameters [ua, ub] x [va, vb].
    bool bestIn(const Region& region, double ua, double ub, double va, double vb) const {
        return bestPatch_ == region.patch && best_.uv.x >= ua && best_.uv.x <= ub && best_.uv.y >= va &&
               best_.uv.y <= vb;
    }

    /// The Bezier abscissa in [ua, ub] x [va, vb] of the region's net point nearest to p (points_
    /// holds the net's points).
    glm::dvec2 nearestAbscissa(double ua, double ub, double va, double vb) const {
        const std::size_t nearest = detail::nearestPoint(points_, p_);
        return {ua + (ub - ua) * static_cast<double>(nearest / qv_) / static_cast<double>(pu_ - 1),
                va + (vb - va) * static_cast<double>(nearest % qv_) / static_cast<double>(qv_ - 1)};
    }

    using Entry = std::pair<double, std::ptrdiff_t>;

    const SurfaceProjector& projector_;
    const BezierPatchTree& tree_;
    const glm::dvec3 p_;
    const std::size_t pu_, qv_, netSize_;
    const double tolerance_;
    SurfacePoint best_;
    std::size_t bestPatch_ = 0;
    std::size_t splits_ = 0;
    glm::dvec3 toward_{0.0};
    std::priority_queue<Entry, std::vector<Entry>, std::greater<Entry>> queue_;
    // Scratch kept per thread between queries, so a query allocates nothing once warm.
    static thread_local std::vector<Region> regions_;
    static thread_local std::vector<glm::dvec4> pool_, work_;
    static thread_local std::vector<glm::dvec3> points_;
};

thread_local std::vector<SurfaceProjector::Search::Region> SurfaceProjector::Search::regions_;
thread_local std::vector<glm::dvec4> SurfaceProjector::Search::pool_, SurfaceProjector::Search::work_;
thread_local std::vector<glm::dvec3> SurfaceProjector::Search::points_;

SurfacePoint SurfaceProjector::closestPoint(const glm::dvec3& p) const {
    detail::checkQueryPoint(p, "closestPoint");
    const SurfacePoint best = Search(*this, p).run();
    detail::checkDistance(best.distance, "closestPoint");
    return beforeJump(best);
}

SurfacePoint closestPoint(const Surface& surface, const glm::dvec3& p) {
    return SurfaceProjector(surface).closestPoint(p);
}

SurfacePoint closestPoint(const Surface& surface, const glm::dvec3& p, const glm::dvec2& guess) {
    return SurfaceProjector(surface).closestPointFrom(p, guess);
}

}  // namespace geom
