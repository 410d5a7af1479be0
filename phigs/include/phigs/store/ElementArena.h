#pragma once

#include "phigs/store/Element.h"

#include <concepts>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <memory>
#include <new>
#include <string>
#include <type_traits>
#include <utility>
#include <variant>
#include <vector>

namespace phigs {

namespace detail {

/// The position of `T` among the alternatives of the variant `V`.
template <class T, class V>
struct AlternativeIndex;
template <class T, class... U>
struct AlternativeIndex<T, std::variant<U...>> {
    static constexpr std::size_t value = [] {
        constexpr bool same[] = {std::is_same_v<T, U>...};
        std::size_t i = 0;
        while (i < sizeof...(U) && !same[i]) ++i;
        return i;
    }();
    static_assert(value < sizeof...(U), "not an element payload");
};

/// Whether `F` takes every payload of the variant `V` as `const T&`, with one result type.
template <class F, class V>
struct TakesEveryPayload;
template <class F, class... U>
struct TakesEveryPayload<F, std::variant<U...>> {
    static constexpr bool value = [] {
        if constexpr ((std::is_invocable_v<F&, const U&> && ...))
            return (std::is_same_v<
                        std::invoke_result_t<F&, const U&>,
                        std::invoke_result_t<F&, const std::variant_alternative_t<0, std::variant<U...>>&>> &&
                    ...);
        else
            return false;
    }();
};

}  // namespace detail

/// An element visitor: it takes every payload (a forgotten one does not compile).
template <class F>
concept ElementVisitor = detail::TakesEveryPayload<std::remove_reference_t<F>, Element>::value;

/// Whether payloads of type `T` keep their points in a PointList (stored in the arena's pool).
template <class T>
concept PooledPoints = requires(T& t) {
    { t.points } -> std::same_as<PointList&>;
};

/// Whether payloads of type `T` live in a shared box of their own (the arena holds a pointer to
/// it): a reader may keep such a payload past any edit (a draw list keeps a surface) without a copy.
template <class T>
concept BoxedPayload = std::same_as<T, NurbsSurfaceElement>;

namespace detail {
/// How the arena keeps a payload of type `T`: itself, or a pointer to its shared box.
template <class T>
using StoredPayload = std::conditional_t<BoxedPayload<T>, std::shared_ptr<const T>, T>;
}  // namespace detail

/// The elements of one structure, compact: each payload kept as its own type in one byte arena
/// (no variant per element), the points of its PointList in one point pool (no allocation per
/// element for them), and one 12-byte slot (serial, place, payload family) per element.
class ElementArena {
public:
    /// Throws when `serial` does not fit a slot; an edit of many elements asks for its last
    /// serial before it changes anything.
    static void checkSerial(std::uint64_t serial);
    ElementArena() = default;
    ElementArena(ElementArena&& other) noexcept { swap(other); }
    ElementArena& operator=(ElementArena&& other) noexcept {
        ElementArena gone(std::move(other));
        swap(gone);
        return *this;
    }
    ElementArena(const ElementArena&) = delete;
    ElementArena& operator=(const ElementArena&) = delete;
    ~ElementArena() { release(); }

    std::size_t size() const { return slots_.size(); }
    bool empty() const { return slots_.empty(); }
    /// The payload family of element `i` (0-based): its alternative index in Element.
    std::size_t family(std::size_t i) const { return slots_[i].family; }
    /// The element's serial: unique in the store's lifetime, renewed on insert and replace.
    std::uint64_t serial(std::size_t i) const { return slots_[i].serial(); }

    /// The payload of element `i` when it is a `T`, else nullptr.
    template <class T>
    const T* get(std::size_t i) const {
        const Slot& s = slots_[i];
        return s.family == detail::AlternativeIndex<T, Element>::value ? object<T>(s.offset) : nullptr;
    }
    /// The shared box of element `i` when it is a boxed `T`, else null: it stays valid, and
    /// unchanged, after the element is replaced or removed.
    template <BoxedPayload T>
    std::shared_ptr<const T> shared(std::size_t i) const {
        const Slot& s = slots_[i];
        if (s.family != detail::AlternativeIndex<T, Element>::value) return nullptr;
        return *std::launder(reinterpret_cast<const std::shared_ptr<const T>*>(data_ + s.offset));
    }
    /// Calls `f` with the payload of element `i` (a `const T&`), as std::visit does with an
    /// Element: `f` must take every payload, else this does not compile.
    template <ElementVisitor F>
    decltype(auto) visit(std::size_t i, F&& f) const {
        return dispatch(slots_[i], f, std::make_index_sequence<std::variant_size_v<Element>>{});
    }
    /// A copy of element `i` as an Element value.
    Element element(std::size_t i) const;
    /// The PHIGS type of element `i`.
    ElementType type(std::size_t i) const;

