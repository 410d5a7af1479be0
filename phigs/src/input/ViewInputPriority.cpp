#include "phigs/input/ViewInputPriority.h"

#include "phigs/input/InputError.h"

#include <algorithm>

namespace phigs {

void ViewInputPriority::ensure(int view) {
    for (int v = static_cast<int>(order_.size()); v <= view; ++v)
        if (std::find(order_.begin(), order_.end(), v) == order_.end()) order_.push_back(v);
}

void ViewInputPriority::set(int view, int reference, bool higher) {
    if (view < 0 || reference < 0)
        throw InputError(114, "SET VIEW TRANSFORMATION INPUT PRIORITY", "view index must not be negative");
    ensure(std::max(view, reference));
    if (view == reference) return;
    std::erase(order_, view);
    auto at = std::find(order_.begin(), order_.end(), reference);
    if (!higher) ++at;
    order_.insert(at, view);
}

std::vector<int> ViewInputPriority::order(std::size_t viewCount) const {
    std::vector<int> out;
    for (int v : order_)
        if (static_cast<std::size_t>(v) < viewCount) out.push_back(v);
    for (int v = 0; static_cast<std::size_t>(v) < viewCount; ++v)
        if (std::find(out.begin(), out.end(), v) == out.end()) out.push_back(v);
    return out;
}

}  // namespace phigs
