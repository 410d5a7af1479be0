#pragma once

#include <glm/vec3.hpp>

#include <cstddef>
#include <span>
#include <vector>

namespace geom {

/// When Molt's recursive midpoint subdivision stops (Molt 1994, section 3.3.2).
enum class StoppingRule {
    FixedDepth,            ///< stop at options.depth
    GlobalError,           ///< depth ceil(log2(M / tol)), M the largest spacing of the input net
    MeshRefinement,        ///< every spacing of consecutive net points below tol
    LocalFlatness,         ///< net within tol of the corner plane, boundary rows within tol of straight
    FlatnessOrRefinement,  ///< LocalFlatness or MeshRefinement (the thesis's combination)
};

/// Options of subdivideAdaptive; depth is the fixed depth or the hard cap (thesis default 10).
struct SubdivisionOptions {
    StoppingRule rule = StoppingRule::FlatnessOrRefinement;
    double tolerance = 1e-4;
    int depth = 10;
};

/// One leaf of the quadtree: its Bézier net and its square of the patch's [0,1]^2.
struct SubdivisionLeaf {
    std::vector<glm::dvec3> net;
    double u0 = 0, u1 = 1, v0 = 0, v1 = 1;
    int depth = 0;
};

/// The thesis's instrumentation: splits = 3 I, gens = 1 + 4 I, leaves = 1 + 3 I for I inner nodes.
struct SubdivisionStats {
    std::size_t splits = 0, gens = 0, leaves = 0, points = 0;
    int minDepth = 0, maxDepth = 0;
};

/// Adaptive midpoint subdivision of a polynomial Bézier patch (countU x countV net, u slow)
/// into a quadtree, depth first, quadrants in the thesis's order [0,1/2]^2, [1/2,1]x[0,1/2],
/// [0,1/2]x[1/2,1], [1/2,1]^2 (u split first, then v on both halves).
std::vector<SubdivisionLeaf> subdivideAdaptive(std::span<const glm::dvec3> net, std::size_t countU,
                                               std::size_t countV, const SubdivisionOptions& options,
                                               SubdivisionStats* stats = nullptr);

}  // namespace geom
