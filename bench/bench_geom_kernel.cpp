// Benchmark of the geom kernel against SISL and OpenCASCADE in the same run: grid evaluation
// (point, first derivatives, unit normal), line/surface intersection and point inversion on a
// 40 x 40 non-uniform bicubic surface, polynomial and rational (with OpenCASCADE too), and on
// the classes that break kernels tuned to it: degree 1, 2 x 5 with double knots, weights over four
// decades, a closed periodic tube. Prints figures, then one JSON
// object.

#include "geom/Evaluate.h"
#include "geom/GlobalInterpolation.h"
#include "geom/GridEvaluator.h"
#include "geom/KnotInsertion.h"
#include "geom/Surface.h"
#include "geom/SurfaceIntersector.h"
#include "geom/SurfaceProjector.h"

#include <sisl.h>
#include <glm/geometric.hpp>

#include <GeomAPI_ProjectPointOnSurf.hxx>
#include <GeomAdaptor_Curve.hxx>
#include <GeomAdaptor_Surface.hxx>
#include <Geom_BSplineSurface.hxx>
#include <Geom_Line.hxx>
#include <IntCurveSurface_HInter.hxx>
#include <IntCurveSurface_IntersectionPoint.hxx>
#include <TColStd_Array1OfInteger.hxx>
#include <TColStd_Array1OfReal.hxx>
#include <TColStd_Array2OfReal.hxx>
#include <TColgp_Array2OfPnt.hxx>
#include <gp_Lin.hxx>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <ctime>
#include <random>
#include <string>
#include <vector>

