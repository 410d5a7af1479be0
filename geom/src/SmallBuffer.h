#pragma once

#include <algorithm>
#include <cstddef>
#include <span>
#include <vector>

namespace geom::detail {

/// Scratch of n values: on the stack up to N, on the heap beyond. Per-point evaluation runs
/// millions of times, and small degrees should not pay an allocation per point.
template <class T, std::size_t N>
class SmallBuffer {
public:
    /// n values left as T's default constructor leaves them (scratch the caller fills).
    explicit SmallBuffer(std::size_t n) : size_(n) {
        if (n > N) {
            heap_.resize(n);
            data_ = heap_.data();
        }
    }
    SmallBuffer(std::size_t n, const T& value) : SmallBuffer(n) { std::fill_n(data_, n, value); }
    SmallBuffer(const SmallBuffer&) = delete;
    SmallBuffer& operator=(const SmallBuffer&) = delete;

    T& operator[](std::size_t i) { return data_[i]; }
    const T& operator[](std::size_t i) const { return data_[i]; }
    std::span<T> span() { return {data_, size_}; }

private:
    T stack_[N];
    std::vector<T> heap_;
    T* data_ = stack_;
    std::size_t size_;
};

}  // namespace geom::detail
