#pragma once

#include "phigs/hardcopy/ItemPipeline.h"

#include <cstdint>
#include <vector>

namespace phigs::hardcopy {

/// Puts a mesh on the page: shaded, its triangles become lit facets and its iso-lines and edges
/// lines, as the raster draws them; as a hidden-line drawing, its triangles only hide (and cover)
/// and it is drawn by its iso-lines, patch boundaries and silhouette in the interior colour.
class MeshProjector {
public:
    MeshProjector(ItemPipeline& pipeline, const DrawMesh& mesh);

    void project();

private:
    void facets(bool coverOnly);
    /// The outline of each HOLLOW side: the facet edges of the triangles showing it, in its colour.
    void hollowEdges();
    void edgeLines(const std::vector<std::vector<std::uint32_t>>& chains, glm::vec3 colour, LineType type,
                   float width);
    void isoLines();
    void outline();

    ItemPipeline& pipeline_;
    const DrawMesh& mesh_;
    const MeshData& data_;
    std::vector<glm::dvec3> world_;
    std::vector<int> facing_;  ///< per triangle, ItemPipeline::facing
    /// Per vertex, ItemPipeline::outsideView: a triangle whose corners share a bit shows nothing.
    std::vector<std::uint32_t> outside_;
    bool allOutside_ = false;  ///< every vertex outside one half space: nothing of the mesh shows
};

}  // namespace phigs::hardcopy
