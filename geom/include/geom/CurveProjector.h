#pragma once

#include "geom/BoundingBox.h"
#include "geom/Curve.h"
#include "geom/Inversion.h"

#include <glm/vec4.hpp>

#include <vector>

namespace geom {

/// Point inversion against one curve, many times: its Bézier pieces and their boxes are built
/// once; a query searches each piece on its own (corners lie on piece ends), nearest first, and
/// subdivides a piece wherever its polygon's bound could still hold a nearer point.
class CurveProjector {
public:
    explicit CurveProjector(const Curve& curve);

    /// Global closest point.
    CurvePoint closestPoint(const glm::dvec3& p) const;
    /// Local closest point: Newton from the guess u inside its piece, going on into the next
    /// piece while that lowers the distance.
    CurvePoint closestPointFrom(const glm::dvec3& p, double guess) const;

private:
    struct Piece {
        std::vector<glm::dvec4> net;
        BoundingBox box;
        double start = 0.0, end = 0.0;
    };
    struct Point {
        glm::dvec3 c, d1, d2;
    };
    Point evaluate(std::size_t piece, double u) const;
    /// Newton from u on piece `index`, held inside [a, b] (a part of the piece).
    CurvePoint polishIn(std::size_t index, const glm::dvec3& p, double u, double a, double b) const;
    /// `best` found on `piece`: at the piece's end, where the curve jumps, u just below the knot.
    CurvePoint beforeJump(CurvePoint best, std::size_t piece) const;
    /// Whether a segment at `depth` with this control polygon may be halved again.
    bool mayHalve(int depth, const std::vector<glm::dvec3>& polygon) const;
    /// Newton from u held inside piece `index` (a local minimum of the distance on it).
    CurvePoint polishOnPiece(std::size_t index, const glm::dvec3& p, double u) const;

    int degree_ = 0;
    bool rational_ = false;
    double scale_ = 0.0;  ///< the largest piece's box diagonal: the length scale for tolerances
    std::vector<Piece> pieces_;
};

}  // namespace geom
