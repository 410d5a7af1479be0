#include "phigs/traverse/ViewClipRectangle.h"

#include <glm/common.hpp>

namespace phigs {

ViewClipRectangle::ViewClipRectangle(const DrawView& view, const glm::dvec3& windowMin,
                                     const glm::dvec3& windowMax)
    : min(windowMin), max(windowMax) {
    if (view.clipXY)
        min = glm::max(min, glm::dvec2(view.clipMin)), max = glm::min(max, glm::dvec2(view.clipMax));
}

bool ViewClipRectangle::contains(glm::dvec2 npc) const {
    return npc.x >= min.x && npc.x <= max.x && npc.y >= min.y && npc.y <= max.y;
}

}  // namespace phigs
