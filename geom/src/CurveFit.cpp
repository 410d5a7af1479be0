#include "geom/CurveFit.h"

#include "geom/Basis.h"
#include "geom/GeometryError.h"

#include <glm/geometric.hpp>

#include <cmath>
#include <string>

namespace geom {

std::vector<double> uniformParameters(std::size_t count) {
    if (count < 2)
        throw GeometryError("uniformParameters: need at least 2 points, got " + std::to_string(count));
    std::vector<double> params(count);
    for (std::size_t i = 0; i < count; ++i)
        params[i] = static_cast<double>(i) / static_cast<double>(count - 1);
    return params;
}

std::vector<double> chordLengthParameters(std::span<const glm::dvec3> points) {
    if (points.size() < 2)
        throw GeometryError("chordLengthParameters: need at least 2 points, got " +
                            std::to_string(points.size()));
    std::vector<double> params(points.size(), 0.0);
    for (std::size_t i = 1; i < points.size(); ++i)
        params[i] = params[i - 1] + glm::length(points[i] - points[i - 1]);
    const double total = params.back();
    if (!(total > 0.0)) return uniformParameters(points.size());
    for (double& t : params) t /= total;
    params.back() = 1.0;
    return params;
}

std::vector<double> averagedKnots(std::span<const double> params, int degree) {
    const std::size_t n = params.size();
    const std::size_t p = static_cast<std::size_t>(degree);
    if (degree < 1 || n < p + 1)
        throw GeometryError("averagedKnots: " + std::to_string(n) + " parameters are too few for degree " +
                            std::to_string(degree));
    std::vector<double> knots(n + p + 1, 0.0);
    for (std::size_t i = n; i < knots.size(); ++i) knots[i] = 1.0;
    for (std::size_t j = 1; j + p < n; ++j) {
        double sum = 0.0;
        for (std::size_t i = j; i < j + p; ++i) sum += params[i];
        knots[j + p] = sum / static_cast<double>(p);
    }
    return knots;
}

Curve interpolateCurve(std::span<const glm::dvec3> points, std::span<const double> params, int degree) {
    const std::size_t n = points.size();
    if (params.size() != n)
        throw GeometryError("interpolateCurve: " + std::to_string(params.size()) + " parameters for " +
                            std::to_string(n) + " points");
    if (degree < 1 || n < static_cast<std::size_t>(degree) + 1)
        throw GeometryError("interpolateCurve: " + std::to_string(n) + " points are too few for degree " +
                            std::to_string(degree));
    if (params.front() != 0.0 || params.back() != 1.0)
        throw GeometryError("interpolateCurve: parameters must run from 0 to 1");
    for (std::size_t i = 1; i < n; ++i)
        if (!(params[i] > params[i - 1]))
            throw GeometryError("interpolateCurve: parameters must increase strictly (index " +
                                std::to_string(i) + ")");
    std::vector<double> knots = averagedKnots(params, degree);

    // The collocation matrix is banded (degree+1 non-zeros per row); a dense solve with partial
    // pivoting keeps the code short and is fast enough for the few hundred points used here.
    const std::size_t p = static_cast<std::size_t>(degree);
    std::vector<double> a(n * n, 0.0), basis(p + 1);
    for (std::size_t i = 0; i < n; ++i) {
        const std::size_t span = findSpan(degree, knots, n, params[i]);
        basisFunctions(span, params[i], degree, knots, basis);
        for (std::size_t j = 0; j <= p; ++j) a[i * n + span - p + j] = basis[j];
    }
    std::vector<glm::dvec3> rhs(points.begin(), points.end());
    for (std::size_t col = 0; col < n; ++col) {
        std::size_t pivot = col;
        for (std::size_t r = col + 1; r < n && r <= col + p + 1; ++r)
            if (std::abs(a[r * n + col]) > std::abs(a[pivot * n + col])) pivot = r;
        if (a[pivot * n + col] == 0.0) throw GeometryError("interpolateCurve: singular collocation matrix");
        if (pivot != col) {
            for (std::size_t c = 0; c < n; ++c) std::swap(a[pivot * n + c], a[col * n + c]);
            std::swap(rhs[pivot], rhs[col]);
        }
        const std::size_t last = std::min(n, col + 2 * p + 2);
        for (std::size_t r = col + 1; r < n && r <= col + p + 1; ++r) {
            const double f = a[r * n + col] / a[col * n + col];
            if (f == 0.0) continue;
            for (std::size_t c = col; c < last; ++c) a[r * n + c] -= f * a[col * n + c];
            rhs[r] -= f * rhs[col];
        }
    }
    std::vector<glm::dvec3> control(n);
    for (std::size_t i = n; i-- > 0;) {
        glm::dvec3 s = rhs[i];
        const std::size_t last = std::min(n, i + 2 * p + 2);
        for (std::size_t c = i + 1; c < last; ++c) s -= a[i * n + c] * control[c];
        control[i] = s / a[i * n + i];
    }
    return Curve(degree, std::move(knots), std::move(control));
}

Surface interpolateSurface(std::span<const glm::dvec3> grid, std::span<const double> paramsU,
                           std::span<const double> paramsV, int degreeU, int degreeV) {
    const std::size_t nu = paramsU.size(), nv = paramsV.size();
    if (grid.size() != nu * nv)
        throw GeometryError("interpolateSurface: " + std::to_string(grid.size()) + " points for a " +
                            std::to_string(nu) + " x " + std::to_string(nv) + " grid");
    std::vector<glm::dvec3> rows(nu * nv), column(nu);
    std::vector<double> knotsV;
    for (std::size_t i = 0; i < nu; ++i) {
        const Curve row = interpolateCurve(grid.subspan(i * nv, nv), paramsV, degreeV);
        std::copy(row.points.begin(), row.points.end(), rows.begin() + static_cast<std::ptrdiff_t>(i * nv));
        if (i == 0) knotsV = row.knots;
    }
    std::vector<glm::dvec3> net(nu * nv);
    std::vector<double> knotsU;
    for (std::size_t j = 0; j < nv; ++j) {
        for (std::size_t i = 0; i < nu; ++i) column[i] = rows[i * nv + j];
        const Curve col = interpolateCurve(column, paramsU, degreeU);
        for (std::size_t i = 0; i < nu; ++i) net[i * nv + j] = col.points[i];
        if (j == 0) knotsU = col.knots;
    }
    return Surface(degreeU, degreeV, std::move(knotsU), std::move(knotsV), nu, nv, std::move(net));
}

}  // namespace geom
