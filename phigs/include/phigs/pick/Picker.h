#pragma once

#include "phigs/input/InputTypes.h"
#include "phigs/pick/PickBoundsTree.h"
#include "phigs/traverse/DrawList.h"
#include "phigs/traverse/WorkstationMapping.h"

#include <glm/vec2.hpp>

#include <cstddef>
#include <cstdint>
#include <memory>
#include <optional>
#include <unordered_map>
#include <vector>

namespace geom {
class SurfaceIntersector;
}

namespace phigs {

/// How a pick is taken: the square aperture's half-size in NPC, the path order and depth.
struct PickOptions {
    double aperture = 0.01;
    PathOrder order = PathOrder::TopFirst;
    int depth = 0;  ///< levels kept; 0: the whole path
};

/// One primitive under the aperture.
struct PickHit {
    std::size_t item = 0;                      ///< index into DrawList::items
    double depth = 0.0;                        ///< NPC z of the hit (1 front, 0 back): larger is nearer
    std::optional<SurfacePickDetail> surface;  ///< exact hit on a NURBS surface (modelling coords)
};

/// The pick traversal over a draw list: tests the pickable items against the aperture in NPC,
/// intersects NURBS surfaces exactly, orders the hits nearest first and builds the pick path.
/// Only items whose NPC box (PickBoundsTree, kept per draw list generation) meets the aperture
/// are tested, nearest boxes first; the answers are those of testing every item. Keeps one
/// intersector per surface, so repeated picks on the same list are cheap.
class Picker {
public:
    Picker();
    ~Picker();
    Picker(const Picker&) = delete;
    Picker& operator=(const Picker&) = delete;

    /// Every hit at `npc` (x, y in NPC), nearest first; ties go to the item drawn later. Meshes
    /// are hit by the side each triangle shows (edge on: the front): a filled side over its area, a
    /// HOLLOW one on its facet edges, an EMPTY or culled one not at all. NURBS surfaces are hit by
    /// the exact line through `npc`, their EMPTY sides too (PHIGS keeps an EMPTY interior
    /// detectable: a wireframe picks points inside patches), with (u, v); outlines and iso-lines
    /// by the tessellation. Tessellations count only when nothing is hit at all exactly (the
    /// aperture catching a silhouette), without surface detail. A surface whose modelling
    /// transform flattens it (singular, or too ill-conditioned to carry the line back) is hit by
    /// its tessellation, as a mesh. A NaN or infinite `npc`, or an aperture that is NaN or
    /// negative, hits nothing.
    /// Marker sizes (in pixels) are measured on a surface whose pixels are device coordinates.
    std::vector<PickHit> hits(const DrawList& list, glm::dvec2 npc, double aperture) const;
    /// The same on the surface `mapping` describes.
    std::vector<PickHit> hits(const DrawList& list, const WorkstationMapping& mapping, glm::dvec2 npc,
                              double aperture) const;
    /// PICK measure of the nearest hit: status OK with its path, or NONE when nothing is hit.
    PickMeasure pick(const DrawList& list, glm::dvec2 npc, const PickOptions& options) const;
    /// The nearest hit itself, for echo.
    std::optional<PickHit> nearest(const DrawList& list, glm::dvec2 npc, double aperture) const;
    std::optional<PickHit> nearest(const DrawList& list, const WorkstationMapping& mapping, glm::dvec2 npc,
                                   double aperture) const;

    /// Forgets the cached surface intersectors and mesh boxes. Entries whose surface or mesh
    /// only the cache still holds are dropped anyway when a list of a new generation is picked.
    void clearCache() const;
    std::size_t cachedSurfaces() const { return intersectors_.size(); }
    /// Off: every item is tested at every pick, no tree (the reference the tree must agree with).
    void setAccelerated(bool accelerated) { accelerated_ = accelerated; }
    bool accelerated() const { return accelerated_; }
    /// The boxes and tree of the last list picked on.
    const PickBoundsTree& boundsTree() const { return tree_; }

private:
    /// How an item with an exact surface is tested: by the line through the aperture centre, or
    /// (only when nothing at all was hit that way) by its tessellation under the aperture.
    enum class SurfaceTest { Exact, Tessellation };
    std::optional<PickHit> test(const DrawList& list, std::size_t index, glm::dvec2 npc, double aperture,
                                const WorkstationMapping& mapping, SurfaceTest surfaceTest,
                                const PickItemBounds* bounds = nullptr) const;
    /// The exact line through `npc` against the surface: its nearest point whose side shown is
    /// detectable (not culled, not HOLLOW) and that trimming keeps (`mesh`'s loops, when given);
    /// `toNpc`, `fromNpc`: the item's transform to NPC and its inverse.
    std::optional<PickHit> testSurface(const DrawItem& item, const DrawView& view,
                                       const std::shared_ptr<const geom::Surface>& surface,
                                       const MeshData* mesh, const InteriorStyleSet& interior, glm::dvec2 npc,
                                       const glm::dmat4& toNpc, const glm::dmat4& fromNpc,
                                       const PickItemBounds* bounds) const;
    /// nearest() on the tree: candidates by their boxes' nearest depth, stopping once no box can
    /// hold a nearer hit.
    std::optional<PickHit> nearestAccelerated(const DrawList& list, const WorkstationMapping& mapping,
                                              glm::dvec2 npc, double aperture) const;

    struct CachedSurface {
        std::shared_ptr<const geom::Surface> surface;  ///< keeps the key alive
        std::unique_ptr<geom::SurfaceIntersector> intersector;
    };
    mutable std::unordered_map<const geom::Surface*, CachedSurface> intersectors_;
    struct CachedBounds {
        std::shared_ptr<const MeshData> mesh;  ///< keeps the key alive
        glm::dvec3 min{0.0}, max{0.0};
        std::vector<std::uint8_t> facetEdges;  ///< render::meshFacetEdges, once an outline needs them
    };
    /// Modelling-coordinate box of a mesh, so meshes far from the aperture cost eight projections.
    const CachedBounds& boundsOf(const std::shared_ptr<const MeshData>& mesh) const;
    /// The mesh's render::meshFacetEdges, kept with its box.
    const std::vector<std::uint8_t>& facetEdgesOf(const std::shared_ptr<const MeshData>& mesh) const;
    mutable std::unordered_map<const MeshData*, CachedBounds> bounds_;
    /// Drops cached entries nobody else holds any more, once per new draw list generation.
    void prune(const DrawList& list) const;
    mutable std::uint64_t generation_ = ~std::uint64_t{0};
    bool accelerated_ = true;
    mutable PickBoundsTree tree_;
    mutable std::vector<std::size_t> candidates_;
};

/// The PHIGS pick path of a draw item's source: top first or bottom first, cut to `depth`
/// levels (0: all) counted from the start of that order.
std::vector<PickPathItem> pickPath(const DrawSource& source, PathOrder order, int depth);

/// What the echo highlights for a hit: every item drawn by the same element instance (same
/// full path), e.g. a fill area's interior and its edges, or a surface and its iso-lines; with
/// `wholeStructure` (pick prompt/echo type 2) every item of the picked structure instance.
std::vector<std::size_t> echoItems(const DrawList& list, const PickHit& hit, bool wholeStructure = false);

}  // namespace phigs
