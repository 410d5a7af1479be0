#pragma once

#include "phigs/store/StructureStore.h"
#include "phigs/traverse/DrawList.h"
#include "phigs/traverse/NameSetFilter.h"
#include "phigs/traverse/TessellationCache.h"
#include "phigs/view/WorkstationTables.h"

#include <cstddef>
#include <cstdint>
#include <memory>
#include <optional>
#include <set>
#include <vector>

namespace phigs {

namespace detail {
class SegmentPool;
}

/// The filters of one traversal; an absent filter passes everything (an absent pick filter
/// makes every primitive pickable, an absent invisibility filter hides nothing).
struct TraversalFilters {
    std::optional<NameSetFilter> pick;
    std::optional<NameSetFilter> highlight;
    std::optional<NameSetFilter> invisibility;
    std::set<int> initialNames;  ///< the name set at the start of every posted root
    bool operator==(const TraversalFilters&) const = default;
};

/// The draw records a picture may take, estimated as it is made (about 1 KiB per structure
/// instance drawn, 64 bytes per item): past it a traversal raises StorageOverflow (900) instead
/// of exhausting memory, as a network of a few dozen elements that executes each structure twice
/// per level draws 2^levels instances.
inline constexpr std::size_t kMaxPictureBytes = std::size_t{2} << 30;

/// Walks posted structure networks depth first and produces the draw list: attributes pushed
/// at every EXECUTE STRUCTURE and restored on return, local and global modelling transforms
/// composed (composite = global * local), ASFs choosing individual values or the workstation
/// bundles, colours resolved through the colour table, the name set run through the filters.
/// Keeps a tessellation cache across traversals.
class Traverser {
public:
    Traverser();
    ~Traverser();
    Traverser(const Traverser&) = delete;
    Traverser& operator=(const Traverser&) = delete;

    /// `roots` in drawing order (lowest display priority first).
    DrawList traverse(const StructureStore& store, const std::vector<int>& roots,
                      const WorkstationTables& tables, const TraversalFilters& filters = {});

    TessellationCache& cache() { return cache_; }
    const TessellationCache& cache() const { return cache_; }
    /// Elements visited by the last traversal.
    std::uint64_t elementsTraversed() const { return elementsTraversed_; }
    /// Elements of the last traversal not visited because an executed structure's subtree was
    /// unchanged (same inherited state, path and versions) and its draw segments were shared.
    std::uint64_t elementsReused() const { return elementsReused_; }
    /// Incremental traversal (the default) reuses unchanged executed subtrees; off: walk everything.
    void setIncremental(bool incremental);
    /// The estimated draw-record bytes past which a traversal raises StorageOverflow
    /// (kMaxPictureBytes unless set: an application short of memory may set less).
    void setMaxPictureBytes(std::size_t bytes) { maxPictureBytes_ = bytes; }
    std::size_t maxPictureBytes() const { return maxPictureBytes_; }

    struct SubtreeCache;
    struct ItemTables;
    struct RunSizes;

private:
    TessellationCache cache_;
    std::unique_ptr<SubtreeCache> subtrees_;
    std::unique_ptr<ItemTables> itemTables_;
    std::unique_ptr<RunSizes> runSizes_;
    std::shared_ptr<detail::SegmentPool> segmentPool_;  ///< the draw segments made, kept for reuse
    std::uint64_t elementsTraversed_ = 0;
    std::uint64_t elementsReused_ = 0;
    std::size_t maxPictureBytes_ = kMaxPictureBytes;
};

}  // namespace phigs
