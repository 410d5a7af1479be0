#include "ShapeBuild.h"

#include "UvPolygon.h"
#include "geom/BezierExtraction.h"
#include "geom/GeometryError.h"
#include "geom/exchange/OcctConversion.h"

#include <BRepBuilderAPI_MakeFace.hxx>
#include <BRep_Builder.hxx>
#include <Geom_BSplineCurve.hxx>
#include <Precision.hxx>
#include <TColStd_Array1OfInteger.hxx>
#include <TColStd_Array1OfReal.hxx>
#include <TColgp_Array1OfPnt.hxx>
#include <TopoDS.hxx>
#include <TopoDS_Edge.hxx>
#include <TopoDS_Face.hxx>
#include <TopoDS_Vertex.hxx>
#include <TopoDS_Wire.hxx>

#include <algorithm>
#include <cmath>
#include <string>

namespace geom::exchange {

namespace {

bool inside(const glm::dvec2& p, const std::vector<glm::dvec2>& polygon) {
    bool in = false;
    for (std::size_t i = 0, j = polygon.size() - 1; i < polygon.size(); j = i++) {
        const glm::dvec2 &a = polygon[i], &b = polygon[j];
        if ((a.y > p.y) != (b.y > p.y) && p.x < (b.x - a.x) * (p.y - a.y) / (b.y - a.y) + a.x) in = !in;
    }
    return in;
}

void checkLoop(const SurfaceLoop& loop, std::size_t index) {
    const std::string where = "loop " + std::to_string(index + 1) + ": ";
    if (loop.uv.size() != loop.points.size())
        throw GeometryError(where + std::to_string(loop.uv.size()) + " (u, v) vertices for " +
                            std::to_string(loop.points.size()) + " points");
    if (loop.points.size() < 4)
        throw GeometryError(where + "a closed loop needs 3 vertices and the first again");
    if (loop.uv.front() != loop.uv.back() || loop.points.front() != loop.points.back())
        throw GeometryError(where + "the last vertex must repeat the first (a closed loop)");
    for (std::size_t i = 0; i < loop.points.size(); ++i) {
        const glm::dvec3& p = loop.points[i];
        if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z))
            throw GeometryError(where + "point " + std::to_string(i) + " is not finite");
    }
}

opencascade::handle<Geom_BSplineCurve> polyline(const std::vector<glm::dvec3>& points) {
    const int n = int(points.size());
    TColgp_Array1OfPnt poles(1, n);
    TColStd_Array1OfReal knots(1, n);
    TColStd_Array1OfInteger mults(1, n);
    for (int i = 0; i < n; ++i) {
        const glm::dvec3& p = points[std::size_t(i)];
        poles(i + 1) = gp_Pnt(p.x, p.y, p.z);
        knots(i + 1) = i;
        mults(i + 1) = i == 0 || i == n - 1 ? 2 : 1;
    }
    return new Geom_BSplineCurve(poles, knots, mults, 1);
}

/// The loop as one closed edge on `face`; its tolerance covers the chords' distance from the
/// surface image of the (u, v) chords (sampled at each chord's quarter points).
TopoDS_Edge loopEdge(const SurfaceLoop& loop, const TopoDS_Face& face,
                     const opencascade::handle<Geom_BSplineSurface>& support) {
    opencascade::handle<Geom_BSplineCurve> curve = polyline(loop.points);
    opencascade::handle<Geom2d_BSplineCurve> pcurve = polylineToOcct(loop.uv);
    double gap = 0;
    for (std::size_t i = 0; i + 1 < loop.points.size(); ++i)
        for (const double f : {0.0, 0.25, 0.5, 0.75}) {
            const gp_Pnt2d uv = pcurve->Value(double(i) + f);
            gap = std::max(gap, support->Value(uv.X(), uv.Y()).Distance(curve->Value(double(i) + f)));
        }
    const double tolerance = std::max(Precision::Confusion(), 1.5 * gap);
    BRep_Builder b;
    TopoDS_Edge edge;
    b.MakeEdge(edge, curve, tolerance);
    TopoDS_Vertex vertex;
    const glm::dvec3& p = loop.points.front();
    b.MakeVertex(vertex, gp_Pnt(p.x, p.y, p.z), tolerance);
    b.Add(edge, vertex.Oriented(TopAbs_FORWARD));
    b.Add(edge, vertex.Oriented(TopAbs_REVERSED));
    b.Range(edge, 0.0, double(loop.points.size() - 1));
    b.UpdateEdge(edge, pcurve, face, tolerance);
    return edge;
}

