#pragma once

#include <algorithm>
#include <set>

namespace phigs {

/// A PHIGS name set filter (pick, highlighting, invisibility): a name set passes when it
/// shares a name with the inclusion set and none with the exclusion set.
struct NameSetFilter {
    std::set<int> inclusion;
    std::set<int> exclusion;

    bool accepts(const std::set<int>& names) const {
        auto meets = [&](const std::set<int>& s) {
            return std::any_of(names.begin(), names.end(), [&](int n) { return s.contains(n); });
        };
        return meets(inclusion) && !meets(exclusion);
    }
    bool operator==(const NameSetFilter&) const = default;
};

}  // namespace phigs
