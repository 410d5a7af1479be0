#include "phigs/pick/DrawListMeasurer.h"

#include "phigs/pick/WorkstationMapping.h"

#include <glm/matrix.hpp>

namespace phigs {

DrawListMeasurer::DrawListMeasurer(const DrawList& display) : display_(display) {
}

glm::dvec3 DrawListMeasurer::toNpc(glm::dvec2 pixels) const {
    const double height = displayHeight_ >= 0 ? displayHeight_ : display_.viewportMax.y;
    const WorkstationMapping mapping(display_);
    glm::dvec3 npc = mapping.toNpc(glm::dvec3(pixels.x, height - pixels.y, display_.viewportMin.z));
    npc.z = locatorDepth_;
    return npc;
}

int DrawListMeasurer::viewFor(const std::vector<glm::dvec3>& npc) const {
    for (int v : priority_.order(display_.views.size())) {
        const DrawView& view = display_.views[static_cast<std::size_t>(v)];
        bool all = true;
        for (const glm::dvec3& p : npc)
            all = all && p.x >= view.clipMin.x && p.x <= view.clipMax.x && p.y >= view.clipMin.y &&
                  p.y <= view.clipMax.y;
        if (all) return v;
    }
    return 0;
}

glm::dvec3 DrawListMeasurer::toWorld(int view, const glm::dvec3& npc) const {
    if (static_cast<std::size_t>(view) >= display_.views.size()) return npc;  // no views: world = NPC
    const DrawView& v = display_.views[static_cast<std::size_t>(view)];
    const glm::dvec4 h = glm::inverse(v.mapping * v.orientation) * glm::dvec4(npc, 1.0);
    return glm::dvec3(h) / h.w;
}

LocatorMeasure DrawListMeasurer::locate(glm::dvec2 deviceCoordinates) const {
    const glm::dvec3 npc = toNpc(deviceCoordinates);
    const int view = viewFor({npc});
    return {view, toWorld(view, npc)};
}

StrokeMeasure DrawListMeasurer::stroke(const std::vector<glm::dvec2>& deviceCoordinates) const {
    std::vector<glm::dvec3> npc;
    for (const glm::dvec2& p : deviceCoordinates) npc.push_back(toNpc(p));
    StrokeMeasure m;
    m.viewIndex = viewFor(npc);
    for (const glm::dvec3& p : npc) m.points.push_back(toWorld(m.viewIndex, p));
    return m;
}

PickMeasure DrawListMeasurer::pick(glm::dvec2 deviceCoordinates, const InputDevice& device) const {
    const DrawList& list = pickList_ ? pickList_(device) : display_;
    const glm::dvec3 npc = toNpc(deviceCoordinates);
    echo_.clear();
    const auto hit = picker_.nearest(list, glm::dvec2(npc), device.setup.pickAperture);
    PickMeasure m;
    if (!hit) return m;
    m.status = InputStatus::Ok;
    m.path = pickPath(list.items[hit->item].source, device.setup.pathOrder, device.pickPathDepth);
    m.surface = hit->surface;
    if (device.echo == EchoSwitch::Echo) echo_ = echoItems(list, *hit, device.setup.promptEchoType == 2);
    return m;
}

}  // namespace phigs
