#include "phigs/traverse/ItemVector.h"

#include <algorithm>

namespace phigs {

namespace {

/// Whether a primitive holds anything of its own, asked of the alternative the variant holds:
/// one overload per kind held in place, so that a new one does not compile until answered here
/// and in ItemVector.h (an out-of-line kind owns exactly when its reference does).
struct PrimitiveOwns {
    bool operator()(const DrawPolyline& p) const { return ItemVector::ownsSomething(p); }
    bool operator()(const DrawPolymarker& p) const { return ItemVector::ownsSomething(p); }
    template <class T>
    bool operator()(const ItemRef<T>& held) const {
        return held.owned();
    }
};

}  // namespace

bool ItemVector::ownsSomething(const DrawItem& item) {
    // Every member of DrawItem that may own is asked: a new one must be added here.
    static_assert(sizeof(DrawItem) == 56 && sizeof(DrawPolyline) == 24 && sizeof(DrawPolymarker) == 24,
                  "DrawItem or a primitive changed: is every member that may own asked below?");
    return item.context.owned() || item.source.owned() || ownsSomething(item.primitive);
}

bool ItemVector::ownsSomething(const DrawPrimitive& primitive) {
    return std::visit(PrimitiveOwns{}, primitive);
}

DrawItem* ItemVector::allocate(std::size_t count) {
    return static_cast<DrawItem*>(
        ::operator new (count * sizeof(DrawItem), std::align_val_t{alignof(DrawItem)}));
}

void ItemVector::deallocate(DrawItem* items) {
    ::operator delete (items, std::align_val_t{alignof(DrawItem)});
}

void ItemVector::relocate(DrawItem* fresh, std::size_t count) {
    static_assert(std::is_nothrow_move_constructible_v<DrawItem>);
    for (std::size_t i = 0; i < size_; ++i) {
        ::new (static_cast<void*>(fresh + i)) DrawItem(std::move(data_[i]));
        data_[i].~DrawItem();
    }
    deallocate(data_);
    data_ = fresh;
    capacity_ = count;
}

void ItemVector::resize(std::size_t count) {
    while (size_ < count) emplace_back();
    if (count >= size_) return;
    for (std::size_t i = count; i < size_; ++i) data_[i].~DrawItem();
    owning_.erase(std::remove_if(owning_.begin(), owning_.end(), [&](std::uint32_t i) { return i >= count; }),
                  owning_.end());
    size_ = count;
}

void ItemVector::clear() {
    if (tracked_) {
        // The others own nothing: their storage is simply reused.
        for (std::uint32_t i : owning_) data_[i].~DrawItem();
    } else {
        destroyAll();
    }
    size_ = 0;
    owning_.clear();
    tracked_ = true;
}

}  // namespace phigs
