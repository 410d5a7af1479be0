#include "geom/BoundingBox.h"

#include <glm/common.hpp>
#include <glm/geometric.hpp>

#include <cmath>

namespace geom {

void BoundingBox::add(const glm::dvec3& p) {
    lo = glm::min(lo, p);
    hi = glm::max(hi, p);
}

void BoundingBox::add(const BoundingBox& b) {
    lo = glm::min(lo, b.lo);
    hi = glm::max(hi, b.hi);
}

bool BoundingBox::contains(const glm::dvec3& p, double tolerance) const {
    return p.x >= lo.x - tolerance && p.y >= lo.y - tolerance && p.z >= lo.z - tolerance &&
           p.x <= hi.x + tolerance && p.y <= hi.y + tolerance && p.z <= hi.z + tolerance;
}

double BoundingBox::diagonal() const {
    return empty() ? 0.0 : glm::length(hi - lo);
}

double BoundingBox::distance(const glm::dvec3& p) const {
    const glm::dvec3 d = glm::max(glm::max(lo - p, p - hi), glm::dvec3(0.0));
    return glm::length(d);
}

bool BoundingBox::hitByLine(const glm::dvec3& origin, const glm::dvec3& inv, double margin) const {
    double tmin = -std::numeric_limits<double>::infinity();
    double tmax = std::numeric_limits<double>::infinity();
    for (int a = 0; a < 3; ++a) {
        const double l = lo[a] - margin, h = hi[a] + margin;
        if (std::isinf(inv[a])) {
            // The line is parallel to this slab: it must start inside it.
            if (origin[a] < l || origin[a] > h) return false;
            continue;
        }
        double t0 = (l - origin[a]) * inv[a];
        double t1 = (h - origin[a]) * inv[a];
        if (t0 > t1) std::swap(t0, t1);
        tmin = std::max(tmin, t0);
        tmax = std::min(tmax, t1);
        if (tmin > tmax) return false;
    }
    return true;
}

BoundingBox boundingBox(std::span<const glm::dvec3> points) {
    BoundingBox box;
    for (const glm::dvec3& p : points) box.add(p);
    return box;
}

BoundingBox boundingBox(const Curve& curve) {
    validate(curve, "boundingBox");
    return boundingBox(std::span<const glm::dvec3>(curve.points));
}

BoundingBox boundingBox(const Surface& surface) {
    validate(surface, "boundingBox");
    return boundingBox(std::span<const glm::dvec3>(surface.points));
}

}  // namespace geom
