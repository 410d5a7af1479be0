#include "phigs/pick/WorkstationMapping.h"

#include <algorithm>

namespace phigs {

WorkstationMapping::WorkstationMapping(const DrawList& list)
    : windowMin(list.windowMin), viewportMin(list.viewportMin) {
    const glm::dvec3 w = list.windowMax - list.windowMin;
    const glm::dvec3 v = list.viewportMax - list.viewportMin;
    scaleXY = std::min(w.x > 0 ? v.x / w.x : 1.0, w.y > 0 ? v.y / w.y : 1.0);
    if (!(scaleXY > 0)) scaleXY = 1.0;
    scaleZ = w.z > 0 && v.z > 0 ? v.z / w.z : 1.0;
}

glm::dvec3 WorkstationMapping::toDevice(const glm::dvec3& npc) const {
    const glm::dvec3 d = npc - windowMin;
    return viewportMin + glm::dvec3(d.x * scaleXY, d.y * scaleXY, d.z * scaleZ);
}

glm::dvec3 WorkstationMapping::toNpc(const glm::dvec3& device) const {
    const glm::dvec3 d = device - viewportMin;
    return windowMin + glm::dvec3(d.x / scaleXY, d.y / scaleXY, d.z / scaleZ);
}

}  // namespace phigs
