#pragma once

// The seam between traversal and its consumers (the Vulkan renderer and the pick traversal):
// a renderer-independent list of primitives with every attribute already resolved. Traversal
// produces it; nothing here knows Vulkan, GLFW or the structure store.

#include "phigs/core/Attributes.h"
#include "phigs/traverse/DrawItems.h"

#include "geom/Curve.h"
#include "geom/Surface.h"

#include <glm/mat4x4.hpp>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include <cstdint>
#include <map>
#include <memory>
#include <string>
#include <variant>
#include <vector>

namespace phigs {

/// One entry of the workstation's view table, as traversal found it.
struct DrawView {
    glm::dmat4 orientation{1.0};  ///< world -> view reference coordinates
    glm::dmat4 mapping{1.0};      ///< VRC -> NPC (the unit cube)
    glm::dvec3 clipMin{0.0};      ///< clip limits in NPC
    glm::dvec3 clipMax{1.0};
    bool clipXY = true, clipBack = true, clipFront = true;
};

/// Where the viewer of `view` is, in world coordinates, for the reflectance equations' V: the
/// centre of projection (w = 1) of a perspective view, the unit direction of projection toward the
/// viewer (w = 0) of a parallel one. Both are M^-1 (0, 0, 1, 0): NPC's +z at infinity, where
/// the mapping sends the centre of projection.
glm::dvec4 viewerOf(const DrawView& view);

/// A pattern representation with its cells' colours looked up in the colour table: `columns`
/// cells along the pattern's x vector, `rows` along its y vector, row by row from the row at
/// the reference point.
struct DrawPattern {
    int columns = 1, rows = 1;
    std::vector<glm::vec3> colours{glm::vec3(1.0f)};
    bool operator==(const DrawPattern&) const = default;
};

/// What one traversal of a workstation's posted networks produced, in drawing order.
struct DrawList {
    DrawItems items;  ///< shared segments, read like a vector
    std::vector<DrawView> views;
    std::vector<std::vector<Light>> lightSets;
    std::vector<DepthCue> depthCues;
    glm::dvec3 windowMin{0.0}, windowMax{1.0};      ///< workstation window, NPC
    glm::dvec3 viewportMin{0.0}, viewportMax{1.0};  ///< workstation viewport, device coordinates
    /// The display surface in device coordinates (the workstation type's display size); a target
    /// of any pixel size shows it isotropically, lower-left aligned (see WorkstationMapping).
    glm::dvec2 displaySize{1.0};
    /// View indices from highest to lowest view transformation input priority; empty: 0, 1, 2, ...
    std::vector<int> viewInputPriority;
    /// The workstation's pattern table, colours resolved (the workstation fills it in).
    std::map<int, DrawPattern> patterns;
    glm::vec3 background{0.0f};         ///< colour index 0
    bool hiddenSurfaceRemoval = false;  ///< HLHSR mode: depth buffer on
    std::uint64_t generation = 0;       ///< changes whenever any item changed
};

}  // namespace phigs
