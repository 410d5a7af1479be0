#include "ShapeRead.h"
#include "FailureText.h"
#include "UvPolygon.h"

#include "geom/GeometryError.h"
#include "geom/Reparameterize.h"
#include "geom/SurfaceProjector.h"
#include "geom/exchange/OcctConversion.h"

#include <BRepAdaptor_Surface.hxx>
#include <BRepTools.hxx>
#include <BRepTools_WireExplorer.hxx>
#include <BRep_Tool.hxx>
#include <Bnd_Box.hxx>
#include <Geom2d_Curve.hxx>
#include <GeomConvert.hxx>
#include <Geom_BSplineCurve.hxx>
#include <Geom_BSplineSurface.hxx>
#include <Geom_Curve.hxx>
#include <Geom_RectangularTrimmedSurface.hxx>
#include <Geom_TrimmedCurve.hxx>
#include <Standard_Failure.hxx>
#include <TColStd_Array1OfReal.hxx>
#include <TopExp_Explorer.hxx>
#include <TopoDS.hxx>
#include <TopoDS_Edge.hxx>
#include <TopoDS_Wire.hxx>

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <optional>

namespace geom::exchange {

namespace {

std::string typeName(const opencascade::handle<Standard_Transient>& object) {
    const std::string name = object->DynamicType()->Name();
    return name.rfind("Geom_", 0) == 0 ? name.substr(5) : name;
}

/// Every edge's curve on the face runs along the sides of the (u, v) box.
bool rectangular(const TopoDS_Face& face, double u0, double u1, double v0, double v1) {
    const double eu = 1e-7 * (u1 - u0), ev = 1e-7 * (v1 - v0);
    for (TopExp_Explorer e(face, TopAbs_EDGE); e.More(); e.Next()) {
        double f = 0, l = 0;
        opencascade::handle<Geom2d_Curve> pcurve =
            BRep_Tool::CurveOnSurface(TopoDS::Edge(e.Current()), face, f, l);
        if (pcurve.IsNull()) return false;
        for (int k = 0; k <= 8; ++k) {
            const gp_Pnt2d p = pcurve->Value(f + (l - f) * k / 8.0);
            const bool onU = std::abs(p.X() - u0) <= eu || std::abs(p.X() - u1) <= eu;
            const bool onV = std::abs(p.Y() - v0) <= ev || std::abs(p.Y() - v1) <= ev;
            if (!onU && !onV) return false;
        }
    }
    return true;
}

/// How far the face's edges lie off its surface at most (each edge's curve in space against its
/// curve on the surface), and the size of the box round the edges. A file with a wrong point or
/// reference in its surface has them far apart; OpenCASCADE's healing then widens the edges'
/// tolerance and puts the curves on the surface anywhere.
std::pair<double, double> edgesOffSurface(const TopoDS_Face& face, const Geom_Surface& surface) {
    double gap = 0;
    Bnd_Box box;
    for (TopExp_Explorer e(face, TopAbs_EDGE); e.More(); e.Next()) {
        const TopoDS_Edge& edge = TopoDS::Edge(e.Current());
        double f = 0, l = 0, pf = 0, pl = 0;
        const opencascade::handle<Geom_Curve> curve = BRep_Tool::Curve(edge, f, l);
        const opencascade::handle<Geom2d_Curve> pcurve = BRep_Tool::CurveOnSurface(edge, face, pf, pl);
        if (curve.IsNull() || pcurve.IsNull()) continue;
        for (int k = 0; k <= 8; ++k) {
            const gp_Pnt p = curve->Value(f + (l - f) * k / 8.0);
            const gp_Pnt2d uv = pcurve->Value(pf + (pl - pf) * k / 8.0);
            gap = std::max(gap, p.Distance(surface.Value(uv.X(), uv.Y())));
            box.Add(p);
        }
    }
    return {gap, box.IsVoid() ? 0.0 : std::sqrt(box.SquareExtent())};
}

/// Moves a face's (u, v) box onto the surface's own bounds where it overshoots them by rounding:
/// BRepTools::UVBounds gives a cone's u from -4e-13 or a sphere's v from -pi/2 - 3e-13, and
/// OpenCASCADE's conversion and Segment throw on a box past the bounds. A box farther out is
/// left as it is.
void clampToBounds(const Geom_Surface& s, double& u0, double& u1, double& v0, double& v1) {
    double a0, a1, b0, b1;
    s.Bounds(a0, a1, b0, b1);
    const auto clamp = [](double& t0, double& t1, double first, double last) {
        const double e = 1e-9 * std::max(1.0, t1 - t0);
        if (t0 < first && first - t0 <= e) t0 = first;
        if (t1 > last && t1 - last <= e) t1 = last;
    };
    clamp(u0, u1, a0, a1);
    clamp(v0, v1, b0, b1);
}

/// The face's surface as a B-spline on [u0, u1] x [v0, v1] (converted and cut by OpenCASCADE).
opencascade::handle<Geom_BSplineSurface> bsplineOn(opencascade::handle<Geom_Surface> s, double u0, double u1,
                                                   double v0, double v1) {
    while (auto trimmed = opencascade::handle<Geom_RectangularTrimmedSurface>::DownCast(s))
        s = trimmed->BasisSurface();
    clampToBounds(*s, u0, u1, v0, v1);
    opencascade::handle<Geom_BSplineSurface> b = opencascade::handle<Geom_BSplineSurface>::DownCast(s);
    if (b.IsNull())
        return GeomConvert::SurfaceToBSplineSurface(new Geom_RectangularTrimmedSurface(s, u0, u1, v0, v1));
    double a0, a1, b0, b1;
    b->Bounds(a0, a1, b0, b1);
    const double eu = 1e-12 * (a1 - a0), ev = 1e-12 * (b1 - b0);
    if (std::abs(a0 - u0) <= eu && std::abs(a1 - u1) <= eu && std::abs(b0 - v0) <= ev &&
        std::abs(b1 - v1) <= ev)
        return b;
    b = opencascade::handle<Geom_BSplineSurface>::DownCast(b->Copy());
    b->Segment(u0, u1, v0, v1);
    return b;
}

/// Gauss-Newton from `guess` to the (u, v) where the surface passes through x, each step halved
/// until it brings the point nearer (on a rational surface with weights far apart a full step
/// can run off to 1e100) and kept inside the surface's bounds where it is not periodic: the
/// answer is never farther from x than the guess.
gp_Pnt2d refine(const BRepAdaptor_Surface& surface, const gp_Pnt& x, gp_Pnt2d guess) {
    double u = guess.X(), v = guess.Y();
    gp_Pnt p;
    gp_Vec su, sv;
    surface.D0(u, v, p);
    double best = p.Distance(x);
    if (best <= 1e-12 * (1.0 + gp_Vec(x.XYZ()).Magnitude())) return guess;  // exact already
    auto inside = [&](double t, double first, double last, bool periodic) {
        return periodic ? t : std::clamp(t, first, last);
    };
    for (int k = 0; k < 30; ++k) {
        surface.D1(u, v, p, su, sv);
        const gp_Vec r(p, x);
        const double a = su.Dot(su), b = su.Dot(sv), c = sv.Dot(sv), ru = su.Dot(r), rv = sv.Dot(r);
        const double det = a * c - b * b;
        if (!(det > 0)) break;
        const double du = (c * ru - b * rv) / det, dv = (a * rv - b * ru) / det;
        bool nearer = false;
        for (double t = 1.0; t > 1e-6 && !nearer; t *= 0.5) {
            const double un = inside(u + t * du, surface.FirstUParameter(), surface.LastUParameter(),
                                     surface.IsUPeriodic());
            const double vn = inside(v + t * dv, surface.FirstVParameter(), surface.LastVParameter(),
                                     surface.IsVPeriodic());
            gp_Pnt q;
            surface.D0(un, vn, q);
            if (const double d = q.Distance(x); d < best) u = un, v = vn, best = d, nearer = true;
        }
        if (!nearer || std::abs(du) + std::abs(dv) <= 1e-15 * (1.0 + std::abs(u) + std::abs(v))) break;
    }
    return gp_Pnt2d(u, v);
}

/// The (u, v) of points on a face's surface: Gauss-Newton from the reader's pcurve (refine),
/// and where that ends off the surface (OpenCASCADE's refitted pcurves can be far off on a
/// rational surface with weights far apart), the global closest point on the B-spline surface.
class FaceParameters {
public:
    explicit FaceParameters(const TopoDS_Face& face) : face_(face), surface_(face, false) {}

