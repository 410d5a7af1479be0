#pragma once

#include "phigs/traverse/DrawList.h"

#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include <vector>

namespace phigs::hardcopy {

/// One vertex of a facet to be lit: world position, world normal (zero: none), base colour.
struct FacetVertex {
    glm::dvec3 position{0.0};
    glm::dvec3 normal{0.0};
    glm::vec3 colour{1.0f};
};

/// The colours of one draw item as the raster path makes them (shaders/scene.glsl and prim.frag):
/// PHIGS PLUS reflectance under the item's light set, flat / Gouraud / Phong chosen as the
/// renderer chooses, distinct back faces, depth cueing and highlighting; evaluated once per facet
/// (at its centroid, Gouraud as the mean of its vertices) rather than per fragment.
class ItemColouring {
public:
    /// How a PATTERN facet's cells are lit: the reflectance equations are affine in the base
    /// colour, so a cell of colour c shows c * gain + offset (then depth cued and highlighted).
    struct CellLighting {
        glm::vec3 gain{1.0f};
        glm::vec3 offset{0.0f};
    };

    /// `viewer`: viewerOf the item's view (a point for a perspective view, else a direction).
    ItemColouring(const DrawList& list, const DrawItem& item, const glm::dvec4& viewer,
                  const glm::vec4& highlight);

    /// The colour of a facet seen from its front or back. `vertexNormals`: the vertices carry
    /// normals that drive the shading method (else the facet is flat shaded); `facetNormals`:
    /// those normals are the facet's given normal, which flat shading then lights with.
    glm::vec3 facet(const InteriorStyleSet& interior, const std::vector<FacetVertex>& vertices,
                    bool vertexNormals, bool back, bool facetNormals = false) const;
    /// The lighting of a PATTERN facet's cells: facet() with the pattern cell as the base colour.
    CellLighting patternLighting(const InteriorStyleSet& interior, std::vector<FacetVertex> vertices,
                                 bool vertexNormals, bool back, bool facetNormals = false) const;
    /// Depth cueing at NPC z (mixed in the rendering colour model `model`: interiors give
    /// theirs), then highlighting, clamped: what every colour goes through last.
    glm::vec3 finish(glm::vec3 colour, double npcZ, ColourModel model = ColourModel::Rgb) const;
    /// Whether the item is depth cued (its lines then change colour along their length).
    bool cued() const { return cue_ != nullptr; }

private:
    glm::vec3 lit(const InteriorStyleSet& interior, bool back, glm::vec3 base, const glm::dvec3& world,
                  const glm::dvec3& normal) const;

    const std::vector<Light>* lights_ = nullptr;
    /// The unit direction from `world` toward the viewer (V).
    glm::dvec3 towardViewer(const glm::dvec3& world) const;

    const DepthCue* cue_ = nullptr;
    glm::dvec4 viewer_{0, 0, 1, 0};
    glm::vec4 highlight_{0.0f};
};

}  // namespace phigs::hardcopy
