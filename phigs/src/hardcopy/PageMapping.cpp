#include "phigs/hardcopy/PageMapping.h"

#include "phigs/traverse/ViewClipRectangle.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace phigs::hardcopy {

namespace {

bool positive(double x) {
    return x > 0.0 && std::isfinite(x);
}

/// Paper no file can hold: every format needs a page of some size, and sizes in nominal pixels.
void checkPage(const PageSetup& page) {
    if (!positive(page.paper.x) || !positive(page.paper.y))
        throw std::invalid_argument("vector hardcopy: the paper (" + std::to_string(page.paper.x) + " x " +
                                    std::to_string(page.paper.y) + " points) must be finite and positive");
    if (!std::isfinite(page.margin))
        throw std::invalid_argument("vector hardcopy: the page margin is not a finite number");
    if (!positive(page.nominalPixel))
        throw std::invalid_argument("vector hardcopy: the nominal pixel (" +
                                    std::to_string(page.nominalPixel) +
                                    " points) must be finite and positive");
}

}  // namespace

PageMapping::PageMapping(const DrawList& list, const PageSetup& page)
    : workstation(list), pageSize((checkPage(page), page.pageSize())), nominalPixel(page.nominalPixel) {
    const glm::dvec2 area = glm::max(pageSize - 2.0 * page.margin, glm::dvec2(1e-9));
    const glm::dvec2 surface = glm::max(list.displaySize, glm::dvec2(1e-300));
    pointsPerDevice = std::min(area.x / surface.x, area.y / surface.y);
    pointsPerNpc = pointsPerDevice * workstation.scaleXY;
    const glm::dvec2 size = surface * pointsPerDevice;
    display.min = 0.5 * (pageSize - size);
    display.max = display.min + size;
    // page x = display.min.x + k * device x, page y = display.max.y - k * device y, where
    // device = viewportMin + scaleXY * (npc - windowMin).
    const glm::dvec3 origin = workstation.toDevice(glm::dvec3(0.0));
    npcToPage = glm::dmat4(1.0);
    npcToPage[0][0] = pointsPerNpc;
    npcToPage[1][1] = -pointsPerNpc;
    npcToPage[3][0] = display.min.x + pointsPerDevice * origin.x;
    npcToPage[3][1] = display.max.y - pointsPerDevice * origin.y;
}

glm::dvec3 PageMapping::toPage(const glm::dvec3& npc) const {
    const glm::dvec4 p = npcToPage * glm::dvec4(npc, 1.0);
    return {p.x, p.y, npc.z};
}

PageRect PageMapping::clipRect(const DrawView& view) const {
    const ViewClipRectangle kept(view, workstation.windowMin, workstation.windowMax);
    const glm::dvec2 lo = kept.min, hi = kept.max;
    if (!(hi.x > lo.x && hi.y > lo.y)) return {};
    const glm::dvec3 a = toPage({lo, 0.0}), b = toPage({hi, 0.0});
    PageRect r;
    r.min = glm::max(glm::min(glm::dvec2(a), glm::dvec2(b)), display.min);
    r.max = glm::min(glm::max(glm::dvec2(a), glm::dvec2(b)), display.max);
    return r;
}

}  // namespace phigs::hardcopy
