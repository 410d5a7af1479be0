#include "geom/SurfaceIntersector.h"

#include "geom/Bezier.h"
#include "geom/GeometryError.h"

#include <glm/geometric.hpp>
#include <glm/vec2.hpp>

#include <algorithm>
#include <cmath>
#include <limits>

namespace geom {
namespace {

constexpr int kMaxSubdivisionDepth = 40;
constexpr std::size_t kNodeBudget = 3000;

/// G(s, t) = sum B_i(s) B_j(t) c_ij of a 2D Bézier patch with its first partials.
struct Projected {
    glm::dvec2 g, gs, gt;
};

struct Scratch {
    std::vector<double> bs, dbs, bt, dbt;
};

Projected evaluateProjected(const glm::dvec2* c, int p, int q, double s, double t, Scratch& w) {
    const std::size_t pu = static_cast<std::size_t>(p) + 1, qv = static_cast<std::size_t>(q) + 1;
    w.bs.resize(pu);
    w.dbs.resize(pu);
    w.bt.resize(qv);
    w.dbt.resize(qv);
    bernsteinBasis(p, s, w.bs, w.dbs);
    bernsteinBasis(q, t, w.bt, w.dbt);
    Projected r{glm::dvec2(0.0), glm::dvec2(0.0), glm::dvec2(0.0)};
    for (std::size_t i = 0; i < pu; ++i) {
        glm::dvec2 row(0.0), rowd(0.0);
        for (std::size_t j = 0; j < qv; ++j) {
            row += w.bt[j] * c[i * qv + j];
            rowd += w.dbt[j] * c[i * qv + j];
        }
        r.g += w.bs[i] * row;
        r.gs += w.dbs[i] * row;
        r.gt += w.bs[i] * rowd;
    }
    return r;
}

/// Splits a (p+1) x (q+1) net at the middle of s (alongT false) or t into a and b.
void splitHalf(const glm::dvec2* src, glm::dvec2* a, glm::dvec2* b, std::size_t pu, std::size_t qv,
               bool alongT, std::vector<glm::dvec2>& work) {
    const std::size_t lines = alongT ? pu : qv;
    const std::size_t length = alongT ? qv : pu;
    work.resize(length);
    for (std::size_t l = 0; l < lines; ++l) {
        auto at = [&](std::size_t k) { return alongT ? l * qv + k : k * qv + l; };
        for (std::size_t k = 0; k < length; ++k) work[k] = src[at(k)];
        a[at(0)] = work[0];
        b[at(length - 1)] = work[length - 1];
        for (std::size_t r = 1; r < length; ++r) {
            for (std::size_t i = 0; i + r < length; ++i) work[i] = 0.5 * (work[i] + work[i + 1]);
            a[at(r)] = work[0];
            b[at(length - 1 - r)] = work[length - 1 - r];
        }
    }
}

/// True when every point of the net lies strictly on one side of the line through the origin
/// along `axis`: the patch cannot reach the origin.
bool excludedAcross(const glm::dvec2* c, std::size_t size, const glm::dvec2& axis, double tolerance) {
    const glm::dvec2 n(-axis.y, axis.x);
    const double len = glm::length(n);
    if (!(len > 0.0)) return false;
    const double tol = tolerance * len;
    bool allAbove = true, allBelow = true;
    for (std::size_t k = 0; k < size && (allAbove || allBelow); ++k) {
        const double d = glm::dot(c[k], n);
        allAbove = allAbove && d > tol;
        allBelow = allBelow && d < -tol;
    }
    return allAbove || allBelow;
}

struct SpanBounds {
    double lo, hi;
};
SpanBounds mul(SpanBounds a, SpanBounds b) {
    const double x1 = a.lo * b.lo, x2 = a.lo * b.hi, x3 = a.hi * b.lo, x4 = a.hi * b.hi;
    return {std::min(std::min(x1, x2), std::min(x3, x4)), std::max(std::max(x1, x2), std::max(x3, x4))};
}

/// True when det [G_s G_t] keeps one strict sign over the whole sub-patch (interval bound on the
/// derivative nets): then the projected map is locally one-to-one and Newton finds its root.
bool jacobianKeepsSign(const glm::dvec2* c, std::size_t pu, std::size_t qv) {
    if (pu < 2 || qv < 2) return false;
    SpanBounds sx{1e300, -1e300}, sy{1e300, -1e300}, tx{1e300, -1e300}, ty{1e300, -1e300};
    for (std::size_t i = 0; i + 1 < pu; ++i)
        for (std::size_t j = 0; j < qv; ++j) {
            const glm::dvec2 d = c[(i + 1) * qv + j] - c[i * qv + j];
            sx = {std::min(sx.lo, d.x), std::max(sx.hi, d.x)};
            sy = {std::min(sy.lo, d.y), std::max(sy.hi, d.y)};
        }
    for (std::size_t i = 0; i < pu; ++i)
        for (std::size_t j = 0; j + 1 < qv; ++j) {
            const glm::dvec2 d = c[i * qv + j + 1] - c[i * qv + j];
            tx = {std::min(tx.lo, d.x), std::max(tx.hi, d.x)};
            ty = {std::min(ty.lo, d.y), std::max(ty.hi, d.y)};
        }
    const SpanBounds a = mul(sx, ty), b = mul(sy, tx);
    const double lo = a.lo - b.hi, hi = a.hi - b.lo;
    return lo > 0.0 || hi < 0.0;
}

struct NewtonResult {
    bool converged = false;
    double s = 0.0, t = 0.0;
};

/// Newton on G(s, t) = 0 kept in the box [s0,s1] x [t0,t1] of the patch, damped where the
/// Jacobian is nearly singular (tangent contact), from the box centre.
NewtonResult newton(const glm::dvec2* c, int p, int q, double s0, double s1, double t0, double t1,
                    double tolerance, Scratch& w, double fs = 0.5, double ft = 0.5) {
    double s = s0 + fs * (s1 - s0), t = t0 + ft * (t1 - t0);
    double residual = 0.0;
    for (int it = 0; it < 80; ++it) {
        const Projected e = evaluateProjected(c, p, q, s, t, w);
        residual = glm::length(e.g);
        if (residual <= 1e-3 * tolerance) break;
        const double det = e.gs.x * e.gt.y - e.gs.y * e.gt.x;
        double ds = -(e.gt.y * e.g.x - e.gt.x * e.g.y) / det;
        double dt = -(-e.gs.y * e.g.x + e.gs.x * e.g.y) / det;
        if (!std::isfinite(ds) || !std::isfinite(dt)) {
            // Singular Jacobian (an exact tangent contact): a damped least-squares step.
            const double a = glm::dot(e.gs, e.gs), b = glm::dot(e.gs, e.gt), d = glm::dot(e.gt, e.gt);
            const double lambda = 1e-12 * (a + d) + 1e-300;
            const double m = (a + lambda) * (d + lambda) - b * b;
            const double gs = glm::dot(e.gs, e.g), gt = glm::dot(e.gt, e.g);
            ds = -((d + lambda) * gs - b * gt) / m;
            dt = -(-b * gs + (a + lambda) * gt) / m;
            if (!std::isfinite(ds) || !std::isfinite(dt)) break;
        }
        const double ns = std::clamp(s + ds, s0, s1), nt = std::clamp(t + dt, t0, t1);
        const double step = std::abs(ns - s) + std::abs(nt - t);
        s = ns;
        t = nt;
        if (step < 1e-17) break;
    }
    residual = glm::length(evaluateProjected(c, p, q, s, t, w).g);
    return {residual <= tolerance, s, t};
}

}  // namespace

SurfaceIntersector::SurfaceIntersector(const Surface& surface) : tree_(surface) {
}

void SurfaceIntersector::intersectPatch(std::size_t index, const glm::dvec3& origin,
                                        const glm::dvec3& direction, const glm::dvec3& n1,
                                        const glm::dvec3& n2, std::vector<LineSurfaceHit>& hits) const {
    const BezierPatchTree::Patch& patch = tree_.patches()[index];
    const int p = tree_.degreeU(), q = tree_.degreeV();
    const std::size_t pu = static_cast<std::size_t>(p) + 1, qv = static_cast<std::size_t>(q) + 1;
    const std::size_t size = pu * qv;

    // Project the homogeneous net across the line: G(s,t) = 0 exactly where S(s,t) is on the line
    // (weights are positive, so the division by w changes no zero).
    thread_local std::vector<glm::dvec2> pool;
    thread_local std::vector<glm::dvec2> work;
    thread_local Scratch scratch;
    struct Sub {
        std::size_t offset;
        double s0, s1, t0, t1;
        int depth;
    };
    thread_local std::vector<Sub> stack;
    pool.resize(size);
    double magnitude = 0.0;
    for (std::size_t k = 0; k < size; ++k) {
        const glm::dvec4& h = patch.net[k];
        const glm::dvec3 rel = glm::dvec3(h) - origin * h.w;
        pool[k] = glm::dvec2(glm::dot(rel, n1), glm::dot(rel, n2));
        magnitude = std::max(magnitude, h.w);
    }
    const double lengthScale = tree_.scale() * magnitude;
    const double boxTolerance = 1e-12 * lengthScale;
    const double newtonTolerance = 1e-13 * lengthScale;

    stack.clear();
    stack.push_back({0, 0.0, 1.0, 0.0, 1.0, 0});
    std::size_t visited = 0;
    auto record = [&](double s, double t) {
        // Polish on the whole patch: near a tangent contact a root found inside a sub-patch may
        // sit on its edge, short of the double root.
        const NewtonResult polished =
            newton(pool.data(), p, q, 0.0, 1.0, 0.0, 1.0, newtonTolerance, scratch, s, t);
        if (polished.converged) {
            s = polished.s;
            t = polished.t;
        }
        const double u = patch.u0 + s * (patch.u1 - patch.u0), v = patch.v0 + t * (patch.v1 - patch.v0);
        const BezierPatchTree::PatchPoint e = tree_.evaluate(index, u, v, 0);
        // t is measured from `origin` (near the surface, see intersect()); the caller shifts it.
        const double lineT = glm::dot(e.point - origin, direction) / glm::dot(direction, direction);
        const glm::dvec3 onLine = origin + lineT * direction;
        if (glm::length(onLine - e.point) > 1e-10 * tree_.scale()) return;
        LineSurfaceHit hit;
        hit.t = lineT;
        hit.uv = glm::dvec2(u, v);
        hit.point = onLine;
        hit.piece = index;
        hits.push_back(hit);
    };
    while (!stack.empty()) {
        const Sub sub = stack.back();
        stack.pop_back();
        const glm::dvec2* c = pool.data() + sub.offset;
        glm::dvec2 lo(std::numeric_limits<double>::infinity()), hi(-std::numeric_limits<double>::infinity());
        for (std::size_t k = 0; k < size; ++k) {
            lo = glm::min(lo, c[k]);
            hi = glm::max(hi, c[k]);
        }
        if (lo.x > boxTolerance || lo.y > boxTolerance || hi.x < -boxTolerance || hi.y < -boxTolerance)
            continue;
        // Two more separating axes, across the net's diagonals: a patch seen nearly edge-on (a
        // line close to tangent) is a thin sliver whose axis-aligned box is much too large.
        if (excludedAcross(c, size, c[size - 1] - c[0], boxTolerance) ||
            excludedAcross(c, size, c[(pu - 1) * qv] - c[qv - 1], boxTolerance))
            continue;

        ++visited;
        const bool unique = jacobianKeepsSign(c, pu, qv);
        const bool last = sub.depth >= kMaxSubdivisionDepth || visited > kNodeBudget;
        // A root on the sub-patch's edge is found from the patches on both sides; a small margin
        // lets Newton reach it, and the merge in intersect() keeps one.
        const double ms = 1e-6 * (sub.s1 - sub.s0), mt = 1e-6 * (sub.t1 - sub.t0);
        const double a0 = std::max(0.0, sub.s0 - ms), a1 = std::min(1.0, sub.s1 + ms);
        const double b0 = std::max(0.0, sub.t0 - mt), b1 = std::min(1.0, sub.t1 + mt);
        if (last) {
            // Out of depth or budget (a tangent contact, a line along the surface): several
            // starts, so that close roots are not lost.
            for (const auto& f : {glm::dvec2(0.5, 0.5), glm::dvec2(0.25, 0.25), glm::dvec2(0.75, 0.25),
                                  glm::dvec2(0.25, 0.75), glm::dvec2(0.75, 0.75)}) {
                const NewtonResult r =
                    newton(pool.data(), p, q, a0, a1, b0, b1, newtonTolerance, scratch, f.x, f.y);
                if (r.converged) record(r.s, r.t);
            }
            continue;
        }
        if (unique) {
            const NewtonResult r = newton(pool.data(), p, q, a0, a1, b0, b1, newtonTolerance, scratch);
            if (r.converged) {
                record(r.s, r.t);
                continue;
            }
        }
        // Four children: split in s, then each half in t.
        const std::size_t o = pool.size();
        pool.resize(o + 6 * size);
        c = pool.data() + sub.offset;
        glm::dvec2* left = pool.data() + o;
        glm::dvec2* right = left + size;
        splitHalf(c, left, right, pu, qv, false, work);
        glm::dvec2* ll = right + size;
        glm::dvec2* lr = ll + size;
        glm::dvec2* rl = lr + size;
        glm::dvec2* rr = rl + size;
        splitHalf(left, ll, lr, pu, qv, true, work);
        splitHalf(right, rl, rr, pu, qv, true, work);
        const double sm = 0.5 * (sub.s0 + sub.s1), tm = 0.5 * (sub.t0 + sub.t1);
        const int d = sub.depth + 1;
        stack.push_back({o + 2 * size, sub.s0, sm, sub.t0, tm, d});
        stack.push_back({o + 3 * size, sub.s0, sm, tm, sub.t1, d});
        stack.push_back({o + 4 * size, sm, sub.s1, sub.t0, tm, d});
        stack.push_back({o + 5 * size, sm, sub.s1, tm, sub.t1, d});
    }
}

std::vector<LineSurfaceHit> SurfaceIntersector::intersect(const glm::dvec3& origin,
                                                          const glm::dvec3& direction) const {
    const double len = glm::length(direction);
    if (!(len > 0.0) || !std::isfinite(len))
        throw GeometryError("intersectLine: the line direction must be a finite, non-zero vector");
    if (!std::isfinite(origin.x) || !std::isfinite(origin.y) || !std::isfinite(origin.z))
        throw GeometryError("intersectLine: the line origin has a non-finite coordinate");
    const glm::dvec3 d = direction / len;
    // Two unit vectors across the line.
    const glm::dvec3 helper = std::abs(d.x) < 0.6 ? glm::dvec3(1, 0, 0) : glm::dvec3(0, 1, 0);
    const glm::dvec3 n1 = glm::normalize(glm::cross(d, helper));
    const glm::dvec3 n2 = glm::cross(d, n1);
    const glm::dvec3 inverse(1.0 / d.x, 1.0 / d.y, 1.0 / d.z);
    const double margin = 1e-9 * tree_.scale();
    const auto& nodes = tree_.nodes();
    if (nodes.empty()) return {};
    // Work from the point of the line nearest the surface's box centre: an origin far away
    // (a pick ray from a distant eye) would otherwise cost digits in every projection.
    const glm::dvec3 centre = nodes[0].box.center();
    const glm::dvec3 base = origin + glm::dot(centre - origin, d) * d;
    const double shift = glm::dot(base - origin, direction) / glm::dot(direction, direction);

    std::vector<LineSurfaceHit> hits;
    int stack[128];
    int top = 0;
    stack[top++] = tree_.root();
    while (top > 0) {
        const BezierPatchTree::Node& node = nodes[static_cast<std::size_t>(stack[--top])];
        if (!node.box.hitByLine(base, inverse, margin)) continue;
        if (node.patch >= 0) {
            intersectPatch(static_cast<std::size_t>(node.patch), base, direction, n1, n2, hits);
            continue;
        }
        stack[top++] = node.first;
        stack[top++] = node.second;
    }
    std::sort(hits.begin(), hits.end(), [](const auto& a, const auto& b) { return a.t < b.t; });
    // One hit per crossing: a root on a patch edge is found from both sides, and a tangent contact
    // (a double root, where Newton converges only linearly) from several sub-patches. Two hits
    // are one when they nearly coincide, or when they are close and the surface between them
    // still lies on the line.
    // A run of such hits (a tangent contact of high order, a line lying in the surface) is
    // reported once, by its middle member.
    std::vector<LineSurfaceHit> unique;
    const double same = 1e-7 * tree_.scale();
    const double near = 1e-2 * tree_.scale();
    // Does the surface pass within tolerance of the line point halfway between two hits?
    // (Gauss-Newton for the nearest surface point, from the middle of their parameters.)
    auto touchesBetween = [&](const LineSurfaceHit& a, const LineSurfaceHit& b) {
        const glm::dvec3 target = 0.5 * (a.point + b.point);
        glm::dvec2 uv = 0.5 * (a.uv + b.uv);
        double distance = 0.0;
        for (int it = 0; it < 6; ++it) {
            const BezierPatchTree::PatchPoint e = tree_.evaluate(uv.x, uv.y, 1);
            const glm::dvec3 r = e.point - target;
            distance = glm::length(r);
            const double a11 = glm::dot(e.su, e.su), a12 = glm::dot(e.su, e.sv), a22 = glm::dot(e.sv, e.sv);
            const double det = a11 * a22 - a12 * a12;
            if (!(det > 0.0)) break;
            const double g1 = glm::dot(e.su, r), g2 = glm::dot(e.sv, r);
            uv.x = std::clamp(uv.x - (a22 * g1 - a12 * g2) / det, tree_.domainStartU(), tree_.domainEndU());
            uv.y = std::clamp(uv.y - (-a12 * g1 + a11 * g2) / det, tree_.domainStartV(), tree_.domainEndV());
        }
        return distance < 1e-12 * tree_.scale();
    };
    std::size_t runStart = 0;
    for (std::size_t k = 0; k <= hits.size(); ++k) {
        if (k > runStart && k < hits.size()) {
            const LineSurfaceHit& previous = hits[k - 1];
            const double gap = glm::length(hits[k].point - previous.point);
            if (gap < same || (gap < near && touchesBetween(previous, hits[k]))) continue;
        }
        if (k > runStart) unique.push_back(hits[(runStart + k - 1) / 2]);
        runStart = k;
    }
    for (LineSurfaceHit& h : unique) {
        h.t += shift;
        h.point = origin + h.t * direction;
    }
    return unique;
}

std::vector<LineSurfaceHit> intersectLine(const Surface& surface, const glm::dvec3& origin,
                                          const glm::dvec3& direction) {
    return SurfaceIntersector(surface).intersect(origin, direction);
}

std::vector<LineSurfaceHit> intersectRay(const Surface& surface, const glm::dvec3& origin,
                                         const glm::dvec3& direction) {
    std::vector<LineSurfaceHit> hits = intersectLine(surface, origin, direction);
    std::erase_if(hits, [](const LineSurfaceHit& h) { return h.t < 0.0; });
    return hits;
}

}  // namespace geom
