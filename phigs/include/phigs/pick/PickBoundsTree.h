#pragma once

#include "phigs/traverse/DrawList.h"

#include <glm/mat4x4.hpp>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include <cstddef>
#include <cstdint>
#include <memory>
#include <unordered_map>
#include <vector>

namespace phigs {

/// One draw item as the pick sees it: its box in NPC and its transform to NPC.
struct PickItemBounds {
    glm::dvec3 lo{0.0}, hi{0.0};                 ///< NPC box; infinite for an item tested at every pick
    glm::dmat4 toNpc{1.0};                       ///< view mapping * view orientation * modelling transform
    glm::dmat4 fromNpc{1.0};                     ///< its inverse
    glm::dvec3 surfaceLo{0.0}, surfaceHi{-1.0};  ///< an exact surface's control-net box (modelling)
    bool tested = false;                         ///< pickable, in a view of the list: a pick tests it at all
    bool bounded = false;                        ///< lo, hi are finite: the tree holds it
};

/// A bounding-volume hierarchy over the pickable items of a draw list by their NPC boxes (the
/// projected box of the control net, mesh or points), so a pick tests exactly only the items
/// whose box holds the aperture. Updated per draw list generation: unchanged items keep their
/// boxes, a few changed ones are refitted into the tree, many changes rebuild it.
class PickBoundsTree {
public:
    /// What update() did, for tests and benchmarks.
    struct Stats {
        std::size_t updates = 0;   ///< update() calls that found the list changed
        std::size_t rebuilds = 0;  ///< whole tree built anew
        std::size_t refits = 0;    ///< changed boxes refitted into the same tree
        std::size_t boxes = 0;     ///< item boxes computed, over all updates
    };

    PickBoundsTree();
    ~PickBoundsTree();
    PickBoundsTree(const PickBoundsTree&) = delete;
    PickBoundsTree& operator=(const PickBoundsTree&) = delete;

    /// Brings the tree up to date with `list`. The same list at the same generation costs
    /// nothing; generation 0 means unversioned (a list built by hand) and is checked item by item.
    void update(const DrawList& list);
    /// Appends the items whose box meets the square of half-size `half` round `npc`, and every
    /// tested item without a finite box (markers, text, items seen from behind the eye).
    void query(glm::dvec2 npc, double half, std::vector<std::size_t>& out) const;
    const PickItemBounds& item(std::size_t index) const { return items_[index]; }
    std::size_t size() const { return items_.size(); }
    const Stats& stats() const { return stats_; }
    /// Forgets everything (the next update rebuilds).
    void clear();

private:
    struct Node {
        glm::dvec2 lo{0.0}, hi{0.0};  ///< x, y box of the node's items in NPC
        std::uint32_t first = 0;      ///< leaf: first slot in order_; inner: left child (right = +1)
        std::uint32_t count = 0;      ///< leaf: items in it; inner: 0
    };
    /// What an item's box depends on besides its transform and view.
    struct Key {
        const void* geometry = nullptr;  ///< the shared surface, mesh or curve; null: inline points
        const void* mesh = nullptr;
        bool pickable = false;
        int view = -1;
        glm::dmat4 transform{1.0};
        bool operator==(const Key&) const = default;
    };
    struct CachedBox {
        std::shared_ptr<const void> keep;  ///< keeps the key's address from being reused
        glm::dvec3 lo{0.0}, hi{0.0};
        std::uint64_t pass = 0;  ///< the last update whose list held the geometry
    };

    bool unchanged(const DrawList& list) const;
    Key keyOf(const DrawItem& item) const;
    PickItemBounds boundsOf(const DrawList& list, const DrawItem& item);
    /// Modelling-coordinate box of the item's geometry; false when it has none that bounds its
    /// picks (markers and text grow with the aperture or live in NPC).
    bool modellingBox(const DrawItem& item, glm::dvec3& lo, glm::dvec3& hi, glm::dvec3& surfaceLo,
                      glm::dvec3& surfaceHi);
    const CachedBox& cachedBox(const std::shared_ptr<const void>& geometry,
                               const std::vector<glm::dvec3>& pts);
    void rebuild();
    void build();
    void refit(const std::vector<std::size_t>& changed);

    std::vector<PickItemBounds> items_;
    std::vector<Key> keys_;
    std::vector<glm::dmat4> views_;  ///< mapping * orientation per view at the last update
    std::vector<Node> nodes_;
    std::vector<std::uint32_t> order_;   ///< item indices, leaves' ranges into it
    std::vector<std::uint32_t> leafOf_;  ///< per item, its leaf node (bounded items only)
    std::vector<std::uint32_t> parent_;  ///< per node, its parent (root: itself)
    std::vector<std::size_t> unbounded_;
    std::unordered_map<const void*, CachedBox> boxes_;
    const DrawList* list_ = nullptr;
    const void* data_ = nullptr;  ///< the list's segment table when the tree was made
    std::uint64_t generation_ = 0;
    std::uint64_t pass_ = 0;  ///< update() calls that looked at the items
    Stats stats_;
};

}  // namespace phigs
