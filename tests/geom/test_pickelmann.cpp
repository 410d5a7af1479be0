// Worked data of M. N. Pickelmann, The Design of Rational B-spline Algorithms for Interactive
// Color Shading of Surfaces (1985): label matrices and Appendices A and E, checked exactly.
#include "geom/Basis.h"
#include "geom/BezierExtraction.h"
#include "geom/Evaluate.h"

#include <catch2/catch.hpp>
#include <glm/geometric.hpp>

#include <array>
#include <cmath>

namespace test_pickelmann {

using namespace geom;

namespace {

/// The power-basis matrix (x 12; rows t^3, t^2, t, 1; columns N0..N3) of the cubic basis on the
/// span [0, 1] of a six-knot effective knot vector.
std::array<std::array<double, 4>, 4> labelMatrix(const std::array<double, 6>& effective) {
    const std::vector<double> knots{effective[0] - 1, effective[0], effective[1], effective[2],
                                    effective[3],     effective[4], effective[5], effective[5] + 1};
    std::vector<double> d(16);
    basisDerivatives(3, 0.0, 3, knots, 3, d);
    std::array<std::array<double, 4>, 4> m{};
    const double factorial[4] = {1, 1, 2, 6};
    for (int k = 0; k <= 3; ++k)
        for (int j = 0; j < 4; ++j)
            m[static_cast<std::size_t>(3 - k)][static_cast<std::size_t>(j)] =
                12.0 * d[static_cast<std::size_t>(k * 4 + j)] / factorial[k];
    return m;
}

}  // namespace

TEST_CASE("Pickelmann 1985 label matrices of the cubic basis", "[geom][pickelmann]") {
    struct Label {
        int label;
        std::array<double, 6> knots;
        std::array<std::array<double, 4>, 4> rows;
    };
    const Label labels[] = {
        {0, {0, 0, 0, 1, 1, 1}, {{{-12, 36, -36, 12}, {36, -72, 36, 0}, {-36, 36, 0, 0}, {12, 0, 0, 0}}}},
        {1, {-1, 0, 0, 1, 1, 1}, {{{-6, 30, -36, 12}, {18, -54, 36, 0}, {-18, 18, 0, 0}, {6, 6, 0, 0}}}},
        {6, {-1, -1, 0, 1, 2, 2}, {{{-3, 7, -7, 3}, {9, -15, 6, 0}, {-9, 3, 6, 0}, {3, 7, 2, 0}}}},
        {10, {-1, -1, 0, 1, 1, 2}, {{{-3, 12, -15, 6}, {9, -18, 9, 0}, {-9, 0, 9, 0}, {3, 6, 3, 0}}}},
        {12, {0, 0, 0, 1, 2, 3}, {{{-12, 21, -11, 2}, {36, -54, 18, 0}, {-36, 36, 0, 0}, {12, 0, 0, 0}}}},
        {14, {-1, -1, 0, 1, 2, 3}, {{{-3, 7, -6, 2}, {9, -15, 6, 0}, {-9, 3, 6, 0}, {3, 7, 2, 0}}}},
        {15, {-2, -1, 0, 1, 2, 3}, {{{-2, 6, -6, 2}, {6, -12, 6, 0}, {-6, 0, 6, 0}, {2, 8, 2, 0}}}},
    };
    for (const Label& l : labels) {
        INFO("label " << l.label);
        const auto m = labelMatrix(l.knots);
        for (std::size_t r = 0; r < 4; ++r)
            for (std::size_t c = 0; c < 4; ++c) REQUIRE(m[r][c] == Approx(l.rows[r][c]).margin(1e-12));
    }
}

TEST_CASE("Pickelmann 1985 Appendix A: cubic on T = [0 0 0 0 1 .. 8 9 9 9 9]", "[geom][pickelmann]") {
    const std::vector<double> T{0, 0, 0, 0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 9, 9, 9};
    const std::vector<glm::dvec3> xy{{-0.1490382E-01, 0.2372459E+01, 0},  {-0.1279431E+01, 0.2134099E+01, 0},
                                     {-0.1903875E+01, -0.1257925E+01, 0}, {0.1243925E+01, -0.7112664E+00, 0},
                                     {0.1540538E-01, 0.1074566E+01, 0},   {-0.7496327E+00, -0.4256855E+00, 0},
                                     {0.6192721E+00, -0.3516818E+00, 0},  {-0.8542724E-02, 0.5969771E+00, 0},
                                     {-0.4414083E+00, -0.2523811E+00, 0}, {0.3807828E+00, -0.2515893E+00, 0},
                                     {0.1471788E+00, 0.2455054E+00, 0},   {0.1153550E-02, 0.1825014E+00, 0}};
    const std::vector<double> w{0.1570818E+01, 0.2268892E+01, 0.3665206E+01, 0.5759564E+01,
                                0.7853872E+01, 0.9948580E+01, 0.1204253E+02, 0.1413716E+02,
                                0.1623156E+02, 0.1832580E+02, 0.1972236E+02, 0.2042028E+02};
    const Curve plain(3, T, xy);
    // W(t) as a non-rational spline of the weights.
    std::vector<glm::dvec3> wx;
    for (double x : w) wx.emplace_back(x, 0, 0);
    const Curve weight(3, T, wx);
    for (double t : {0.0, 0.25, 0.5, 0.75, 1.0}) {
        const glm::dvec3 p = evaluate(plain, t);
        REQUIRE(p.x == Approx(-0.272 * t * t * t + 2.857 * t * t - 3.794 * t - 0.015).margin(2e-3));
        REQUIRE(p.y == Approx(2.397 * t * t * t - 4.373 * t * t - 0.715 * t + 2.372).margin(2e-3));
        REQUIRE(evaluate(weight, t).x == Approx(2.094 * t + 1.571).margin(2e-3));
    }
}

TEST_CASE("Pickelmann 1985 Appendix E: Bezier form of the non-uniform curve", "[geom][pickelmann]") {
    const Curve c(
        3, {0, 0, 0, 0, 0.3, 0.75, 1.0, 1.66, 1.66, 1.66, 1.66},
        {{0, 0, 0}, {0.5, 1, 0}, {1, 0.5, 0}, {1.5, 0.25, 0}, {2, 0.5, 0}, {2.5, 1, 0}, {3, 0.75, 0}});
    const auto pieces = extractBezier(c);
    REQUIRE(pieces.size() == 4);
    std::vector<glm::dvec3> distinct{pieces[0].curve.points[0]};
    for (const auto& piece : pieces)
        for (std::size_t k = 1; k < 4; ++k) distinct.push_back(piece.curve.points[k]);
    const glm::dvec3 expected[13] = {{0, 0, 0},
                                     {0.5, 1, 0},
                                     {0.7, 0.8, 0},
                                     {0.88, 0.65, 0},
                                     {1.15, 0.425, 0},
                                     {1.375, 0.3125, 0},
                                     {1.5617122, 0.3254989, 0},
                                     {1.6654412, 0.3327206, 0},
                                     {1.7573529, 0.3786765, 0},
                                     {1.8617512, 0.4497441, 0},
                                     {2.1373626, 0.6373626, 0},
                                     {2.5, 1, 0},
                                     {3, 0.75, 0}};
    REQUIRE(distinct.size() == 13);
    for (std::size_t k = 0; k < 13; ++k) REQUIRE(glm::length(distinct[k] - expected[k]) < 1e-7);
}

}  // namespace test_pickelmann
