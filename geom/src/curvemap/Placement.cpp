#include "geom/curvemap/Placement.h"
#include "../NumberText.h"

#include "geom/Evaluate.h"
#include "geom/GeometryError.h"

#include <glm/geometric.hpp>

#include <cmath>
#include <string>

namespace geom::curvemap {

glm::dvec3 PlacementFrame::toModel(const glm::dvec3& p) const {
    return origin + p.x * x + p.y * y + p.z * z;
}

glm::dvec3 PlacementFrame::toCurve(const glm::dvec3& p) const {
    const glm::dvec3 d = p - origin;
    return {glm::dot(d, x), glm::dot(d, y), glm::dot(d, z)};
}

PlacementFrame placementFrame(const Surface& surface, const Placement& placement) {
    validate(surface, "placementFrame");
    const double u = placement.reference.x, w = placement.reference.y;
    const double slack = 1e-12 * (1.0 + std::abs(surface.domainEndU() - surface.domainStartU()) +
                                  std::abs(surface.domainEndV() - surface.domainStartV()));
    if (!(u >= surface.domainStartU() - slack && u <= surface.domainEndU() + slack &&
          w >= surface.domainStartV() - slack && w <= surface.domainEndV() + slack))
        throw GeometryError("placementFrame: reference point (" + detail::numberText(u) + ", " +
                            detail::numberText(w) + ") lies outside the surface domain");
    const SurfaceDerivatives d = derivatives(surface, u, w, 1);
    glm::dvec3 n = normalFromDerivatives(surface, u, w, d.at(1, 0), d.at(0, 1));
    if (glm::length(n) < 0.5)
        throw GeometryError("placementFrame: the surface has no tangent plane at the reference point");
    PlacementFrame f;
    f.surfacePoint = d.at(0, 0);
    if (placement.flipped) n = -n;
    f.z = n;
    // The u tangent, made orthogonal to the normal (it already is except at degenerate points).
    glm::dvec3 tu = d.at(1, 0) - glm::dot(d.at(1, 0), n) * n;
    if (glm::length(tu) < 1e-300) tu = glm::cross(d.at(0, 1), n);
    if (glm::length(tu) < 1e-300)
        throw GeometryError("placementFrame: no tangent direction at the reference point");
    tu = glm::normalize(tu);
    f.tangentU = glm::length(d.at(1, 0)) > 0 ? glm::normalize(d.at(1, 0)) : tu;
    f.tangentW = glm::length(d.at(0, 1)) > 0 ? glm::normalize(d.at(0, 1)) : glm::cross(n, tu);
    // Quarter turns counter-clockwise about z: x -> y -> -x -> -y.
    const int turns = ((placement.quarterTurns % 4) + 4) % 4;
    glm::dvec3 x = tu;
    for (int i = 0; i < turns; ++i) x = glm::cross(f.z, x);
    f.x = x;
    f.y = glm::cross(f.z, f.x);
    f.origin = f.surfacePoint + placement.offset * f.z;
    f.transform = glm::dmat4(glm::dvec4(f.x, 0.0), glm::dvec4(f.y, 0.0), glm::dvec4(f.z, 0.0),
                             glm::dvec4(f.origin, 1.0));
    return f;
}

}  // namespace geom::curvemap
