#pragma once

#include <algorithm>
#include <array>
#include <cstddef>
#include <memory>
#include <new>
#include <utility>
#include <vector>

namespace phigs {

/// Values built in place in blocks that never move, so views of them stay valid until the list
/// is cleared or goes; a cleared list fills its blocks again. With `InlineCount`, the first
/// values live in the list itself (a record that holds the list holds them too: reading them
/// touches no other allocation); without, an empty list holds no storage.
template <class T, std::size_t InlineCount = 0>
class StableList {
public:
    StableList() { rewind(); }
    StableList(const StableList&) = delete;
    StableList& operator=(const StableList&) = delete;
    ~StableList() {
        clear();
        for (const Block& b : heap_) std::allocator<T>().deallocate(b.data, b.capacity);
    }

    std::size_t size() const { return size_; }
    bool empty() const { return size_ == 0; }

    /// A new last value made from `args`, in place until the list is cleared or goes.
    template <class... Args>
    T& emplace_back(Args&&... args) {
        if (next_ == end_) nextBlock();
        T* value = ::new (static_cast<void*>(next_)) T(std::forward<Args>(args)...);
        ++next_, ++size_;
        return *value;
    }

    /// Destroys every value (views of them dangle) and keeps the blocks for the next ones.
    void clear() {
        if (size_ == 0) return rewind();
        for (std::size_t b = 0; b <= current_; ++b) {
            const Block block = blockAt(b);
            T* const stop = b < current_ ? block.data + block.capacity : next_;
            for (T* value = block.data; value != stop; ++value) value->~T();
        }
        rewind();
    }

    /// Values the blocks hold room for (the inline room included).
    std::size_t capacity() const {
        std::size_t total = InlineCount;
        for (const Block& b : heap_) total += b.capacity;
        return total;
    }

private:
    struct Block {
        T* data = nullptr;
        std::size_t capacity = 0;
    };
    static constexpr std::size_t kInlineBlocks = InlineCount > 0 ? 1 : 0;

    T* inlineData() { return std::launder(reinterpret_cast<T*>(inline_.data())); }
    std::size_t blockCount() const { return kInlineBlocks + heap_.size(); }
    /// Block b of the list: the inline room first (when there is one), then the heap blocks.
    Block blockAt(std::size_t b) {
        if constexpr (kInlineBlocks > 0)
            if (b == 0) return {inlineData(), InlineCount};
        return heap_[b - kInlineBlocks];
    }
    /// Fills from the first block again (none yet: the next value allocates one).
    void rewind() {
        current_ = 0, size_ = 0;
        const Block first = blockCount() ? blockAt(0) : Block{};
        next_ = first.data, end_ = first.data + first.capacity;
    }
    /// Moves on to the next block, allocating it (twice the last one's size) when there is none.
    void nextBlock() {
        const std::size_t b = blockCount() == 0 ? 0 : current_ + 1;
        if (b == blockCount()) {
            const std::size_t capacity = b == 0 ? kFirstBlock : 2 * blockAt(b - 1).capacity;
            heap_.reserve(heap_.size() + 1);  // the push below cannot throw and leak the block
            heap_.push_back({std::allocator<T>().allocate(capacity), capacity});
        }
        const Block block = blockAt(b);
        current_ = b, next_ = block.data, end_ = block.data + block.capacity;
    }

    /// About 128 bytes: most segments hold one or two records of a kind (a context, a mesh), and
    /// a draw list has one segment per structure, so a first block of large records costs much.
    static constexpr std::size_t kFirstBlock = std::max<std::size_t>(1, 128 / sizeof(T));
    alignas(T) std::array<std::byte, InlineCount * sizeof(T)> inline_;
    T* next_ = nullptr;                   ///< where the next value goes
    T* end_ = nullptr;                    ///< the end of the block being filled
    std::size_t current_ = 0, size_ = 0;  ///< the block being filled; the values held
    std::vector<Block> heap_;             ///< the blocks past the inline room
};

}  // namespace phigs
