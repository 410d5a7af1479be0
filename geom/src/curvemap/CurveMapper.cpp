#include "geom/curvemap/CurveMapper.h"

#include "../NumberText.h"
#include "../SegmentDistance.h"

#include "KnotLines.h"
#include "ProjectedBoxes.h"

#include "geom/Evaluate.h"
#include "geom/EvenOdd.h"
#include "geom/GeometryError.h"

#include <glm/geometric.hpp>
#include <glm/mat3x3.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <limits>

namespace geom::curvemap {

namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

using detail::segmentDistance;

/// One projection of a placed curve point along the normal.
struct Sample {
    double s = 0.0;
    glm::dvec3 local{0.0};  ///< the curve point in its own plane coordinates
    glm::dvec3 from{0.0};   ///< the placed curve point in model space
    bool hit = false;
    glm::dvec2 uv{0.0};
    glm::dvec3 point{0.0};
    double t = 0.0;
};

/// A place on the surface boundary: which boundary component and how far along it (the
/// coordinate runs with the domain on its left, i.e. counter-clockwise).
struct BoundaryPosition {
    int component = -1;
    double sigma = 0.0;
};

struct Vertex {
    glm::dvec2 uv{0.0};
    double s = kNaN;
    glm::dvec3 from{kNaN};
};

/// A mapped piece of curve from an entry on the boundary to an exit.
struct Arc {
    std::vector<Vertex> vertices;
    BoundaryPosition entry, exit;
    bool used = false;
};

/// One straight piece of a boundary component: tau is the free parameter (u or w),
/// sigma = base + sign * (tau - tauRef).
struct Edge {
    int component;
    bool constantU;
    double value;
    double base, sign, tauRef;
    double tau0, tau1;  ///< domain of tau
};

/// The boundary of the domain as components with a counter-clockwise coordinate.
struct Boundary {
    std::vector<Edge> edges;
    std::vector<double> lengths;               ///< per component
    std::vector<std::vector<double>> corners;  ///< sigma of each corner, per component

    explicit Boundary(const SurfaceDomain& d) {
        const double lu = d.u1 - d.u0, lw = d.w1 - d.w0;
        if (!d.closedU && !d.closedW) {
            edges = {{0, false, d.w0, 0.0, 1.0, d.u0, d.u0, d.u1},
                     {0, true, d.u1, lu, 1.0, d.w0, d.w0, d.w1},
                     {0, false, d.w1, lu + lw, -1.0, d.u1, d.u0, d.u1},
                     {0, true, d.u0, 2 * lu + lw, -1.0, d.w1, d.w0, d.w1}};
            lengths = {2 * (lu + lw)};
            corners = {{0.0, lu, lu + lw, 2 * lu + lw}};
        } else if (d.closedU && !d.closedW) {
            edges = {{0, false, d.w0, 0.0, 1.0, d.u0, d.u0, d.u1},
                     {1, false, d.w1, 0.0, -1.0, d.u1, d.u0, d.u1}};
            lengths = {lu, lu};
            corners = {{}, {}};
        } else if (!d.closedU && d.closedW) {
            edges = {{0, true, d.u0, 0.0, -1.0, d.w1, d.w0, d.w1},
                     {1, true, d.u1, 0.0, 1.0, d.w0, d.w0, d.w1}};
            lengths = {lw, lw};
            corners = {{}, {}};
        }
    }

