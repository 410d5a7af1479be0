#include "geom/Interpolate.h"

#include "EndsAtStart.h"
#include "SparseLu.h"
#include "geom/Basis.h"
#include "geom/GeometryError.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <string>

namespace geom {

namespace {

constexpr int kDegree = 3;

int extraKnots(Continuity c) {
    return c == Continuity::C0 ? 2 : c == Continuity::C1 ? 1 : 0;
}

std::string pointName(std::size_t i) {
    return "data point " + std::to_string(i + 1);
}

/// One equation of the interpolation system: sum_k coefficient[k] * X[k] = rhs, the
/// coefficients that are not zero in column order.
struct Row {
    detail::SparseLu::Row coefficients;
    glm::dvec3 rhs{0.0};
};

/// Solves the square system of the rows (banded, with wrapped corners when periodic).
std::vector<glm::dvec3> solve(std::vector<Row> rows) {
    std::vector<detail::SparseLu::Row> matrix;
    std::vector<glm::dvec3> rhs;
    matrix.reserve(rows.size());
    for (Row& r : rows) {
        // Each row over its largest coefficient: derivative rows scale as 1 / h^order with the
        // parameter steps h, so at 1e-7 or 1e8 model units they would dwarf the value rows, and
        // the pivot test (relative to the largest entry) would find them singular.
        double largest = 0.0;
        for (const auto& entry : r.coefficients) largest = std::max(largest, std::abs(entry.second));
        if (largest > 0.0 && std::isfinite(largest)) {
            for (auto& entry : r.coefficients) entry.second /= largest;
            r.rhs /= largest;
        }
        matrix.push_back(std::move(r.coefficients));
        rhs.push_back(r.rhs);
    }
    const detail::SparseLu lu(std::move(matrix), 1e-13);
    if (lu.singular())
        throw GeometryError("interpolateCubic: the interpolation system is singular (unknown " +
                            std::to_string(lu.singularColumn()) + "); check the continuities and tangents");
    return lu.solve(std::move(rhs));
}

void checkData(const InterpolationData& data, const std::vector<Continuity>& continuities) {
    const std::size_t n = data.points.size();
    if (n < (data.closed ? 3u : 2u))
        throw GeometryError("interpolateCubic: " + std::string(data.closed ? "a closed" : "an open") +
                            " curve needs at least " + (data.closed ? "3" : "2") + " data points, got " +
                            std::to_string(n));
    if (continuities.size() != n)
        throw GeometryError("interpolateCubic: " + std::to_string(continuities.size()) +
                            " continuities for " + std::to_string(n) + " data points");
    for (std::size_t i = 0; i < n; ++i) {
        const int c = static_cast<int>(continuities[i]);
        if (c < 0 || c > 2)
            throw GeometryError("interpolateCubic: continuity " + std::to_string(c) + " of " + pointName(i) +
                                " is not 0, 1 or 2");
        for (int k = 0; k < 3; ++k)
            if (!std::isfinite(data.points[i][k]))
                throw GeometryError("interpolateCubic: " + pointName(i) + " is not finite");
    }
    const std::size_t needed = constraintCount(continuities);
    if (data.tangents.size() != needed)
        throw GeometryError("interpolateCubic: the continuities ask for " + std::to_string(needed) +
                            " tangent constraints, got " + std::to_string(data.tangents.size()));
    for (std::size_t i = 0; i < data.tangents.size(); ++i)
        for (int k = 0; k < 3; ++k)
            if (!std::isfinite(data.tangents[i][k]))
                throw GeometryError("interpolateCubic: tangent constraint " + std::to_string(i + 1) +
                                    " is not finite");
    if (data.closed) {
        if (!detail::endsAtStart(data.points))
            throw GeometryError("interpolateCubic: a closed curve must end at its first point (" +
                                pointName(n - 1) + " differs from data point 1)");
        if (continuities.back() != continuities.front())
            throw GeometryError("interpolateCubic: the closing " + pointName(n - 1) +
                                " must have the continuity of data point 1");
    }
}

}  // namespace

std::size_t constraintCount(const std::vector<Continuity>& continuities) {
    std::size_t count = 0;
    for (Continuity c : continuities) count += static_cast<std::size_t>(extraKnots(c));
    return count;
}

std::size_t interpolationKnotCount(const std::vector<Continuity>& continuities, std::size_t pointCount) {
    std::size_t count = pointCount + 6;
    for (std::size_t i = 1; i + 1 < continuities.size(); ++i)
        count += static_cast<std::size_t>(extraKnots(continuities[i]));
    return count;
}

std::vector<double> interpolationParameters(const std::vector<glm::dvec3>& points, Parameterization kind) {
    if (kind != Parameterization::Uniform && kind != Parameterization::ChordLength &&
        kind != Parameterization::Centripetal)
        throw GeometryError("interpolationParameters: parameterization " +
                            std::to_string(static_cast<int>(kind)) +
                            " is not Uniform, ChordLength or Centripetal");
    std::vector<double> t(points.size(), 0.0);
    for (std::size_t i = 1; i < points.size(); ++i) {
        const double d = glm::length(points[i] - points[i - 1]);
        double step = 1.0;
        if (kind == Parameterization::ChordLength) step = d;
        if (kind == Parameterization::Centripetal) step = std::sqrt(d);
        if (kind != Parameterization::Uniform && !(step > 0.0))
            throw GeometryError("interpolateCubic: " + pointName(i - 1) + " and " + pointName(i) +
                                " coincide (or lie too close to tell apart), so they get the same parameter");
        t[i] = t[i - 1] + step;
        // A chord too long for a double (coordinates past about 1e154), or one lost to rounding
        // next to a much longer sum, leaves no usable parameter.
        if (!std::isfinite(t[i]) || !(t[i] > t[i - 1]))
            throw GeometryError("interpolateCubic: the parameter of " + pointName(i) +
                                " is not a finite number above the one before (the points are too far "
                                "apart, or too close for their distance from the start)");
    }
    return t;
}

Curve interpolateCubic(const InterpolationData& data) {
    std::vector<Continuity> cont = data.continuities;
    if (cont.empty()) cont.assign(data.points.size(), Continuity::C2);
    checkData(data, cont);
    const std::size_t n = data.points.size();
    const std::vector<double> t = interpolationParameters(data.points, data.parameterization);

    // Each point's tangents in file order: C0 -> {incoming, outgoing}, C1 -> {tangent}.
    std::vector<std::vector<glm::dvec3>> tangentsAt(n);
    for (std::size_t i = 0, next = 0; i < n; ++i)
        for (int k = 0; k < extraKnots(cont[i]); ++k) tangentsAt[i].push_back(data.tangents[next++]);

    const bool periodic = data.closed && cont.front() == Continuity::C2;
    std::vector<double> knots;
    std::size_t unknowns = 0;
    if (periodic) {
        std::vector<double> domain{t.front()};
        for (std::size_t i = 1; i + 1 < n; ++i) domain.insert(domain.end(), 1 + extraKnots(cont[i]), t[i]);
        domain.push_back(t.back());
        const long m = static_cast<long>(domain.size()) - 1;
        const double period = t.back() - t.front();
        // The periodic extension of the domain knots, three beyond each end.
        for (long i = -kDegree; i <= m + kDegree; ++i) {
            const long q = (i >= 0 ? i / m : -((-i + m - 1) / m));
            knots.push_back(domain[static_cast<std::size_t>(i - q * m)] + static_cast<double>(q) * period);
        }
        unknowns = static_cast<std::size_t>(m);
    } else {
        knots.assign(kDegree + 1, t.front());
        for (std::size_t i = 1; i + 1 < n; ++i) knots.insert(knots.end(), 1 + extraKnots(cont[i]), t[i]);
        knots.insert(knots.end(), kDegree + 1, t.back());
        unknowns = knots.size() - kDegree - 1;
    }
    const std::size_t controlCount = knots.size() - kDegree - 1;

    std::vector<Row> rows;
    double basis[3 * (kDegree + 1)];
    // side: 0 = value span (findSpan), -1 = the span ending at u, +1 = the span starting at u.
    auto addRow = [&](double u, int side, int order, const glm::dvec3& rhs) {
        std::size_t span = findSpan(kDegree, knots, controlCount, u);
        if (side < 0)
            span =
                static_cast<std::size_t>(std::lower_bound(knots.begin(), knots.end(), u) - knots.begin()) - 1;
        if (side > 0)
            span =
                static_cast<std::size_t>(std::upper_bound(knots.begin(), knots.end(), u) - knots.begin()) - 1;
        basisDerivatives(span, u, kDegree, knots, order, basis);
        Row row{{}, rhs};
        for (int j = 0; j <= kDegree; ++j) {
            const std::size_t column = (span - kDegree + static_cast<std::size_t>(j)) % unknowns;
            detail::SparseLu::add(row.coefficients, column, basis[order * (kDegree + 1) + j]);
        }
        detail::SparseLu::finish(row.coefficients);
        rows.push_back(std::move(row));
    };

    for (std::size_t i = 0; i < (periodic ? n - 1 : n); ++i) addRow(t[i], 0, 0, data.points[i]);
    for (std::size_t i = 1; i + 1 < n; ++i) {
        if (cont[i] == Continuity::C1) addRow(t[i], +1, 1, tangentsAt[i][0]);
        if (cont[i] == Continuity::C0) {
            addRow(t[i], -1, 1, tangentsAt[i][0]);
            addRow(t[i], +1, 1, tangentsAt[i][1]);
        }
    }
    if (data.closed && !periodic) {
        // Clamped at the closing point: its tangent(s) replace the end conditions.
        const auto& tan = tangentsAt.front();
        addRow(t.front(), +1, 1, tan.size() == 2 ? tan[1] : tan[0]);
        addRow(t.back(), -1, 1, tan[0]);
    } else if (!data.closed) {
        if (cont.front() == Continuity::C2)
            addRow(t.front(), +1, 2, glm::dvec3(0.0));
        else
            addRow(t.front(), +1, 1, tangentsAt.front().back());
        if (cont.back() == Continuity::C2)
            addRow(t.back(), -1, 2, glm::dvec3(0.0));
        else
            addRow(t.back(), -1, 1, tangentsAt.back().front());
    }
    if (rows.size() != unknowns)
        throw GeometryError("interpolateCubic: internal error, " + std::to_string(rows.size()) +
                            " equations for " + std::to_string(unknowns) + " unknowns");

    const std::vector<glm::dvec3> x = solve(std::move(rows));
    std::vector<glm::dvec3> control(controlCount);
    for (std::size_t c = 0; c < controlCount; ++c) control[c] = x[c % unknowns];
    return Curve(kDegree, std::move(knots), std::move(control));
}

}  // namespace geom
