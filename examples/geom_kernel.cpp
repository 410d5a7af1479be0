// Example 6, the geometry kernel alone (geom: no graphics, no PHIGS): interpolate a cubic
// B-spline through data points, intersect a line with a surface, and reduce the curve to fewer
// control points within a tolerance.
#include "geom/DataReduction.h"
#include "geom/Evaluate.h"
#include "geom/GlobalInterpolation.h"
#include "geom/Intersect.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <exception>
#include <numbers>

int main() {
    try {
        // Interpolate: 41 points on a spiral, a cubic through them at chord-length parameters.
        std::vector<glm::dvec3> data;
        for (int k = 0; k <= 40; ++k) {
            const double t = k / 40.0 * 4.0 * std::numbers::pi;
            data.push_back({(1 + 0.1 * t) * std::cos(t), (1 + 0.1 * t) * std::sin(t), 0.05 * t});
        }
        const geom::Curve curve = geom::interpolateCurve(data, 3, geom::Closure::Open);
        const std::vector<double> parameters = geom::chordLengthParameters(data, geom::Closure::Open);
        double miss = 0.0;  // how far the curve passes from its data points
        for (std::size_t k = 0; k < data.size(); ++k)
            miss = std::max(miss, glm::length(geom::evaluate(curve, parameters[k]) - data[k]));
        std::printf("interpolated %zu points: %zu control points, passes within %.1e of the data\n",
                    data.size(), curve.points.size(), miss);

        // Intersect: a bicubic patch over [0, 1]^2 (height z = 4 x y (1 - x) (1 - y) roughly)
        // and the vertical line through (0.5, 0.5).
        std::vector<glm::dvec3> net;
        for (int i = 0; i < 4; ++i)
            for (int j = 0; j < 4; ++j)
                net.push_back({i / 3.0, j / 3.0, (i == 1 || i == 2) && (j == 1 || j == 2) ? 0.5 : 0.0});
        const geom::Surface patch(3, 3, {0, 0, 0, 0, 1, 1, 1, 1}, {0, 0, 0, 0, 1, 1, 1, 1}, 4, 4, net);
        for (const geom::LineSurfaceHit& hit : geom::intersectLine(patch, {0.5, 0.5, -1.0}, {0, 0, 1}))
            std::printf("line meets surface at (u, v) = (%.6f, %.6f), point (%.6f, %.6f, %.6f)\n", hit.uv.x,
                        hit.uv.y, hit.point.x, hit.point.y, hit.point.z);

        // Reduce: remove knots while the curve stays within 1e-3 of the original.
        geom::ReductionOptions options;
        options.tolerance = 1e-3;
        const geom::CurveReduction reduced = geom::reduceCurve(curve, options);
        std::printf("reduced to %zu control points, measured distance %.2e: %s the tolerance %.0e\n",
                    reduced.curve.points.size(), reduced.deviation.maxError,
                    reduced.deviation.maxError <= options.tolerance ? "within" : "OUTSIDE",
                    options.tolerance);
        return reduced.curve.points.size() < curve.points.size() && miss < 1e-9 ? 0 : 1;
    } catch (const std::exception& e) {
        std::fprintf(stderr, "geom_kernel: %s\n", e.what());
        return 1;
    }
}
