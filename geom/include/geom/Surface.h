#pragma once

#include <glm/vec3.hpp>

#include <cstddef>
#include <string_view>
#include <vector>

namespace geom {

/// A tensor-product (rational) B-spline surface. Control points are stored row by row with
/// u as the slow index: point(i, j) = points[i * countV + j], i along u, j along v.
struct Surface {
    int degreeU = 0;
    int degreeV = 0;
    std::vector<double> knotsU;
    std::vector<double> knotsV;
    std::size_t countU = 0;
    std::size_t countV = 0;
    std::vector<glm::dvec3> points;
    std::vector<double> weights;  ///< empty: polynomial; else one positive weight per point

    Surface() = default;
    /// Builds the surface and checks it with validate(); throws GeometryError on bad input.
    Surface(int degreeU, int degreeV, std::vector<double> knotsU, std::vector<double> knotsV,
            std::size_t countU, std::size_t countV, std::vector<glm::dvec3> points,
            std::vector<double> weights = {});

    bool rational() const { return !weights.empty(); }
    const glm::dvec3& point(std::size_t i, std::size_t j) const { return points[i * countV + j]; }
    glm::dvec3& point(std::size_t i, std::size_t j) { return points[i * countV + j]; }
    double weight(std::size_t i, std::size_t j) const {
        return weights.empty() ? 1.0 : weights[i * countV + j];
    }
    double domainStartU() const { return knotsU[static_cast<std::size_t>(degreeU)]; }
    double domainEndU() const { return knotsU[countU]; }
    double domainStartV() const { return knotsV[static_cast<std::size_t>(degreeV)]; }
    double domainEndV() const { return knotsV[countV]; }
};

/// Checks the same rules as validate(const Curve&) in both directions, plus
/// points.size() == countU * countV. Throws GeometryError naming the rule and index, after `where`.
void validate(const Surface& surface, std::string_view where = {});

}  // namespace geom
