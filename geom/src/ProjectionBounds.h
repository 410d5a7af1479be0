#pragma once

#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include <cstddef>
#include <vector>

// Private to geom: the bounds with which the closest-point searches (SurfaceProjector,
// CurveProjector) discard or settle a Bézier piece without running Newton on it. A piece is its
// homogeneous net h, (pu x qv), u slow, positive weights, in its own parameters [0, 1]^2, and the
// net's points c = h.xyz / h.w; a curve piece is one row (qv = 1).
namespace geom::detail {

/// Splits the Bézier polygon in[0], in[stride], ... of n points at 1/2 into left and right
/// (same stride), by de Casteljau's midpoint rule; work is scratch.
void halveLine(const glm::dvec4* in, std::size_t stride, std::size_t n, glm::dvec4* left, glm::dvec4* right,
               std::vector<glm::dvec4>& work);

/// The points of a homogeneous net.
void project(const glm::dvec4* net, std::size_t count, std::vector<glm::dvec3>& points);

/// The index of the net point nearest to p: its Bézier abscissa starts Newton on the piece.
std::size_t nearestPoint(const std::vector<glm::dvec3>& c, const glm::dvec3& p);

/// A lower bound on the distance from p to the piece: the box of its points, and their extent
/// along the unit direction `toward` (the best point so far; null for none). Both hold the piece
/// by the convex hull property.
double lowerBound(const std::vector<glm::dvec3>& c, const glm::dvec3& p, const glm::dvec3* toward);

/// True when no point of the piece is nearer to p than `distance`: every Bernstein coefficient
/// of |X - p w|^2 - distance^2 w^2 (X = w S, the homogeneous point; a polynomial of twice the
/// degrees) is non-negative. Unlike the hull bounds it sees the weights, so it stays tight on
/// rational nets whose small weights leave control points far from the surface.
bool provablyFarther(const glm::dvec4* h, std::size_t pu, std::size_t qv, const glm::dvec3& p,
                     double distance);

/// The sign of (S - p) . S_u over the piece (alongV: of (S - p) . S_v), +1 or -1 where the net
/// proves it, else 0. Where it is proved, the piece's nearest point lies on the edge towards
/// which the distance falls.
int gradientSign(const glm::dvec4* h, const std::vector<glm::dvec3>& c, std::size_t pu, std::size_t qv,
                 bool rational, bool alongV, const glm::dvec3& p);

/// True when |S - p|^2 is provably strictly convex over the piece (for a curve piece, qv = 1:
/// along u). Then a local minimum of the distance found inside the piece is the piece's minimum.
bool provablyConvex(const glm::dvec4* h, const std::vector<glm::dvec3>& c, std::size_t pu, std::size_t qv,
                    const glm::dvec3& p);

/// How far the piece can stray from its edge curve at v = 0 (alongV; at u = 0 otherwise): the
/// largest distance of a net point from the first of its line across, plus twice the net's extent
/// times the largest relative departure of the weights from a product a_i b_j. S is then a
/// weighted mean of its line's points with weights that depend on the other parameter alone, so
/// 0 means the piece does not change along v (a surface collapsed to a curve there).
double departureFromEdge(const glm::dvec4* h, const std::vector<glm::dvec3>& c, std::size_t pu,
                         std::size_t qv, bool alongV);

}  // namespace geom::detail
