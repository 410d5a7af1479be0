#pragma once

// Draw lists built by hand for the pick and input tests: one view (world = NPC unless a test
// changes it), workstation window the unit cube on a 100 x 100 pixel viewport.

#include "phigs/traverse/DrawList.h"

#include <cmath>
#include <memory>

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
    list.displaySize = {100.0, 100.0};
    return list;
}

inline DrawSource sourceOf(const std::vector<DrawPathLevel>& path) {
    return DrawSource(path);
}

inline DrawItem item(DrawPrimitive primitive, std::vector<DrawPathLevel> path) {
    DrawItem i;
    i.primitive = std::move(primitive);
    i.source = sourceOf(path);
    return i;
}

/// A square fill area in the plane z = `z`, from `lo` to `hi` in x and y.
inline DrawFillArea square(double lo, double hi, double z, InteriorStyle style = InteriorStyle::Solid) {
    DrawFillArea f;
    f.contours = {{{lo, lo, z}, {hi, lo, z}, {hi, hi, z}, {lo, hi, z}}};
    f.interior.edit().style = style;
    return f;
}

/// A rational circular cylinder of radius r about the y axis, for y in [-1, 1]: four quadratic
/// pieces in u starting at +x and turning toward +z, one linear piece in v.
inline std::shared_ptr<const geom::Surface> cylinder(double r) {
    const double s = std::sqrt(0.5);
    const glm::dvec2 circle[9] = {{1, 0},   {1, 1},  {0, 1},  {-1, 1}, {-1, 0},
                                  {-1, -1}, {0, -1}, {1, -1}, {1, 0}};
    std::vector<glm::dvec3> points;
    std::vector<double> weights;
    for (int i = 0; i < 9; ++i)
        for (double y : {-1.0, 1.0}) {
            points.emplace_back(r * circle[i].x, y, r * circle[i].y);
            weights.push_back(i % 2 ? s : 1.0);
        }
    return std::make_shared<const geom::Surface>(
        2, 1, std::vector<double>{0, 0, 0, .25, .25, .5, .5, .75, .75, 1, 1, 1},
        std::vector<double>{0, 0, 1, 1}, 9, 2, points, weights);
}

/// A NURBS surface item, SOLID (a HOLLOW or EMPTY side is hit on its edges only).
inline DrawItem surfaceItem(std::shared_ptr<const geom::Surface> surface, std::vector<DrawPathLevel> path) {
    DrawMesh m;
    m.surface = std::move(surface);
    m.interior.edit().style = InteriorStyle::Solid;
    return item(m, std::move(path));
}

}  // namespace phigs::test
