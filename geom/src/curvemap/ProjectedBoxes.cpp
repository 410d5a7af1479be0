#include "ProjectedBoxes.h"

#include <glm/common.hpp>

#include <algorithm>
#include <limits>

namespace geom::curvemap {

ProjectedBoxes::ProjectedBoxes(const BezierPatchTree& tree, const PlacementFrame& frame)
    : boxes_(tree.nodes().size()),
      first_(tree.nodes().size(), -1),
      second_(tree.nodes().size(), -1),
      root_(tree.root()) {
    if (root_ >= 0) build(root_, tree, frame);
}

ProjectedBoxes::Box ProjectedBoxes::build(int node, const BezierPatchTree& tree,
                                          const PlacementFrame& frame) {
    const BezierPatchTree::Node& n = tree.nodes()[std::size_t(node)];
    Box box{glm::dvec2(std::numeric_limits<double>::infinity()),
            glm::dvec2(-std::numeric_limits<double>::infinity())};
    if (n.patch >= 0) {
        for (const glm::dvec4& h : tree.patches()[std::size_t(n.patch)].net) {
            const glm::dvec3 local = frame.toCurve(glm::dvec3(h) / h.w);
            box.lo = glm::min(box.lo, glm::dvec2(local));
            box.hi = glm::max(box.hi, glm::dvec2(local));
        }
    } else {
        first_[std::size_t(node)] = n.first;
        second_[std::size_t(node)] = n.second;
        for (const int child : {n.first, n.second}) {
            if (child < 0) continue;
            const Box c = build(child, tree, frame);
            box.lo = glm::min(box.lo, c.lo);
            box.hi = glm::max(box.hi, c.hi);
        }
    }
    boxes_[std::size_t(node)] = box;
    return box;
}

bool ProjectedBoxes::mayMeet(const glm::dvec2& p, const glm::dvec2& q, double pad) const {
    return root_ >= 0 && meets(root_, p, q, pad);
}

bool ProjectedBoxes::meets(int node, const glm::dvec2& p, const glm::dvec2& q, double pad) const {
    // Slabs: the parameter interval of the segment inside the widened box, axis by axis.
    const Box& b = boxes_[std::size_t(node)];
    if (!(b.lo.x <= b.hi.x && b.lo.y <= b.hi.y)) return false;  // no patch under it
    double t0 = 0.0, t1 = 1.0;
    for (int axis = 0; axis < 2; ++axis) {
        const double lo = b.lo[axis] - pad, hi = b.hi[axis] + pad, d = q[axis] - p[axis];
        if (d == 0.0) {
            if (p[axis] < lo || p[axis] > hi) return false;
            continue;
        }
        double a = (lo - p[axis]) / d, c = (hi - p[axis]) / d;
        if (a > c) std::swap(a, c);
        t0 = std::max(t0, a);
        t1 = std::min(t1, c);
        if (t0 > t1) return false;
    }
    const int first = first_[std::size_t(node)], second = second_[std::size_t(node)];
    if (first < 0 && second < 0) return true;  // a leaf: a patch's box
    return (first >= 0 && meets(first, p, q, pad)) || (second >= 0 && meets(second, p, q, pad));
}

}  // namespace geom::curvemap
