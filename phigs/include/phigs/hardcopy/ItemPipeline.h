#pragma once

#include "phigs/hardcopy/HomogeneousClipper.h"
#include "phigs/hardcopy/ItemColouring.h"
#include "phigs/hardcopy/PageMapping.h"
#include "phigs/hardcopy/ProjectedScene.h"
#include "phigs/hardcopy/VectorOptions.h"
#include "phigs/render/ItemGeometry.h"
#include "phigs/render/PatternMapping.h"
#include "phigs/traverse/DrawList.h"

#include <glm/mat4x4.hpp>

#include <cstdint>
#include <optional>
#include <span>
#include <vector>

namespace phigs::hardcopy {

/// How a facet is to be painted (its colour comes from ItemColouring).
struct FacetPaint {
    glm::vec3 colour{1.0f};
    float opacity = 1.0f;
    bool hatch = false;
    int hatchIndex = 1;
    bool pattern = false;      ///< a PATTERN interior: the item's pattern, when it has one, not `colour`
    bool backPattern = false;  ///< the pattern is the distinguished back style's, not the front's
    ItemColouring::CellLighting cells;     ///< a PATTERN interior: how its cells are lit
    ColourModel model = ColourModel::Rgb;  ///< the rendering colour model depth cueing mixes in
    bool coverOnly = false;
    bool seam = false;
    /// The hatch or pattern of the side a facet shows (facing < 0: its back; the back style when
    /// face distinguishing is on).
    void styleFor(const InteriorStyleSet& in, int facing);
    /// The colour of a facet facing that way (ItemColouring::facet), its style (styleFor), and
    /// for a PATTERN side the lighting of its cells.
    void paintFor(const ItemColouring& colouring, const InteriorStyleSet& in,
                  const std::vector<FacetVertex>& vertices, bool vertexNormals, int facing,
                  bool facetNormals = false);
    /// Whether a facet facing that way is not filled: its side culled, or of a HOLLOW or EMPTY style.
    static bool unfilled(const InteriorStyleSet& in, int facing);
};

/// The road from one draw item's world coordinates to the page: model clipping volume (world),
/// view orientation and mapping, the view's volume (homogeneous NPC), the division, the page
/// mapping; lines carry the distance along them in nominal pixels for their dashes, measured on
/// the page before clipping as the raster measures it on screen. Appends to a ProjectedScene.
class ItemPipeline {
public:
    ItemPipeline(const DrawList& list, const DrawItem& item, const PageMapping& mapping,
                 const VectorOptions& options, ProjectedScene& out);

    /// A polyline (closed: back to its first point) in world coordinates; with `colours` (one per
    /// point) segment k takes colours[k], or with `interpolated` goes from colours[k] to
    /// colours[k + 1] (in pieces at most 1/255 apart); the dashes run on along the whole line.
    void line(const std::vector<glm::dvec3>& world, bool closed, glm::vec3 colour, LineType type, float width,
              std::span<const glm::vec3> colours = {}, bool interpolated = false);
    /// A polyline given as homogeneous NPC points (annotation text), past the model clipping.
    void npcLine(const std::vector<ClipVertex>& npc, glm::vec3 colour, LineType type, float width);
    /// A planar region (even-odd contours) in world coordinates.
    void facet(const std::vector<std::vector<glm::dvec3>>& world, const FacetPaint& paint);
    /// A marker at a world point (kept whole when its position is inside, as the raster does).
    void marker(const glm::dvec3& world, const MarkerStyle& style);
    /// +1 when the world triangle a, b, c is counter-clockwise on screen (its front), -1 when
    /// clockwise, 0 when it cannot tell (edge on, or reaching behind the eye).
    int facing(const glm::dvec3& a, const glm::dvec3& b, const glm::dvec3& c) const;
    /// The side of a world plane (positive on its front) the item's view shows: +1, -1, 0 edge on.
    int sideShown(const glm::dvec4& plane) const { return render::sideShown(plane, worldToNpc_); }
    /// facing() of a triangle given by its homogeneous NPC points.
    static int facingNpc(const glm::dvec4& a, const glm::dvec4& b, const glm::dvec4& c);
    /// Homogeneous NPC of a world point.
    glm::dvec4 toNpc(const glm::dvec3& world) const { return worldToNpc_ * glm::dvec4(world, 1.0); }
    /// The distance on the page between two NPC points in nominal pixels (what dashes measure).
    double npcPixels(const glm::dvec3& a, const glm::dvec3& b) const;
    /// One bit for each half space of the view's volume that a homogeneous NPC point lies outside:
    /// a polygon or line whose points share a bit lies outside the view whole, and clipping it
    /// leaves nothing.
    std::uint32_t outsideView(const glm::dvec4& npc) const;
    /// Whether a world point survives the model clipping volume.
    bool modelClipKeeps(const glm::dvec3& world) const;
    /// A world point's NPC (homogeneous, w > 0) when it survives every clip (model volume, view
    /// limits, workstation window): a marker's position or an annotation's reference point, which
    /// keep or drop it whole; nullopt when clipped.
    std::optional<glm::dvec4> keptPoint(const glm::dvec3& world) const;

    const DrawItem& item() const { return item_; }
    const PageMapping& mapping() const { return mapping_; }
    const VectorOptions& options() const { return options_; }
    const ItemColouring& colouring() const { return colouring_; }
    /// World to homogeneous page points (x / w, y / w in points), for curve refinement.
    glm::dmat4 worldToPage() const { return mapping_.npcToPage * worldToNpc_; }

private:
    /// The page pattern of a facet given by its world contours (the item's map at three of its
    /// points; exact under parallel projection, fitted at those points under perspective), its
    /// cells lit by `lighting` and depth cued in `model`.
    std::shared_ptr<const PagePattern> pagePattern(const std::vector<std::vector<glm::dvec3>>& world,
                                                   double depth, int side,
                                                   const ItemColouring::CellLighting& lighting,
                                                   ColourModel model) const;
    void emitRun(const std::vector<ClipVertex>& run, glm::vec3 colour, LineType type, float width);
    /// A view-clipped run of a line with vertex colours (see line()), as pieces of one colour.
    void colouredRun(const std::vector<ClipVertex>& run, std::span<const glm::vec3> colours,
                     bool interpolated, LineType type, float width);

    const DrawList& list_;
    const DrawItem& item_;
    const PageMapping& mapping_;
    const VectorOptions& options_;
    ProjectedScene& out_;
    glm::dmat4 worldToNpc_{1.0};
    std::vector<HalfSpace> view_, model_;
    ItemColouring colouring_;
    const DrawPattern* pattern_[2] = {};               ///< a PATTERN side's pattern (front, back), or null
    std::optional<render::PatternMap> patternMap_[2];  ///< and its world map
    std::vector<ClipVertex> polygon_;                  ///< facet()'s contour being clipped, kept
};

}  // namespace phigs::hardcopy
