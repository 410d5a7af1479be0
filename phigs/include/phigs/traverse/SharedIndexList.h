#pragma once

#include <cstddef>
#include <cstdint>
#include <initializer_list>
#include <memory>
#include <utility>
#include <vector>

namespace phigs {

/// Mesh indices that meshes of one shape share (every surface tessellated on the same grid has
/// the same triangles): read as a const std::vector, copied on the first change while shared.
class SharedIndexList {
public:
    using Vector = std::vector<std::uint32_t>;
    using value_type = std::uint32_t;
    using size_type = std::size_t;
    using const_iterator = Vector::const_iterator;
    using iterator = const_iterator;

    SharedIndexList() = default;
    SharedIndexList(Vector values)  // NOLINT: a vector reads as its list
        : values_(std::make_shared<Vector>(std::move(values))), writable_(true) {}
    SharedIndexList(std::initializer_list<std::uint32_t> values) : SharedIndexList(Vector(values)) {}
    /// A list reading `values`, which it never changes (a change copies them first).
    static SharedIndexList shared(std::shared_ptr<const Vector> values) {
        SharedIndexList list;
        list.values_ = std::move(values);
        return list;
    }
    /// Copies read the same values; either copies them before its first change.
    SharedIndexList(const SharedIndexList& other) : values_(other.values_) {}
    SharedIndexList& operator=(const SharedIndexList& other) {
        values_ = other.values_;
        writable_ = false;
        return *this;
    }
    SharedIndexList(SharedIndexList&& other) noexcept
        : values_(std::move(other.values_)), writable_(std::exchange(other.writable_, false)) {}
    SharedIndexList& operator=(SharedIndexList&& other) noexcept {
        values_ = std::move(other.values_);
        writable_ = std::exchange(other.writable_, false);
        return *this;
    }

    const Vector& values() const { return values_ ? *values_ : none(); }
    operator const Vector&() const { return values(); }  // NOLINT: reads as the vector
    /// Whether both read the same storage (shared, not copied).
    bool sharesWith(const SharedIndexList& other) const { return values_ && values_ == other.values_; }

    std::size_t size() const { return values().size(); }
    bool empty() const { return values().empty(); }
    const std::uint32_t* data() const { return values().data(); }
    const std::uint32_t& operator[](std::size_t i) const { return values()[i]; }
    const_iterator begin() const { return values().begin(); }
    const_iterator end() const { return values().end(); }

    void push_back(std::uint32_t value) { own().push_back(value); }
    void emplace_back(std::uint32_t value) { own().push_back(value); }
    void reserve(std::size_t count) { own().reserve(count); }
    void shrink_to_fit() { own().shrink_to_fit(); }
    void clear() { own().clear(); }
    const_iterator insert(const_iterator at, std::initializer_list<std::uint32_t> values) {
        const auto offset = at - begin();
        Vector& v = own();
        return v.insert(v.begin() + offset, values);
    }
    template <class It>
    const_iterator insert(const_iterator at, It first, It last) {
        const auto offset = at - begin();
        Vector& v = own();
        return v.insert(v.begin() + offset, first, last);
    }

    friend bool operator==(const SharedIndexList& a, const SharedIndexList& b) {
        return a.values() == b.values();
    }
    friend bool operator==(const SharedIndexList& a, const Vector& b) { return a.values() == b; }

private:
    static const Vector& none() {
        static const Vector empty;
        return empty;
    }
    /// The values, this list's own and not shared: copied first when they are not.
    Vector& own() {
        if (!values_ || !writable_ || values_.use_count() > 1) {
            values_ = std::make_shared<Vector>(values());
            writable_ = true;
        }
        return const_cast<Vector&>(*values_);  // made here, as a non-const vector
    }

    std::shared_ptr<const Vector> values_;
    bool writable_ = false;  ///< values_ made by this list (never by a shared source)
};

}  // namespace phigs
