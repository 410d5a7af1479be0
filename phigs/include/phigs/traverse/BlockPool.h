#pragma once

#include <algorithm>
#include <cstddef>
#include <memory>
#include <vector>

namespace phigs {

/// Values copied into blocks that never move, so views of them stay valid while the pool lives.
template <class T>
class BlockPool {
public:
    BlockPool() = default;
    BlockPool(const BlockPool&) = delete;
    BlockPool& operator=(const BlockPool&) = delete;
    BlockPool(BlockPool&&) noexcept = default;
    BlockPool& operator=(BlockPool&&) noexcept = default;

    /// The size of the first block, when nothing was added yet.
    void reserve(std::size_t count) { nextBlock_ = std::max(nextBlock_, count); }

    /// A copy of `count` values at `values`, in place until the pool goes.
    const T* add(const T* values, std::size_t count) {
        if (count == 0) return nullptr;
        if (capacity_ - used_ < count) {
            capacity_ = std::max(count, nextBlock_);
            nextBlock_ = capacity_ * 2;
            blocks_.push_back(std::make_unique_for_overwrite<T[]>(capacity_));
            used_ = 0;
        }
        T* at = blocks_.back().get() + used_;
        std::copy(values, values + count, at);
        used_ += count;
        return at;
    }

private:
    std::vector<std::unique_ptr<T[]>> blocks_;
    std::size_t used_ = 0, capacity_ = 0;
    /// Unreserved, the first block holds just the first values (a segment's one transform is
    /// the common case: 16 of them were 2 KiB a segment), and blocks double from there.
    std::size_t nextBlock_ = 1;
};

}  // namespace phigs
