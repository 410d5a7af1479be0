#include "SegmentPool.h"

#include <new>

namespace phigs::detail {

namespace {

/// Past this many items (or point values) a given-back segment is freed, not kept: one very
/// large part would otherwise hold its storage for whatever small part takes it next.
constexpr std::size_t kKeepItems = 4096;
constexpr std::size_t kKeepPoints = 1 << 16;

/// Empties a segment, keeping its storage.
void empty(DrawSegment& segment) {
    segment.items.clear();
    segment.styles.reset();
    segment.source.prefix.clear();
    segment.points.clear();
    segment.transforms.clear();
    segment.contexts.clear();
    segment.meshes.clear();
    if (DrawSegment::Rare* rare = segment.rare.get()) {
        rare->clipPlanes.clear();
        rare->fillAreas.clear();
        rare->texts.clear();
        rare->curves.clear();
        rare->colouredPolylines.clear();
    }
    segment.storePoints.reset();
}

}  // namespace

/// Places a segment's control block in its slot; freeing the block gives the slot back. The
/// pool is kept alive by the allocator, the last thing a control block lets go of.
template <class T>
struct SegmentPool::SlotAllocator {
    using value_type = T;
    std::shared_ptr<SegmentPool> pool;
    Slot* slot = nullptr;

    SlotAllocator(std::shared_ptr<SegmentPool> p, Slot* s) : pool(std::move(p)), slot(s) {}
    template <class U>
    SlotAllocator(const SlotAllocator<U>& other) : pool(other.pool), slot(other.slot) {}  // NOLINT
    T* allocate(std::size_t n) {
        static_assert(sizeof(T) <= Slot::kControl && alignof(T) <= alignof(std::max_align_t));
        if (n != 1) throw std::bad_alloc();
        return reinterpret_cast<T*>(slot->control);
    }
    void deallocate(T*, std::size_t) { pool->give(slot); }
    template <class U>
    bool operator==(const SlotAllocator<U>& other) const {
        return slot == other.slot;
    }
};

std::shared_ptr<DrawSegment> SegmentPool::take() {
    std::unique_ptr<Slot> slot;
    {
        std::lock_guard lock(mutex_);
        ++taken_;
        if (!given_.empty()) {
            slot = std::move(given_.front());
            given_.pop_front();
        } else if (!free_.empty()) {
            slot = std::move(free_.back());
            free_.pop_back();
        }
    }
    if (slot)
        empty(slot->segment);
    else
        slot = std::make_unique<Slot>();
    Slot* s = slot.release();
    // The deleter does nothing: the slot comes back when its control block is freed.
    return {&s->segment, [](DrawSegment*) {}, SlotAllocator<DrawSegment>(shared_from_this(), s)};
}

void SegmentPool::give(Slot* slot) {
    std::unique_ptr<Slot> owned(slot);
    const DrawSegment& segment = owned->segment;
    if (segment.items.capacity() > kKeepItems || segment.points.capacity() > kKeepPoints) return;
    std::lock_guard lock(mutex_);
    if (!closed_) given_.push_back(std::move(owned));
}

void SegmentPool::settle(std::size_t count) {
    std::vector<std::unique_ptr<Slot>> dropped;
    std::lock_guard lock(mutex_);
    for (auto& slot : given_) free_.push_back(std::move(slot));
    given_.clear();
    if (free_.size() > count) {
        dropped.assign(std::make_move_iterator(free_.begin() + static_cast<std::ptrdiff_t>(count)),
                       std::make_move_iterator(free_.end()));
        free_.resize(count);
    }
    for (auto& slot : free_) empty(slot->segment);
}

void SegmentPool::close() {
    std::vector<std::unique_ptr<Slot>> dropped;
    std::lock_guard lock(mutex_);
    closed_ = true;
    dropped.swap(free_);
    for (auto& slot : given_) dropped.push_back(std::move(slot));
    given_.clear();
}

std::size_t SegmentPool::takenSince() {
    std::lock_guard lock(mutex_);
    return std::exchange(taken_, 0);
}

}  // namespace phigs::detail
