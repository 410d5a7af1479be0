#pragma once

#include "phigs/traverse/DrawItem.h"

#include <cstddef>
#include <cstdint>
#include <memory>
#include <new>
#include <type_traits>
#include <utility>
#include <vector>

namespace phigs {

/// A draw segment's items: a vector that, when cleared for reuse, runs the destructors of only
/// the items that own something (a copy of their own, a mesh, a curve). Items made of views of
/// their segment's storage own nothing, and clearing skips them without reading them again.
class ItemVector {
public:
    using value_type = DrawItem;
    using size_type = std::size_t;
    using iterator = DrawItem*;
    using const_iterator = const DrawItem*;

    ItemVector() = default;
    ItemVector(const ItemVector& other) {
        reserve(other.size_);
        for (const DrawItem& item : other) push_back(item);
    }
    explicit ItemVector(std::vector<DrawItem>&& items) {
        reserve(items.size());
        for (DrawItem& item : items) push_back(std::move(item));
    }
    ItemVector(ItemVector&& other) noexcept { swap(other); }
    ItemVector& operator=(ItemVector other) noexcept {
        swap(other);
        return *this;
    }
    ~ItemVector() {
        destroyAll();
        deallocate(data_);
    }

    std::size_t size() const { return size_; }
    bool empty() const { return size_ == 0; }
    std::size_t capacity() const { return capacity_; }
    const DrawItem* begin() const { return data_; }
    const DrawItem* end() const { return data_ + size_; }
    const DrawItem& operator[](std::size_t i) const { return data_[i]; }
    const DrawItem& front() const { return data_[0]; }
    const DrawItem& back() const { return data_[size_ - 1]; }
    // Writable access may give an item something of its own: clearing then destroys every item.
    DrawItem* begin() { return tracked_ = false, data_; }
    DrawItem* end() { return tracked_ = false, data_ + size_; }
    DrawItem& operator[](std::size_t i) { return tracked_ = false, data_[i]; }
    DrawItem& front() { return tracked_ = false, data_[0]; }
    DrawItem& back() { return tracked_ = false, data_[size_ - 1]; }

    void reserve(std::size_t count) {
        if (count > capacity_) grow(count);
    }
    /// A new last item made from `fields` (the members of DrawItem, in order), in place.
    template <class... Fields>
    DrawItem& emplace_back(Fields&&... fields) {
        DrawItem& item = construct(std::forward<Fields>(fields)...);
        if (ownsSomething(item)) owning_.push_back(static_cast<std::uint32_t>(size_ - 1));
        return item;
    }
    /// emplace_back for a caller that knows whether the item will own something (asked of the
    /// fields before they are moved in, the new item is not read back).
    template <class... Fields>
    DrawItem& emplaceKnown(bool owns, Fields&&... fields) {
        if (owns) owning_.push_back(static_cast<std::uint32_t>(size_));
        return construct(std::forward<Fields>(fields)...);
    }
    void push_back(const DrawItem& item) { emplace_back(item); }
    void push_back(DrawItem&& item) { emplace_back(std::move(item)); }
    /// Drops items past `count`, or appends default items up to it.
    void resize(std::size_t count);
    /// Forgets every item, keeping the storage: destructors run for the items that own something.
    void clear();

    /// Whether `item` holds anything of its own that its destructor must let go of.
    static bool ownsSomething(const DrawItem& item);
    static bool ownsSomething(const DrawPrimitive& primitive);
    /// The same of a primitive held in place, as its own type before it is held (inline:
    /// traversal asks it of every item).
    static bool ownsSomething(const DrawPolyline& p) { return p.points.owned() || p.style.owned(); }
    static bool ownsSomething(const DrawPolymarker& p) { return p.points.owned() || p.style.owned(); }

private:
    template <class... Fields>
    DrawItem& construct(Fields&&... fields) {
        if (size_ < capacity_) {
            DrawItem* item =
                ::new (static_cast<void*>(data_ + size_)) DrawItem{std::forward<Fields>(fields)...};
            ++size_;
            return *item;
        }
        // The new item is built before the old ones move, as the fields may refer to one of them
        // (v.push_back(v[i])).
        const std::size_t count = capacity_ ? 2 * capacity_ : 4;
        DrawItem* fresh = allocate(count);
        DrawItem* item = nullptr;
        try {
            item = ::new (static_cast<void*>(fresh + size_)) DrawItem{std::forward<Fields>(fields)...};
        } catch (...) {
            deallocate(fresh);
            throw;
        }
        relocate(fresh, count);
        ++size_;
        return *item;
    }
    static DrawItem* allocate(std::size_t count);
    static void deallocate(DrawItem* items);
    /// Moves the items into `fresh` (room for `count`) and frees the old storage.
    void relocate(DrawItem* fresh, std::size_t count);
    void grow(std::size_t count) { relocate(allocate(count), count); }
    void destroyAll() {
        for (std::size_t i = 0; i < size_; ++i) data_[i].~DrawItem();
    }
    void swap(ItemVector& other) noexcept {
        std::swap(data_, other.data_);
        std::swap(size_, other.size_);
        std::swap(capacity_, other.capacity_);
        std::swap(owning_, other.owning_);
        std::swap(tracked_, other.tracked_);
    }

    DrawItem* data_ = nullptr;
    std::size_t size_ = 0, capacity_ = 0;
    std::vector<std::uint32_t> owning_;  ///< the items that own something (while tracked_)
    bool tracked_ = true;                ///< no writable access since the last clear: owning_ is all
};

}  // namespace phigs
