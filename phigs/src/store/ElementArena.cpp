#include "phigs/store/ElementArena.h"

#include <algorithm>
#include <array>
#include <limits>
#include <memory>
#include <optional>
#include <stdexcept>

namespace phigs {

namespace {

/// How the arena handles one payload family without knowing its type.
struct FamilyOps {
    std::uint32_t size = 0, align = 0;
    void (*moveTo)(std::byte* from, std::byte* to) = nullptr;  ///< move-constructs at `to`, destroys `from`
    void (*destroy)(std::byte* at) = nullptr;
    PointList* (*points)(std::byte* at) = nullptr;  ///< the payload's point list; null: none
};

template <class T>
auto pointsOfPayload() -> PointList* (*)(std::byte*) {
    static_assert(!(PooledPoints<T> && BoxedPayload<T>), "boxed payloads keep no pooled points");
    if constexpr (PooledPoints<T>)
        return [](std::byte* at) { return &std::launder(reinterpret_cast<T*>(at))->points; };
    else
        return nullptr;
}

template <class Payload, class T = detail::StoredPayload<Payload>>
FamilyOps opsOf() {
    static_assert(std::is_nothrow_move_constructible_v<T>, "payloads move without throwing");
    return {static_cast<std::uint32_t>(sizeof(T)), static_cast<std::uint32_t>(alignof(T)),
            [](std::byte* from, std::byte* to) {
                T* source = std::launder(reinterpret_cast<T*>(from));
                ::new (static_cast<void*>(to)) T(std::move(*source));
                source->~T();
            },
            [](std::byte* at) { std::launder(reinterpret_cast<T*>(at))->~T(); }, pointsOfPayload<Payload>()};
}

template <std::size_t... I>
std::array<FamilyOps, sizeof...(I)> familyTable(std::index_sequence<I...>) {
    return {opsOf<std::variant_alternative_t<I, Element>>()...};
}

const std::array<FamilyOps, std::variant_size_v<Element>> kFamilies =
    familyTable(std::make_index_sequence<std::variant_size_v<Element>>{});

template <class... T>
constexpr std::size_t maxAlignOf(const std::variant<T...>*) {
    return std::max({alignof(T)...});
}
/// The arena's own alignment: that of the most aligned payload.
constexpr std::align_val_t kArenaAlign{maxAlignOf(static_cast<const Element*>(nullptr))};

constexpr std::size_t alignUp(std::size_t offset, std::size_t align) {
    return (offset + align - 1) / align * align;
}

/// Arenas keep 32-bit places: at most 4 GiB of payload records per structure.
constexpr std::size_t kArenaLimit = std::numeric_limits<std::uint32_t>::max() / 2;
/// The room a growing arena and pool take at least: few relocations while a structure is built;
/// settle() gives what stays unused back.
constexpr std::size_t kFirstBytes = 4096, kFirstPoints = 256;

/// Pools keep 32-bit places too.
constexpr std::size_t kPoolLimit = std::numeric_limits<std::uint32_t>::max() / 2;

/// The point list of an element value, or nullptr when its payload has none.
PointList* pointsOf(Element& e) {
    return std::visit(
        [](auto& payload) -> PointList* {
            if constexpr (PooledPoints<std::decay_t<decltype(payload)>>)
                return &payload.points;
            else
                return nullptr;
        },
        e);
}

/// The summed length of [begin, end) spans (sorted here), or nothing when two overlap.
std::optional<std::size_t> disjointLength(std::vector<std::pair<std::size_t, std::size_t>>& spans) {
    std::sort(spans.begin(), spans.end());
    std::size_t length = 0;
    for (std::size_t i = 0; i < spans.size(); ++i) {
        if (i > 0 && spans[i].first < spans[i - 1].second) return std::nullopt;
        length += spans[i].second - spans[i].first;
    }
    return length;
}

}  // namespace

Element ElementArena::element(std::size_t i) const {
    return visit(i, [](const auto& payload) { return Element(payload); });
}

ElementType ElementArena::type(std::size_t i) const {
    // The tagged families name their type; the others are read from a copy (an inquiry).
    return visit(i, [](const auto& payload) {
        if constexpr (requires { payload.type; })
            return payload.type;
        else
            return elementType(Element(payload));
    });
}

std::uint32_t ElementArena::emplace(Element&& e) {
    const FamilyOps& ops = kFamilies[e.index()];
    auto at = static_cast<std::uint32_t>(alignUp(used_, ops.align));
    if (static_cast<std::size_t>(at) + ops.size > capacity_) {
        relocate(ops.size + ops.align);
        at = static_cast<std::uint32_t>(alignUp(used_, ops.align));
    }
    if (PointList* list = pointsOf(e)) {
        reservePoints(list->size());
        pool(*list);
    }
    std::visit(
        [&](auto& payload) {
            using T = std::decay_t<decltype(payload)>;
            if constexpr (BoxedPayload<T>)
                ::new (static_cast<void*>(data_ + at))
                    detail::StoredPayload<T>(std::make_shared<const T>(std::move(payload)));
            else
                ::new (static_cast<void*>(data_ + at)) T(std::move(payload));
        },
        e);
    dead_ += at - used_;  // alignment padding
    used_ = at + ops.size;
    return at;
}

void ElementArena::relocate(std::size_t extra, bool exact) {
    std::size_t live = 0;  // the payloads packed in element order, with their padding
    for (const Slot& s : slots_) live = alignUp(live, kFamilies[s.family].align) + kFamilies[s.family].size;
    const std::size_t wanted =
        exact ? std::max<std::size_t>(live, 1) : std::max<std::size_t>(kFirstBytes, (live + extra) * 2);
    if (live + extra > kArenaLimit)
        throw std::length_error("ElementArena: a structure's element records exceed 2 GiB");
    const std::size_t capacity = std::min(wanted, kArenaLimit);
    auto* fresh = static_cast<std::byte*>(::operator new(capacity, kArenaAlign));
    std::uint32_t at = 0, padding = 0;
    for (Slot& s : slots_) {
        const FamilyOps& ops = kFamilies[s.family];
        const auto aligned = static_cast<std::uint32_t>(alignUp(at, ops.align));
        padding += aligned - at;
        at = aligned;
        ops.moveTo(data_ + s.offset, fresh + at);
        s.offset = at;
        at += ops.size;
    }
    if (data_) ::operator delete(data_, kArenaAlign);
    data_ = fresh;
    capacity_ = static_cast<std::uint32_t>(capacity);
    used_ = at;
    dead_ = padding;
}

PointList* ElementArena::pointsAt(std::uint32_t family, std::uint32_t offset) const {
    const FamilyOps& ops = kFamilies[family];
    return ops.points ? ops.points(data_ + offset) : nullptr;
}

void ElementArena::reservePoints(std::size_t count) {
    if (pointsUsed_ + count > pointsCapacity_) repool(count);
}

void ElementArena::pool(PointList& list) noexcept {
    const auto count = static_cast<std::uint32_t>(list.size());
    if (count == 0) return list.view(nullptr, 0);
    glm::dvec3* at = points_.get() + pointsUsed_;
    std::copy(list.begin(), list.end(), at);
    list.view(at, count);
    pointsUsed_ += count;
}

void ElementArena::repool(std::size_t extra, bool exact) {
    const std::size_t live = pointsUsed_ - pointsDead_;
    if (live + extra > kPoolLimit) throw std::length_error("ElementArena: a structure's points exceed 2^31");
    const std::size_t capacity =
        exact ? live : std::min(std::max<std::size_t>(kFirstPoints, (live + extra) * 2), kPoolLimit);
    // A new pool every time: a held one (pointPool) keeps its points as they were.
    std::shared_ptr<glm::dvec3[]> fresh =
        capacity ? std::make_shared_for_overwrite<glm::dvec3[]>(capacity) : nullptr;
    std::uint32_t at = 0;
    for (const Slot& s : slots_)
        if (PointList* list = pointsAt(s.family, s.offset); list && !list->empty()) {
            std::copy(list->begin(), list->end(), fresh.get() + at);
            list->view(fresh.get() + at, static_cast<std::uint32_t>(list->size()));
            at += static_cast<std::uint32_t>(list->size());
        }
    points_ = std::move(fresh);
    pointsCapacity_ = static_cast<std::uint32_t>(capacity);
    pointsUsed_ = at;
    pointsDead_ = 0;
}

void ElementArena::destroy(const Slot& s) {
    const FamilyOps& ops = kFamilies[s.family];
    if (ops.points) pointsDead_ += static_cast<std::uint32_t>(ops.points(data_ + s.offset)->size());
    ops.destroy(data_ + s.offset);
    dead_ += ops.size;
}

void ElementArena::checkSerial(std::uint64_t serial) {
    if (serial >= kSerialLimit)
        throw std::length_error("ElementArena: element serials exhausted (2^48 inserts and replaces)");
}

void ElementArena::insert(std::size_t at, Element&& e, std::uint64_t serial) {
    checkSerial(serial);
    // Room for the slot first, so that nothing can fail once the payload is in the arena.
    if (slots_.size() == slots_.capacity()) slots_.reserve(std::max<std::size_t>(4, slots_.size() * 2));
    const auto family = static_cast<std::uint16_t>(e.index());
    const std::uint32_t offset = emplace(std::move(e));
    Slot slot{offset, 0, 0, family};
    slot.setSerial(serial);
    slots_.insert(slots_.begin() + static_cast<std::ptrdiff_t>(at), slot);
}

void ElementArena::replace(std::size_t at, Element&& e, std::uint64_t serial) {
    checkSerial(serial);
    const auto family = static_cast<std::uint16_t>(e.index());
    if (slots_[at].family == family) {
        // Same family: the payload is assigned where it is, and the arena does not grow.
        if (PointList* list = pointsOf(e)) {
            reservePoints(list->size());
            pool(*list);
            pointsDead_ += static_cast<std::uint32_t>(pointsAt(family, slots_[at].offset)->size());
        }
        std::byte* place = data_ + slots_[at].offset;
        std::visit(
            [&](auto& payload) {
                using T = std::decay_t<decltype(payload)>;
                // A boxed payload gets a new box: readers may still hold the old one.
                if constexpr (BoxedPayload<T>)
                    *std::launder(reinterpret_cast<detail::StoredPayload<T>*>(place)) =
                        std::make_shared<const T>(std::move(payload));
                else
                    *std::launder(reinterpret_cast<T*>(place)) = std::move(payload);
            },
            e);
    } else {
        const std::uint32_t offset = emplace(std::move(e));  // may move the old payload too
        destroy(slots_[at]);
        slots_[at].offset = offset;
        slots_[at].family = family;
    }
    slots_[at].setSerial(serial);
    compactIfSparse();
}

void ElementArena::erase(std::size_t first, std::size_t last) {
    for (std::size_t i = first; i < last; ++i) destroy(slots_[i]);
    slots_.erase(slots_.begin() + static_cast<std::ptrdiff_t>(first),
                 slots_.begin() + static_cast<std::ptrdiff_t>(last));
    if (slots_.empty())
        clear();
    else
        compactIfSparse();
}

void ElementArena::eraseMarked(const std::vector<char>& marked) {
    std::size_t kept = 0;
    for (std::size_t i = 0; i < slots_.size(); ++i) {
        if (marked[i])
            destroy(slots_[i]);
        else
            slots_[kept++] = slots_[i];
    }
    slots_.resize(kept);
    if (slots_.empty())
        clear();
    else
        compactIfSparse();
}

void ElementArena::settle() {
    // Doubled since the last settle (amortized), or holding the first room mostly unused (a
    // bounded copy): a small structure edited once does not keep its first room.
    const bool doubled = slots_.size() >= 2 * settled_;
    const bool sparse = (capacity_ >= kFirstBytes && used_ < capacity_ / 4) ||
                        (pointsCapacity_ >= kFirstPoints && pointsUsed_ < pointsCapacity_ / 4);
    if (slots_.empty() || !(doubled || sparse)) return;
    relocate(0, true);
    repool(0, true);
    slots_.shrink_to_fit();
    settled_ = static_cast<std::uint32_t>(slots_.size());
}

void ElementArena::compactIfSparse() {
    if (dead_ >= 4096 && dead_ > (used_ - dead_)) relocate(0);
    if (pointsDead_ >= 256 && pointsDead_ > (pointsUsed_ - pointsDead_)) repool(0);
}

void ElementArena::clear() {
    release();
    slots_ = {};
    data_ = nullptr;
    used_ = capacity_ = dead_ = 0;
    points_.reset();
    pointsUsed_ = pointsCapacity_ = pointsDead_ = 0;
    settled_ = 0;
}

void ElementArena::release() noexcept {
    for (const Slot& s : slots_) kFamilies[s.family].destroy(data_ + s.offset);
    if (data_) ::operator delete(data_, kArenaAlign);
    points_.reset();
}

std::string ElementArena::checkLayout() const {
    std::vector<std::pair<std::size_t, std::size_t>> spans;  // [begin, end) of each payload
    for (const Slot& s : slots_) {
        if (s.family >= kFamilies.size()) return "a slot with no payload family";
        const FamilyOps& ops = kFamilies[s.family];
        if (s.offset % ops.align != 0) return "a misaligned payload";
        if (static_cast<std::size_t>(s.offset) + ops.size > used_) return "a payload past the arena's end";
        spans.emplace_back(s.offset, s.offset + ops.size);
    }
    const std::optional<std::size_t> live = disjointLength(spans);
    if (!live) return "two payloads overlap";
    if (used_ > capacity_) return "more bytes used than held";
    if (*live + dead_ != used_) return "live and dead bytes do not add up";
    return checkPool();
}

std::string ElementArena::checkPool() const {
    std::vector<std::pair<std::size_t, std::size_t>> spans;  // [begin, end) of each point list
    for (const Slot& s : slots_) {
        const PointList* list = pointsAt(s.family, s.offset);
        if (!list) continue;
        if (list->ownsPoints()) return "a stored point list outside the pool";
        if (list->empty()) {
            if (list->data()) return "an empty point list viewing the pool";
            continue;
        }
        const glm::dvec3* pool = points_.get();
        if (list->data() < pool || list->data() + list->size() > pool + pointsUsed_)
            return "a point list past the pool's end";
        const auto begin = static_cast<std::size_t>(list->data() - pool);
        spans.emplace_back(begin, begin + list->size());
    }
    const std::optional<std::size_t> live = disjointLength(spans);
    if (!live) return "two point lists overlap";
    if (pointsUsed_ > pointsCapacity_) return "more points used than held";
    if (*live + pointsDead_ != pointsUsed_) return "live and dead points do not add up";
    return {};
}

}  // namespace phigs
