#pragma once

#include <glm/vec4.hpp>

namespace phigs::hardcopy {

/// How surfaces (meshes) appear in a vector hardcopy.
enum class SurfaceDrawing {
    Shaded,     ///< facets lit as the raster path lights them, painted back to front
    HiddenLine  ///< iso-lines, patch boundaries and silhouettes with their hidden parts removed
};

/// Drawing choices of a vector hardcopy that the draw list does not carry.
struct VectorOptions {
    SurfaceDrawing surfaces = SurfaceDrawing::Shaded;
    /// NURBS curves are re-tessellated from their exact form until every chord lies within this
    /// many points of the curve on the page.
    double curveTolerance = 0.05;
    glm::vec4 highlight{1.0f, 1.0f, 0.0f, 0.6f};  ///< colour and mix amount (vk::Renderer's default)
};

}  // namespace phigs::hardcopy