    /// Inserts `e` before element `at` (at == size(): appends) with `serial`.
    void insert(std::size_t at, Element&& e, std::uint64_t serial);
    /// Replaces element `at` by `e` with `serial`.
    void replace(std::size_t at, Element&& e, std::uint64_t serial);
    /// Removes elements [first, last).
    void erase(std::size_t first, std::size_t last);
    /// Removes every element i with marked[i] (marked.size() == size()), the rest kept in order:
    /// one pass, however the marked ones are spread.
    void eraseMarked(const std::vector<char>& marked);
    void clear();
    /// Gives back the room held for growth once the arena has at least doubled its elements
    /// since it last did (a structure built, then closed): each element is moved a bounded
    /// number of times however the structure is edited.
    void settle();
    void swap(ElementArena& other) noexcept {
        slots_.swap(other.slots_);
        std::swap(data_, other.data_);
        std::swap(used_, other.used_);
        std::swap(capacity_, other.capacity_);
        std::swap(dead_, other.dead_);
        std::swap(points_, other.points_);
        std::swap(pointsUsed_, other.pointsUsed_);
        std::swap(pointsCapacity_, other.pointsCapacity_);
        std::swap(pointsDead_, other.pointsDead_);
        std::swap(settled_, other.settled_);
    }

    /// Arena bytes held, and of those the ones left by removed or replaced payloads.
    std::size_t capacityBytes() const { return capacity_; }
    std::size_t deadBytes() const { return dead_; }
    /// The point pool, shared: a reader that views stored points (a draw list) holds it to keep
    /// them. The arena never writes over points once a list viewed them: edits append, and a
    /// growth or compaction moves the live lists to a new pool, leaving the held one as it was.
    std::shared_ptr<const void> pointPool() const { return points_; }
    /// Point pool places held, and of those the ones left by removed or replaced point lists.
    std::size_t poolCapacity() const { return pointsCapacity_; }
    std::size_t poolDead() const { return pointsDead_; }
    /// Checks the arena's bookkeeping (places in bounds, aligned, not overlapping, byte counts);
    /// an empty string when consistent, else what is wrong.
    std::string checkLayout() const;

private:
    /// Serials are kept in 48 bits (12-byte slots): 2^48 inserts and replaces per store.
    static constexpr std::uint64_t kSerialLimit = std::uint64_t{1} << 48;
    struct Slot {
        std::uint32_t offset;  ///< the payload's place in the arena
        std::uint32_t serialLow;
        std::uint16_t serialHigh;
        std::uint16_t family;
        std::uint64_t serial() const { return serialLow | std::uint64_t{serialHigh} << 32; }
        void setSerial(std::uint64_t serial) {
            serialLow = static_cast<std::uint32_t>(serial);
            serialHigh = static_cast<std::uint16_t>(serial >> 32);
        }
    };
    static_assert(sizeof(Slot) == 12);

    template <class T>
    const T* object(std::uint32_t offset) const {
        const auto* stored = std::launder(reinterpret_cast<const detail::StoredPayload<T>*>(data_ + offset));
        if constexpr (BoxedPayload<T>)
            return stored->get();
        else
            return stored;
    }
    template <std::size_t I, class R, class F>
    static R call(const ElementArena& a, std::uint32_t offset, F& f) {
        return std::invoke(f, *a.object<std::variant_alternative_t<I, Element>>(offset));
    }
    template <class F, std::size_t... I>
    decltype(auto) dispatch(const Slot& s, F& f, std::index_sequence<I...>) const {
        using R = std::invoke_result_t<F&, const std::variant_alternative_t<0, Element>&>;
        using Call = R (*)(const ElementArena&, std::uint32_t, F&);
        static constexpr Call calls[] = {&call<I, R, F>...};
        return calls[s.family](*this, s.offset, f);
    }

    /// Moves `e`'s payload into the arena (growing it when full), its points into the pool;
    /// returns its place.
    std::uint32_t emplace(Element&& e);
    /// Makes room in the pool for `count` more points.
    void reservePoints(std::size_t count);
    /// Copies `list`'s points to the pool's end (room made) and makes `list` view them there.
    void pool(PointList& list) noexcept;
    /// Moves every live point list, in element order, into a new pool with room for `extra` more
    /// (and as much again for growth), or `exact`ly the live ones.
    void repool(std::size_t extra, bool exact = false);
    /// checkLayout's part for the point pool.
    std::string checkPool() const;
    /// The point list of the payload at `offset` of family `family`, or nullptr.
    PointList* pointsAt(std::uint32_t family, std::uint32_t offset) const;
    /// Moves every live payload, in element order, into a new arena with room for `extra` more
    /// bytes (and as much again for growth), or `exact`ly the live ones.
    void relocate(std::size_t extra, bool exact = false);
    void destroy(const Slot& s);
    /// Compacts the arena (the pool) when most of it is left over from removed payloads (lists).
    void compactIfSparse();
    void release() noexcept;

    std::vector<Slot> slots_;
    std::byte* data_ = nullptr;
    std::uint32_t used_ = 0;                ///< bytes up to the end of the last payload placed
    std::uint32_t capacity_ = 0;            ///< bytes allocated
    std::uint32_t dead_ = 0;                ///< bytes below used_ that no slot refers to
    std::shared_ptr<glm::dvec3[]> points_;  ///< the point pool
    std::uint32_t pointsUsed_ = 0;          ///< points up to the end of the last list placed
    std::uint32_t pointsCapacity_ = 0;      ///< points allocated
    std::uint32_t pointsDead_ = 0;          ///< points below pointsUsed_ that no list views
    std::uint32_t settled_ = 0;             ///< elements when settle() last gave room back
};

/// std::visit's form of ElementArena::visit: `f` on the payload of element `i` of `elements`.
template <ElementVisitor F>
decltype(auto) visitElement(F&& f, const ElementArena& elements, std::size_t i) {
    return elements.visit(i, std::forward<F>(f));
}

}  // namespace phigs
