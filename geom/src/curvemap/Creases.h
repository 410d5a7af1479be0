#pragma once
// The knot lines along which a surface may fold.

#include "geom/Surface.h"
#include "geom/curvemap/SurfaceDomain.h"

#include <glm/vec2.hpp>

#include <vector>

namespace geom::curvemap {

/// The iso-parameter lines where a surface may have a crease: interior knots of multiplicity at
/// least the degree (every interior knot at degree 1) and the seam of a closed direction. A mapped
/// curve may kink only where its (u, w) path crosses one of them.
class Creases {
public:
    Creases(const Surface& surface, const SurfaceDomain& domain);

    /// Whether the straight (u, w) segment from a to b (b already unwrapped near a) crosses a
    /// crease strictly between its ends.
    bool crossed(const glm::dvec2& a, const glm::dvec2& b) const;

private:
    struct Lines {
        std::vector<double> at;  ///< sorted parameters inside one period
        bool closed = false;
        double start = 0.0, period = 0.0;
        bool crossed(double a, double b) const;
    };
    Lines u_, w_;
};

}  // namespace geom::curvemap