    gp_Pnt2d at(const gp_Pnt& x, const gp_Pnt2d& guess) {
        const gp_Pnt2d local = refine(surface_, x, guess);
        const double off = surface_.Value(local.X(), local.Y()).Distance(x);
        if (off <= 1e-9 * (1.0 + gp_Vec(x.XYZ()).Magnitude()) || !projector()) return local;
        const SurfacePoint global = projector_->closestPoint(glm::dvec3(x.X(), x.Y(), x.Z()));
        return global.distance < off ? gp_Pnt2d(global.uv.x, global.uv.y) : local;
    }

private:
    /// The face's B-spline surface's projector, made when first needed; nullptr for another kind.
    const SurfaceProjector* projector() {
        if (!tried_) {
            tried_ = true;
            const auto b = opencascade::handle<Geom_BSplineSurface>::DownCast(BRep_Tool::Surface(face_));
            if (!b.IsNull()) {
                try {
                    spline_ = fromOcct(*b);
                    projector_.emplace(*spline_);
                } catch (const GeometryError&) {
                    // a surface geom refuses: the reader's own (u, v), refined, stand
                }
            }
        }
        return projector_ ? &*projector_ : nullptr;
    }

    TopoDS_Face face_;
    BRepAdaptor_Surface surface_;
    bool tried_ = false;
    std::optional<Surface> spline_;
    std::optional<SurfaceProjector> projector_;
};

/// Appends an edge's poles (in the wire's direction) and their (u, v) to the loop.
bool appendEdge(const TopoDS_Edge& edge, const TopoDS_Face& face, FaceParameters& parameters,
                SurfaceLoop& loop, std::string& problem) {
    double f = 0, l = 0;
    opencascade::handle<Geom_Curve> curve = BRep_Tool::Curve(edge, f, l);
    double pf = 0, pl = 0;
    opencascade::handle<Geom2d_Curve> pcurve = BRep_Tool::CurveOnSurface(edge, face, pf, pl);
    if (curve.IsNull() || pcurve.IsNull()) {
        problem = "an edge without a curve in space and on its surface";
        return false;
    }
    opencascade::handle<Geom_BSplineCurve> b =
        GeomConvert::CurveToBSplineCurve(new Geom_TrimmedCurve(curve, f, l));
    if (b->Degree() != 1) {
        problem = "edges of degree " + std::to_string(b->Degree()) + " (mapped curves are polylines)";
        return false;
    }
    std::vector<glm::dvec3> points;
    std::vector<glm::dvec2> uv;
    TColStd_Array1OfReal flat(1, b->NbPoles() + 2);
    b->KnotSequence(flat);
    for (int i = 1; i <= b->NbPoles(); ++i) {
        const gp_Pnt& p = b->Pole(i);
        points.emplace_back(p.X(), p.Y(), p.Z());
        const gp_Pnt2d w = parameters.at(p, pcurve->Value(flat(i + 1)));  // a pole's parameter: its knot
        uv.emplace_back(w.X(), w.Y());
    }
    if (edge.Orientation() == TopAbs_REVERSED) {
        std::reverse(points.begin(), points.end());
        std::reverse(uv.begin(), uv.end());
    }
    const std::size_t skip = loop.points.empty() ? 0 : 1;  // the vertex the previous edge ended at
    loop.points.insert(loop.points.end(), points.begin() + std::ptrdiff_t(skip), points.end());
    loop.uv.insert(loop.uv.end(), uv.begin() + std::ptrdiff_t(skip), uv.end());
    return true;
}

/// Makes a loop's (u, v) continuous along a periodic direction (a reader may have moved some
/// vertices by a period) with the middle of its range inside the domain, as the curve mapper
/// leaves its loops.
void unwrap(std::vector<glm::dvec2>& uv, int axis, double start, double period) {
    for (std::size_t k = 1; k < uv.size(); ++k)
        uv[k][axis] -= period * std::round((uv[k][axis] - uv[k - 1][axis]) / period);
    double low = uv[0][axis], high = low;
    for (const auto& p : uv) low = std::min(low, p[axis]), high = std::max(high, p[axis]);
    // A middle within rounding of the domain's end counts as at its start (the same seam).
    const double shift = period * std::floor(((low + high) / 2 - start) / period + 1e-9);
    if (shift != 0)
        for (auto& p : uv) p[axis] -= shift;
}

}  // namespace

FaceSurface faceSurface(const TopoDS_Face& face) {
    FaceSurface r;
    const opencascade::handle<Geom_Surface> s = BRep_Tool::Surface(face);
    if (s.IsNull()) {
        r.problem = "a face without a surface";
        return r;
    }
    double u0 = 0, u1 = 0, v0 = 0, v1 = 0;
    BRepTools::UVBounds(face, u0, u1, v0, v1);
    if (!(u1 > u0 && v1 > v0) || !std::isfinite(u1 - u0) || !std::isfinite(v1 - v0)) {
        r.problem = "a face with an empty or unbounded (u, v) box";
        return r;
    }
    if (!rectangular(face, u0, u1, v0, v1)) {
        // Only which message: a face off its surface is not one trimmed inside it.
        if (const auto [gap, size] = edgesOffSurface(face, *s); gap > 1e-7 && gap > 1e-4 * size) {
            char text[160];
            std::snprintf(text, sizeof text,
                          "a face whose edges lie up to %.3g off its %s surface, the face %.3g across "
                          "(a wrong point or reference in the file)",
                          gap, typeName(s).c_str(), size);
            r.problem = text;
        } else {
            r.problem = "a face trimmed inside its " + typeName(s) + " surface (surfaces are kept untrimmed)";
        }
        return r;
    }
    try {
        Surface g = fromOcct(*bsplineOn(s, u0, u1, v0, v1));
        r.surface = face.Orientation() == TopAbs_REVERSED ? reverse(g, false) : std::move(g);
    } catch (const Standard_Failure& e) {
        r.problem =
            "a " + typeName(s) + " surface OpenCASCADE cannot convert to a B-spline (" + failureText(e) + ")";
    } catch (const GeometryError& e) {
        r.problem = std::string("a surface that is not a valid B-spline: ") + e.what();
    }
    return r;
}

std::optional<std::vector<SurfaceLoop>> faceLoops(const TopoDS_Face& face, std::string& problem) {
    FaceParameters parameters(face);
    std::vector<TopoDS_Wire> wires{BRepTools::OuterWire(face)};
    for (TopExp_Explorer e(face, TopAbs_WIRE); e.More(); e.Next())
        if (!e.Current().IsSame(wires.front())) wires.push_back(TopoDS::Wire(e.Current()));
    std::vector<SurfaceLoop> loops;
    try {
        for (const TopoDS_Wire& wire : wires) {
            if (wire.IsNull()) continue;
            SurfaceLoop loop;
            for (BRepTools_WireExplorer ex(wire, face); ex.More(); ex.Next())
                if (!appendEdge(ex.Current(), face, parameters, loop, problem)) return std::nullopt;
            if (loop.points.size() < 4 || glm::length(loop.points.front() - loop.points.back()) >
                                              1e-9 * (1.0 + glm::length(loop.points.front()))) {
                problem = "a wire that is not a closed loop";
                return std::nullopt;
            }
            loop.points.back() = loop.points.front();
            loop.uv.back() = loop.uv.front();
            if (face.Orientation() == TopAbs_REVERSED) {
                std::reverse(loop.points.begin(), loop.points.end());
                std::reverse(loop.uv.begin(), loop.uv.end());
            }
            loops.push_back(std::move(loop));
        }
    } catch (const Standard_Failure& e) {
        problem = "edges OpenCASCADE cannot read: " + failureText(e);
        return std::nullopt;
    }
    return loops;
}

void unwrapLoops(std::vector<SurfaceLoop>& loops, const Surface& surface) {
    for (const int axis : {0, 1})
        if (periodicByConstruction(surface, axis == 1)) {
            const double start = axis == 0 ? surface.domainStartU() : surface.domainStartV();
            const double end = axis == 0 ? surface.domainEndU() : surface.domainEndV();
            for (SurfaceLoop& loop : loops) unwrap(loop.uv, axis, start, end - start);
        }
}

void outerLoopsFirst(std::vector<SurfaceLoop>& loops) {
    auto area = [](const SurfaceLoop& loop) { return twiceSignedArea(loop.uv); };
    if (loops.empty()) return;
    // The outer loop holds the holes: the largest, turned counter-clockwise; every other loop is
    // a hole, turned clockwise (a confused reader can turn any of them round).
    const auto outer = std::max_element(loops.begin(), loops.end(), [&](const auto& a, const auto& b) {
        return std::abs(area(a)) < std::abs(area(b));
    });
    std::iter_swap(loops.begin(), outer);
    for (std::size_t k = 0; k < loops.size(); ++k)
        if ((area(loops[k]) > 0.0) != (k == 0)) {
            std::reverse(loops[k].points.begin(), loops[k].points.end());
            std::reverse(loops[k].uv.begin(), loops[k].uv.end());
        }
}

}  // namespace geom::exchange
