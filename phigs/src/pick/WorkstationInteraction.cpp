#include "phigs/pick/WorkstationInteraction.h"

namespace phigs {

WorkstationInteraction::WorkstationInteraction(Workstation& workstation, InputSource& source,
                                               InputQueue& queue, DeviceCounts counts)
    : workstation_(workstation),
      measurer_([this]() -> const DrawList& { return workstation_.display(); }),
      input_(std::make_unique<WorkstationInput>(workstation.id(), source, measurer_, queue, counts)) {
    measurer_.setSurfaceSize([this] {
        const DrawableSize size = workstation_.drawableSize();
        if (size.width > 0 && size.height > 0) return DrawListMeasurer::SurfaceSize{size.width, size.height};
        const glm::dvec2 display = workstation_.displaySize();  // minimised: no pixels to map
        return DrawListMeasurer::SurfaceSize{std::uint32_t(display.x), std::uint32_t(display.y)};
    });
    measurer_.setPickListProvider(
        [this](const InputDevice& device) -> const DrawList& { return pickList(device); });
}

namespace {

bool sameFilter(const std::optional<NameSetFilter>& a, const std::optional<NameSetFilter>& b) {
    if (a.has_value() != b.has_value()) return false;
    return !a || (a->inclusion == b->inclusion && a->exclusion == b->exclusion);
}

bool sameFilters(const TraversalFilters& a, const TraversalFilters& b) {
    return sameFilter(a.pick, b.pick) && sameFilter(a.highlight, b.highlight) &&
           sameFilter(a.invisibility, b.invisibility) && a.initialNames == b.initialNames;
}

}  // namespace

const DrawList& WorkstationInteraction::pickList(const InputDevice& device) {
    TraversalFilters filters = workstation_.filters();
    if (device.pickFilterSet) filters.pick = NameSetFilter{device.pickInclusion, device.pickExclusion};
    PickList& cached = pickLists_[device.number];
    lastPickList_ = &cached.list;
    const std::uint64_t stamp = workstation_.contentStamp();
    // Nothing the traversal reads changed: the list, its generation and the Picker's tree stay.
    if (cached.made && cached.stamp == stamp && sameFilters(cached.filters, filters)) return cached.list;
    cached.list = workstation_.traverse(filters);
    // A new generation per traversal lets the Picker drop intersectors of deleted surfaces.
    cached.list.generation = ++traversals_;
    cached.filters = std::move(filters);
    cached.stamp = stamp;
    cached.made = true;
    return cached.list;
}

std::vector<std::vector<DrawPathLevel>> WorkstationInteraction::lastEcho() const {
    std::vector<std::vector<DrawPathLevel>> paths;
    if (!lastPickList_) return paths;
    for (std::size_t i : measurer_.lastEcho()) paths.push_back(lastPickList_->items.at(i).source.path);
    return paths;
}

}  // namespace phigs
