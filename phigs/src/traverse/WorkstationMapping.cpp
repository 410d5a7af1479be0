#include "phigs/traverse/WorkstationMapping.h"

#include <algorithm>
#include <cmath>

namespace phigs {

WorkstationMapping::WorkstationMapping(const DrawList& list)
    : WorkstationMapping(list, static_cast<std::uint32_t>(std::max(1.0, std::round(list.displaySize.x))),
                         static_cast<std::uint32_t>(std::max(1.0, std::round(list.displaySize.y)))) {
}

WorkstationMapping::WorkstationMapping(const DrawList& list, std::uint32_t width, std::uint32_t height)
    : windowMin(list.windowMin),
      windowMax(list.windowMax),
      viewportMin(list.viewportMin),
      width(width),
      height(height) {
    const glm::dvec3 w = list.windowMax - list.windowMin;
    const glm::dvec3 v = list.viewportMax - list.viewportMin;
    scaleXY = std::min(w.x > 0 ? v.x / w.x : 1.0, w.y > 0 ? v.y / w.y : 1.0);
    if (!(scaleXY > 0)) scaleXY = 1.0;
    scaleZ = w.z > 0 && v.z > 0 ? v.z / w.z : 1.0;
    const glm::dvec2 display = glm::max(list.displaySize, glm::dvec2(1e-300));
    pixelsPerDevice = std::min(width / display.x, height / display.y);
    pixelsPerNpc = scaleXY * pixelsPerDevice;
    // pixel x = k * (viewportMin + s * (npc - windowMin)), pixel y = height - the same for y;
    // clip = 2 * pixel / size - 1; depth = 1 - npc z.
    const double k = pixelsPerDevice;
    glm::dmat4 m(0.0);
    m[0][0] = 2.0 * pixelsPerNpc / width;
    m[1][1] = -2.0 * pixelsPerNpc / height;
    m[3][0] = 2.0 * k * (viewportMin.x - scaleXY * windowMin.x) / width - 1.0;
    m[3][1] = 1.0 - 2.0 * k * (viewportMin.y - scaleXY * windowMin.y) / height;
    m[2][2] = -1.0;
    m[3][2] = 1.0;
    m[3][3] = 1.0;
    npcToClip = m;
}

glm::dvec3 WorkstationMapping::toDevice(const glm::dvec3& npc) const {
    const glm::dvec3 d = npc - windowMin;
    return viewportMin + glm::dvec3(d.x * scaleXY, d.y * scaleXY, d.z * scaleZ);
}

glm::dvec3 WorkstationMapping::toNpc(const glm::dvec3& device) const {
    const glm::dvec3 d = device - viewportMin;
    return windowMin + glm::dvec3(d.x / scaleXY, d.y / scaleXY, d.z / scaleZ);
}

glm::dvec2 WorkstationMapping::toPixels(const glm::dvec3& npc) const {
    const glm::dvec3 device = toDevice(npc);
    return {device.x * pixelsPerDevice, height - device.y * pixelsPerDevice};
}

glm::dvec3 WorkstationMapping::pixelsToNpc(glm::dvec2 pixels, double npcZ) const {
    const glm::dvec3 device(pixels.x / pixelsPerDevice, (height - pixels.y) / pixelsPerDevice, viewportMin.z);
    glm::dvec3 npc = toNpc(device);
    npc.z = npcZ;
    return npc;
}

PixelRect WorkstationMapping::scissor(glm::dvec2 npcMin, glm::dvec2 npcMax) const {
    npcMin = glm::max(npcMin, glm::dvec2(windowMin));
    npcMax = glm::min(npcMax, glm::dvec2(windowMax));
    const glm::dvec2 a = toPixels({npcMin, 0.0}), b = toPixels({npcMax, 0.0});
    const double x0 = std::clamp(std::round(std::min(a.x, b.x)), 0.0, double(width));
    const double x1 = std::clamp(std::round(std::max(a.x, b.x)), 0.0, double(width));
    const double y0 = std::clamp(std::round(std::min(a.y, b.y)), 0.0, double(height));
    const double y1 = std::clamp(std::round(std::max(a.y, b.y)), 0.0, double(height));
    PixelRect r;
    r.x = std::int32_t(x0);
    r.y = std::int32_t(y0);
    r.width = npcMax.x > npcMin.x ? std::uint32_t(x1 - x0) : 0;
    r.height = npcMax.y > npcMin.y ? std::uint32_t(y1 - y0) : 0;
    return r;
}

}  // namespace phigs
