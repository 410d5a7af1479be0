#include "phigs/render/WorkstationMapping.h"

#include <algorithm>
#include <cmath>

namespace phigs::render {

WorkstationMapping::WorkstationMapping(const DrawList& list, std::uint32_t width, std::uint32_t height)
    : windowMin(list.windowMin), windowMax(list.windowMax), width_(width), height_(height) {
    const double unit = std::min(width, height);
    const glm::dvec2 window = glm::dvec2(list.windowMax) - glm::dvec2(list.windowMin);
    const glm::dvec2 viewport = glm::dvec2(list.viewportMax) - glm::dvec2(list.viewportMin);
    const double scale =
        (window.x > 0 && window.y > 0) ? std::min(viewport.x / window.x, viewport.y / window.y) : 0.0;
    pixelsPerNpc = scale * unit;
    // pixel = (viewportMin + scale * (npc - windowMin)) * unit, y flipped; clip = 2 * pixel / size - 1.
    glm::dmat4 m(0.0);
    m[0][0] = 2.0 * pixelsPerNpc / width;
    m[1][1] = -2.0 * pixelsPerNpc / height;
    m[3][0] = 2.0 * (list.viewportMin.x - scale * list.windowMin.x) * unit / width - 1.0;
    m[3][1] = 1.0 - 2.0 * (list.viewportMin.y - scale * list.windowMin.y) * unit / height;
    m[2][2] = -1.0;
    m[3][2] = 1.0;
    m[3][3] = 1.0;
    npcToClip = m;
}

glm::dvec2 WorkstationMapping::toPixels(glm::dvec3 npc) const {
    const glm::dvec4 clip = npcToClip * glm::dvec4(npc, 1.0);
    return {(clip.x + 1.0) * 0.5 * width_, (clip.y + 1.0) * 0.5 * height_};
}

PixelRect WorkstationMapping::scissor(glm::dvec2 npcMin, glm::dvec2 npcMax) const {
    npcMin = glm::max(npcMin, glm::dvec2(windowMin));
    npcMax = glm::min(npcMax, glm::dvec2(windowMax));
    const glm::dvec2 a = toPixels({npcMin, 0.0}), b = toPixels({npcMax, 0.0});
    const double x0 = std::clamp(std::round(std::min(a.x, b.x)), 0.0, double(width_));
    const double x1 = std::clamp(std::round(std::max(a.x, b.x)), 0.0, double(width_));
    const double y0 = std::clamp(std::round(std::min(a.y, b.y)), 0.0, double(height_));
    const double y1 = std::clamp(std::round(std::max(a.y, b.y)), 0.0, double(height_));
    PixelRect r;
    r.x = std::int32_t(x0);
    r.y = std::int32_t(y0);
    r.width = npcMax.x > npcMin.x ? std::uint32_t(x1 - x0) : 0;
    r.height = npcMax.y > npcMin.y ? std::uint32_t(y1 - y0) : 0;
    return r;
}

}  // namespace phigs::render
