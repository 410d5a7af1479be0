#include "phigs/pick/DrawListMeasurer.h"

#include <glm/matrix.hpp>

#include <algorithm>

namespace phigs {

DrawListMeasurer::DrawListMeasurer(const DrawList& display)
    : display_([&display]() -> const DrawList& { return display; }) {
}

DrawListMeasurer::DrawListMeasurer(std::function<const DrawList&()> display) : display_(std::move(display)) {
}

WorkstationMapping DrawListMeasurer::mappingOf(const DrawList& list) const {
    if (!surface_) return WorkstationMapping(list);
    const auto [width, height] = surface_();
    return WorkstationMapping(list, width, height);
}

glm::dvec3 DrawListMeasurer::toNpc(glm::dvec2 pixels) const {
    return mapping().pixelsToNpc(pixels, locatorDepth_);
}

int DrawListMeasurer::viewFor(const DrawList& list, const std::vector<glm::dvec3>& npc) const {
    std::vector<int> order;
    for (int v : list.viewInputPriority)
        if (v >= 0 && static_cast<std::size_t>(v) < list.views.size()) order.push_back(v);
    for (int v = 0; static_cast<std::size_t>(v) < list.views.size(); ++v)
        if (std::find(order.begin(), order.end(), v) == order.end()) order.push_back(v);
    for (int v : order) {
        const DrawView& view = list.views[static_cast<std::size_t>(v)];
        bool all = true;
        for (const glm::dvec3& p : npc)
            all = all && p.x >= view.clipMin.x && p.x <= view.clipMax.x && p.y >= view.clipMin.y &&
                  p.y <= view.clipMax.y;
        if (all) return v;
    }
    return 0;
}

glm::dvec3 DrawListMeasurer::toWorld(const DrawList& list, int view, const glm::dvec3& npc) const {
    if (static_cast<std::size_t>(view) >= list.views.size()) return npc;  // no views: world = NPC
    const DrawView& v = list.views[static_cast<std::size_t>(view)];
    const glm::dvec4 h = glm::inverse(v.mapping * v.orientation) * glm::dvec4(npc, 1.0);
    return glm::dvec3(h) / h.w;
}

LocatorMeasure DrawListMeasurer::locate(glm::dvec2 deviceCoordinates) const {
    const DrawList& list = display();
    const glm::dvec3 npc = mappingOf(list).pixelsToNpc(deviceCoordinates, locatorDepth_);
    const int view = viewFor(list, {npc});
    return {view, toWorld(list, view, npc)};
}

StrokeMeasure DrawListMeasurer::stroke(const std::vector<glm::dvec2>& deviceCoordinates) const {
    const DrawList& list = display();
    const WorkstationMapping mapping = mappingOf(list);
    std::vector<glm::dvec3> npc;
    for (const glm::dvec2& p : deviceCoordinates) npc.push_back(mapping.pixelsToNpc(p, locatorDepth_));
    StrokeMeasure m;
    m.viewIndex = viewFor(list, npc);
    for (const glm::dvec3& p : npc) m.points.push_back(toWorld(list, m.viewIndex, p));
    return m;
}

PickMeasure DrawListMeasurer::pick(glm::dvec2 deviceCoordinates, const InputDevice& device) const {
    const DrawList& list = pickList_ ? pickList_(device) : display();
    const WorkstationMapping mapping = mappingOf(list);
    const glm::dvec3 npc = mapping.pixelsToNpc(deviceCoordinates, locatorDepth_);
    echo_.clear();
    const auto hit = picker_.nearest(list, mapping, glm::dvec2(npc), device.setup.pickAperture);
    PickMeasure m;
    if (!hit) return m;
    m.status = InputStatus::Ok;
    m.path = pickPath(list.items[hit->item].source, device.setup.pathOrder, device.pickPathDepth);
    m.surface = hit->surface;
    if (device.echo == EchoSwitch::Echo) echo_ = echoItems(list, *hit, device.setup.promptEchoType == 2);
    return m;
}

}  // namespace phigs
