#pragma once

#include "geom/BoundingBox.h"
#include "geom/Curve.h"
#include "geom/Inversion.h"

#include <glm/vec4.hpp>

#include <vector>

namespace geom {

/// Point inversion against one curve, many times: its Bézier pieces and their boxes are built
/// once; a query tries pieces nearest first and stops when no box can hold a nearer point.
class CurveProjector {
public:
    explicit CurveProjector(const Curve& curve);

    /// Global closest point.
    CurvePoint closestPoint(const glm::dvec3& p) const;
    /// Newton from the guess u, held in the domain.
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
    Point evaluate(double u) const;

    int degree_ = 0;
    std::vector<Piece> pieces_;
};

}  // namespace geom