namespace {

using Clock = std::chrono::steady_clock;

double seconds(Clock::time_point a, Clock::time_point b) {
    return std::chrono::duration<double>(b - a).count();
}

std::vector<double> nonUniformKnots(std::mt19937& rng, int degree, std::size_t count) {
    std::uniform_real_distribution<double> step(0.5, 1.5);
    std::vector<double> k(static_cast<std::size_t>(degree + 1), 0.0);
    const std::size_t interior = count - static_cast<std::size_t>(degree) - 1;
    double x = 0.0;
    std::vector<double> inner;
    for (std::size_t i = 0; i < interior; ++i) inner.push_back(x += step(rng));
    const double end = x + step(rng);
    for (double& v : inner) k.push_back(v / end);
    k.insert(k.end(), static_cast<std::size_t>(degree + 1), 1.0);
    return k;
}

geom::Surface benchSurface(bool rational) {
    std::mt19937 rng(2024);
    std::uniform_real_distribution<double> height(-0.01, 0.01), jitter(-0.004, 0.004), weight(0.5, 2.0);
    const std::size_t n = 40;
    std::vector<glm::dvec3> points;
    std::vector<double> weights;
    for (std::size_t i = 0; i < n; ++i)
        for (std::size_t j = 0; j < n; ++j) {
            const double x = static_cast<double>(i) / (n - 1), y = static_cast<double>(j) / (n - 1);
            points.emplace_back(x + jitter(rng), y + jitter(rng),
                                0.1 * std::sin(6 * x) * std::cos(5 * y) + height(rng));
            if (rational) weights.push_back(weight(rng));
        }
    return geom::Surface(3, 3, nonUniformKnots(rng, 3, n), nonUniformKnots(rng, 3, n), n, n, points, weights);
}

/// Degree 1 x 1 over the same heights: every interior knot line is a crease.
geom::Surface degreeOneSurface() {
    const geom::Surface base = benchSurface(false);
    std::mt19937 rng(7);
    return geom::Surface(1, 1, nonUniformKnots(rng, 1, base.countU), nonUniformKnots(rng, 1, base.countV),
                         base.countU, base.countV, base.points);
}

/// Clamped knots for `count` points of `degree` with every other interior knot doubled.
std::vector<double> doubledKnots(std::mt19937& rng, int degree, std::size_t count) {
    const std::size_t interior = count - static_cast<std::size_t>(degree) - 1;
    std::uniform_real_distribution<double> unit(0.02, 0.98);
    std::vector<double> distinct;
    for (std::size_t i = 0; i < interior; ++i) distinct.push_back(unit(rng));
    std::sort(distinct.begin(), distinct.end());
    std::vector<double> k(static_cast<std::size_t>(degree + 1), 0.0);
    for (std::size_t i = 0; k.size() < interior + static_cast<std::size_t>(degree) + 1; ++i) {
        k.push_back(distinct[i]);
        if (i % 2 == 0 && k.size() < interior + static_cast<std::size_t>(degree) + 1)
            k.push_back(distinct[i]);
    }
    k.insert(k.end(), static_cast<std::size_t>(degree + 1), 1.0);
    return k;
}

/// Degree 2 x 5 over the same heights with doubled knots: C0 creases along u, C3 lines along v.
geom::Surface creasedSurface() {
    const geom::Surface base = benchSurface(false);
    std::mt19937 rng(8);
    return geom::Surface(2, 5, doubledKnots(rng, 2, base.countU), doubledKnots(rng, 5, base.countV),
                         base.countU, base.countV, base.points);
}

/// The bicubic surface with weights spread log-uniformly over 1e-2 .. 1e2.
geom::Surface wideWeightSurface() {
    geom::Surface s = benchSurface(true);
    std::mt19937 rng(9);
    std::uniform_real_distribution<double> decade(-2.0, 2.0);
    for (double& w : s.weights) w = std::pow(10.0, decade(rng));
    geom::validate(s);
    return s;
}

/// A bumpy closed tube, periodic around (the seam on the domain edge), bicubic, interpolated.
geom::Surface tubeSurface() {
    std::mt19937 rng(10);
    std::uniform_real_distribution<double> bump(-0.03, 0.03);
    const std::size_t around = 32, along = 24;
    std::vector<glm::dvec3> grid;
    for (std::size_t i = 0; i < around; ++i)
        for (std::size_t j = 0; j < along; ++j) {
            const double a = 6.283185307179586 * static_cast<double>(i) / around;
            const double r = 0.3 + bump(rng);
            grid.emplace_back(0.5 + r * std::cos(a), 0.5 + r * std::sin(a),
                              static_cast<double>(j) / (along - 1));
        }
    return geom::interpolateSurface(grid, around, along, 3, 3, geom::Closure::Periodic, geom::Closure::Open);
}

/// The same surface with clamped knots in u (end knots of multiplicity degree + 1): SISL's
/// surfaces are clamped, and s1856 runs on for minutes on the periodic tube's unclamped knots.
geom::Surface clampedInU(geom::Surface s) {
    const int p = s.degreeU;
    const double u0 = s.domainStartU(), u1 = s.domainEndU();
    for (double end : {u0, u1}) {
        const int m = static_cast<int>(std::count(s.knotsU.begin(), s.knotsU.end(), end));
        if (m < p) s = geom::insertKnotU(s, end, p - m);
    }
    // The surface passes through row `first` at u0, where first = (last index of u0) - p.
    const std::size_t first =
        static_cast<std::size_t>(std::upper_bound(s.knotsU.begin(), s.knotsU.end(), u0) - s.knotsU.begin()) -
        1 - static_cast<std::size_t>(p);
    std::vector<double> knots(static_cast<std::size_t>(p) + 1, u0);
    for (double k : s.knotsU)
        if (k > u0 && k < u1) knots.push_back(k);
    knots.insert(knots.end(), static_cast<std::size_t>(p) + 1, u1);
    const std::size_t rows = knots.size() - static_cast<std::size_t>(p) - 1;
    std::vector<glm::dvec3> points;
    std::vector<double> weights;
    for (std::size_t i = first; i < first + rows; ++i)
        for (std::size_t j = 0; j < s.countV; ++j) {
            points.push_back(s.point(i, j));
            if (s.rational()) weights.push_back(s.weight(i, j));
        }
    return geom::Surface(p, s.degreeV, knots, s.knotsV, rows, s.countV, points, weights);
}

/// The same surface for SISL: first parameter direction = u, vertices with u running fastest.
SISLSurf* toSisl(const geom::Surface& s) {
    const int dim = s.rational() ? 4 : 3;
    std::vector<double> coef;
    for (std::size_t j = 0; j < s.countV; ++j)
        for (std::size_t i = 0; i < s.countU; ++i) {
            const glm::dvec3& p = s.point(i, j);
            const double w = s.weight(i, j);
            if (s.rational())
                coef.insert(coef.end(), {p.x * w, p.y * w, p.z * w, w});
            else
                coef.insert(coef.end(), {p.x, p.y, p.z});
        }
    std::vector<double> ku = s.knotsU, kv = s.knotsV;
    (void)dim;
    return newSurf(static_cast<int>(s.countU), static_cast<int>(s.countV), s.degreeU + 1, s.degreeV + 1,
                   ku.data(), kv.data(), coef.data(), s.rational() ? 2 : 1, 3, 1);
}

/// OpenCASCADE keeps a knot vector as distinct values with multiplicities.
void toOcctKnots(const std::vector<double>& knots, Handle(TColStd_HArray1OfReal) & values,
                 Handle(TColStd_HArray1OfInteger) & multiplicities) {
    std::vector<double> distinct;
    std::vector<int> counts;
    for (double k : knots) {
        if (!distinct.empty() && k == distinct.back())
            ++counts.back();
        else {
            distinct.push_back(k);
            counts.push_back(1);
        }
    }
    const int n = static_cast<int>(distinct.size());
    values = new TColStd_HArray1OfReal(1, n);
    multiplicities = new TColStd_HArray1OfInteger(1, n);
    for (int i = 0; i < n; ++i) {
        values->SetValue(i + 1, distinct[static_cast<std::size_t>(i)]);
        multiplicities->SetValue(i + 1, counts[static_cast<std::size_t>(i)]);
    }
}

/// The same surface for OpenCASCADE: pole (i, j) is control point (i, j), u the first index.
Handle(Geom_BSplineSurface) toOcct(const geom::Surface& s) {
    const int nu = static_cast<int>(s.countU), nv = static_cast<int>(s.countV);
    TColgp_Array2OfPnt poles(1, nu, 1, nv);
    TColStd_Array2OfReal weights(1, nu, 1, nv);
    for (int i = 0; i < nu; ++i)
        for (int j = 0; j < nv; ++j) {
            const glm::dvec3& p = s.point(static_cast<std::size_t>(i), static_cast<std::size_t>(j));
            poles.SetValue(i + 1, j + 1, gp_Pnt(p.x, p.y, p.z));
            weights.SetValue(i + 1, j + 1,
                             s.weight(static_cast<std::size_t>(i), static_cast<std::size_t>(j)));
        }
    Handle(TColStd_HArray1OfReal) ku, kv;
    Handle(TColStd_HArray1OfInteger) mu, mv;
    toOcctKnots(s.knotsU, ku, mu);
    toOcctKnots(s.knotsV, kv, mv);
    if (s.rational())
        return new Geom_BSplineSurface(poles, weights, ku->Array1(), kv->Array1(), mu->Array1(), mv->Array1(),
                                       s.degreeU, s.degreeV);
    return new Geom_BSplineSurface(poles, ku->Array1(), kv->Array1(), mu->Array1(), mv->Array1(), s.degreeU,
                                   s.degreeV);
}

glm::dvec3 toGlm(const gp_XYZ& p) {
    return {p.X(), p.Y(), p.Z()};
}

// Queries per surface for intersection and closest point; OpenCASCADE, slower by 100x or more,
// gets every occtStride-th one.
constexpr int queries = 10000;
constexpr std::size_t occtStride = 10;
constexpr int occtQueries = queries / static_cast<int>(occtStride);

struct Figures {
    double fastNs = 0, plainNs = 0, sislPointNs = 0, sislGridNs = 0;
    double intersectUs = 0, sislIntersectUs = 0, worstHitError = 0;
    int missed = 0, sislMissed = 0, countMismatch = 0;
    double closestUs = 0, sislClosestUs = 0, worstClosestError = 0, worstSislClosestError = 0;
    int closestFartherThanFoot = 0, sislFartherThanFoot = 0;
    // OpenCASCADE: GeomAdaptor_Surface::D1 (span cache) and Geom_BSplineSurface::D1 per point,
    // IntCurveSurface_HInter, GeomAPI_ProjectPointOnSurf.
    double occtAdaptorNs = 0, occtBsplineNs = 0, occtWorstNormalDiff = 0;
    double occtIntersectUs = 0, occtWorstHitDistance = 0;
    int occtMissed = 0, occtCountMismatch = 0;
    double occtClosestUs = 0, worstOcctClosestError = 0;
    int occtFartherThanFoot = 0, occtNoAnswer = 0;
    double occtTreeClosestUs = 0, worstOcctTreeClosestError = 0;
    int occtTreeFartherThanFoot = 0, occtTreeNoAnswer = 0;
};

Figures run(const geom::Surface& s, const char* name, bool withOcct) {
    Figures f;
    SISLSurf* ss = toSisl(clampedInU(s));
    const Handle(Geom_BSplineSurface) occt = toOcct(s);
    const int grid = 512;
    std::vector<double> us(grid), vs(grid);
    for (int i = 0; i < grid; ++i) us[i] = vs[i] = (i + 0.5) / grid;
    double checksum = 0.0;

    // Fast path.
    const geom::GridEvaluator evaluator(s);
    std::vector<geom::GridSample> samples(us.size() * vs.size());
    // The machine may be shared: each grid figure is the best of several passes.
    const int repeats = 7;
    f.fastNs = 1e300;
    for (int r = 0; r < repeats; ++r) {
        const auto a = Clock::now();
        evaluator.evaluate(us, vs, samples);
        f.fastNs = std::min(f.fastNs, seconds(a, Clock::now()) * 1e9 / (grid * grid));
    }
    for (const auto& g : samples) checksum += g.normal.z;

    // Plain de Boor path.
    auto t0 = Clock::now();
    double worstDiff = 0.0;
    for (int i = 0; i < grid; ++i)
        for (int j = 0; j < grid; ++j) {
            const geom::SurfaceDerivatives d = geom::derivatives(s, us[i], vs[j], 1);
            const glm::dvec3 n = geom::normalFromDerivatives(s, us[i], vs[j], d.at(1, 0), d.at(0, 1));
            worstDiff =
                std::max(worstDiff, glm::length(n - samples[static_cast<std::size_t>(i * grid + j)].normal));
            checksum += n.z;
        }
    auto t1 = Clock::now();
    f.plainNs = seconds(t0, t1) * 1e9 / (grid * grid);

    // SISL per point (s1421) and grid (s1506).
    t0 = Clock::now();
    int left1 = 0, left2 = 0, stat = 0;
    double der[9], nrm[3];
    for (int i = 0; i < grid; ++i)
        for (int j = 0; j < grid; ++j) {
            double par[2] = {us[i], vs[j]};
            s1421(ss, 1, par, &left1, &left2, der, nrm, &stat);
            const double len = std::sqrt(nrm[0] * nrm[0] + nrm[1] * nrm[1] + nrm[2] * nrm[2]);
            checksum += nrm[2] / len;
        }
    t1 = Clock::now();
    f.sislPointNs = seconds(t0, t1) * 1e9 / (grid * grid);
    std::vector<double> gder(static_cast<std::size_t>(3 * 3 * grid * grid)),
        gnorm(static_cast<std::size_t>(3 * grid * grid));
    f.sislGridNs = 1e300;
    for (int r = 0; r < repeats; ++r) {
        const auto a = Clock::now();
        s1506(ss, 1, grid, us.data(), grid, vs.data(), gder.data(), gnorm.data(), &stat);
        for (std::size_t k = 0; k < gnorm.size(); k += 3) {
            const double len =
                std::sqrt(gnorm[k] * gnorm[k] + gnorm[k + 1] * gnorm[k + 1] + gnorm[k + 2] * gnorm[k + 2]);
            checksum += gnorm[k + 2] / len;
        }
        f.sislGridNs = std::min(f.sislGridNs, seconds(a, Clock::now()) * 1e9 / (grid * grid));
    }

    // OpenCASCADE: the adaptor caches the polynomial form of the current span (best of several
    // passes, like the grid evaluators); the bare surface evaluates from the poles each call.
    if (withOcct) {
        const GeomAdaptor_Surface adaptor(occt);
        gp_Pnt p;
        gp_Vec du, dv;
        f.occtAdaptorNs = 1e300;
        for (int r = 0; r < repeats; ++r) {
            const auto a = Clock::now();
            for (int i = 0; i < grid; ++i)
                for (int j = 0; j < grid; ++j) {
                    adaptor.D1(us[i], vs[j], p, du, dv);
                    const gp_Vec n = du.Crossed(dv).Normalized();
                    checksum += n.Z();
                    if (r == 0)
                        f.occtWorstNormalDiff =
                            std::max(f.occtWorstNormalDiff,
                                     glm::length(toGlm(n.XYZ()) -
                                                 samples[static_cast<std::size_t>(i * grid + j)].normal) +
                                         glm::length(toGlm(p.XYZ()) -
                                                     samples[static_cast<std::size_t>(i * grid + j)].point));
                }
            f.occtAdaptorNs = std::min(f.occtAdaptorNs, seconds(a, Clock::now()) * 1e9 / (grid * grid));
        }
        t0 = Clock::now();
        for (int i = 0; i < grid; ++i)
            for (int j = 0; j < grid; ++j) {
                occt->D1(us[i], vs[j], p, du, dv);
                checksum += du.Crossed(dv).Normalized().Z();
            }
        f.occtBsplineNs = seconds(t0, Clock::now()) * 1e9 / (grid * grid);
    }

    // Line/surface intersection: random lines through known points, within 45 degrees of the normal.
    std::mt19937 rng(99);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    struct Line {
        glm::dvec3 o, d, p;
    };
    std::vector<Line> lines;
    for (int k = 0; k < queries; ++k) {
        const double u = unit(rng), v = unit(rng);
        const glm::dvec3 p = geom::evaluate(s, u, v), n = geom::normal(s, u, v);
        const glm::dvec3 a =
            glm::normalize(glm::cross(n, std::abs(n.x) < 0.6 ? glm::dvec3(1, 0, 0) : glm::dvec3(0, 1, 0)));
        const glm::dvec3 b = glm::cross(n, a);
        const double angle = unit(rng) * 0.785398, phi = unit(rng) * 6.283185;
        const glm::dvec3 d = std::cos(angle) * n + std::sin(angle) * (std::cos(phi) * a + std::sin(phi) * b);
        lines.push_back({p - (0.2 + 0.5 * unit(rng)) * d, d, p});
    }
    const geom::SurfaceIntersector intersector(s);
    std::vector<std::size_t> ourCounts;
    std::vector<std::vector<glm::dvec3>> occtHits(lines.size());
    t0 = Clock::now();
    for (const Line& l : lines) {
        const auto hits = intersector.intersect(l.o, l.d);
        ourCounts.push_back(hits.size());
        bool found = false;
        for (const auto& h : hits) {
            found = found || glm::length(h.point - l.p) < 1e-9;
            checksum += h.t;
        }
        if (!found) ++f.missed;
    }
    t1 = Clock::now();
    f.intersectUs = seconds(t0, t1) * 1e6 / queries;
    for (std::size_t k = 0; k < lines.size(); k += 10) {
        for (const auto& h : intersector.intersect(lines[k].o, lines[k].d))
            f.worstHitError =
                std::max(f.worstHitError, glm::length(geom::evaluate(s, h.uv.x, h.uv.y) - h.point));
    }
    t0 = Clock::now();
    for (std::size_t k = 0; k < lines.size(); ++k) {
        double point[3] = {lines[k].o.x, lines[k].o.y, lines[k].o.z};
        double dir[3] = {lines[k].d.x, lines[k].d.y, lines[k].d.z};
        int npt = 0, ncrv = 0;
        double* par = nullptr;
        SISLIntcurve** curves = nullptr;
        s1856(ss, point, dir, 3, 1e-9, 1e-9, &npt, &par, &ncrv, &curves, &stat);
        bool found = false;
        for (int h = 0; h < npt; ++h) {
            const glm::dvec3 x = geom::evaluate(s, par[2 * h], par[2 * h + 1]);
            found = found || glm::length(x - lines[k].p) < 1e-7;
        }
        if (!found) ++f.sislMissed;
        if (static_cast<std::size_t>(npt) != ourCounts[k]) ++f.countMismatch;
        if (par) free(par);
        if (curves) freeIntcrvlist(curves, ncrv);
    }
    t1 = Clock::now();
    f.sislIntersectUs = seconds(t0, t1) * 1e6 / queries;

    // OpenCASCADE on the infinite line, like ours and s1856, on every occtStride-th line only: it
    // builds a polyhedron of the surface per query, tens of ms each. Each OCCT hit is compared
    // with the nearest of our hits on the same line.
    if (withOcct) {
        const Handle(GeomAdaptor_Surface) surface = new GeomAdaptor_Surface(occt);
        IntCurveSurface_HInter inter;
        t0 = Clock::now();
        for (std::size_t k = 0; k < lines.size(); k += occtStride) {
            const Line& l = lines[k];
            const Handle(GeomAdaptor_Curve) curve = new GeomAdaptor_Curve(
                new Geom_Line(gp_Lin(gp_Pnt(l.o.x, l.o.y, l.o.z), gp_Dir(l.d.x, l.d.y, l.d.z))));
            inter.Perform(curve, surface);
            const int count = inter.IsDone() ? inter.NbPoints() : 0;
            bool found = false;
            for (int h = 1; h <= count; ++h) {
                const glm::dvec3 x = toGlm(inter.Point(h).Pnt().XYZ());
                found = found || glm::length(x - l.p) < 1e-7;
                occtHits[k].push_back(x);
                checksum += inter.Point(h).W();
            }
            if (!found) ++f.occtMissed;
            if (static_cast<std::size_t>(count) != ourCounts[k]) ++f.occtCountMismatch;
        }
        f.occtIntersectUs = seconds(t0, Clock::now()) * 1e6 / occtQueries;
        for (std::size_t k = 0; k < lines.size(); k += occtStride) {
            const auto ours = intersector.intersect(lines[k].o, lines[k].d);
            for (const glm::dvec3& x : occtHits[k]) {
                double nearest = 1e300;
                for (const auto& h : ours) nearest = std::min(nearest, glm::length(h.point - x));
                if (!ours.empty()) f.occtWorstHitDistance = std::max(f.occtWorstHitDistance, nearest);
            }
        }
    }

    // Closest points for points near the surface (the foot point is known).
    const geom::SurfaceProjector projector(s);
    std::vector<std::pair<glm::dvec3, double>> near;
    for (int k = 0; k < queries; ++k) {
        const double u = 0.01 + 0.98 * unit(rng), v = 0.01 + 0.98 * unit(rng);
        const double h = (unit(rng) - 0.5) * 0.01;
        near.push_back({geom::evaluate(s, u, v) + h * geom::normal(s, u, v), std::abs(h)});
    }
    t0 = Clock::now();
    for (const auto& [p, h] : near) {
        const geom::SurfacePoint q = projector.closestPoint(p);
        f.worstClosestError = std::max(f.worstClosestError, std::abs(q.distance - h));
        if (q.distance > h + 1e-12) ++f.closestFartherThanFoot;
    }
    t1 = Clock::now();
    f.closestUs = seconds(t0, t1) * 1e6 / queries;
    t0 = Clock::now();
    for (const auto& [p, h] : near) {
        double point[3] = {p.x, p.y, p.z}, par[2] = {0, 0}, dist = 0;
        s1958(ss, point, 3, 1e-12, 1e-12, par, &dist, &stat);
        f.worstSislClosestError = std::max(f.worstSislClosestError, std::abs(dist - h));
        if (dist > h + 1e-12) ++f.sislFartherThanFoot;
    }
    t1 = Clock::now();
    f.sislClosestUs = seconds(t0, t1) * 1e6 / queries;
    // OpenCASCADE, initialised once for many points, then one Perform per point (every
    // occtStride-th point), with its default search (Grad) and its tree search.
    for (const Extrema_ExtAlgo algo : {Extrema_ExtAlgo_Grad, Extrema_ExtAlgo_Tree}) {
        if (!withOcct) break;
        const bool tree = algo == Extrema_ExtAlgo_Tree;
        double u1 = 0, u2 = 0, v1 = 0, v2 = 0;
        occt->Bounds(u1, u2, v1, v2);
        GeomAPI_ProjectPointOnSurf projection;
        projection.Init(occt, u1, u2, v1, v2, algo);
        t0 = Clock::now();
        for (std::size_t k = 0; k < near.size(); k += occtStride) {
            const auto& [p, h] = near[k];
            projection.Perform(gp_Pnt(p.x, p.y, p.z));
            if (projection.NbPoints() == 0) {
                ++(tree ? f.occtTreeNoAnswer : f.occtNoAnswer);
                continue;
            }
            const double dist = projection.LowerDistance();
            double& worst = tree ? f.worstOcctTreeClosestError : f.worstOcctClosestError;
            worst = std::max(worst, std::abs(dist - h));
            if (dist > h + 1e-12) ++(tree ? f.occtTreeFartherThanFoot : f.occtFartherThanFoot);
        }
        (tree ? f.occtTreeClosestUs : f.occtClosestUs) = seconds(t0, Clock::now()) * 1e6 / occtQueries;
    }

    freeSurf(ss);
    std::printf(
        "%s surface: grid fast %.1f ns/pt, plain %.1f ns/pt (fast vs plain max normal diff %.2e), "
        "SISL s1421 %.1f ns/pt, SISL s1506 %.1f ns/pt\n",
        name, f.fastNs, f.plainNs, worstDiff, f.sislPointNs, f.sislGridNs);
    std::printf(
        "  intersect %.2f us/query (missed %d, worst hit error %.2e), SISL s1856 %.2f us/query (missed %d), "
        "hit-count mismatches %d\n",
        f.intersectUs, f.missed, f.worstHitError, f.sislIntersectUs, f.sislMissed, f.countMismatch);
    std::printf(
        "  closest point %.2f us (worst |d - h| %.2e), SISL s1958 %.2f us (worst %.2e)   [checksum %.3f]\n",
        f.closestUs, f.worstClosestError, f.sislClosestUs, f.worstSislClosestError, checksum);
    if (!withOcct) return f;
    std::printf(
        "  OpenCASCADE: GeomAdaptor_Surface::D1 %.1f ns/pt, Geom_BSplineSurface::D1 %.1f ns/pt (worst point "
        "+ "
        "normal diff from ours %.2e)\n",
        f.occtAdaptorNs, f.occtBsplineNs, f.occtWorstNormalDiff);
    std::printf(
        "  OpenCASCADE IntCurveSurface_HInter %.2f us/query (missed %d, hit-count mismatches with ours %d, "
        "worst distance of a hit from ours %.2e)\n",
        f.occtIntersectUs, f.occtMissed, f.occtCountMismatch, f.occtWorstHitDistance);
    std::printf(
        "  OpenCASCADE GeomAPI_ProjectPointOnSurf Grad %.2f us (worst %.2e, farther than foot %d, no answer "
        "%d), "
        "Tree %.2f us (worst %.2e, farther than foot %d, no answer %d)\n",
        f.occtClosestUs, f.worstOcctClosestError, f.occtFartherThanFoot, f.occtNoAnswer, f.occtTreeClosestUs,
        f.worstOcctTreeClosestError, f.occtTreeFartherThanFoot, f.occtTreeNoAnswer);
    return f;
}

}  // namespace

