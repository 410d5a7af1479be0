#include "geom/SurfaceIntersector.h"
#include "UnitScale.h"

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
/// How far past its own edges (a fraction of the patch) Newton may follow a root. A root on a
/// patch edge (a domain edge, a knot line, a crease) lies, after the rounding of the projection,
/// just outside the patch on one side or on both; kept inside, Newton stops short of it on both.
/// The root is then taken on the edge, where the line check decides.
constexpr double kEdgeReach = 1e-9;

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
    // Degree 0 (an edge divided out of a degree-1 direction): constant, so its derivative is 0.
    if (p == 0) w.dbs[0] = 0.0;
    if (q == 0) w.dbt[0] = 0.0;
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

/// Bounds of a net's differences along s and along t (the derivative nets over p and q):
/// slope[row][column], rows the x and y of G, columns s and t.
struct NetSlopes {
    SpanBounds slope[2][2] = {{{1e300, -1e300}, {1e300, -1e300}}, {{1e300, -1e300}, {1e300, -1e300}}};
};

NetSlopes netSlopes(const glm::dvec2* c, std::size_t pu, std::size_t qv) {
    NetSlopes n;
    auto widen = [](SpanBounds& b, double x) { b = {std::min(b.lo, x), std::max(b.hi, x)}; };
    for (std::size_t i = 0; i + 1 < pu; ++i)
        for (std::size_t j = 0; j < qv; ++j) {
            const glm::dvec2 d = c[(i + 1) * qv + j] - c[i * qv + j];
            widen(n.slope[0][0], d.x), widen(n.slope[1][0], d.y);
        }
    for (std::size_t i = 0; i < pu; ++i)
        for (std::size_t j = 0; j + 1 < qv; ++j) {
            const glm::dvec2 d = c[i * qv + j + 1] - c[i * qv + j];
            widen(n.slope[0][1], d.x), widen(n.slope[1][1], d.y);
        }
    return n;
}

/// True when det [G_s G_t] keeps one strict sign over the whole sub-patch (interval bound on the
/// derivative nets): then the projected map is locally one-to-one and Newton finds its root.
bool jacobianKeepsSign(const NetSlopes& n) {
    const SpanBounds a = mul(n.slope[0][0], n.slope[1][1]), b = mul(n.slope[1][0], n.slope[0][1]);
    const double lo = a.lo - b.hi, hi = a.hi - b.lo;
    return lo > 0.0 || hi < 0.0;
}

/// Krawczyk's test of G on the sub-net c over its own unit square X: true when X holds no root.
/// With Y the inverse Jacobian at the centre x0 and J(X) the bounds of the derivative nets, every
/// root in X lies in K = x0 - Y G(x0) + (I - Y J(X)) (X - x0), so K apart from X proves there is
/// none. `error` bounds the rounding in G: no root hidden by it is excluded. Degrees p, q >= 1;
/// `slopes` are the net's own (netSlopes).
bool krawczykExcludes(const glm::dvec2* c, int p, int q, const NetSlopes& slopes, double error, Scratch& w) {
    // j[row][column]: the Jacobian's entries, columns d/ds and d/dt (the slopes times p and q).
    SpanBounds j[2][2];
    for (int r = 0; r < 2; ++r) {
        j[r][0] = {double(p) * slopes.slope[r][0].lo, double(p) * slopes.slope[r][0].hi};
        j[r][1] = {double(q) * slopes.slope[r][1].lo, double(q) * slopes.slope[r][1].hi};
    }
    const Projected e = evaluateProjected(c, p, q, 0.5, 0.5, w);
    const double det = e.gs.x * e.gt.y - e.gs.y * e.gt.x;
    const double y[2][2] = {{e.gt.y / det, -e.gt.x / det}, {-e.gs.y / det, e.gs.x / det}};
    for (int r = 0; r < 2; ++r) {
        const double centre = 0.5 - (y[r][0] * e.g.x + y[r][1] * e.g.y);
        double radius = (std::abs(y[r][0]) + std::abs(y[r][1])) * error;
        for (int col = 0; col < 2; ++col) {
            SpanBounds m{r == col ? 1.0 : 0.0, r == col ? 1.0 : 0.0};
            for (int k = 0; k < 2; ++k) {
                const SpanBounds t = mul({y[r][k], y[r][k]}, j[k][col]);
                m = {m.lo - t.hi, m.hi - t.lo};
            }
            radius += 0.5 * std::max(std::abs(m.lo), std::abs(m.hi));
        }
        // A little more for the rounding of these sums themselves.
        radius = radius * (1.0 + 1e-9) + 1e-12;
        if (std::isfinite(centre) && std::isfinite(radius) &&
            (centre + radius < 0.0 || centre - radius > 1.0))
            return true;
    }
    return false;
}

