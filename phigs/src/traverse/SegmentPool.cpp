#include "SegmentPool.h"

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
    segment.pathPrefix.clear();
    segment.points.clear();
    segment.transforms.clear();
    segment.clipPlanes.clear();
}

}  // namespace

std::shared_ptr<DrawSegment> SegmentPool::take() {
    std::unique_ptr<DrawSegment> segment;
    {
        std::lock_guard lock(mutex_);
        ++taken_;
        if (!free_.empty()) {
            segment = std::move(free_.back());
            free_.pop_back();
        }
    }
    if (segment)
        empty(*segment);
    else
        segment = std::make_unique<DrawSegment>();
    auto self = shared_from_this();
    return {segment.release(), [self](DrawSegment* s) { self->give(s); }};
}

void SegmentPool::give(DrawSegment* segment) {
    std::unique_ptr<DrawSegment> owned(segment);
    if (owned->items.capacity() > kKeepItems || owned->points.capacity() > kKeepPoints) return;
    std::lock_guard lock(mutex_);
    if (!closed_) free_.push_back(std::move(owned));
}

void SegmentPool::settle(std::size_t count) {
    std::vector<std::unique_ptr<DrawSegment>> dropped;
    std::lock_guard lock(mutex_);
    if (free_.size() > count) {
        dropped.assign(std::make_move_iterator(free_.begin() + static_cast<std::ptrdiff_t>(count)),
                       std::make_move_iterator(free_.end()));
        free_.resize(count);
    }
    for (auto& segment : free_) empty(*segment);
}

void SegmentPool::close() {
    std::vector<std::unique_ptr<DrawSegment>> dropped;
    std::lock_guard lock(mutex_);
    closed_ = true;
    dropped.swap(free_);
}

std::size_t SegmentPool::freeCount() {
    std::lock_guard lock(mutex_);
    return free_.size();
}

std::size_t SegmentPool::takenSince() {
    std::lock_guard lock(mutex_);
    return std::exchange(taken_, 0);
}

}  // namespace phigs::detail
