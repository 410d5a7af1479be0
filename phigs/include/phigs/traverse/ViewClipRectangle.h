#pragma once

#include "phigs/traverse/DrawList.h"

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

namespace phigs {

/// The NPC rectangle in which a view keeps its primitives in x and y (a marker by its position):
/// the workstation window, within the view's clip limits when the view clips in x and y. The
/// renderer's scissor, the pick and the vector hardcopy all clip to it.
struct ViewClipRectangle {
    ViewClipRectangle(const DrawView& view, const glm::dvec3& windowMin, const glm::dvec3& windowMax);

    glm::dvec2 min{0.0}, max{1.0};
    /// Whether the point lies in it, edges included.
    bool contains(glm::dvec2 npc) const;
};

}  // namespace phigs
