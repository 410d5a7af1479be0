#pragma once

#include "phigs/traverse/ItemArray.h"

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <initializer_list>
#include <iterator>
#include <utility>
#include <vector>

namespace phigs {

/// One level of the path from a posted root to the element that produced a draw item.
struct DrawPathLevel {
    int structureId = 0;
    int elementNumber = 0;  ///< 1-based position of the element (the execute structure, or the primitive)
    int pickId = 0;         ///< current pick id at that element
    bool operator==(const DrawPathLevel&) const = default;
};

/// A draw item's path, read like a vector: the levels above its structure (shared by the items
/// of one segment) and its own element's level, kept in place.
class DrawPath {
public:
    class Iterator {
    public:
        using iterator_category = std::random_access_iterator_tag;
        using value_type = DrawPathLevel;
        using difference_type = std::ptrdiff_t;
        using reference = const DrawPathLevel&;
        using pointer = const DrawPathLevel*;

        Iterator() = default;
        Iterator(const DrawPath* path, std::size_t index) : path_(path), index_(index) {}
        reference operator*() const { return (*path_)[index_]; }
        pointer operator->() const { return &(*path_)[index_]; }
        reference operator[](difference_type n) const { return (*path_)[index_ + n]; }
        Iterator& operator++() { return ++index_, *this; }
        Iterator operator++(int) { return {path_, index_++}; }
        Iterator& operator--() { return --index_, *this; }
        Iterator operator--(int) { return {path_, index_--}; }
        Iterator& operator+=(difference_type n) { return index_ += n, *this; }
        Iterator& operator-=(difference_type n) { return index_ -= n, *this; }
        friend Iterator operator+(Iterator i, difference_type n) { return i += n; }
        friend Iterator operator+(difference_type n, Iterator i) { return i += n; }
        friend Iterator operator-(Iterator i, difference_type n) { return i -= n; }
        friend difference_type operator-(const Iterator& a, const Iterator& b) {
            return static_cast<difference_type>(a.index_) - static_cast<difference_type>(b.index_);
        }
        friend bool operator==(const Iterator& a, const Iterator& b) { return a.index_ == b.index_; }
        friend auto operator<=>(const Iterator& a, const Iterator& b) { return a.index_ <=> b.index_; }

    private:
        const DrawPath* path_ = nullptr;
        std::size_t index_ = 0;
    };
    using value_type = DrawPathLevel;
    using size_type = std::size_t;
    using const_iterator = Iterator;
    using iterator = Iterator;

    DrawPath() = default;
    DrawPath(const std::vector<DrawPathLevel>& levels) { assign(levels.data(), levels.size()); }  // NOLINT
    DrawPath(std::initializer_list<DrawPathLevel> levels) { assign(levels.begin(), levels.size()); }
    /// `prefix` (a view of a segment's storage, or a copy) with `last` below it.
    static DrawPath below(ItemArray<DrawPathLevel> prefix, const DrawPathLevel& last) {
        DrawPath p;
        if (prefix.owned())
            p.copyPrefix(prefix.data(), prefix.size());
        else
            p.prefix_ = prefix.data(), p.bits_ = static_cast<std::uint32_t>(prefix.size()) << kSizeShift;
        p.last_ = last;
        p.bits_ |= kHasLast;
        return p;
    }
    /// Every copy holds its own prefix (as ItemArray does).
    DrawPath(const DrawPath& other) : last_(other.last_) {
        copyPrefix(other.prefix_, other.prefixSize());
        bits_ |= other.bits_ & kHasLast;
    }
    DrawPath(DrawPath&& other) noexcept
        : prefix_(std::exchange(other.prefix_, nullptr)),
          bits_(std::exchange(other.bits_, 0)),
          last_(other.last_) {}
    DrawPath& operator=(DrawPath other) noexcept {
        std::swap(prefix_, other.prefix_);
        std::swap(bits_, other.bits_);
        std::swap(last_, other.last_);
        return *this;
    }
    ~DrawPath() {
        if (bits_ & kOwned) delete[] prefix_;
    }

    std::size_t size() const { return prefixSize() + ((bits_ & kHasLast) ? 1 : 0); }
    bool empty() const { return (bits_ & kHasLast) == 0; }
    const DrawPathLevel& operator[](std::size_t i) const { return i < prefixSize() ? prefix_[i] : last_; }
    const DrawPathLevel& front() const { return (*this)[0]; }
    const DrawPathLevel& back() const { return last_; }
    /// Whether the levels above the last are a copy of its own (false: a view, or none).
    bool ownsPrefix() const { return (bits_ & kOwned) != 0; }
    Iterator begin() const { return {this, 0}; }
    Iterator end() const { return {this, size()}; }
    operator std::vector<DrawPathLevel>() const { return {begin(), end()}; }  // NOLINT: reads as a vector

    friend bool operator==(const DrawPath& a, const DrawPath& b) {
        return a.size() == b.size() && std::equal(a.begin(), a.end(), b.begin());
    }
    friend bool operator==(const DrawPath& a, const std::vector<DrawPathLevel>& b) {
        return a.size() == b.size() && std::equal(a.begin(), a.end(), b.begin());
    }

private:
    static constexpr std::uint32_t kHasLast = 1, kOwned = 2, kSizeShift = 2;
    std::size_t prefixSize() const { return bits_ >> kSizeShift; }
    void assign(const DrawPathLevel* levels, std::size_t size) {
        if (size == 0) return;
        copyPrefix(levels, size - 1);
        last_ = levels[size - 1];
        bits_ |= kHasLast;
    }
    /// Sets the prefix to a copy of its own of `size` levels at `levels` (none: no storage).
    void copyPrefix(const DrawPathLevel* levels, std::size_t size) {
        bits_ = static_cast<std::uint32_t>(size) << kSizeShift;
        if (size == 0) return;
        auto* own = new DrawPathLevel[size];
        std::copy(levels, levels + size, own);
        prefix_ = own;
        bits_ |= kOwned;
    }

    // Three fields in 24 bytes: a draw item holds one.
    const DrawPathLevel* prefix_ = nullptr;  ///< the levels above the last (a view, or owned)
    std::uint32_t bits_ = 0;                 ///< prefix size << kSizeShift | kOwned | kHasLast
    DrawPathLevel last_{};
};

}  // namespace phigs
