#pragma once

#include <cstdint>
#include <utility>

namespace phigs {

/// One read-only value of a draw item: a view of a record shared by many items (a segment's
/// transform, an interned style; what traversal makes), or a copy of its own (any other
/// construction, and every copy of a view but a permanent one). One pointer wide: the low bits
/// say whether it owns, or views a record that lives for the program.
template <class T>
class ItemRef {
    static_assert(alignof(T) >= 4, "the two low bits of the pointer tell an owned copy or a permanent view");

public:
    /// A view of one default value, shared by every default reference.
    ItemRef() : bits_(reinterpret_cast<std::uintptr_t>(&defaultValue()) | kPermanent) {}
    ItemRef(const T& value) : bits_(ownedCopy(value)) {}  // NOLINT
    ItemRef(T&& value)
        : bits_(reinterpret_cast<std::uintptr_t>(new T(std::move(value))) | kOwned) {}  // NOLINT
    /// A view of `record`, which must outlive it (segment storage, an interned style).
    static ItemRef view(const T* record) { return ItemRef(reinterpret_cast<std::uintptr_t>(record)); }
    /// A view of `record`, which lives for the program (a static default): copies view it too.
    static ItemRef permanent(const T* record) {
        return ItemRef(reinterpret_cast<std::uintptr_t>(record) | kPermanent);
    }
    /// A copy of its own, except that a copy of a permanent view is that view (default items
    /// are copied often, and need not allocate).
    ItemRef(const ItemRef& other)
        : bits_((other.bits_ & kPermanent) ? other.bits_ : ownedCopy(other.get())) {}
    ItemRef(ItemRef&& other) noexcept : bits_(std::exchange(other.bits_, 0)) {}
    ItemRef& operator=(ItemRef other) noexcept {
        std::swap(bits_, other.bits_);
        return *this;
    }
    ~ItemRef() {
        if (owned()) delete ptr();
    }

    const T& get() const { return *ptr(); }
    const T& operator*() const { return *ptr(); }
    const T* operator->() const { return ptr(); }
    operator const T&() const { return *ptr(); }  // NOLINT: reads as the value
    /// The value to change in place: a view becomes a copy of its own first.
    T& edit() {
        if (!owned()) *this = ItemRef(get());
        return *const_cast<T*>(ptr());
    }
    /// Whether this holds its own copy (false: a view of shared storage).
    bool owned() const { return (bits_ & kOwned) != 0; }
    /// Whether two references show the same record (views of one interned style do).
    bool sameRecord(const ItemRef& other) const { return ptr() == other.ptr(); }

    friend bool operator==(const ItemRef& a, const ItemRef& b) { return a.get() == b.get(); }

private:
    static const T& defaultValue() {
        static const T value{};
        return value;
    }
    static constexpr std::uintptr_t kOwned = 1, kPermanent = 2;
    static std::uintptr_t ownedCopy(const T& value) {
        return reinterpret_cast<std::uintptr_t>(new T(value)) | kOwned;
    }
    explicit ItemRef(std::uintptr_t bits) : bits_(bits) {}
    const T* ptr() const { return reinterpret_cast<const T*>(bits_ & ~(kOwned | kPermanent)); }

    std::uintptr_t bits_ = 0;
};

}  // namespace phigs
