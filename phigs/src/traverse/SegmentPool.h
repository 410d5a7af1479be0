#pragma once

// Private: the draw segments one traverser makes, kept when the last draw list holding one lets
// go of it and handed out again with their storage (items, points, transforms) still
// allocated, so a traversal that follows another allocates and frees almost nothing. A segment
// given back keeps its items until it is taken again (destroying them then, when the new items
// are about to be written to the same memory) or until `settle` empties the spare ones.

#include "phigs/traverse/DrawItems.h"

#include <cstddef>
#include <cstdint>
#include <deque>
#include <memory>
#include <mutex>
#include <vector>

namespace phigs::detail {

/// Empty draw segments with their storage kept, shared by a traverser and the segments it made.
class SegmentPool : public std::enable_shared_from_this<SegmentPool> {
public:
    /// An empty segment (reused when one is free) that comes back here when its last owner goes.
    std::shared_ptr<DrawSegment> take();
    /// Keeps at most `count` free segments and empties them (their items may hold meshes and
    /// surfaces that the tessellation cache would otherwise see as still drawn). A traverser
    /// calls it at the end of each traversal with about what the traversal took.
    void settle(std::size_t count);
    /// No more keeping: frees the free segments, and those given back later are freed at once.
    void close();
    /// Segments taken since the last call.
    std::size_t takenSince();

private:
    /// A segment and the room for the shared pointer's control block next to it: handing one
    /// out allocates nothing, and a draw list reading a segment finds both in one place.
    struct Slot {
        static constexpr std::size_t kControl = 64;
        DrawSegment segment;
        alignas(std::max_align_t) std::byte control[kControl];
    };
    template <class T>
    struct SlotAllocator;
    /// Called when the control block of `slot` is gone (the last owner let go of its segment).
    void give(Slot* slot);

    std::mutex mutex_;  ///< a draw list may be dropped on another thread
    /// Given back since the last settle, in the order given: a list drops its segments in
    /// drawing order, and the next traversal taking them in that order mostly gets a segment
    /// whose old items hold the meshes it is about to draw again (their counts then touch
    /// memory just read, not another structure's).
    std::deque<std::unique_ptr<Slot>> given_;
    std::vector<std::unique_ptr<Slot>> free_;  ///< emptied by a settle, taken when given_ is
    std::size_t taken_ = 0;
    bool closed_ = false;
};

}  // namespace phigs::detail
