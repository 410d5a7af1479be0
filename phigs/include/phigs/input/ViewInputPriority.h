#pragma once

#include <cstddef>
#include <vector>

namespace phigs {

/// The view transformation input priority list of a workstation: the order in which views
/// are tried when a device position is mapped back to world coordinates. Initially view 0
/// first, then 1, 2, ... (ISO 9592); views the list has not seen yet come last.
class ViewInputPriority {
public:
    /// SET VIEW TRANSFORMATION INPUT PRIORITY: moves `view` just above (higher) or just below
    /// `reference`. Error 114 (as an InputError) for a negative view index.
    void set(int view, int reference, bool higher);
    /// The order for a view table of `viewCount` entries, highest priority first.
    std::vector<int> order(std::size_t viewCount) const;

private:
    void ensure(int view);
    std::vector<int> order_{0};
};

}  // namespace phigs
