#pragma once
// The knot lines of a surface, and those along which it may fold.

#include "geom/Surface.h"
#include "geom/curvemap/SurfaceDomain.h"

#include <glm/vec2.hpp>

#include <vector>

namespace geom::curvemap {

// Creases are knots of multiplicity at least the degree (every interior knot at degree 1) and the
// seam of a closed direction: a mapped curve may kink only where its (u, w) path crosses one, and
// the image of a straight (u, w) segment changes its parametrisation only across a knot line.

/// A surface's interior knot lines in (u, w), and which of them are creases.
class KnotLines {
public:
    KnotLines(const Surface& surface, const SurfaceDomain& domain);

    /// Whether the straight (u, w) segment from a to b (b already unwrapped near a) crosses a
    /// crease strictly between its ends.
    bool crossesCrease(const glm::dvec2& a, const glm::dvec2& b) const;
    /// The same for any knot line (creases included).
    bool crossesKnot(const glm::dvec2& a, const glm::dvec2& b) const;

private:
    struct Lines {
        std::vector<double> at;  ///< sorted parameters in the domain
        bool closed = false;
        double start = 0.0, period = 0.0;
        /// The interior knots occurring at least `least` times, and the seam where closed.
        static Lines of(const std::vector<double>& knots, int degree, std::size_t count, std::size_t least,
                        bool closed, double start, double period);
        bool crossed(double a, double b) const;
    };
    Lines creaseU_, creaseW_, knotU_, knotW_;
};

}  // namespace geom::curvemap