    double wrapSigma(int c, double sigma) const {
        const double l = lengths[static_cast<std::size_t>(c)];
        double r = std::fmod(sigma, l);
        return r < 0 ? r + l : r;
    }
    BoundaryPosition position(const Edge& e, double tau) const {
        return {e.component, wrapSigma(e.component, e.base + e.sign * (tau - e.tauRef))};
    }
    /// (u, w) at a boundary coordinate (base domain, closed coordinates possibly one period off).
    glm::dvec2 uvAt(int c, double sigma) const {
        sigma = wrapSigma(c, sigma);
        const Edge* best = nullptr;
        for (const Edge& e : edges) {
            if (e.component != c) continue;
            const double len = e.tau1 - e.tau0;
            if (sigma >= e.base - 1e-15 && sigma <= e.base + len + 1e-15) best = &e;
            if (best) break;
        }
        if (!best) best = &edges.front();
        const double tau = best->tauRef + (sigma - best->base) / best->sign;
        return best->constantU ? glm::dvec2(best->value, tau) : glm::dvec2(tau, best->value);
    }
};

/// The largest distance of a control point from the origin.
double largestNorm(const std::vector<glm::dvec3>& points) {
    double size = 0.0;
    for (const glm::dvec3& p : points) size = std::max(size, glm::length(p));
    return size;
}

/// The diagonal of the points' bounding box (0 for none).
double boxDiagonal(const std::vector<glm::dvec3>& points) {
    glm::dvec3 lo(std::numeric_limits<double>::max()), hi(-std::numeric_limits<double>::max());
    for (const glm::dvec3& p : points) {
        lo = glm::min(lo, p);
        hi = glm::max(hi, p);
    }
    return points.empty() ? 0.0 : glm::length(hi - lo);
}

/// Maps one curve: the state of a single MAP CURVE of one part.
class PartMapper {
public:
    PartMapper(const Surface& surface, const SurfaceDomain& domain, const SurfaceIntersector& intersector,
               const PlacementFrame& frame, const Curve& curve, const MapOptions& options, MappedPart& out)
        : surface_(surface),
          domain_(domain),
          intersector_(intersector),
          frame_(frame),
          curve_(curve),
          options_(options),
          out_(out),
          boundary_(domain),
          boxes_(intersector.tree(), frame),
          knotLines_(surface, domain) {}

    void run();

private:
    Sample project(double s);
    bool needsSplit(const Sample& a, const Sample& m, const Sample& b, double fraction) const;
    bool jumps(const Sample& a, const Sample& b) const;
    void refine(const Sample& a, const Sample& b, int depth, std::vector<Sample>& samples);
    bool foldsBetween(const Sample& a, const Sample& b) const;
    bool subChordStrays(const std::array<Sample, 4>& q, int piece) const;
    bool crossing(const Sample& inside, const Sample& outside, Vertex& vertex, BoundaryPosition& where);
    std::vector<Vertex> boundaryWalk(int component, double from, double length) const;
    void densifyWalk(int component, double a, double b, int depth, std::vector<Vertex>& out) const;
    void emitLoop(std::vector<Vertex> vertices, std::size_t walks);
    std::vector<Sample> sampleCurve();
    void mapWithoutHits(const std::vector<Sample>& samples);
    bool regionLeftAt(const glm::dvec2& uv, double area) const;
    bool cutArcs(const std::vector<Sample>& samples, std::vector<Arc>& arcs);
    std::size_t nextEntry(const std::vector<Arc>& arcs, std::size_t cur, double& distance);
    void closeLoops(std::vector<Arc>& arcs);
    glm::dvec3 pointAt(const glm::dvec2& uv) const {
        return evaluate(surface_, domain_.wrap(uv).x, domain_.wrap(uv).y);
    }

