#pragma once

// The items of a draw list as a sequence of shared segments: traversal builds one segment per
// structure execution between EXECUTE STRUCTURE elements, and a later traversal that finds a
// subtree unchanged appends the same segments again instead of copying their items. Reading
// looks like a vector (size, [], at, iteration); writing a shared segment copies it first, so
// a draw list keeps value semantics.

#include "phigs/traverse/BlockPool.h"
#include "phigs/traverse/DrawItem.h"
#include "phigs/traverse/ItemVector.h"
#include "phigs/traverse/StableList.h"
#include "phigs/traverse/StylePool.h"

#include <cstddef>
#include <initializer_list>
#include <iterator>
#include <memory>
#include <vector>

namespace phigs {

/// Consecutive draw items produced together (one structure's elements between two executes),
/// with the storage their views refer to (points, transforms, clipping volumes, contexts, the path above
/// the structure, the interned styles). A copy copies the items only: each copied item holds
/// its own values.
struct DrawSegment {
    /// The records fewer segments hold, made with the first of them: a draw list has a segment per
    /// structure, most of which hold polylines, markers and at most a mesh.
    struct Rare {
        BlockPool<glm::dvec4> clipPlanes;                    ///< one volume per run of items that share it
        StableList<DrawFillArea> fillAreas;                  ///< what the items' fill area views show
        StableList<DrawText> texts;                          ///< what the items' text views show
        StableList<DrawCurve> curves;                        ///< what the items' curve views show
        StableList<DrawColouredPolyline> colouredPolylines;  ///< what their views show
    };

    ItemVector items;
    BlockPool<glm::dvec3> points;  ///< what the items' point views show
    // The first transform, context and mesh lie in the segment itself: a segment most often
    // holds one of each, and reading them then touches no allocation but the segment's own.
    BlockPool<glm::dmat4, 1> transforms;      ///< one per run of items that share a transform
    StableList<DrawContext, 1> contexts;      ///< one per run of items in one state
    StableList<DrawMesh, 1> meshes;           ///< what the items' mesh views show
    DrawSource::Shared source;                ///< what the items' sources view (set before any item)
    std::shared_ptr<const StylePool> styles;  ///< the records the items' styles view
    /// The point pool of the items' structure, which polyline and marker points view (not copied).
    std::shared_ptr<const void> storePoints;
    std::unique_ptr<Rare> rare;  ///< null until the first rare record

    DrawSegment() = default;
    DrawSegment(const DrawSegment& other) : items(other.items) {}
    DrawSegment& operator=(const DrawSegment&) = delete;

    /// The rare records, made when first asked for.
    Rare& rareRecords() {
        if (!rare) rare = std::make_unique<Rare>();
        return *rare;
    }
};

/// A draw list's items: shared segments read as one sequence.
class DrawItems {
public:
    using value_type = DrawItem;
    using size_type = std::size_t;
    using SegmentPtr = std::shared_ptr<const DrawSegment>;

    template <bool Const>
    class Iterator {
    public:
        using iterator_category = std::random_access_iterator_tag;
        using value_type = DrawItem;
        using difference_type = std::ptrdiff_t;
        using reference = std::conditional_t<Const, const DrawItem&, DrawItem&>;
        using pointer = std::conditional_t<Const, const DrawItem*, DrawItem*>;
        using Owner = std::conditional_t<Const, const DrawItems, DrawItems>;

        Iterator() = default;
        Iterator(Owner* owner, std::size_t index) : owner_(owner), index_(index) {}
        operator Iterator<true>() const { return {owner_, index_}; }

        /// The item, found through the segment of the last one read: stepping costs no search.
        reference operator*() const {
            if (index_ < first_ || index_ >= last_) {
                segment_ = owner_->segmentOf(index_);
                first_ = owner_->starts_[segment_];
                last_ = owner_->starts_[segment_ + 1];
            }
            return owner_->itemIn(segment_, index_ - first_);
        }
        pointer operator->() const { return &**this; }
        reference operator[](difference_type n) const { return (*owner_)[index_ + n]; }
        Iterator& operator++() { return ++index_, *this; }
        Iterator operator++(int) { return {owner_, index_++}; }
        Iterator& operator--() { return --index_, *this; }
        Iterator operator--(int) { return {owner_, index_--}; }
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
        Owner* owner_ = nullptr;
        std::size_t index_ = 0;
        mutable std::size_t segment_ = 0, first_ = 0, last_ = 0;  ///< where item index_ was last found
    };
    using iterator = Iterator<false>;
    using const_iterator = Iterator<true>;

    DrawItems() = default;
    DrawItems(std::initializer_list<DrawItem> items) : DrawItems(std::vector<DrawItem>(items)) {}
    /// One segment of these items.
    DrawItems(std::vector<DrawItem> items);  // NOLINT(google-explicit-constructor): reads as a vector

    std::size_t size() const { return starts_.back(); }
    bool empty() const { return size() == 0; }
    const DrawItem& operator[](std::size_t i) const;
    /// Copies the segment holding item i first when another draw list shares it.
    DrawItem& operator[](std::size_t i);
    const DrawItem& at(std::size_t i) const;
    DrawItem& at(std::size_t i);
    const DrawItem& front() const { return (*this)[0]; }
    const DrawItem& back() const { return (*this)[size() - 1]; }
    DrawItem& back() { return (*this)[size() - 1]; }
    const_iterator begin() const { return {this, 0}; }
    const_iterator end() const { return {this, size()}; }
    iterator begin() { return {this, 0}; }
    iterator end() { return {this, size()}; }

    /// Appends one item (to a segment of this list's own).
    void push_back(DrawItem item);
    void clear();
    void reserve(std::size_t) {}
    /// Drops items past `count`, or appends default items up to it.
    void resize(std::size_t count);

    /// Appends a whole segment, shared, not copied (empty segments are skipped).
    void appendSegment(SegmentPtr segment);
    const std::vector<SegmentPtr>& segments() const { return segments_; }
    std::size_t segmentCount() const { return segments_.size(); }

private:
    std::size_t segmentOf(std::size_t i) const;
    DrawSegment& own(std::size_t segment);
    const DrawItem& itemIn(std::size_t segment, std::size_t offset) const {
        return segments_[segment]->items[offset];
    }
    DrawItem& itemIn(std::size_t segment, std::size_t offset) { return own(segment).items[offset]; }

    std::vector<SegmentPtr> segments_;
    std::vector<std::size_t> starts_{0};  ///< starts_[k]: index of segment k's first item; back(): size
    bool lastOwned_ = false;              ///< the last segment was made by push_back and is not shared
};

}  // namespace phigs
