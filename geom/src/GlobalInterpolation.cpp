#include "geom/GlobalInterpolation.h"

#include "Checked.h"
#include "SparseLu.h"
#include "geom/Basis.h"
#include "geom/GeometryError.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <string>

namespace geom {
namespace {

/// The interpolation problem of one direction: knots, the factored collocation matrix and
/// how many control points a solution has.
struct Interpolator {
    int degree;
    Closure closure;
    std::size_t dataCount;
    std::vector<double> knots;
    detail::SparseLu lu;

    std::size_t controlCount() const {
        return closure == Closure::Periodic ? dataCount + static_cast<std::size_t>(degree) : dataCount;
    }

    std::vector<glm::dvec3> controlPoints(std::vector<glm::dvec3> data) const {
        std::vector<glm::dvec3> unique = lu.solve(std::move(data));
        if (closure == Closure::Periodic)
            for (int i = 0; i < degree; ++i) unique.push_back(unique[static_cast<std::size_t>(i)]);
        return unique;
    }
};

/// Parameters finite and strictly increasing, else GeometryError naming `where` and the index.
void checkIncreasing(std::span<const double> parameters, const char* where) {
    for (std::size_t i = 0; i < parameters.size(); ++i) {
        if (!std::isfinite(parameters[i]))
            throw GeometryError(std::string(where) + ": parameter " + std::to_string(i) +
                                " is not a finite number");
        if (i > 0 && !(parameters[i] > parameters[i - 1]))
            throw GeometryError(std::string(where) + ": parameters do not increase at index " +
                                std::to_string(i));
    }
}

void checkParameters(std::span<const double> parameters, std::size_t dataCount, int degree, Closure closure) {
    if (degree < 1) throw GeometryError("interpolation: degree " + std::to_string(degree) + " must be >= 1");
    if (closure == Closure::Periodic && degree % 2 == 0)
        throw GeometryError("interpolation: periodic interpolation needs an odd degree, got " +
                            std::to_string(degree));
    if (dataCount < static_cast<std::size_t>(degree) + 1)
        throw GeometryError("interpolation: " + std::to_string(dataCount) +
                            " points are too few for degree " + std::to_string(degree) + " (need at least " +
                            std::to_string(degree + 1) + ")");
    const std::size_t expected = closure == Closure::Periodic ? dataCount + 1 : dataCount;
    if (parameters.size() != expected)
        throw GeometryError("interpolation: " + std::to_string(parameters.size()) + " parameters given for " +
                            std::to_string(dataCount) + " points, need " + std::to_string(expected));
    checkIncreasing(parameters, "interpolation");
}

Interpolator makeInterpolator(std::span<const double> parameters, std::size_t dataCount, int degree,
                              Closure closure) {
    checkParameters(parameters, dataCount, degree, closure);
    std::vector<double> knots = interpolationKnots(parameters, degree, closure);
    const std::size_t p = static_cast<std::size_t>(degree);
    const std::size_t controls = closure == Closure::Periodic ? dataCount + p : dataCount;
    // Each row holds the degree + 1 basis functions that reach its parameter: the matrix is
    // banded (with wrapped corners when periodic), solved in O(n p^2).
    std::vector<detail::SparseLu::Row> rows(dataCount);
    std::vector<double> basis(p + 1);
    for (std::size_t k = 0; k < dataCount; ++k) {
        const double t = parameters[k];
        const std::size_t span = findSpan(degree, knots, controls, t);
        basisFunctions(span, t, degree, knots, basis);
        detail::SparseLu::Row& row = rows[k];
        for (std::size_t j = 0; j <= p; ++j) {
            // Periodic: control point c and c + dataCount are the same unknown.
            detail::SparseLu::add(row, (span - p + j) % dataCount, basis[j]);
        }
        detail::SparseLu::finish(row);
    }
    detail::SparseLu lu(std::move(rows), 1e-13);
    if (lu.singular())
        throw GeometryError("interpolation: the collocation matrix is singular at column " +
                            std::to_string(lu.singularColumn()) + " (parameters too close together)");
    return Interpolator{degree, closure, dataCount, std::move(knots), std::move(lu)};
}

/// The distance from a to b; where its square overflows but it does not, taken again by hypot.
double chordLength(const glm::dvec3& a, const glm::dvec3& b) {
    const double d = glm::distance(a, b);
    return std::isfinite(d) ? d : std::hypot(b.x - a.x, b.y - a.y, b.z - a.z);
}

/// Chord-length parameters of one polyline, or empty when it has no length. Throws GeometryError
/// naming `what` when the length is not finite (it overflows a double): that is no zero length.
std::vector<double> chordParametersOrEmpty(std::span<const glm::dvec3> points, Closure closure,
                                           const std::string& what) {
    const std::size_t n = points.size();
    const std::size_t chords = closure == Closure::Periodic ? n : n - 1;
    std::vector<double> t(chords + 1, 0.0);
    for (std::size_t k = 1; k <= chords; ++k) t[k] = t[k - 1] + chordLength(points[k - 1], points[k % n]);
    const double total = t.back();
    if (!std::isfinite(total))
        throw GeometryError(what + " has a length that is not finite (overflows a double)");
    if (!(total > 0.0)) return {};
    for (double& x : t) x /= total;
    t.back() = 1.0;
    return t;
}

void checkFinite(std::span<const glm::dvec3> points) {
    for (std::size_t i = 0; i < points.size(); ++i)
        if (!std::isfinite(points[i].x) || !std::isfinite(points[i].y) || !std::isfinite(points[i].z))
            throw GeometryError("interpolation: data point " + std::to_string(i) + " is not finite");
}

}  // namespace

std::vector<double> uniformParameters(std::size_t count) {
    if (count < 2)
        throw GeometryError("uniformParameters: need at least 2 points, got " + std::to_string(count));
    if (count > kMaxSamplePoints)
        throw GeometryError("uniformParameters: " + std::to_string(count) + " points are more than " +
                            std::to_string(kMaxSamplePoints));
    std::vector<double> t(count);
    for (std::size_t i = 0; i < count; ++i) t[i] = static_cast<double>(i) / static_cast<double>(count - 1);
    return t;
}

std::vector<double> chordLengthParameters(std::span<const glm::dvec3> points, Closure closure) {
    if (points.size() < 2) throw GeometryError("chord-length parameters: need at least 2 points");
    checkFinite(points);
    std::vector<double> t = chordParametersOrEmpty(points, closure, "chord-length parameters: the polyline");
    if (t.empty()) throw GeometryError("chord-length parameters: the polyline has zero length");
    for (std::size_t k = 1; k < t.size(); ++k)
        if (!(t[k] > t[k - 1]))
            throw GeometryError("chord-length parameters: points " + std::to_string(k - 1) + " and " +
                                std::to_string(k % points.size()) +
                                " coincide or lie too close to tell apart");
    return t;
}

std::vector<double> interpolationKnots(std::span<const double> parameters, int degree, Closure closure) {
    if (degree < 1)
        throw GeometryError("interpolation knots: degree " + std::to_string(degree) + " must be at least 1");
    if (closure != Closure::Open && closure != Closure::Periodic)
        throw GeometryError("interpolation knots: closure " + std::to_string(static_cast<int>(closure)) +
                            " is neither Open nor Periodic");
    const std::size_t p = static_cast<std::size_t>(degree);
    // Knots from parameters out of order or not finite would not be a knot vector.
    checkIncreasing(parameters, "interpolation knots");
    if (closure == Closure::Open) {
        const std::size_t n = parameters.size();
        if (n < p + 1) throw GeometryError("interpolation knots: too few parameters for the degree");
        std::vector<double> knots(n + p + 1);
        for (std::size_t i = 0; i <= p; ++i) {
            knots[i] = parameters.front();
            knots[n + i] = parameters.back();
        }
        for (std::size_t j = 1; j + p < n; ++j) {
            double sum = 0.0;
            for (std::size_t i = j; i < j + p; ++i) sum += parameters[i];
            knots[j + p] = sum / static_cast<double>(p);
        }
        return knots;
    }
    if (degree % 2 == 0) throw GeometryError("interpolation knots: periodic knots need an odd degree");
    if (parameters.empty()) throw GeometryError("interpolation knots: too few parameters for the degree");
    const std::size_t n = parameters.size() - 1;  // distinct data points
    if (n < p + 1) throw GeometryError("interpolation knots: too few parameters for the degree");
    const double period = parameters[n] - parameters[0];
    if (!std::isfinite(period))
        throw GeometryError("interpolation knots: the parameter range overflows a double");
    std::vector<double> knots(n + 2 * p + 1);
    for (std::size_t k = 0; k <= n; ++k) knots[p + k] = parameters[k];
    for (std::size_t j = 1; j <= p; ++j) {
        knots[p - j] = parameters[n - j] - period;
        knots[n + p + j] = parameters[j] + period;
    }
    return knots;
}

Curve interpolateCurve(std::span<const glm::dvec3> points, std::span<const double> parameters, int degree,
                       Closure closure) {
    checkFinite(points);
    const Interpolator solver = makeInterpolator(parameters, points.size(), degree, closure);
    std::vector<glm::dvec3> control = solver.controlPoints({points.begin(), points.end()});
    return Curve(degree, solver.knots, std::move(control));
}

Curve interpolateCurve(std::span<const glm::dvec3> points, int degree, Closure closure) {
    const std::vector<double> t = chordLengthParameters(points, closure);
    return interpolateCurve(points, t, degree, closure);
}

GridParameters chordLengthGridParameters(std::span<const glm::dvec3> grid, std::size_t countU,
                                         std::size_t countV, Closure closureU, Closure closureV) {
    if (countU < 2 || countV < 2) throw GeometryError("grid parameters: need at least 2 x 2 points");
    if (!detail::gridSizeIs(grid.size(), countU, countV))
        throw GeometryError("grid parameters: " + std::to_string(grid.size()) + " points for a " +
                            std::to_string(countU) + " x " + std::to_string(countV) + " grid");
    checkFinite(grid);
    auto average = [](std::vector<std::vector<double>> lines, const char* direction) {
        std::vector<double> mean;
        std::size_t used = 0;
        for (const auto& t : lines) {
            if (t.empty()) continue;
            if (mean.empty()) mean.assign(t.size(), 0.0);
            for (std::size_t k = 0; k < t.size(); ++k) mean[k] += t[k];
            ++used;
        }
        if (used == 0)
            throw GeometryError(std::string("grid parameters: every line in ") + direction +
                                " has zero length");
        for (double& x : mean) x /= static_cast<double>(used);
        mean.front() = 0.0;
        mean.back() = 1.0;
        for (std::size_t k = 1; k < mean.size(); ++k)
            if (!(mean[k] > mean[k - 1]))
                throw GeometryError(std::string("grid parameters: data lines ") + std::to_string(k - 1) +
                                    " and " + std::to_string(k) + " in " + direction + " coincide");
        return mean;
    };
    std::vector<std::vector<double>> columns, rows;
    std::vector<glm::dvec3> line(countU);
    for (std::size_t j = 0; j < countV; ++j) {
        for (std::size_t i = 0; i < countU; ++i) line[i] = grid[i * countV + j];
        columns.push_back(
            chordParametersOrEmpty(line, closureU, "grid parameters: column " + std::to_string(j)));
    }
    for (std::size_t i = 0; i < countU; ++i)
        rows.push_back(chordParametersOrEmpty(grid.subspan(i * countV, countV), closureV,
                                              "grid parameters: row " + std::to_string(i)));
    return GridParameters{average(std::move(columns), "u"), average(std::move(rows), "v")};
}

Surface interpolateSurface(std::span<const glm::dvec3> grid, std::size_t countU, std::size_t countV,
                           const GridParameters& parameters, int degreeU, int degreeV, Closure closureU,
                           Closure closureV) {
    if (!detail::gridSizeIs(grid.size(), countU, countV))
        throw GeometryError("surface interpolation: " + std::to_string(grid.size()) + " points for a " +
                            std::to_string(countU) + " x " + std::to_string(countV) + " grid");
    checkFinite(grid);
    const Interpolator alongU = makeInterpolator(parameters.u, countU, degreeU, closureU);
    const Interpolator alongV = makeInterpolator(parameters.v, countV, degreeV, closureV);
    const std::size_t controlsU = alongU.controlCount();
    const std::size_t controlsV = alongV.controlCount();

    // Columns first: R(i, j) for i over the u control points, j over the data in v.
    std::vector<glm::dvec3> intermediate(controlsU * countV);
    std::vector<glm::dvec3> column(countU);
    for (std::size_t j = 0; j < countV; ++j) {
        for (std::size_t i = 0; i < countU; ++i) column[i] = grid[i * countV + j];
        const std::vector<glm::dvec3> r = alongU.controlPoints(column);
        for (std::size_t i = 0; i < controlsU; ++i) intermediate[i * countV + j] = r[i];
    }
    std::vector<glm::dvec3> control(controlsU * controlsV);
    for (std::size_t i = 0; i < controlsU; ++i) {
        const std::vector<glm::dvec3> row(
            intermediate.begin() + static_cast<std::ptrdiff_t>(i * countV),
            intermediate.begin() + static_cast<std::ptrdiff_t>((i + 1) * countV));
        const std::vector<glm::dvec3> p = alongV.controlPoints(row);
        std::copy(p.begin(), p.end(), control.begin() + static_cast<std::ptrdiff_t>(i * controlsV));
    }
    return Surface(degreeU, degreeV, alongU.knots, alongV.knots, controlsU, controlsV, std::move(control));
}

Surface interpolateSurface(std::span<const glm::dvec3> grid, std::size_t countU, std::size_t countV,
                           int degreeU, int degreeV, Closure closureU, Closure closureV) {
    const GridParameters parameters = chordLengthGridParameters(grid, countU, countV, closureU, closureV);
    return interpolateSurface(grid, countU, countV, parameters, degreeU, degreeV, closureU, closureV);
}

}  // namespace geom