/// The four edges of a patch, as net rows (s = 0, s = 1) or columns (t = 0, t = 1).
enum class Edge { S0, S1, T0, T1 };
constexpr Edge kEdges[] = {Edge::S0, Edge::S1, Edge::T0, Edge::T1};

/// Index of the k-th net point along `edge` of a (p+1) x (q+1) net.
std::size_t edgePoint(Edge edge, std::size_t k, int p, int q) {
    const std::size_t qv = static_cast<std::size_t>(q) + 1;
    switch (edge) {
        case Edge::S0:
            return k;
        case Edge::S1:
            return static_cast<std::size_t>(p) * qv + k;
        case Edge::T0:
            return k * qv;
        case Edge::T1:
            break;
    }
    return k * qv + static_cast<std::size_t>(q);
}

/// G with the factor s, 1 - s, t or 1 - t of a vanishing edge divided out (its degree one less
/// that way): B^p_i(s) = (p / i) s B^(p-1)_(i-1)(s) and (p / (p - i)) (1 - s) B^(p-1)_i(s). The
/// edge's own coefficients, zero within the tolerance, are dropped.
std::vector<glm::dvec2> divideEdge(const std::vector<glm::dvec2>& c, int& p, int& q, Edge edge) {
    const std::size_t pu = static_cast<std::size_t>(p) + 1, qv = static_cast<std::size_t>(q) + 1;
    const bool alongS = edge == Edge::S0 || edge == Edge::S1;
    const bool start = edge == Edge::S0 || edge == Edge::T0;
    const int n = alongS ? p : q;
    const std::size_t newPu = alongS ? pu - 1 : pu, newQv = alongS ? qv : qv - 1;
    std::vector<glm::dvec2> out(newPu * newQv);
    for (std::size_t i = 0; i < newPu; ++i)
        for (std::size_t k = 0; k < newQv; ++k) {
            const std::size_t a = alongS ? i : k;  // index along the divided direction, new net
            const std::size_t from = start ? a + 1 : a;
            const double factor = start ? double(n) / double(from) : double(n) / double(n - int(from));
            const std::size_t src = alongS ? from * qv + k : i * qv + from;
            out[i * newQv + k] = factor * c[src];
        }
    (alongS ? p : q) -= 1;
    return out;
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

/// How near zero G must come, in its own units.
struct Tolerances {
    double box;     ///< a cell whose box is farther from the origin holds no root
    double newton;  ///< Newton's residual at a root
    double error;   ///< the rounding in G, for Krawczyk's test
};

/// The roots of G on the net (degrees p, q) over the unit square, each handed to found(s, t). A
/// cell far from the origin by its box or two diagonal axes goes; one whose Jacobian keeps its
/// sign hands over Newton's root, or, when Newton reaches none, goes if Krawczyk's test excludes
/// it; the rest split four ways, breadth first. So when the budget runs out (a tangent contact, a
/// line lying in the surface) every region has been searched as deeply as the others, and what is
/// left gets several Newton starts.
template <class Found>
void findRoots(const std::vector<glm::dvec2>& net, int p, int q, const Tolerances& tol, Found&& found) {
    const std::size_t pu = static_cast<std::size_t>(p) + 1, qv = static_cast<std::size_t>(q) + 1;
    const std::size_t size = pu * qv;
    struct Cell {
        std::size_t offset;
        double s0, s1, t0, t1;
        int depth;
    };
    thread_local std::vector<glm::dvec2> pool, work;
    thread_local std::vector<Cell> queue;
    thread_local Scratch scratch;
    pool.assign(net.begin(), net.end());
    queue.assign(1, Cell{0, 0.0, 1.0, 0.0, 1.0, 0});
    std::size_t visited = 0;
    for (std::size_t head = 0; head < queue.size(); ++head) {
        const Cell cell = queue[head];
        const glm::dvec2* c = pool.data() + cell.offset;
        glm::dvec2 lo(std::numeric_limits<double>::infinity()), hi(-std::numeric_limits<double>::infinity());
        for (std::size_t k = 0; k < size; ++k) lo = glm::min(lo, c[k]), hi = glm::max(hi, c[k]);
        if (lo.x > tol.box || lo.y > tol.box || hi.x < -tol.box || hi.y < -tol.box) continue;
        // Two more separating axes, across the net's diagonals: a patch seen nearly edge-on (a
        // line close to tangent) is a thin sliver whose axis-aligned box is much too large.
        if (excludedAcross(c, size, c[size - 1] - c[0], tol.box) ||
            excludedAcross(c, size, c[(pu - 1) * qv] - c[qv - 1], tol.box))
            continue;
        ++visited;
        const bool last = cell.depth >= kMaxSubdivisionDepth || visited > kNodeBudget;
        // A root on the cell's edge is found from the cells on both sides; a small margin lets
        // Newton reach it, and the merge in intersect() keeps one.
        const double ms = 1e-6 * (cell.s1 - cell.s0), mt = 1e-6 * (cell.t1 - cell.t0);
        const double a0 = std::max(-kEdgeReach, cell.s0 - ms), a1 = std::min(1.0 + kEdgeReach, cell.s1 + ms);
        const double b0 = std::max(-kEdgeReach, cell.t0 - mt), b1 = std::min(1.0 + kEdgeReach, cell.t1 + mt);
        auto newtonFinds = [&](double fs, double ft) {
            const NewtonResult r = newton(pool.data(), p, q, a0, a1, b0, b1, tol.newton, scratch, fs, ft);
            if (r.converged) found(r.s, r.t);
            return r.converged;
        };
        if (!last && pu > 1 && qv > 1) {
            const NetSlopes slopes = netSlopes(c, pu, qv);
            if (jacobianKeepsSign(slopes)) {
                if (newtonFinds(0.5, 0.5)) continue;
                // No root reached: a cell beside one, kept by the box test's tolerance. Where the
                // Jacobian varies this little, Krawczyk's test tells such a cell apart.
                if (krawczykExcludes(c, p, q, slopes, tol.error, scratch)) continue;
            }
        }
        if (last) {
            // At full depth several starts, so that close roots are not lost; out of budget (a
            // line lying in the surface leaves thousands of cells queued) one from the centre.
            newtonFinds(0.5, 0.5);
            if (visited <= kNodeBudget)
                for (const auto& f : {glm::dvec2(0.25, 0.25), glm::dvec2(0.75, 0.25), glm::dvec2(0.25, 0.75),
                                      glm::dvec2(0.75, 0.75)})
                    newtonFinds(f.x, f.y);
            continue;
        }
        const std::size_t o = pool.size();
        pool.resize(o + 6 * size);
        c = pool.data() + cell.offset;
        glm::dvec2* left = pool.data() + o;
        glm::dvec2* right = left + size;
        splitHalf(c, left, right, pu, qv, false, work);
        splitHalf(left, right + size, right + 2 * size, pu, qv, true, work);
        splitHalf(right, right + 3 * size, right + 4 * size, pu, qv, true, work);
        const double sm = 0.5 * (cell.s0 + cell.s1), tm = 0.5 * (cell.t0 + cell.t1);
        const int d = cell.depth + 1;
        queue.push_back({o + 2 * size, cell.s0, sm, cell.t0, tm, d});
        queue.push_back({o + 3 * size, cell.s0, sm, tm, cell.t1, d});
        queue.push_back({o + 4 * size, sm, cell.s1, cell.t0, tm, d});
        queue.push_back({o + 5 * size, sm, cell.s1, tm, cell.t1, d});
    }
}

/// Does the surface pass within 1e-12 of its size of the line point halfway between two hits?
/// (Gauss-Newton for the nearest surface point, from the middle of their parameters.)
bool touchesBetween(const BezierPatchTree& tree, const LineSurfaceHit& a, const LineSurfaceHit& b) {
    const glm::dvec3 target = 0.5 * (a.point + b.point);
    glm::dvec2 uv = 0.5 * (a.uv + b.uv);
    double distance = 0.0;
    for (int it = 0; it < 6; ++it) {
        const BezierPatchTree::PatchPoint e = tree.evaluate(uv.x, uv.y, 1);
        const glm::dvec3 r = e.point - target;
        distance = glm::length(r);
        const double a11 = glm::dot(e.su, e.su), a12 = glm::dot(e.su, e.sv), a22 = glm::dot(e.sv, e.sv);
        const double det = a11 * a22 - a12 * a12;
        if (!(det > 0.0)) break;
        const double g1 = glm::dot(e.su, r), g2 = glm::dot(e.sv, r);
        uv.x = std::clamp(uv.x - (a22 * g1 - a12 * g2) / det, tree.domainStartU(), tree.domainEndU());
        uv.y = std::clamp(uv.y - (-a12 * g1 + a11 * g2) / det, tree.domainStartV(), tree.domainEndV());
    }
    return distance < 1e-12 * tree.scale();
}

/// The surface's unit normal at uv, or zero where it is degenerate: a first derivative (over the
/// whole domain width) below a millionth of the surface's size or at the rounding level of its
/// coordinates (a collapsed edge, or a surface collapsed to one point).
glm::dvec3 sheetNormal(const BezierPatchTree& tree, const glm::dvec2& uv, double rounding) {
    const BezierPatchTree::PatchPoint e = tree.evaluate(uv.x, uv.y, 1);
    const double small = std::max(1e-6 * tree.scale(), rounding);
    const double su = glm::length(e.su), sv = glm::length(e.sv);
    if (!(su * (tree.domainEndU() - tree.domainStartU()) > small) ||
        !(sv * (tree.domainEndV() - tree.domainStartV()) > small))
        return glm::dvec3(0.0);
    const glm::dvec3 n = glm::cross(e.su / su, e.sv / sv);
    const double length = glm::length(n);
    return length > 1e-6 ? n / length : glm::dvec3(0.0);
}

/// Whether two hits at one point are one crossing: the same root found twice (nearly the same
/// parameters), the two sides of a seam, or a degenerate place (a pole, a surface collapsed to
/// the point). Two smooth sheets of a self-intersection crossing there have different tangent
/// planes, and are two crossings.
bool oneCrossing(const BezierPatchTree& tree, const LineSurfaceHit& a, const LineSurfaceHit& b,
                 double rounding) {
    const double widthU = tree.domainEndU() - tree.domainStartU();
    const double widthV = tree.domainEndV() - tree.domainStartV();
    if (std::abs(a.uv.x - b.uv.x) <= 1e-5 * widthU && std::abs(a.uv.y - b.uv.y) <= 1e-5 * widthV) return true;
    auto opposite = [](double x, double y, double start, double end) {
        const double slack = 1e-9 * (end - start);
        return (x <= start + slack && y >= end - slack) || (y <= start + slack && x >= end - slack);
    };
    if (opposite(a.uv.x, b.uv.x, tree.domainStartU(), tree.domainEndU()) ||
        opposite(a.uv.y, b.uv.y, tree.domainStartV(), tree.domainEndV()))
        return true;
    const glm::dvec3 na = sheetNormal(tree, a.uv, rounding), nb = sheetNormal(tree, b.uv, rounding);
    return na == glm::dvec3(0.0) || nb == glm::dvec3(0.0) || glm::length(glm::cross(na, nb)) <= 1e-3;
}

/// One hit per crossing, from hits sorted by t. A root on a patch edge is found from both sides,
/// a tangent contact (a double root, where Newton converges only linearly) from several
/// sub-patches, and every cell of a degenerate piece (a surface collapsed to a point) converges
/// to its point. Hits follow each other in one run when they nearly coincide (within 1e-7 of the
/// surface's size, or the rounding of their coordinates), or when they are close and the surface
/// between them still lies on the line (a tangent contact of high order, a line lying in the
/// surface): a run is reported once, by its middle member. A run at one point is first parted
/// into its crossings (oneCrossing), one hit each.
std::vector<LineSurfaceHit> oneHitPerCrossing(const BezierPatchTree& tree,
                                              const std::vector<LineSurfaceHit>& hits) {
    std::vector<LineSurfaceHit> unique;
    const double near = 1e-2 * tree.scale();
    auto sameAt = [&](const LineSurfaceHit& h) {
        return std::max(1e-7 * tree.scale(),
                        64.0 * std::numeric_limits<double>::epsilon() * detail::largestCoordinate(h.point));
    };
    auto emitRun = [&](std::size_t first, std::size_t end) {
        const double rounding =
            1e3 * std::numeric_limits<double>::epsilon() * detail::largestCoordinate(hits[first].point);
        if (glm::length(hits[end - 1].point - hits[first].point) >= sameAt(hits[first])) {
            unique.push_back(hits[(first + end - 1) / 2]);
            return;
        }
        std::vector<std::vector<std::size_t>> crossings;
        for (std::size_t k = first; k < end; ++k) {
            auto same = std::find_if(crossings.begin(), crossings.end(), [&](const auto& members) {
                return oneCrossing(tree, hits[members.front()], hits[k], rounding);
            });
            if (same == crossings.end())
                crossings.push_back({k});
            else
                same->push_back(k);
        }
        for (const auto& members : crossings) unique.push_back(hits[members[(members.size() - 1) / 2]]);
    };
    std::size_t runStart = 0;
    for (std::size_t k = 0; k <= hits.size(); ++k) {
        if (k > runStart && k < hits.size()) {
            const LineSurfaceHit& previous = hits[k - 1];
            const double gap = glm::length(hits[k].point - previous.point);
            if (gap < sameAt(previous) || (gap < near && touchesBetween(tree, previous, hits[k]))) continue;
        }
        if (k > runStart) emitRun(runStart, k);
        runStart = k;
    }
    std::sort(unique.begin(), unique.end(), [](const auto& a, const auto& b) { return a.t < b.t; });
    return unique;
}

}  // namespace

