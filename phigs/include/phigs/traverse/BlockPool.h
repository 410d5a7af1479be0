#pragma once

#include <algorithm>
#include <array>
#include <cstddef>
#include <memory>
#include <new>
#include <utility>
#include <vector>

namespace phigs {

/// Values copied into blocks that never move, so views of them stay valid until the pool is
/// cleared or goes; a cleared pool fills its blocks again without allocating. With
/// `InlineCount`, the first values live in the pool itself (a record that holds the pool holds
/// them too: reading them touches no other allocation), and the pool does not move.
template <class T, std::size_t InlineCount = 0>
class BlockPool {
public:
    BlockPool() { rewind(); }
    BlockPool(const BlockPool&) = delete;
    BlockPool& operator=(const BlockPool&) = delete;
    /// The moved-from pool is empty (no blocks, filling from the start).
    BlockPool(BlockPool&& other) noexcept requires(InlineCount == 0) { *this = std::move(other); }
    BlockPool& operator=(BlockPool&& other) noexcept requires(InlineCount == 0) {
        heap_ = std::exchange(other.heap_, {});
        current_ = std::exchange(other.current_, 0);
        next_ = std::exchange(other.next_, nullptr);
        end_ = std::exchange(other.end_, nullptr);
        nextBlock_ = std::exchange(other.nextBlock_, 1);
        return *this;
    }

    /// The size of the next block to allocate (at least).
    void reserve(std::size_t count) { nextBlock_ = std::max(nextBlock_, count); }

    /// A copy of `count` values at `values`, in place until the pool is cleared or goes.
    const T* add(const T* values, std::size_t count) {
        if (count == 0) return nullptr;
        if (static_cast<std::size_t>(end_ - next_) < count) advance(count);
        T* at = next_;
        std::copy(values, values + count, at);
        next_ += count;
        return at;
    }

    /// Forgets every value (views of them dangle) and keeps the blocks for the next ones.
    void clear() { rewind(); }

    /// Values the blocks hold room for (the inline room included).
    std::size_t capacity() const {
        std::size_t total = InlineCount;
        for (const Block& b : heap_) total += b.size;
        return total;
    }

private:
    struct Block {
        std::unique_ptr<T[]> data;
        std::size_t size = 0;
    };
    struct Room {
        T* data = nullptr;
        std::size_t size = 0;
    };
    static constexpr std::size_t kInlineBlocks = InlineCount > 0 ? 1 : 0;

    std::size_t blockCount() const { return kInlineBlocks + heap_.size(); }
    /// Block b of the pool: the inline room first (when there is one), then the heap blocks.
    Room blockAt(std::size_t b) {
        if constexpr (kInlineBlocks > 0)
            if (b == 0) return {std::launder(reinterpret_cast<T*>(inline_.data())), InlineCount};
        const Block& block = heap_[b - kInlineBlocks];
        return {block.data.get(), block.size};
    }
    /// Fills from the first block again (none yet: the next value allocates one).
    void rewind() {
        current_ = 0;
        const Room first = blockCount() ? blockAt(0) : Room{};
        next_ = first.data, end_ = first.data + first.size;
    }
    /// Moves on to the next block with room for `count` values, allocating one when none has.
    void advance(std::size_t count) {
        std::size_t b = blockCount() == 0 ? 0 : current_ + 1;
        while (b < blockCount() && blockAt(b).size < count) ++b;
        if (b == blockCount()) {
            const std::size_t size = std::max(count, nextBlock_);
            nextBlock_ = size * 2;
            heap_.push_back({std::make_unique_for_overwrite<T[]>(size), size});
        }
        const Room room = blockAt(b);
        current_ = b, next_ = room.data, end_ = room.data + room.size;
    }

    alignas(T) std::array<std::byte, InlineCount * sizeof(T)> inline_;
    T* next_ = nullptr;        ///< where the next values go
    T* end_ = nullptr;         ///< the end of the block being filled
    std::size_t current_ = 0;  ///< the block being filled
    /// Unreserved, the first heap block holds just the first values (a segment's one transform
    /// is the common case), and blocks double from there.
    std::size_t nextBlock_ = std::max<std::size_t>(1, 2 * InlineCount);
    std::vector<Block> heap_;  ///< the blocks past the inline room
};

}  // namespace phigs
