#pragma once

#include "geom/Curve.h"
#include "geom/SurfaceIntersector.h"
#include "geom/curvemap/Placement.h"
#include "geom/curvemap/SurfaceDomain.h"

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include <cstddef>
#include <optional>
#include <string>
#include <vector>

namespace geom::curvemap {

/// How finely curves are mapped.
struct MapOptions {
    /// Largest allowed deviation in model units: of the plane curve from its chords, of the
    /// mapped curve from the 3D polyline, and of the surface image of each (u, w) segment
    /// from the mapped curve. Boundary walks keep the same tolerance.
    double tolerance = 1e-3;
    int maxDepth = 20;  ///< subdivision levels (each into thirds) per initial interval
    /// Projection lines per part; refinement stops there (and says so in the part's issues),
    /// which bounds the time and memory of one part whatever the tolerance and curve size.
    std::size_t maxProjections = 200000;
    /// A part whose plane extent (the diagonal of its control points' box) exceeds this many
    /// times the surface's (its control net's box diagonal) is refused with GeometryError:
    /// nearly all of it would miss the surface, at a cost that grows with its size.
    double maxExtentRatio = 100.0;
};

/// A closed mapped loop: the same vertices in (u, w) and in model space; the first vertex is
/// repeated at the end. The region the loop bounds lies on its left in (u, w) (outer loops run
/// counter-clockwise). In a closed direction (u, w) stay continuous across the seam, so they
/// may leave the domain (the middle of a loop's range lies inside); SurfaceDomain::wrap
/// brings single points back.
struct MappedLoop {
    std::vector<glm::dvec2> uv;
    std::vector<glm::dvec3> points;         ///< S(uv), on the surface
    std::vector<double> curveParameters;    ///< plane-curve parameter; NaN on boundary walks
    std::vector<glm::dvec3> projectedFrom;  ///< the placed curve point a vertex was projected from
    std::size_t boundaryWalks = 0;          ///< pieces taken along the surface boundary
};

/// A hit of a projection line that was not kept (farther from the curve point than another).
struct OtherHit {
    double curveParameter = 0.0;
    glm::dvec2 uv{0.0};
    glm::dvec3 point{0.0};
    double lineParameter = 0.0;  ///< signed distance from the placed curve point along the normal
};

/// The mapping of one plane curve part.
struct MappedPart {
    std::vector<MappedLoop> loops;
    std::vector<OtherHit> otherHits;
    std::size_t projections = 0;  ///< projection lines intersected with the surface
    std::size_t exits = 0, entries = 0;
    std::vector<std::string> issues;  ///< what could not be mapped exactly, and why
};

/// Everything one MAP CURVE produces.
struct MapResult {
    PlacementFrame frame;
    std::vector<MappedPart> parts;
};

/// Maps plane curves onto one multi-patch surface (the ACSYNT curve-mapping thesis, Ch. 7-8, done robustly):
/// places them at a reference point, projects them along the normal onto every patch (the hit nearest the
/// curve point is kept, others reported), samples adaptively to a tolerance, finds exits and entries exactly
/// on the boundary and closes each part's loops along it for any number of crossings. Built once per surface
/// (the intersector's patch tree is reused).
class CurveMapper {
public:
    explicit CurveMapper(Surface surface, std::optional<bool> closedU = {}, std::optional<bool> closedW = {});

    /// Maps each curve (in its own plane coordinates, z = 0 the curve plane) into a part.
    /// Throws GeometryError for a bad tolerance or budget, a curve with non-finite control points,
    /// or one larger than options.maxExtentRatio times the surface, before any part is mapped.
    MapResult map(const std::vector<Curve>& curves, const Placement& placement,
                  const MapOptions& options = {}) const;

    const Surface& surface() const { return surface_; }
    const SurfaceDomain& domain() const { return domain_; }

private:
    Surface surface_;
    SurfaceDomain domain_;
    SurfaceIntersector intersector_;
};

}  // namespace geom::curvemap