SurfaceIntersector::SurfaceIntersector(const Surface& surface) : tree_(surface) {
    const double scale = detail::unitScale(surface.points);
    if (scale > 0x1p-400 && scale < 0x1p400) return;
    Surface unit = surface;
    for (glm::dvec3& p : unit.points) p *= scale;
    unitTree_.emplace(unit);
    unitScale_ = scale;
}

void SurfaceIntersector::intersectPatch(std::size_t index, const SearchLine& line,
                                        std::vector<LineSurfaceHit>& hits) const {
    const glm::dvec3 &origin = line.origin, &direction = line.direction, &n1 = line.n1, &n2 = line.n2;
    const BezierPatchTree& tree = searchTree();
    const BezierPatchTree::Patch& patch = tree.patches()[index];
    const int p = tree.degreeU(), q = tree.degreeV();
    const std::size_t size = (static_cast<std::size_t>(p) + 1) * (static_cast<std::size_t>(q) + 1);

    // Project the homogeneous net across the line: G(s,t) = 0 exactly where S(s,t) is on the line
    // (weights are positive, so the division by w changes no zero).
    thread_local std::vector<glm::dvec2> projected;
    thread_local Scratch scratch;
    projected.resize(size);
    // `terms` bounds the size of what each projection sums (in the 1-norm), for its rounding.
    const double originSize = std::abs(origin.x) + std::abs(origin.y) + std::abs(origin.z);
    double magnitude = 0.0, terms = 0.0;
    for (std::size_t k = 0; k < size; ++k) {
        const glm::dvec4& h = patch.net[k];
        const glm::dvec3 rel = glm::dvec3(h) - origin * h.w;
        projected[k] = glm::dvec2(glm::dot(rel, n1), glm::dot(rel, n2));
        magnitude = std::max(magnitude, h.w);
        terms = std::max(terms, std::abs(h.x) + std::abs(h.y) + std::abs(h.z) + originSize * h.w);
    }
    const double lengthScale = tree.scale() * magnitude;
    // The rounding bound covers the projection and 40 levels of halving (each adds at most an
    // epsilon of the net's size), times the factor p an edge division can bring. The box test and
    // Newton's residual allow for the projection's own rounding (a few epsilons of `terms`): far
    // from the origin, or with large weights, it exceeds 1e-13 of the patch, and a root on a patch
    // edge or corner (where the net's corner value is G itself) would go with its cell, or lie
    // out of Newton's reach. accept() still asks the point itself to be on the line.
    const double rounding =
        std::max(8.0 * std::numeric_limits<double>::epsilon() * terms, line.placing * magnitude);
    const Tolerances tolerances{std::max(1e-12 * lengthScale, rounding),
                                std::max(1e-13 * lengthScale, rounding), 1e-13 * terms};

    auto accept = [&](double s, double t) {
        s = std::clamp(s, 0.0, 1.0), t = std::clamp(t, 0.0, 1.0);
        const double u = patch.u0 + s * (patch.u1 - patch.u0), v = patch.v0 + t * (patch.v1 - patch.v0);
        const BezierPatchTree::PatchPoint e = tree.evaluate(index, u, v, 0);
        // t is measured from `origin` (near the surface, see intersect()); the caller shifts it.
        const double lineT = glm::dot(e.point - origin, direction) / glm::dot(direction, direction);
        const glm::dvec3 onLine = origin + lineT * direction;
        // Far from the origin the point itself carries the rounding of its coordinates' size,
        // which may pass 1e-10 of a small patch (one unit across at 1e6 from the origin).
        const double pointSize = std::abs(e.point.x) + std::abs(e.point.y) + std::abs(e.point.z);
        const double reach = std::max(
            {1e-10 * tree.scale(), 64.0 * std::numeric_limits<double>::epsilon() * pointSize, line.placing});
        if (glm::length(onLine - e.point) > reach) return;
        LineSurfaceHit hit;
        hit.t = lineT;
        hit.uv = glm::dvec2(u, v);
        hit.point = onLine;
        hit.piece = index;
        hits.push_back(hit);
    };
    auto record = [&](double s, double t) {
        // Polish on the whole patch's own G: near a tangent contact a root found inside a cell may
        // sit on its edge, short of the double root, and a divided net is only G's factor.
        const NewtonResult polished = newton(projected.data(), p, q, -kEdgeReach, 1.0 + kEdgeReach,
                                             -kEdgeReach, 1.0 + kEdgeReach, tolerances.newton, scratch, s, t);
        if (polished.converged) s = polished.s, t = polished.t;
        accept(s, t);
    };

    // An edge on the line (a pole on it: the apex of a cone, the nose of a fuselage) makes G vanish
    // along the whole edge, and no test could ever part its cells from the root. Its middle is one
    // hit, and the other roots are those of G with the edge's factor divided out.
    thread_local std::vector<glm::dvec2> net;
    net = projected;
    int np = p, nq = q;
    for (const Edge edge : kEdges) {
        const bool alongS = edge == Edge::S0 || edge == Edge::S1;
        if ((alongS ? np : nq) < 1) continue;
        bool onLine = true;
        for (std::size_t k = 0; k <= static_cast<std::size_t>(alongS ? q : p) && onLine; ++k) {
            const std::size_t at = edgePoint(edge, k, p, q);
            const double near = std::max(1e-11 * tree.scale() * patch.net[at].w, rounding);
            onLine = glm::dot(projected[at], projected[at]) <= near * near;
        }
        if (!onLine) continue;
        accept(edge == Edge::S1 ? 1.0 : alongS ? 0.0 : 0.5, edge == Edge::T1 ? 1.0 : alongS ? 0.5 : 0.0);
        net = divideEdge(net, np, nq, edge);
    }
    findRoots(net, np, nq, tolerances, record);
}

