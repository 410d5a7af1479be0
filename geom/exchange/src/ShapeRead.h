#pragma once
// Surfaces and loops of the faces read from a file (private to geom_exchange).

#include "geom/Surface.h"
#include "geom/exchange/CadModel.h"

#include <TopoDS_Face.hxx>

#include <optional>
#include <string>
#include <vector>

namespace geom::exchange {

/// A face's surface in geom's form, or why it cannot be taken.
struct FaceSurface {
    std::optional<Surface> surface;
    std::string problem;
};

/// The face's surface as a B-spline on the face's (u, v) box (OpenCASCADE converts other types
/// and cuts a larger surface down), its u reversed where the face is. A face whose boundary is
/// not that box (trimmed inside its surface) or whose surface cannot be converted gives a problem.
FaceSurface faceSurface(const TopoDS_Face& face);

/// A face's loops (outer wire first), each from edges that are degree-1 curves: their poles in
/// space and, on the face's surface, the (u, v) where each pole lies (the curve on the surface
/// where it matches, else Newton's method from it, since a reader may have refitted it). The
/// loops run counter-clockwise round the face (holes clockwise). nullopt, with the problem, for
/// edges of another kind.
std::optional<std::vector<SurfaceLoop>> faceLoops(const TopoDS_Face& face, std::string& problem);

/// Makes each loop's (u, v) continuous along the directions in which `surface` is periodic by
/// construction (a reader may have moved vertices by a period, or wrapped the surface so its
/// period is lost), with the middle of the loop's range inside the domain, as the curve mapper
/// leaves its loops.
void unwrapLoops(std::vector<SurfaceLoop>& loops, const Surface& surface);

/// One face's loops (unwrapped) as the files promise them: the outer loop (the largest)
/// counter-clockwise and first, then the holes clockwise. BRepTools::OuterWire can take a hole
/// for the outer wire, and healing can turn wires round, where the outer loop crosses a seam.
void outerLoopsFirst(std::vector<SurfaceLoop>& loops);

}  // namespace geom::exchange
