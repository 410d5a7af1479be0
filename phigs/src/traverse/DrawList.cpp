#include "phigs/traverse/DrawList.h"

#include <glm/geometric.hpp>
#include <glm/matrix.hpp>

#include <cmath>

namespace phigs {

glm::dvec4 viewerOf(const DrawView& view) {
    const glm::dvec4 c = glm::inverse(view.mapping * view.orientation) * glm::dvec4(0, 0, 1, 0);
    const glm::dvec3 xyz(c);
    const double length = glm::length(xyz);
    if (std::abs(c.w) > 1e-12 * length && std::isfinite(c.w)) return glm::dvec4(xyz / c.w, 1.0);
    if (length > 0.0 && std::isfinite(length)) return glm::dvec4(xyz / length, 0.0);
    return {0, 0, 1, 0};
}

}  // namespace phigs
