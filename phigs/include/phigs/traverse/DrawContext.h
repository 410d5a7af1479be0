#pragma once

#include "phigs/traverse/ItemArray.h"
#include "phigs/traverse/ItemRef.h"

#include <glm/mat4x4.hpp>
#include <glm/vec4.hpp>

#include <cstdint>

namespace phigs {

/// The identity transform, shared by the items that have no modelling transform of their own.
inline const glm::dmat4& identityTransform() {
    static const glm::dmat4 identity(1.0);
    return identity;
}

/// What a draw item's placement and state resolve to besides its primitive and styles: one
/// record per run of items of a segment in the same state, which the items view (a draw item
/// holds one pointer for all of it); a copy of its own for any other item.
struct DrawContext {
    /// Composite modelling transform (global * local), to world.
    ItemRef<glm::dmat4> modelTransform = ItemRef<glm::dmat4>::permanent(&identityTransform());
    std::int32_t viewIndex = 0;  ///< index into DrawList::views
    std::int32_t lightSet = -1;  ///< index into DrawList::lightSets (the active lights, maybe none); -1 unset
    std::int32_t depthCue = -1;  ///< index into DrawList::depthCues, -1: none
    bool highlighted = false;
    bool pickable = true;  ///< false when the pick filter or detectability excludes it
    /// Model clipping volume in world coordinates: keep x where dot(plane.xyz, x) + plane.w >= 0
    /// for every plane; empty when the model clipping indicator is off.
    ItemArray<glm::dvec4> modelClipPlanes;
};

}  // namespace phigs