    const Surface& surface_;
    const SurfaceDomain& domain_;
    const SurfaceIntersector& intersector_;
    const PlacementFrame& frame_;
    const Curve& curve_;
    const MapOptions& options_;
    MappedPart& out_;
    Boundary boundary_;
    ProjectedBoxes boxes_;
    KnotLines knotLines_;
    bool budgetSpent_ = false;  ///< refinement stopped at options_.maxProjections
};

Sample PartMapper::project(double s) {
    Sample r;
    r.s = s;
    r.local = evaluate(curve_, s);
    r.from = frame_.toModel(r.local);
    const std::vector<LineSurfaceHit> hits = intersector_.intersect(r.from, frame_.z);
    ++out_.projections;
    if (hits.empty()) return r;
    std::size_t best = 0;
    for (std::size_t i = 1; i < hits.size(); ++i)
        if (std::abs(hits[i].t) < std::abs(hits[best].t)) best = i;
    for (std::size_t i = 0; i < hits.size(); ++i)
        if (i != best) out_.otherHits.push_back({s, hits[i].uv, hits[i].point, hits[i].t});
    r.hit = true;
    r.uv = domain_.wrap(hits[best].uv);
    r.point = hits[best].point;
    r.t = hits[best].t;
    return r;
}

bool PartMapper::needsSplit(const Sample& a, const Sample& m, const Sample& b, double fraction) const {
    const double tol = options_.tolerance;
    if (segmentDistance(m.local, a.local, b.local) > tol) return true;  // the plane curve's own bend
    if (a.hit != b.hit) return glm::length(a.from - b.from) > tol;      // bracket the crossing tightly
    if (!a.hit) {
        // Both ends and the inner samples miss; the lines between may still cut a corner of the
        // surface's outline: split while the chord's strip of lines meets a patch's box.
        const glm::dvec2 p(a.local), q(b.local);
        return m.hit || (glm::length(q - p) > tol && boxes_.mayMeet(p, q, tol));
    }
    if (!m.hit) return true;
    if (segmentDistance(m.point, a.point, b.point) > tol) return true;  // the mapped curve's bend
    // A jump to another sheet (the nearest hit switching surfaces) puts the inner sample near one
    // end instead of near its share of the chord; smooth curves stay far from this bound.
    const glm::dvec3 share = a.point + fraction * (b.point - a.point);
    if (glm::length(m.point - share) > std::max(tol, 0.3 * glm::length(b.point - a.point))) return true;
    // The surface image of the straight (u, w) segment must follow the mapped curve too.
    const glm::dvec2 ub = domain_.unwrapNear(b.uv, a.uv), um = domain_.unwrapNear(m.uv, a.uv);
    const glm::dvec2 d = ub - a.uv;
    const double len2 = glm::dot(d, d);
    const double lambda = len2 > 0.0 ? std::clamp(glm::dot(um - a.uv, d) / len2, 0.0, 1.0) : 0.0;
    return glm::length(pointAt(a.uv + lambda * d) - m.point) > tol;
}

bool PartMapper::jumps(const Sample& a, const Sample& b) const {
    // After refinement a jump between sheets is left as a pair of samples whose mapped points
    // are far apart while their curve points almost coincide.
    const double step = glm::length(b.point - a.point);
    return a.hit && b.hit && step > 10.0 * options_.tolerance && step > 100.0 * glm::length(b.from - a.from);
}

bool PartMapper::foldsBetween(const Sample& a, const Sample& b) const {
    // Across a crease the mapped curve may kink anywhere between two samples, where neither
    // inner sample need see it: such a pair is kept shorter than a quarter of the tolerance.
    return a.hit && b.hit && glm::length(b.point - a.point) > 0.25 * options_.tolerance &&
           knotLines_.crossesCrease(a.uv, domain_.unwrapNear(b.uv, a.uv));
}

bool PartMapper::subChordStrays(const std::array<Sample, 4>& q, int piece) const {
    // The cubic through the four samples (at thirds of the interval) predicts the mapped point and
    // its (u, w) halfway along one of the three sub-chords; the sub-chord and the surface image of
    // its straight (u, w) segment must both stay within the tolerance of the prediction.
    const double x = (piece + 0.5) / 3.0;
    const std::array<double, 4> nodes{0.0, 1.0 / 3.0, 2.0 / 3.0, 1.0};
    glm::dvec3 point(0.0);
    glm::dvec2 uv(0.0);
    for (std::size_t i = 0; i < 4; ++i) {
        double weight = 1.0;
        for (std::size_t j = 0; j < 4; ++j)
            if (j != i) weight *= (x - nodes[j]) / (nodes[i] - nodes[j]);
        point += weight * q[i].point;
        uv += weight * domain_.unwrapNear(q[i].uv, q[0].uv);
    }
    const Sample &a = q[static_cast<std::size_t>(piece)], &b = q[static_cast<std::size_t>(piece) + 1];
    const double tol = options_.tolerance;
    const double bow = segmentDistance(point, a.point, b.point);  // of the mapped curve from the chord
    if (bow > tol) return true;
    const glm::dvec2 ua = domain_.unwrapNear(a.uv, q[0].uv), d = domain_.unwrapNear(b.uv, ua) - ua;
    const double len2 = glm::dot(d, d);
    const double lambda = len2 > 0.0 ? std::clamp(glm::dot(uv - ua, d) / len2, 0.0, 1.0) : 0.0;
    if (glm::length(pointAt(ua + lambda * d) - point) > tol) return true;
    // Across a knot line a steep parametrisation (wide weights) bends the image away from the
    // chord between the predicted points too; surface points cost far less than projections.
    // The image's distance from the mapped curve is at most its distance from the chord plus the
    // curve's bow.
    if (!knotLines_.crossesKnot(ua, ua + d)) return false;
    for (int k = 1; k < 8; ++k)
        if (segmentDistance(pointAt(ua + (k / 8.0) * d), a.point, b.point) + bow > tol) return true;
    return false;
}

void PartMapper::refine(const Sample& a, const Sample& b, int depth, std::vector<Sample>& samples) {
    // Two inner samples at the thirds: one midpoint alone misses an S-bend (an inflection
    // between the ends puts the middle back on the chord).
    if (out_.projections + 2 > options_.maxProjections) {
        budgetSpent_ = true;
        samples.push_back(b);
        return;
    }
    const std::array<Sample, 4> q{a, project(a.s + (b.s - a.s) / 3.0), project(a.s + 2.0 * (b.s - a.s) / 3.0),
                                  b};
    const bool deeper = depth < options_.maxDepth;
    if (deeper && (needsSplit(a, q[1], b, 1.0 / 3.0) || needsSplit(a, q[2], b, 2.0 / 3.0) ||
                   foldsBetween(a, q[1]) || foldsBetween(q[1], q[2]) || foldsBetween(q[2], b))) {
        for (std::size_t i = 0; i < 3; ++i) refine(q[i], q[i + 1], depth + 1, samples);
        return;
    }
    // The sub-chords are what is emitted: one the prediction says strays is refined on its own.
    // Across a crease (within a quarter of the tolerance, by the test above) the cubic cannot
    // predict: there the pieces beside the crossing are refined on their own instead.
    const bool hits = std::all_of(q.begin(), q.end(), [](const Sample& x) { return x.hit; });
    const bool folded = hits && knotLines_.crossesCrease(a.uv, domain_.unwrapNear(b.uv, a.uv));
    for (int piece = 0; piece < 3; ++piece) {
        const auto i = static_cast<std::size_t>(piece);
        const bool strays =
            deeper && hits &&
            (folded ? !knotLines_.crossesCrease(q[i].uv, domain_.unwrapNear(q[i + 1].uv, q[i].uv))
                    : subChordStrays(q, piece));
        if (strays)
            refine(q[i], q[i + 1], depth + 1, samples);
        else
            samples.push_back(q[i + 1]);
    }
}

bool PartMapper::crossing(const Sample& inside, const Sample& outside, Vertex& vertex,
                          BoundaryPosition& where) {
    // Newton on (s, tau, t): S(edge(tau)) = P(s) + t * z for each open edge; the exact place where
    // the projection of the curve meets the boundary, not a snap to a boundary knot.
    const double sLo = std::min(inside.s, outside.s), sHi = std::max(inside.s, outside.s);
    const double sSlack = 1e-9 * (sHi - sLo + 1e-300);
    bool found = false;
    double bestScore = 1e300;
    for (const Edge& e : boundary_.edges) {
        double s = inside.s, t = inside.t;
        double tau = e.constantU ? inside.uv.y : inside.uv.x;
        bool converged = false;
        for (int iter = 0; iter < 50 && !converged; ++iter) {
            const glm::dvec2 uv = e.constantU ? glm::dvec2(e.value, tau) : glm::dvec2(tau, e.value);
            const glm::dvec2 wrapped = domain_.wrap(uv);
            const SurfaceDerivatives sd = derivatives(surface_, wrapped.x, wrapped.y, 1);
            const std::vector<glm::dvec3> cd = derivatives(curve_, s, 1);
            const glm::dvec3 p = frame_.toModel(cd[0]);
            const glm::dvec3 dp = cd[1].x * frame_.x + cd[1].y * frame_.y + cd[1].z * frame_.z;
            const glm::dvec3 f = sd.at(0, 0) - p - t * frame_.z;
            const glm::dvec3 stau = e.constantU ? sd.at(0, 1) : sd.at(1, 0);
            const glm::dmat3 jac(-dp, stau, -frame_.z);
            if (std::abs(glm::determinant(jac)) < 1e-300) break;
            const glm::dvec3 step = glm::inverse(jac) * (-f);
            s = std::clamp(s + step.x, std::max(sLo - 0.5 * (sHi - sLo), curve_.domainStart()),
                           std::min(sHi + 0.5 * (sHi - sLo), curve_.domainEnd()));
            tau += step.y;
            const bool closedTau = e.constantU ? domain_.closedW : domain_.closedU;
            if (!closedTau) tau = std::clamp(tau, e.tau0, e.tau1);
            t += step.z;
            // f cannot fall below what rounding the parameters leaves: a domain far from 0 (u near
            // 1e4) moves S by |dS/dtau| eps |tau| per rounding.
            const double rounding = 8.0 * std::numeric_limits<double>::epsilon() *
                                    (std::abs(tau) * glm::length(stau) + std::abs(s) * glm::length(dp));
            converged = glm::length(f) < 1e-13 * (1.0 + glm::length(p)) + rounding &&
                        std::abs(step.x) <= 1e-14 * (1.0 + std::abs(s)) + sSlack;
        }
        if (!converged || s < sLo - sSlack || s > sHi + sSlack) continue;
        const double score = std::abs(t - inside.t);
        if (score >= bestScore) continue;
        bestScore = score;
        found = true;
        s = std::clamp(s, sLo, sHi);
        const glm::dvec2 uv = e.constantU ? glm::dvec2(e.value, tau) : glm::dvec2(tau, e.value);
        vertex.uv = domain_.wrap(uv);
        vertex.s = s;
        vertex.from = frame_.toModel(evaluate(curve_, s));
        where = boundary_.position(e, e.constantU ? vertex.uv.y : vertex.uv.x);
    }
    return found;
}

void PartMapper::densifyWalk(int component, double a, double b, int depth, std::vector<Vertex>& out) const {
    const double m = 0.5 * (a + b);
    const glm::dvec3 pa = pointAt(boundary_.uvAt(component, a)), pb = pointAt(boundary_.uvAt(component, b));
    const glm::dvec3 pm = pointAt(boundary_.uvAt(component, m));
    if (depth < options_.maxDepth &&
        (depth < 2 || segmentDistance(pm, pa, pb) > options_.tolerance ||
         b - a > 0.25 * boundary_.lengths[static_cast<std::size_t>(component)])) {
        densifyWalk(component, a, m, depth + 1, out);
        densifyWalk(component, m, b, depth + 1, out);
        return;
    }
    out.push_back({boundary_.uvAt(component, m)});
    out.push_back({boundary_.uvAt(component, b)});
}

std::vector<Vertex> PartMapper::boundaryWalk(int component, double from, double length) const {
    // Vertices strictly after `from` up to and excluding from + length, through every corner.
    std::vector<double> stops;
    const double l = boundary_.lengths[static_cast<std::size_t>(component)];
    for (double c : boundary_.corners[static_cast<std::size_t>(component)])
        for (double k = -1; k <= 1; ++k) {
            const double at = c + k * l;
            if (at > from + 1e-14 * l && at < from + length - 1e-14 * l) stops.push_back(at);
        }
    std::sort(stops.begin(), stops.end());
    stops.push_back(from + length);
    std::vector<Vertex> out;
    double prev = from;
    for (double stop : stops) {
        densifyWalk(component, prev, stop, 0, out);
        prev = stop;
    }
    out.pop_back();  // the end itself is the next arc's entry
    return out;
}

void PartMapper::emitLoop(std::vector<Vertex> vertices, std::size_t walks) {
    MappedLoop loop;
    loop.boundaryWalks = walks;
    for (std::size_t i = 0; i < vertices.size(); ++i) {
        if (i > 0) vertices[i].uv = domain_.unwrapNear(vertices[i].uv, vertices[i - 1].uv);
        if (i > 0 && vertices[i].uv == vertices[i - 1].uv) continue;
        loop.uv.push_back(vertices[i].uv);
        loop.points.push_back(pointAt(vertices[i].uv));
        loop.curveParameters.push_back(vertices[i].s);
        loop.projectedFrom.push_back(vertices[i].from);
    }
    // Whole periods off: shift so the middle of the loop's range lies in the domain.
    glm::dvec2 lo(1e300), hi(-1e300);
    for (const glm::dvec2& uv : loop.uv) {
        lo = glm::min(lo, uv);
        hi = glm::max(hi, uv);
    }
    const glm::dvec2 middle = 0.5 * (lo + hi), shift = domain_.wrap(middle) - middle;
    for (glm::dvec2& uv : loop.uv) uv += shift;
    const glm::dvec2 closing = domain_.unwrapNear(loop.uv.front(), loop.uv.back());
    if (glm::length(closing - loop.uv.front()) > 1e-9)
        out_.issues.push_back(
            "a loop winds around a closed direction of the surface; its (u, w) end one period "
            "from where they start");
    if (loop.uv.size() > 1 && loop.uv.back() == loop.uv.front()) {
        loop.uv.pop_back();
        loop.points.pop_back();
        loop.curveParameters.pop_back();
        loop.projectedFrom.pop_back();
    }
    loop.uv.push_back(loop.uv.front());
    loop.points.push_back(loop.points.front());
    loop.curveParameters.push_back(loop.curveParameters.front());
    loop.projectedFrom.push_back(loop.projectedFrom.front());
    out_.loops.push_back(std::move(loop));
}

std::vector<Sample> PartMapper::sampleCurve() {
    const double s1 = curve_.domainEnd();
    const double size = largestNorm(curve_.points);
    // Initial samples at every distinct knot (C0 corners included) and inside each span.
    const auto degree = static_cast<std::size_t>(curve_.degree);
    std::vector<double> params;
    for (std::size_t i = degree; i < curve_.points.size(); ++i) {
        const double a = curve_.knots[i], b = curve_.knots[i + 1];
        if (!(b > a)) continue;
        // A straight span (its inner control points on the chord) needs fewer starting samples.
        const glm::dvec3 first = curve_.points[i - degree], last = curve_.points[i];
        double bend = 0.0;
        for (std::size_t k = i - degree + 1; k < i; ++k)
            bend = std::max(bend, segmentDistance(curve_.points[k], first, last));
        const int pieces = bend <= 1e-12 * (1.0 + size) ? 2 : 4;
        for (int k = 0; k < pieces; ++k) params.push_back(a + (b - a) * k / pieces);
    }
    params.push_back(s1);
    std::vector<Sample> samples{project(params.front())};
    for (std::size_t i = 1; i < params.size(); ++i) {
        const Sample a = samples.back();
        refine(a, project(params[i]), 0, samples);
    }
    if (budgetSpent_)
        out_.issues.push_back("refinement stopped at the budget of " +
                              std::to_string(options_.maxProjections) +
                              " projection lines; the mapped curve may be farther than the tolerance from "
                              "the true one");
    // The closing sample repeats the first line.
    samples.back() = samples.front();
    samples.back().s = s1;
    return samples;
}

void PartMapper::mapWithoutHits(const std::vector<Sample>& samples) {
    // No line meets the surface: the part misses it, or surrounds all of it.
    std::vector<glm::dvec2> poly;
    for (const Sample& x : samples) poly.push_back({x.local.x, x.local.y});
    const glm::dvec3 centre =
        frame_.toCurve(pointAt({0.5 * (domain_.u0 + domain_.u1), 0.5 * (domain_.w0 + domain_.w1)}));
    if (!oddCrossings({centre.x, centre.y}, poly, [](glm::dvec2 q) { return q; })) {
        out_.issues.push_back("the curve part misses the surface");
    } else if (boundary_.lengths.size() != 1) {
        out_.issues.push_back(
            "the curve part surrounds a closed surface: the region would be bounded by "
            "silhouettes, not by the surface boundary; not mapped");
    } else {
        std::vector<Vertex> walk{{boundary_.uvAt(0, 0.0)}};
        for (const Vertex& v : boundaryWalk(0, 0.0, boundary_.lengths[0])) walk.push_back(v);
        emitLoop(std::move(walk), 1);
    }
}

bool PartMapper::regionLeftAt(const glm::dvec2& uv, double area) const {
    // Which side of a loop the region lies on depends on the sheet: the surface Jacobian's sign
    // against z (a sheet seen from behind, e.g. inside an open end, reverses it).
    const glm::dvec2 w = domain_.wrap(uv);
    const SurfaceDerivatives jd = derivatives(surface_, w.x, w.y, 1);
    return (area > 0.0) == (glm::dot(glm::cross(jd.at(1, 0), jd.at(0, 1)), frame_.z) > 0.0);
}

bool PartMapper::cutArcs(const std::vector<Sample>& samples, std::vector<Arc>& arcs) {
    const std::size_t n = samples.size() - 1;  // distinct samples; samples[n] repeats samples[0]
    // Cut the cycle into arcs from an entry to an exit, starting just after some exit.
    std::size_t start = 0;
    const auto leaves = [&](std::size_t i) {
        return samples[i].hit && (!samples[i + 1].hit || jumps(samples[i], samples[i + 1]));
    };
    while (!leaves(start)) ++start;
    Arc current;
    bool inArc = false;
    const auto silhouette = [&](const Sample& a) {
        out_.issues.push_back(
            "the nearest hit leaves a sheet of the surface away from its boundary (at a silhouette, or "
            "where another sheet comes in front, near curve parameter " +
            detail::numberText(a.s) + "); the part cannot be closed and is not mapped");
        return false;
    };
    // The pair (start, start + 1) is visited twice: first for an entry into the next sheet
    // (when it is a jump), last for the exit that closes the final arc.
    for (std::size_t k = 0; k <= n; ++k) {
        const std::size_t i = (start + k) % n;
        const Sample& a = samples[i];
        const Sample& b = samples[i + 1];
        if (a.hit && k > 0) current.vertices.push_back({a.uv, a.s, a.from});
        const bool jump = jumps(a, b);
        if (k > 0 && a.hit && (!b.hit || jump)) {  // leaves a's sheet between a and b
            Vertex v;
            BoundaryPosition where;
            if (!crossing(a, b, v, where)) return silhouette(a);
            if (!inArc) {
                out_.issues.push_back("internal: an exit without an entry");
                return false;
            }
            ++out_.exits;
            current.vertices.push_back(v);
            current.exit = where;
            arcs.push_back(std::move(current));
            current = Arc{};
            inArc = false;
        }
        if (k < n && b.hit && (!a.hit || jump)) {  // enters b's sheet between a and b
            Vertex v;
            BoundaryPosition where;
            if (!crossing(b, a, v, where)) return silhouette(b);
            ++out_.entries;
            current = Arc{};
            current.vertices.push_back(v);
            current.entry = where;
            inArc = true;
        }
    }
    return true;
}

std::size_t PartMapper::nextEntry(const std::vector<Arc>& arcs, std::size_t cur, double& distance) {
    const Arc& arc = arcs[cur];
    const int c = arc.exit.component;
    std::size_t next = arcs.size();
    double nearestExit = 1e300;
    distance = 1e300;
    for (std::size_t j = 0; j < arcs.size(); ++j) {
        if (arcs[j].entry.component == c) {
            const double d = boundary_.wrapSigma(c, arcs[j].entry.sigma - arc.exit.sigma);
            if (d < distance) {
                distance = d;
                next = j;
            }
        }
        if (j != cur && arcs[j].exit.component == c)
            nearestExit = std::min(nearestExit, boundary_.wrapSigma(c, arcs[j].exit.sigma - arc.exit.sigma));
    }
    if (next == arcs.size())
        out_.issues.push_back("an exit has no entry on the same boundary component; the part is not closed");
    else if (nearestExit < distance)
        out_.issues.push_back(
            "exits and entries do not alternate along the boundary (the nearest-hit rule "
            "switched sheets); the loops may overlap");
    return next;
}

void PartMapper::closeLoops(std::vector<Arc>& arcs) {
    // From each exit walk counter-clockwise along its boundary component to the nearest entry,
    // follow that arc, and so on; every number of exits and entries is handled alike.
    for (std::size_t first = 0; first < arcs.size(); ++first) {
        if (arcs[first].used) continue;
        std::vector<Vertex> loop;
        std::size_t walks = 0;
        std::size_t cur = first;
        for (std::size_t guard = 0; guard <= arcs.size(); ++guard) {
            Arc& arc = arcs[cur];
            arc.used = true;
            loop.insert(loop.end(), arc.vertices.begin(), arc.vertices.end());
            double distance = 0.0;
            const std::size_t next = nextEntry(arcs, cur, distance);
            if (next == arcs.size()) return;
            if (distance > 0.0) {
                ++walks;
                for (const Vertex& v : boundaryWalk(arc.exit.component, arc.exit.sigma, distance))
                    loop.push_back(v);
            }
            cur = next;
            if (cur == first) break;
            if (arcs[cur].used) {
                out_.issues.push_back("internal: boundary walk reached a used arc");
                return;
            }
        }
        emitLoop(std::move(loop), walks);
    }
}

void PartMapper::run() {
    // Rounding in the curve's evaluation grows with its coordinates' size.
    const double size = largestNorm(curve_.points);
    if (glm::length(evaluate(curve_, curve_.domainStart()) - evaluate(curve_, curve_.domainEnd())) >
        1e-9 * (1.0 + size)) {
        out_.issues.push_back("the curve part is not closed, so it cannot bound a region; not mapped");
        return;
    }
    const std::vector<Sample> samples = sampleCurve();
    // Orientation: the region inside the plane curve must lie left of the loops in (u, w).
    double area = 0.0;
    for (std::size_t i = 0; i + 1 < samples.size(); ++i)
        area += samples[i].local.x * samples[i + 1].local.y - samples[i + 1].local.x * samples[i].local.y;
    const auto firstHit = std::find_if(samples.begin(), samples.end(), [](const Sample& x) { return x.hit; });
    if (firstHit == samples.end()) return mapWithoutHits(samples);

    const std::size_t n = samples.size() - 1;
    bool anyJump = false;
    for (std::size_t i = 0; i < n; ++i) anyJump = anyJump || jumps(samples[i], samples[i + 1]);
    if (!anyJump && std::all_of(samples.begin(), samples.end(), [](const Sample& x) { return x.hit; })) {
        std::vector<Vertex> loop;
        for (std::size_t i = 0; i < n; ++i) loop.push_back({samples[i].uv, samples[i].s, samples[i].from});
        if (!regionLeftAt(firstHit->uv, area)) std::reverse(loop.begin(), loop.end());
        return emitLoop(std::move(loop), 0);
    }
    std::vector<Arc> arcs;
    if (!cutArcs(samples, arcs)) return;
    for (Arc& arc : arcs)
        if (!regionLeftAt(arc.vertices[arc.vertices.size() / 2].uv, area)) {
            std::reverse(arc.vertices.begin(), arc.vertices.end());
            std::swap(arc.entry, arc.exit);
        }
    closeLoops(arcs);
}

}  // namespace

