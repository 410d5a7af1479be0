#include "phigs/traverse/DrawItems.h"

#include <stdexcept>

#include <algorithm>
#include <string>

namespace phigs {

std::size_t DrawItems::segmentOf(std::size_t i) const {
    // starts_ is strictly increasing (empty segments are never kept): the last start <= i.
    auto it = std::upper_bound(starts_.begin(), starts_.end() - 1, i);
    return static_cast<std::size_t>(it - starts_.begin()) - 1;
}

const DrawItem& DrawItems::operator[](std::size_t i) const {
    std::size_t k = segmentOf(i);
    return segments_[k]->items[i - starts_[k]];
}

DrawSegment& DrawItems::own(std::size_t k) {
    if (segments_[k].use_count() > 1) segments_[k] = std::make_shared<const DrawSegment>(*segments_[k]);
    // Unique now: the only owner may write through it.
    return const_cast<DrawSegment&>(*segments_[k]);
}

DrawItem& DrawItems::operator[](std::size_t i) {
    std::size_t k = segmentOf(i);
    return own(k).items[i - starts_[k]];
}

const DrawItem& DrawItems::at(std::size_t i) const {
    if (i >= size())
        throw std::out_of_range("DrawItems::at: item " + std::to_string(i) + " of " + std::to_string(size()));
    return (*this)[i];
}

DrawItem& DrawItems::at(std::size_t i) {
    if (i >= size())
        throw std::out_of_range("DrawItems::at: item " + std::to_string(i) + " of " + std::to_string(size()));
    return (*this)[i];
}

void DrawItems::push_back(DrawItem item) {
    if (!lastOwned_ || segments_.empty()) {
        segments_.push_back(std::make_shared<const DrawSegment>());
        starts_.push_back(starts_.back());
        lastOwned_ = true;
    }
    own(segments_.size() - 1).items.push_back(std::move(item));
    ++starts_.back();
}

DrawItems::DrawItems(std::vector<DrawItem> items) {
    auto segment = std::make_shared<DrawSegment>();
    segment->items = ItemVector(std::move(items));
    appendSegment(std::move(segment));
    lastOwned_ = true;
}

void DrawItems::resize(std::size_t count) {
    while (size() > count) {
        std::size_t last = segments_.size() - 1;
        std::size_t keep = std::max(count, starts_[last]) - starts_[last];
        if (keep == 0) {
            segments_.pop_back();
            starts_.pop_back();
            lastOwned_ = false;
            continue;
        }
        own(last).items.resize(keep);
        starts_.back() = starts_[last] + keep;
    }
    while (size() < count) push_back(DrawItem{});
}

void DrawItems::clear() {
    segments_.clear();
    starts_.assign(1, 0);
    lastOwned_ = false;
}

void DrawItems::appendSegment(SegmentPtr segment) {
    if (!segment || segment->items.empty()) return;
    starts_.push_back(starts_.back() + segment->items.size());
    segments_.push_back(std::move(segment));
    lastOwned_ = false;
}

}  // namespace phigs
