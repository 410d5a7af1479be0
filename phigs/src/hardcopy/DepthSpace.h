#pragma once

// Private to phigs_hardcopy: how facet ordering compares facets in depth.

#include "phigs/hardcopy/ProjectedScene.h"
#include "phigs/render/ItemGeometry.h"

#include <glm/common.hpp>
#include <glm/geometric.hpp>
#include <glm/vec4.hpp>

#include <algorithm>
#include <vector>

namespace phigs::hardcopy {

/// Which side of a plane a facet lies on (On: every point within the tolerance of it).
enum class Side { On, Front, Back, Both };

/// The page's x and y with depth scaled to points, where facets' planes are compared, and the
/// tolerance a point counts as on a plane within: 1e-9 of the facets' extent.
class DepthSpace {
public:
    DepthSpace(const std::vector<ProjectedFacet>& facets, double pointsPerDepth)
        : depthScale_(pointsPerDepth) {
        glm::dvec3 lo(1e300), hi(-1e300);
        for (const ProjectedFacet& f : facets)
            for (const auto& c : f.contours)
                for (const PagePoint& p : c) lo = glm::min(lo, scaled(p)), hi = glm::max(hi, scaled(p));
        epsilon_ = 1e-9 * std::max(1.0, glm::length(hi - lo));
    }

    double epsilon() const { return epsilon_; }
    glm::dvec3 scaled(const PagePoint& p) const { return {p.x, p.y, p.z * depthScale_}; }

    /// The facet's plane through its centre, its normal `render::contoursNormal`'s (unit; zero
    /// for no area): a bow-tie's lobes, whose Newell sum cancels, still have a plane to order by.
    glm::dvec4 planeOf(const ProjectedFacet& f) const {
        // The normal on the page (x, y, depth) taken to scaled depth: normals map by the inverse
        // transpose of the scaling.
        glm::dvec3 normal = render::contoursNormal(f.contours), centre(0.0);
        normal.z /= depthScale_;
        std::size_t count = 0;
        for (const auto& c : f.contours)
            for (const PagePoint& p : c) centre += scaled(p), ++count;
        const double length = glm::length(normal);
        if (!(length > 0.0) || count == 0) return glm::dvec4(0.0);
        normal /= length;
        centre /= double(count);
        return {normal, -glm::dot(normal, centre)};
    }

    double distance(const glm::dvec4& plane, const PagePoint& p) const {
        return glm::dot(glm::dvec3(plane), scaled(p)) + plane.w;
    }

    Side classify(const glm::dvec4& plane, const ProjectedFacet& f) const {
        bool front = false, back = false;
        for (const auto& c : f.contours)
            for (const PagePoint& p : c) {
                const double d = distance(plane, p);
                front = front || d > epsilon_;
                back = back || d < -epsilon_;
                if (front && back) return Side::Both;
            }
        return front ? Side::Front : back ? Side::Back : Side::On;
    }

private:
    double depthScale_;
    double epsilon_ = 0.0;
};

}  // namespace phigs::hardcopy
