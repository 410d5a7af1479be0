#pragma once
// OpenCASCADE shapes of the surfaces and loops written to a file (private to geom_exchange).

#include "geom/Surface.h"
#include "geom/exchange/CadModel.h"

#include <Geom_BSplineSurface.hxx>
#include <TopoDS_Compound.hxx>

#include <vector>

namespace geom::exchange {

/// One face per Bézier patch of the surface (extractBezier's order), each on its natural bounds.
TopoDS_Compound patchFaces(const Surface& surface);

/// Trimmed faces on `support` bounded by the loops: one per counter-clockwise loop in (u, v),
/// with the clockwise loops inside it as holes; a clockwise loop inside none bounds a face of
/// its own (its edge reversed, so the face is the region it encloses). Each loop is one closed
/// edge: a degree-1 curve through its points and the same in (u, v) on the support, with the
/// edge's tolerance the largest gap between the two. Throws GeometryError for a loop that is
/// not closed, has fewer than 4 vertices or differing (u, v) and point counts.
TopoDS_Compound loopFaces(const opencascade::handle<Geom_BSplineSurface>& support,
                          const std::vector<SurfaceLoop>& loops);

}  // namespace geom::exchange
