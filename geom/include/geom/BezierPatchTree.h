#pragma once

#include "geom/BoundingBox.h"
#include "geom/Surface.h"

#include <glm/vec4.hpp>

#include <cstddef>
#include <vector>

namespace geom {

/// A surface cut into its Bézier patches (homogeneous nets, boxes, parameter intervals) under a
/// bounding-volume tree, built once and shared by line intersection and point inversion.
class BezierPatchTree {
public:
    struct Patch {
        std::vector<glm::dvec4> net;  ///< (degreeU+1) x (degreeV+1) homogeneous points, u slow
        BoundingBox box;
        double u0 = 0.0, u1 = 0.0, v0 = 0.0, v1 = 0.0;
    };
    struct Node {
        BoundingBox box;
        int first = -1, second = -1;  ///< children; both -1 at a leaf
        int patch = -1;               ///< the patch of a leaf
    };

    /// A point of one patch with its partial derivatives in the surface's own (u, v).
    struct PatchPoint {
        glm::dvec3 point, su, sv, suu, suv, svv;
    };

    BezierPatchTree() = default;
    explicit BezierPatchTree(const Surface& surface);

    int degreeU() const { return degreeU_; }
    int degreeV() const { return degreeV_; }
    const std::vector<Patch>& patches() const { return patches_; }
    const std::vector<Node>& nodes() const { return nodes_; }
    /// Index of the root node (0) or -1 for an empty tree.
    int root() const { return nodes_.empty() ? -1 : 0; }
    /// Diagonal of the box of the whole surface: the length scale for tolerances.
    double scale() const { return scale_; }

    /// Point and derivatives up to `order` (0, 1 or 2) of patch `index` at the surface parameters
    /// (u, v), which should lie in the patch's interval; rational patches by the quotient rule.
    PatchPoint evaluate(std::size_t index, double u, double v, int order) const;
    /// The patch whose interval holds (u, v), clamped into the domain.
    std::size_t patchAt(double u, double v) const;
    /// Evaluation at any (u, v) of the domain: patchAt, then evaluate.
    PatchPoint evaluate(double u, double v, int order) const { return evaluate(patchAt(u, v), u, v, order); }
    double domainStartU() const { return breaksU_.front(); }
    double domainEndU() const { return breaksU_.back(); }
    double domainStartV() const { return breaksV_.front(); }
    double domainEndV() const { return breaksV_.back(); }
    /// The distinct knot values bounding the patches along u and along v.
    const std::vector<double>& breaksU() const { return breaksU_; }
    const std::vector<double>& breaksV() const { return breaksV_; }

private:
    int build(std::size_t iu0, std::size_t iu1, std::size_t iv0, std::size_t iv1, std::size_t countV);

    int degreeU_ = 0, degreeV_ = 0;
    std::vector<Patch> patches_;
    std::vector<Node> nodes_;
    double scale_ = 0.0;
    std::vector<double> breaksU_, breaksV_;
};

}  // namespace geom
