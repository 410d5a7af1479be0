#pragma once

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <initializer_list>
#include <span>
#include <utility>
#include <vector>

namespace phigs {

/// Read-only values of a draw item: a view of storage its draw segment owns (what traversal
/// makes: no allocation per item), or a copy of its own (any other construction, and every copy).
template <class T>
class ItemArray {
public:
    using value_type = T;
    using size_type = std::size_t;
    using const_iterator = const T*;
    using iterator = const T*;

    ItemArray() = default;
    ItemArray(const std::vector<T>& values) { copy(values.data(), values.size()); }  // NOLINT: reads as one
    ItemArray(std::initializer_list<T> values) { copy(values.begin(), values.size()); }
    ItemArray(std::span<const T> values) { copy(values.data(), values.size()); }  // NOLINT
    /// A view of `size` values at `data`, which must outlive it (a segment's storage).
    static ItemArray view(const T* data, std::size_t size) {
        ItemArray a;
        a.data_ = size ? data : nullptr;
        a.size_ = static_cast<std::uint32_t>(size);
        return a;
    }
    ItemArray(const ItemArray& other) { copy(other.data_, other.size_); }
    ItemArray(ItemArray&& other) noexcept
        : data_(std::exchange(other.data_, nullptr)),
          size_(std::exchange(other.size_, 0)),
          owned_(std::exchange(other.owned_, false)) {}
    ItemArray& operator=(ItemArray other) noexcept {
        std::swap(data_, other.data_);
        std::swap(size_, other.size_);
        std::swap(owned_, other.owned_);
        return *this;
    }
    ~ItemArray() {
        if (owned_) delete[] data_;
    }

    std::size_t size() const { return size_; }
    bool empty() const { return size_ == 0; }
    const T* data() const { return data_; }
    const T* begin() const { return data_; }
    const T* end() const { return data_ + size_; }
    const T& operator[](std::size_t i) const { return data_[i]; }
    const T& front() const { return data_[0]; }
    const T& back() const { return data_[size_ - 1]; }
    /// Whether this array holds its own copy (false: a view of a segment's storage, or empty).
    bool owned() const { return owned_; }
    operator std::span<const T>() const { return {data_, size_}; }  // NOLINT: reads as a span
    operator std::vector<T>() const { return {begin(), end()}; }    // NOLINT: reads as a vector

    friend bool operator==(const ItemArray& a, const ItemArray& b) {
        return std::equal(a.begin(), a.end(), b.begin(), b.end());
    }

private:
    void copy(const T* values, std::size_t size) {
        if (size == 0) return;
        T* own = new T[size];
        std::copy(values, values + size, own);
        data_ = own;
        size_ = static_cast<std::uint32_t>(size);
        owned_ = true;
    }

    const T* data_ = nullptr;
    std::uint32_t size_ = 0;
    bool owned_ = false;
};

}  // namespace phigs
