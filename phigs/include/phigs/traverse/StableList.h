#pragma once

#include <algorithm>
#include <cstddef>
#include <memory>
#include <new>
#include <utility>
#include <vector>

namespace phigs {

/// Values built in place in blocks that never move, so views of them stay valid until the list
/// is cleared or goes; an empty list holds no storage, and a cleared one fills its blocks again.
template <class T>
class StableList {
public:
    StableList() = default;
    StableList(const StableList&) = delete;
    StableList& operator=(const StableList&) = delete;
    ~StableList() {
        clear();
        for (const Block& b : blocks_) std::allocator<T>().deallocate(b.data, b.capacity);
    }

    std::size_t size() const { return size_; }
    bool empty() const { return size_ == 0; }

    /// A new last value made from `args`, in place until the list is cleared or goes.
    template <class... Args>
    T& emplace_back(Args&&... args) {
        if (current_ == blocks_.size() || used_ == blocks_[current_].capacity) nextBlock();
        T* value = ::new (static_cast<void*>(blocks_[current_].data + used_)) T(std::forward<Args>(args)...);
        ++used_, ++size_;
        return *value;
    }

    /// Destroys every value (views of them dangle) and keeps the blocks for the next ones.
    void clear() {
        for (std::size_t b = 0; b < blocks_.size() && b <= current_; ++b) {
            const std::size_t count = b < current_ ? blocks_[b].capacity : used_;
            for (std::size_t i = 0; i < count; ++i) blocks_[b].data[i].~T();
        }
        current_ = used_ = size_ = 0;
    }

    /// Values the blocks hold room for.
    std::size_t capacity() const {
        std::size_t total = 0;
        for (const Block& b : blocks_) total += b.capacity;
        return total;
    }

private:
    struct Block {
        T* data = nullptr;
        std::size_t capacity = 0;
    };
    /// Moves on to the next block, allocating it (twice the last one's size) when there is none.
    void nextBlock() {
        if (current_ < blocks_.size()) ++current_;
        used_ = 0;
        if (current_ < blocks_.size()) return;
        const std::size_t capacity = blocks_.empty() ? kFirstBlock : 2 * blocks_.back().capacity;
        blocks_.reserve(blocks_.size() + 1);  // the push below cannot throw and leak the block
        blocks_.push_back({std::allocator<T>().allocate(capacity), capacity});
    }

    /// About 128 bytes: most segments hold one or two records of a kind (a context, a mesh), and
    /// a draw list has one segment per structure, so a first block of large records costs much.
    static constexpr std::size_t kFirstBlock = std::max<std::size_t>(1, 128 / sizeof(T));
    std::vector<Block> blocks_;
    std::size_t current_ = 0, used_ = 0;  ///< the block being filled and the values it holds
    std::size_t size_ = 0;
};

}  // namespace phigs
