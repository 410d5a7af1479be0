#pragma once

#include <algorithm>
#include <cstddef>
#include <unordered_map>
#include <utility>
#include <vector>

namespace phigs {

/// Values by structure id: a vector for the small, nearly contiguous ids applications use (one
/// array access per lookup, the hot path of traversal), a hash map for the others. A value
/// equal to `T{}` (or empty) reads as absent.
template <class T>
class IdTable {
public:
    const T* find(int id) const {
        const T* value = nullptr;
        if (dense(id)) {
            value = &dense_[static_cast<std::size_t>(id)];
        } else if (auto it = sparse_.find(id); it != sparse_.end()) {
            value = &it->second;
        }
        return value && !absent(*value) ? value : nullptr;
    }
    T* find(int id) { return const_cast<T*>(std::as_const(*this).find(id)); }

    /// The value of `id`, default-made (absent) when missing.
    T& operator[](int id) {
        if (!dense(id) && id >= 0 && id < kDenseLimit &&
            static_cast<std::size_t>(id) < 2 * dense_.size() + kDenseSlack)
            grow(static_cast<std::size_t>(id) + 1);
        return dense(id) ? dense_[static_cast<std::size_t>(id)] : sparse_[id];
    }

    void erase(int id) {
        if (dense(id))
            dense_[static_cast<std::size_t>(id)] = T{};
        else
            sparse_.erase(id);
    }
    void clear() {
        dense_.clear();
        sparse_.clear();
    }

    /// Calls f(id, value) for every value present (dense ids ascending, then the others).
    template <class F>
    void forEach(F f) {
        for (std::size_t i = 0; i < dense_.size(); ++i)
            if (!absent(dense_[i])) f(static_cast<int>(i), dense_[i]);
        for (auto& [id, value] : sparse_)
            if (!absent(value)) f(id, value);
    }

private:
    static constexpr int kDenseLimit = 1 << 22;
    static constexpr std::size_t kDenseSlack = 1024;

    static bool absent(const T& value) {
        if constexpr (requires { value.empty(); })
            return value.empty();
        else
            return value == T{};
    }
    bool dense(int id) const { return id >= 0 && static_cast<std::size_t>(id) < dense_.size(); }

    void grow(std::size_t size) {
        const std::size_t from = dense_.size();
        // Exactly to `size`: the vector's own growth keeps this amortized, and the room it keeps
        // past the last id is never written (so never resident).
        dense_.resize(size);
        // Values kept in the map for ids the vector now covers move into it: looked up one by one
        // where fewer ids were added than the map holds (the vector grows an id at a time), else
        // by one pass over the map.
        if (size - from < sparse_.size()) {
            for (std::size_t id = from; id < size; ++id)
                if (auto it = sparse_.find(static_cast<int>(id)); it != sparse_.end()) {
                    dense_[id] = std::move(it->second);
                    sparse_.erase(it);
                }
            return;
        }
        for (auto it = sparse_.begin(); it != sparse_.end();) {
            if (it->first >= 0 && static_cast<std::size_t>(it->first) >= from && dense(it->first)) {
                dense_[static_cast<std::size_t>(it->first)] = std::move(it->second);
                it = sparse_.erase(it);
            } else {
                ++it;
            }
        }
    }

    std::vector<T> dense_;
    std::unordered_map<int, T> sparse_;
};

}  // namespace phigs
