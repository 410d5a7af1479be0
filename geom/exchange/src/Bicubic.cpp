#include "geom/exchange/Bicubic.h"

#include "geom/DegreeElevation.h"
#include "geom/Evaluate.h"
#include "geom/GeometryError.h"
#include "geom/GlobalInterpolation.h"
#include "geom/Split.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <optional>
#include <string>
#include <utility>

namespace geom::exchange {

namespace {

constexpr std::size_t maxSamples = 513;  ///< per direction: bounds the dense solves and the time

/// `perSpan` parameters evenly spread over each non-empty knot span of the domain, and its end.
std::vector<double> samples(const std::vector<double>& knots, int degree, std::size_t count, int perSpan) {
    std::vector<double> t;
    for (std::size_t k = std::size_t(degree); k < count; ++k)
        for (int i = 0; i < perSpan && knots[k] < knots[k + 1]; ++i)
            t.push_back(knots[k] + (knots[k + 1] - knots[k]) * i / perSpan);
    t.push_back(knots[count]);
    return t;
}

/// The largest distance between the surfaces at the parameters halfway between the samples.
double gapBetween(const Surface& a, const Surface& b, const std::vector<double>& us,
                  const std::vector<double>& vs) {
    auto halves = [](const std::vector<double>& t) {
        std::vector<double> h;
        for (std::size_t i = 0; i < t.size(); ++i) {
            h.push_back(t[i]);
            if (i + 1 < t.size()) h.push_back((t[i] + t[i + 1]) / 2);
        }
        return h;
    };
    double gap = 0;
    for (double u : halves(us))
        for (double v : halves(vs)) gap = std::max(gap, glm::length(evaluate(a, u, v) - evaluate(b, u, v)));
    return gap;
}

Surface bicubicFromPolynomial(Surface s) {
    if (s.degreeU < 3) s = elevateDegree(s, 3 - s.degreeU, false);
    if (s.degreeV < 3) s = elevateDegree(s, 3 - s.degreeV, true);
    return s;
}

/// Interior knots where the surface is less than C3 in one direction (multiplicity above degree
/// - 3): a C2 cubic interpolant across such a knot converges only as fast as its jump in the
/// third derivative allows (huge beside a short span) and rings beside a crease, so the surface
/// is interpolated in pieces between them, joined there with C0 knots.
std::vector<double> creases(const std::vector<double>& knots, int degree, std::size_t count) {
    std::vector<double> out;
    for (std::size_t i = std::size_t(degree) + 1; i < count;) {
        std::size_t j = i;
        while (j < count && knots[j] == knots[i]) ++j;
        if (int(j - i) > degree - 3) out.push_back(knots[i]);
        i = j;
    }
    return out;
}

/// The surface cut at `at` (ascending, inside its domain) along u or v, in order.
std::vector<Surface> cut(Surface s, const std::vector<double>& at, bool alongV) {
    std::vector<Surface> pieces;
    for (double t : at) {
        auto [first, rest] = split(s, t, alongV);
        pieces.push_back(std::move(first));
        s = std::move(rest);
    }
    pieces.push_back(std::move(s));
    return pieces;
}

/// Clamped knot vectors of pieces in order joined end to start with multiplicity 3 (C0).
std::vector<double> joinedKnots(const std::vector<const std::vector<double>*>& pieces) {
    std::vector<double> out;
    for (std::size_t a = 0; a < pieces.size(); ++a) {
        const std::vector<double>& k = *pieces[a];
        const std::size_t from = a == 0 ? 0 : 4, to = a + 1 == pieces.size() ? k.size() : k.size() - 1;
        out.insert(out.end(), k.begin() + std::ptrdiff_t(from), k.begin() + std::ptrdiff_t(to));
    }
    return out;
}

/// A grid of bicubic pieces (grid[a][b]: a along u) joined into one surface with C0 knots
/// between them; a shared edge's points are the same in both pieces (the same edge data
/// interpolated alike), up to rounding.
Surface joinGrid(const std::vector<std::vector<Surface>>& grid) {
    std::vector<const std::vector<double>*> ku, kv;
    std::vector<std::size_t> offU{0}, offV{0};
    for (const auto& column : grid) {
        ku.push_back(&column.front().knotsU);
        offU.push_back(offU.back() + column.front().countU - 1);
    }
    for (const Surface& piece : grid.front()) {
        kv.push_back(&piece.knotsV);
        offV.push_back(offV.back() + piece.countV - 1);
    }
    const std::size_t countU = offU.back() + 1, countV = offV.back() + 1;
    std::vector<glm::dvec3> points(countU * countV);
    for (std::size_t a = 0; a < grid.size(); ++a)
        for (std::size_t b = 0; b < grid[a].size(); ++b) {
            const Surface& p = grid[a][b];
            for (std::size_t i = 0; i < p.countU; ++i)
                for (std::size_t j = 0; j < p.countV; ++j)
                    points[(offU[a] + i) * countV + offV[b] + j] = p.points[i * p.countV + j];
        }
    return Surface(3, 3, joinedKnots(ku), joinedKnots(kv), countU, countV, std::move(points));
}

/// The bicubic interpolating one smooth piece at `perSpan` points per knot span each way, and
/// its distance from the piece halfway between them; nullopt past maxSamples a direction.
std::optional<std::pair<Surface, double>> interpolatePiece(const Surface& piece, int perSpan) {
    const auto us = samples(piece.knotsU, piece.degreeU, piece.countU, perSpan);
    const auto vs = samples(piece.knotsV, piece.degreeV, piece.countV, perSpan);
    if (us.size() > maxSamples || vs.size() > maxSamples) return std::nullopt;
    std::vector<glm::dvec3> grid;
    for (double u : us)
        for (double v : vs) grid.push_back(evaluate(piece, u, v));
    Surface b = interpolateSurface(grid, us.size(), vs.size(), GridParameters{us, vs}, 3, 3, Closure::Open,
                                   Closure::Open);
    const double gap = gapBetween(piece, b, us, vs);
    return std::pair{std::move(b), gap};
}

}  // namespace

BicubicSurface toBicubic(const Surface& surface, double tolerance) {
    validate(surface, "toBicubic");
    if (!(tolerance > 0)) throw GeometryError("toBicubic: the tolerance must be positive");
    BicubicSurface r;
    if (!surface.rational() && surface.degreeU <= 3 && surface.degreeV <= 3) {
        r.surface = bicubicFromPolynomial(surface);
        return r;
    }
    // The pieces between the surface's creases, each interpolated through samples on its own
    // parameters, twice as dense each round until every piece is within the tolerance.
    std::vector<std::vector<Surface>> pieces;
    for (Surface& column : cut(surface, creases(surface.knotsU, surface.degreeU, surface.countU), false))
        pieces.push_back(cut(column, creases(column.knotsV, column.degreeV, column.countV), true));
    double gap = 0;
    for (int perSpan = 4;; perSpan *= 2) {  // 5 points or more: a cubic needs 4
        std::vector<std::vector<Surface>> bicubics(pieces.size());
        gap = 0;
        bool tooMany = false;
        for (std::size_t a = 0; a < pieces.size() && !tooMany; ++a)
            for (const Surface& piece : pieces[a]) {
                auto made = interpolatePiece(piece, perSpan);
                if (!made) {
                    tooMany = true;
                    break;
                }
                bicubics[a].push_back(std::move(made->first));
                gap = std::max(gap, made->second);
            }
        if (tooMany)
            throw GeometryError("toBicubic: no bicubic within " + std::to_string(tolerance) + " from " +
                                std::to_string(maxSamples) + " samples a direction");
        if (gap <= tolerance) {
            r.surface = joinGrid(bicubics);
            break;
        }
    }
    r.exact = false;
    r.maxError = gap;
    return r;
}

}  // namespace geom::exchange
