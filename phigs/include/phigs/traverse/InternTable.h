#pragma once

#include <cstddef>
#include <deque>
#include <functional>
#include <unordered_map>

namespace phigs {

/// Distinct values, each stored once at an address that never changes: `intern` gives the
/// record equal to a value (made on first sight), so equal values share one record. `Hash` may
/// look at a few fields only: equality decides, the hash only narrows the search.
template <class T, class Hash>
class InternTable {
public:
    const T* intern(const T& value) {
        const std::size_t h = Hash{}(value);
        auto [first, last] = index_.equal_range(h);
        for (auto it = first; it != last; ++it)
            if (*it->second == value) return it->second;
        const T* record = &records_.emplace_back(value);  // a deque never moves its elements
        index_.emplace(h, record);
        return record;
    }
    std::size_t size() const { return records_.size(); }

private:
    std::deque<T> records_;
    std::unordered_multimap<std::size_t, const T*> index_;
};

}  // namespace phigs