int main() {
    std::setvbuf(stdout, nullptr, _IOLBF, 0);  // figures appear as they come: a run takes minutes
    const auto wallStart = Clock::now();
    const std::clock_t cpuStart = std::clock();
    struct Case {
        const char* name;
        geom::Surface surface;
        bool withOcct;  // OpenCASCADE (tens of ms a query) on the two reference surfaces only
    };
    const std::vector<Case> cases{
        {"poly", benchSurface(false), true},          {"rational", benchSurface(true), true},
        {"degree1", degreeOneSurface(), false},       {"deg2x5_double_knots", creasedSurface(), false},
        {"wide_weights", wideWeightSurface(), false}, {"periodic_tube", tubeSurface(), false}};
    std::vector<Figures> figures;
    for (const Case& c : cases) figures.push_back(run(c.surface, c.name, c.withOcct));
    auto emit = [](const char* prefix, const Figures& f, bool withOcct) {
        std::printf(
            "\"%s_grid_fast_ns_per_point\": %.2f, \"%s_grid_plain_ns_per_point\": %.2f, "
            "\"%s_sisl_s1421_ns_per_point\": %.2f, \"%s_sisl_s1506_ns_per_point\": %.2f, "
            "\"%s_intersect_us_per_query\": %.3f, \"%s_sisl_s1856_us_per_query\": %.3f, "
            "\"%s_intersect_missed\": %d, \"%s_sisl_missed\": %d, \"%s_hit_count_mismatches\": %d, "
            "\"%s_worst_hit_error\": %.3e, \"%s_closest_us_per_query\": %.3f, "
            "\"%s_sisl_s1958_us_per_query\": %.3f, \"%s_closest_worst_error\": %.3e, "
            "\"%s_sisl_closest_worst_error\": %.3e, \"%s_closest_farther_than_foot\": %d, "
            "\"%s_sisl_closest_farther_than_foot\": %d, \"%s_plain_vs_s1421\": %.3f, "
            "\"%s_intersect_speedup_vs_s1856\": %.2f, \"%s_closest_speedup_vs_s1958\": %.2f, ",
            prefix, f.fastNs, prefix, f.plainNs, prefix, f.sislPointNs, prefix, f.sislGridNs, prefix,
            f.intersectUs, prefix, f.sislIntersectUs, prefix, f.missed, prefix, f.sislMissed, prefix,
            f.countMismatch, prefix, f.worstHitError, prefix, f.closestUs, prefix, f.sislClosestUs, prefix,
            f.worstClosestError, prefix, f.worstSislClosestError, prefix, f.closestFartherThanFoot, prefix,
            f.sislFartherThanFoot, prefix, f.plainNs / f.sislPointNs, prefix,
            f.sislIntersectUs / f.intersectUs, prefix, f.sislClosestUs / f.closestUs);
        if (!withOcct) return;
        std::printf(
            "\"%s_occt_adaptor_d1_ns_per_point\": %.2f, \"%s_occt_bspline_d1_ns_per_point\": %.2f, "
            "\"%s_occt_grid_worst_diff\": %.3e, \"%s_occt_hinter_us_per_query\": %.3f, "
            "\"%s_occt_missed\": %d, \"%s_occt_hit_count_mismatches\": %d, "
            "\"%s_occt_worst_hit_distance_from_ours\": %.3e, \"%s_occt_project_us_per_query\": %.3f, "
            "\"%s_occt_closest_worst_error\": %.3e, \"%s_occt_closest_farther_than_foot\": %d, "
            "\"%s_occt_closest_no_answer\": %d, \"%s_occt_project_tree_us_per_query\": %.3f, "
            "\"%s_occt_tree_closest_worst_error\": %.3e, \"%s_occt_tree_closest_farther_than_foot\": %d, "
            "\"%s_occt_tree_closest_no_answer\": %d, ",
            prefix, f.occtAdaptorNs, prefix, f.occtBsplineNs, prefix, f.occtWorstNormalDiff, prefix,
            f.occtIntersectUs, prefix, f.occtMissed, prefix, f.occtCountMismatch, prefix,
            f.occtWorstHitDistance, prefix, f.occtClosestUs, prefix, f.worstOcctClosestError, prefix,
            f.occtFartherThanFoot, prefix, f.occtNoAnswer, prefix, f.occtTreeClosestUs, prefix,
            f.worstOcctTreeClosestError, prefix, f.occtTreeFartherThanFoot, prefix, f.occtTreeNoAnswer);
    };
    // The worst surface of each comparison: what the targets are read against.
    double worstPlain = 0.0, worstIntersect = 1e300, worstClosest = 1e300;
    int farther = 0, missed = 0;
    std::printf("{\"occt_queries_per_surface\": %d, ", occtQueries);
    for (std::size_t k = 0; k < cases.size(); ++k) {
        const Figures& f = figures[k];
        emit(cases[k].name, f, cases[k].withOcct);
        worstPlain = std::max(worstPlain, f.plainNs / f.sislPointNs);
        worstIntersect = std::min(worstIntersect, f.sislIntersectUs / f.intersectUs);
        worstClosest = std::min(worstClosest, f.sislClosestUs / f.closestUs);
        farther += f.closestFartherThanFoot;
        missed += f.missed;
    }
    std::printf(
        "\"worst_plain_vs_s1421\": %.3f, \"worst_intersect_speedup_vs_s1856\": %.2f, "
        "\"worst_closest_speedup_vs_s1958\": %.2f, \"closest_farther_than_foot\": %d, "
        "\"intersect_missed\": %d, \"wall_seconds\": %.1f, \"cpu_seconds\": %.1f}\n",
        worstPlain, worstIntersect, worstClosest, farther, missed, seconds(wallStart, Clock::now()),
        static_cast<double>(std::clock() - cpuStart) / CLOCKS_PER_SEC);
    return 0;
}