TopoDS_Wire wireOf(const TopoDS_Edge& edge) {
    BRep_Builder b;
    TopoDS_Wire wire;
    b.MakeWire(wire);
    b.Add(wire, edge);
    wire.Closed(true);
    return wire;
}

}  // namespace

TopoDS_Compound patchFaces(const Surface& surface) {
    BRep_Builder b;
    TopoDS_Compound faces;
    b.MakeCompound(faces);
    for (const BezierSurfacePiece& piece : extractBezier(surface))
        b.Add(faces,
              BRepBuilderAPI_MakeFace(toOcct(piece.surface, Periodicity::Never), Precision::Confusion())
                  .Face());
    return faces;
}

TopoDS_Compound loopFaces(const opencascade::handle<Geom_BSplineSurface>& support,
                          const std::vector<SurfaceLoop>& loops) {
    std::vector<double> area(loops.size());
    for (std::size_t i = 0; i < loops.size(); ++i) {
        checkLoop(loops[i], i);
        area[i] = twiceSignedArea(loops[i].uv);
    }
    // Each clockwise loop is a hole of the smallest counter-clockwise loop around it, a period
    // along a periodic direction counting as none: a loop across the seam has its middle in the
    // domain, and a hole in it may lie a period away (it is moved there).
    const glm::dvec2 period(support->IsUPeriodic() ? support->UPeriod() : 0.0,
                            support->IsVPeriodic() ? support->VPeriod() : 0.0);
    std::vector<int> holeOf(loops.size(), -1);
    std::vector<glm::dvec2> shiftOf(loops.size(), glm::dvec2(0.0));
    for (std::size_t h = 0; h < loops.size(); ++h) {
        if (area[h] >= 0) continue;
        for (std::size_t o = 0; o < loops.size(); ++o) {
            if (!(area[o] > 0) || (holeOf[h] >= 0 && area[o] >= area[std::size_t(holeOf[h])])) continue;
            for (const int i : {0, -1, 1})
                for (const int j : {0, -1, 1}) {
                    const glm::dvec2 shift(i * period.x, j * period.y);
                    if ((i != 0 && period.x == 0) || (j != 0 && period.y == 0) || holeOf[h] == int(o) ||
                        !inside(loops[h].uv.front() + shift, loops[o].uv))
                        continue;
                    holeOf[h] = int(o);
                    shiftOf[h] = shift;
                }
        }
    }
    BRep_Builder b;
    TopoDS_Compound faces;
    b.MakeCompound(faces);
    for (std::size_t o = 0; o < loops.size(); ++o) {
        if (area[o] < 0 && holeOf[o] >= 0) continue;
        TopoDS_Face face;
        b.MakeFace(face, support, Precision::Confusion());
        const TopoDS_Edge outer = loopEdge(loops[o], face, support);
        b.Add(face, wireOf(area[o] < 0 ? TopoDS::Edge(outer.Reversed()) : outer));
        for (std::size_t h = 0; h < loops.size(); ++h) {
            if (holeOf[h] != int(o)) continue;
            SurfaceLoop hole = loops[h];
            for (glm::dvec2& uv : hole.uv) uv += shiftOf[h];
            b.Add(face, wireOf(loopEdge(hole, face, support)));
        }
        b.Add(faces, face);
    }
    return faces;
}

}  // namespace geom::exchange
