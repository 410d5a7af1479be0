// Reducing a closed component (fuselage, nacelle) keeps it smooth round its seam.
#include "acsynt/Model.h"
#include "geom/DataReduction.h"
#include "geom/Evaluate.h"

#include <catch2/catch.hpp>
#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <vector>

namespace test_closed_reduction {

using namespace acsynt;

/// The largest angle in degrees between the tangents round the section at w's two ends, over the
/// control rows along u (the surface's seam round its sections).
double seamAngleDegrees(const geom::Surface& s) {
    double worst = 0.0;
    for (int k = 0; k <= 64; ++k) {
        const double u = s.domainStartU() + (s.domainEndU() - s.domainStartU()) * double(k) / 64.0;
        const glm::dvec3 a = geom::derivatives(s, u, s.domainStartV(), 1).at(0, 1),
                         b = geom::derivatives(s, u, s.domainEndV(), 1).at(0, 1);
        if (glm::length(a) == 0.0 || glm::length(b) == 0.0) continue;  // a point section (the nose)
        worst = std::max(worst, std::atan2(glm::length(glm::cross(a, b)), glm::dot(a, b)) * 180.0 / M_PI);
    }
    return worst;
}

TEST_CASE("reducing a shipped model's closed components keeps their seams smooth", "[acsynt][reduction]") {
    // Reduced in W, the seam was clamped as two ends: the tangent round the section broke by
    // 1-66 degrees along the fuselage's bottom line.
    std::size_t closed = 0;
    for (const char* file : {ACSYNT_DATA_DIR "/transport.acm", ACSYNT_DATA_DIR "/fighter.acm"}) {
        const Model m = loadModel(file);
        for (const Component& c : m.components) {
            if (!c.closedW) continue;
            ++closed;
            REQUIRE(seamAngleDegrees(c.surface) <= 1e-6);
            for (const double tolerance : {0.01, 0.05}) {
                for (const auto direction : {geom::ReductionDirection::V, geom::ReductionDirection::Both}) {
                    geom::ReductionOptions o;
                    o.tolerance = tolerance;
                    const geom::SurfaceReduction r = geom::reduceSurface(c.surface, direction, o);
                    INFO(file << ": " << c.name << " at " << tolerance << ", direction " << int(direction)
                              << ": W " << c.surface.countV << " -> " << r.surface.countV);
                    CHECK(r.removedV > 0);
                    CHECK(r.deviation.maxError <= tolerance);
                    CHECK(seamAngleDegrees(r.surface) <= 1e-6);
                }
            }
        }
    }
    CHECK(closed >= 3);
}

}  // namespace test_closed_reduction
