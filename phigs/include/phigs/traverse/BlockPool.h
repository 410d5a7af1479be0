#pragma once

#include <algorithm>
#include <cstddef>
#include <memory>
#include <utility>
#include <vector>

namespace phigs {

/// Values copied into blocks that never move, so views of them stay valid until the pool is
/// cleared or goes; a cleared pool fills its blocks again without allocating.
template <class T>
class BlockPool {
public:
    BlockPool() = default;
    BlockPool(const BlockPool&) = delete;
    BlockPool& operator=(const BlockPool&) = delete;
    /// The moved-from pool is empty (no blocks, filling from the start).
    BlockPool(BlockPool&& other) noexcept { *this = std::move(other); }
    BlockPool& operator=(BlockPool&& other) noexcept {
        blocks_ = std::exchange(other.blocks_, {});
        current_ = std::exchange(other.current_, 0);
        used_ = std::exchange(other.used_, 0);
        nextBlock_ = std::exchange(other.nextBlock_, 1);
        return *this;
    }

    /// The size of the next block to allocate (at least).
    void reserve(std::size_t count) { nextBlock_ = std::max(nextBlock_, count); }

    /// A copy of `count` values at `values`, in place until the pool is cleared or goes.
    const T* add(const T* values, std::size_t count) {
        if (count == 0) return nullptr;
        while (current_ < blocks_.size() && blocks_[current_].size - used_ < count) ++current_, used_ = 0;
        if (current_ == blocks_.size()) {
            const std::size_t size = std::max(count, nextBlock_);
            nextBlock_ = size * 2;
            blocks_.push_back({std::make_unique_for_overwrite<T[]>(size), size});
            used_ = 0;
        }
        T* at = blocks_[current_].data.get() + used_;
        std::copy(values, values + count, at);
        used_ += count;
        return at;
    }

    /// Forgets every value (views of them dangle) and keeps the blocks for the next ones.
    void clear() { current_ = used_ = 0; }

    /// Values the blocks hold room for.
    std::size_t capacity() const {
        std::size_t total = 0;
        for (const Block& b : blocks_) total += b.size;
        return total;
    }

private:
    struct Block {
        std::unique_ptr<T[]> data;
        std::size_t size = 0;
    };
    std::vector<Block> blocks_;
    std::size_t current_ = 0, used_ = 0;  ///< the block being filled and the values it holds
    /// Unreserved, the first block holds just the first values (a segment's one transform is
    /// the common case), and blocks double from there.
    std::size_t nextBlock_ = 1;
};

}  // namespace phigs