std::vector<LineSurfaceHit> SurfaceIntersector::intersect(const glm::dvec3& lineOrigin,
                                                          const glm::dvec3& direction) const {
    const BezierPatchTree& tree = searchTree();
    const double len = glm::length(direction);
    if (!(len > 0.0) || !std::isfinite(len))
        throw GeometryError("intersectLine: the line direction must be a finite, non-zero vector");
    if (!std::isfinite(lineOrigin.x) || !std::isfinite(lineOrigin.y) || !std::isfinite(lineOrigin.z))
        throw GeometryError("intersectLine: the line origin has a non-finite coordinate");
    const auto& nodes = tree.nodes();
    if (nodes.empty()) return {};
    const glm::dvec3 d = direction / len;
    // Two unit vectors across the line.
    const glm::dvec3 helper = std::abs(d.x) < 0.6 ? glm::dvec3(1, 0, 0) : glm::dvec3(0, 1, 0);
    const glm::dvec3 n1 = glm::normalize(glm::cross(d, helper));
    const glm::dvec3 n2 = glm::cross(d, n1);
    const glm::dvec3 inverse(1.0 / d.x, 1.0 / d.y, 1.0 / d.z);
    // Work from the point of the line nearest the surface's box centre: an origin far away
    // (a pick ray from a distant eye) would otherwise cost digits in every projection. It is
    // found in the caller's coordinates, where the origin is finite; the search runs in the
    // search tree's (the surface's, or scaled to unit size), where a line parameter is unitScale_
    // times the caller's.
    const glm::dvec3 centre = nodes[0].box.center() / unitScale_;
    const glm::dvec3 callerBase = lineOrigin + glm::dot(centre - lineOrigin, d) * d;
    const double shift = glm::dot(callerBase - lineOrigin, direction) / glm::dot(direction, direction);
    const glm::dvec3 base = callerBase * unitScale_;
    // Where the line passes the surface is known to the rounding of the coordinates that placed
    // it (the origin's and the centre's): the boxes are widened by it (a surface collapsed to a
    // point has boxes of no size) and a hit may lie that far off the line.
    using detail::largestCoordinate;
    const double placing =
        64.0 * std::numeric_limits<double>::epsilon() *
        (largestCoordinate(lineOrigin) + largestCoordinate(centre) + largestCoordinate(callerBase)) *
        unitScale_;
    if (!std::isfinite(placing) || !std::isfinite(base.x) || !std::isfinite(base.y) || !std::isfinite(base.z))
        throw GeometryError(
            "intersectLine: the line origin lies too far from the surface (relative to its size) "
            "to place the line near it");
    const double margin = std::max(1e-9 * tree.scale(), placing);

    std::vector<LineSurfaceHit> hits;
    int stack[128];
    int top = 0;
    stack[top++] = tree.root();
    while (top > 0) {
        const BezierPatchTree::Node& node = nodes[static_cast<std::size_t>(stack[--top])];
        if (!node.box.hitByLine(base, inverse, margin)) continue;
        if (node.patch >= 0) {
            intersectPatch(static_cast<std::size_t>(node.patch), {base, direction, n1, n2, placing}, hits);
            continue;
        }
        stack[top++] = node.first;
        stack[top++] = node.second;
    }
    std::sort(hits.begin(), hits.end(), [](const auto& a, const auto& b) { return a.t < b.t; });
    std::vector<LineSurfaceHit> unique = oneHitPerCrossing(tree, hits);
    for (LineSurfaceHit& h : unique) {
        h.t = h.t / unitScale_ + shift;
        h.point = lineOrigin + h.t * direction;
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
