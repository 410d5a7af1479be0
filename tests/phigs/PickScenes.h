#pragma once

// Draw lists built by hand for the pick and input tests: one view (world = NPC unless a test
// changes it), workstation window the unit cube on a 100 x 100 pixel viewport.

#include "phigs/traverse/DrawList.h"

#include <utility>
#include <vector>

namespace phigs::test {

inline DrawList unitList() {
    DrawList list;
    list.views.push_back(DrawView{});
    list.windowMin = glm::dvec3(0.0);
    list.windowMax = glm::dvec3(1.0);
    list.viewportMin = glm::dvec3(0.0);
    list.viewportMax = glm::dvec3(100.0, 100.0, 1.0);
    return list;
}

inline DrawSource sourceOf(std::vector<DrawPathLevel> path) {
    DrawSource s;
    s.path = std::move(path);
    return s;
}

inline DrawItem item(DrawPrimitive primitive, std::vector<DrawPathLevel> path) {
    DrawItem i;
    i.primitive = std::move(primitive);
    i.source = sourceOf(std::move(path));
    return i;
}

/// A square fill area in the plane z = `z`, from `lo` to `hi` in x and y.
inline DrawFillArea square(double lo, double hi, double z, InteriorStyle style = InteriorStyle::Solid) {
    DrawFillArea f;
    f.contours = {{{lo, lo, z}, {hi, lo, z}, {hi, hi, z}, {lo, hi, z}}};
    f.interior.style = style;
    return f;
}

}  // namespace phigs::test
