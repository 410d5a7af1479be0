#pragma once

#include "geom/Curve.h"
#include "geom/Surface.h"

#include <glm/vec3.hpp>

#include <array>
#include <cstddef>
#include <vector>

namespace geom {

/// Point C(u) of a curve. Per-point entries here check what they read (sizes, the span's knots,
/// a finite result) and that the parameter is finite and in the domain (up to 1e-9 of its width,
/// clamped); anything else throws GeometryError naming the function and the argument.
glm::dvec3 evaluate(const Curve& curve, double u);

/// C(u), C'(u), ..., C^(order)(u); rational curves by the quotient rule (The NURBS Book A4.2).
std::vector<glm::dvec3> derivatives(const Curve& curve, double u, int order);

/// The highest derivative order the evaluations take.
inline constexpr int kMaxDerivativeOrder = 64;

/// Partial derivatives of a surface: at(k, l) = d^(k+l) S / du^k dv^l for k + l <= order (the
/// others are zero). Orders up to 3 are held inline, so a per-point call allocates nothing.
class SurfaceDerivatives {
public:
    /// Throws GeometryError for an order outside 0..kMaxDerivativeOrder (as derivatives() does).
    explicit SurfaceDerivatives(int order = 0) : order_(order) {
        if (order < 0 || order > kMaxDerivativeOrder) [[unlikely]]
            rejectOrder(order);
        if (side() * side() > small_.size()) large_.resize(side() * side());
    }
    int order() const { return order_; }
    const glm::dvec3& at(int k, int l) const { return data()[index(k, l)]; }
    glm::dvec3& at(int k, int l) { return data()[index(k, l)]; }
    /// (order+1) x (order+1) values, row k, column l.
    const glm::dvec3* data() const { return large_.empty() ? small_.data() : large_.data(); }
    glm::dvec3* data() { return large_.empty() ? small_.data() : large_.data(); }

private:
    /// Throws derivatives()' error for an order outside its range.
    static void rejectOrder(int order);
    std::size_t side() const { return static_cast<std::size_t>(order_) + 1; }
    std::size_t index(int k, int l) const {
        return static_cast<std::size_t>(k) * side() + static_cast<std::size_t>(l);
    }

    int order_ = 0;
    std::array<glm::dvec3, 16> small_;  // filled by whoever computes the derivatives
    std::vector<glm::dvec3> large_;
};

/// Point S(u, v) of a surface; (u, v) checked as for curves.
glm::dvec3 evaluate(const Surface& surface, double u, double v);

/// All partial derivatives up to total order `order` (plain de Boor path, A3.6 / A4.4).
SurfaceDerivatives derivatives(const Surface& surface, double u, double v, int order);

/// Unit normal Su x Sv / |Su x Sv|. Where that cross product vanishes (a collapsed edge, a
/// pole) the answer is the limit of the normal approached from the inside of the domain along
/// the diagonal, so the result is always a unit vector when the surface is not degenerate in
/// a whole neighbourhood; a surface degenerate everywhere near (u, v) gives (0, 0, 0).
glm::dvec3 normal(const Surface& surface, double u, double v);

/// Unit normal from first derivatives already at hand, with the same degenerate-point rule.
glm::dvec3 normalFromDerivatives(const Surface& surface, double u, double v, const glm::dvec3& su,
                                 const glm::dvec3& sv);

}  // namespace geom
