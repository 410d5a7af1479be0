#include "phigs/view/RealizedLighting.h"

#include <algorithm>
#include <cmath>
#include <utility>

#include <glm/common.hpp>
#include <glm/ext/scalar_constants.hpp>
#include <glm/geometric.hpp>

namespace phigs {

Light realized(const Light& l) {
    Light r = l;
    r.colour = glm::clamp(l.colour, glm::vec3(0.0f), glm::vec3(1.0f));
    const double length = glm::length(l.direction);
    r.direction = length > 0.0 && std::isfinite(length) ? l.direction / length : glm::dvec3(0, 0, -1);
    r.attenuation = glm::max(l.attenuation, glm::vec2(0.0f));
    r.concentration = std::clamp(l.concentration, 0.0f, 128.0f);
    r.spreadAngle = std::clamp(l.spreadAngle, 0.0f, glm::pi<float>());
    return r;
}

DepthCue realized(const DepthCue& d) {
    DepthCue r = d;
    r.frontPlane = std::clamp(d.frontPlane, 0.0, 1.0), r.backPlane = std::clamp(d.backPlane, 0.0, 1.0);
    r.frontScale = std::clamp(d.frontScale, 0.0f, 1.0f), r.backScale = std::clamp(d.backScale, 0.0f, 1.0f);
    if (r.frontPlane < r.backPlane)
        std::swap(r.frontPlane, r.backPlane), std::swap(r.frontScale, r.backScale);
    r.colour = glm::clamp(d.colour, glm::vec3(0.0f), glm::vec3(1.0f));
    return r;
}

}  // namespace phigs