CurveMapper::CurveMapper(Surface surface, std::optional<bool> closedU, std::optional<bool> closedW)
    : surface_(std::move(surface)),
      domain_(surfaceDomain(surface_, closedU, closedW)),
      intersector_(surface_) {
}

MapResult CurveMapper::map(const std::vector<Curve>& curves, const Placement& placement,
                           const MapOptions& options) const {
    if (!(options.tolerance > 0.0) || !std::isfinite(options.tolerance))
        throw GeometryError("CurveMapper::map: the tolerance must be a positive number");
    if (options.maxProjections < 16 || !(options.maxExtentRatio > 0.0))
        throw GeometryError(
            "CurveMapper::map: maxProjections must be at least 16 and maxExtentRatio positive");
    const double surfaceExtent = boxDiagonal(surface_.points);
    for (std::size_t i = 0; i < curves.size(); ++i) {
        validate(curves[i], "CurveMapper::map");
        const double extent = boxDiagonal(curves[i].points);
        if (!(extent <= options.maxExtentRatio * surfaceExtent))
            throw GeometryError("CurveMapper::map: curve part " + std::to_string(i + 1) + " is " +
                                detail::numberText(extent) + " across, more than " +
                                detail::numberText(options.maxExtentRatio) + " times the surface's " +
                                detail::numberText(surfaceExtent) + "; not mapped");
    }
    MapResult result;
    result.frame = placementFrame(surface_, placement);
    result.parts.resize(curves.size());
    for (std::size_t i = 0; i < curves.size(); ++i) {
        PartMapper(surface_, domain_, intersector_, result.frame, curves[i], options, result.parts[i]).run();
    }
    return result;
}

}  // namespace geom::curvemap
