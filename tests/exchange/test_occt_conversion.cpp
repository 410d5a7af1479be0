// geom <-> OpenCASCADE B-splines: poles, weights, knots and periodicity exactly.
#include "ExchangeTestUtil.h"

#include "geom/GeometryError.h"
#include "geom/Primitives.h"
#include "geom/exchange/OcctConversion.h"

#include <BSplCLib.hxx>
#include <TColStd_Array1OfInteger.hxx>
#include <TColStd_Array1OfReal.hxx>
#include <TColgp_Array2OfPnt.hxx>

#include <random>

namespace test_occt_conversion {

using namespace geom::exchange;
using exchange_test::requireSameSurface;

namespace {

std::vector<double> occtFlatKnots(const Geom_BSplineCurve& c) {
    TColStd_Array1OfReal flat(1,
                              BSplCLib::KnotSequenceLength(c.Multiplicities(), c.Degree(), c.IsPeriodic()));
    c.KnotSequence(flat);
    return {flat.begin(), flat.end()};
}

/// The OpenCASCADE curve evaluates as the geom one (within 1e-12) across the domain.
double largestCurveGap(const geom::Curve& g, const Geom_BSplineCurve& o) {
    double gap = 0;
    for (int k = 0; k <= 50; ++k) {
        const double u = g.domainStart() + (g.domainEnd() - g.domainStart()) * k / 50.0;
        const gp_Pnt p = o.Value(u);
        gap = std::max(gap, glm::length(geom::evaluate(g, u) - glm::dvec3(p.X(), p.Y(), p.Z())));
    }
    return gap;
}

double largestSurfaceGap(const geom::Surface& g, const Geom_BSplineSurface& o) {
    double gap = 0;
    for (int i = 0; i <= 20; ++i)
        for (int j = 0; j <= 20; ++j) {
            const double u = g.domainStartU() + (g.domainEndU() - g.domainStartU()) * i / 20.0;
            const double v = g.domainStartV() + (g.domainEndV() - g.domainStartV()) * j / 20.0;
            const gp_Pnt p = o.Value(u, v);
            gap = std::max(gap, glm::length(geom::evaluate(g, u, v) - glm::dvec3(p.X(), p.Y(), p.Z())));
        }
    return gap;
}

geom::Curve randomCurve(std::mt19937& rng, int degree, std::size_t count, bool clamped, bool rational) {
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    std::vector<double> knots;
    for (std::size_t i = 0; i < count + std::size_t(degree) + 1; ++i) knots.push_back(unit(rng) * 4);
    std::sort(knots.begin(), knots.end());
    if (clamped) {
        std::fill(knots.begin(), knots.begin() + degree + 1, 0.0);
        std::fill(knots.end() - degree - 1, knots.end(), 4.0);
    }
    std::vector<glm::dvec3> points;
    std::vector<double> weights;
    for (std::size_t i = 0; i < count; ++i) {
        points.emplace_back(unit(rng) * 10 - 5, unit(rng) * 10 - 5, unit(rng) * 10 - 5);
        if (rational) weights.push_back(0.2 + unit(rng) * 3);
    }
    return geom::Curve(degree, knots, points, weights);
}

}  // namespace

TEST_CASE("conversion: open curves keep their poles, weights and flat knots exactly",
          "[exchange][conversion]") {
    std::mt19937 rng(23);
    for (int trial = 0; trial < 40; ++trial) {
        const int degree = 1 + trial % 5;
        const geom::Curve c = randomCurve(rng, degree, std::size_t(degree) + 2 + std::size_t(trial % 7),
                                          trial % 2 == 0, trial % 3 == 0);
        INFO("trial " << trial << " degree " << degree << (trial % 2 == 0 ? " clamped" : " unclamped"));
        const auto o = toOcct(c);
        REQUIRE_FALSE(o->IsPeriodic());
        REQUIRE(o->Degree() == degree);
        REQUIRE(std::size_t(o->NbPoles()) == c.points.size());
        CHECK(occtFlatKnots(*o) == c.knots);
        CHECK(largestCurveGap(c, *o) <= 1e-12);
        const geom::Curve back = fromOcct(*o);
        CHECK(back.knots == c.knots);
        CHECK(back.points == c.points);
        CHECK(back.weights == c.weights);
    }
}

TEST_CASE("conversion: a periodic curve goes to OpenCASCADE periodic, each pole once, and back",
          "[exchange][conversion]") {
    std::vector<glm::dvec3> ring;
    for (int k = 0; k < 7; ++k) ring.emplace_back(std::cos(k * 0.9), std::sin(k * 0.9), 0.1 * k);
    for (const bool rational : {false, true}) {
        const std::vector<double> weights =
            rational ? std::vector<double>{1, 2, 0.5, 1, 3, 1, 0.7} : std::vector<double>{};
        const geom::Curve c = geom::makePeriodicCurve(3, ring, weights);
        REQUIRE(periodicByConstruction(c));
        const auto o = toOcct(c);
        REQUIRE(o->IsPeriodic());
        CHECK(o->NbPoles() == 7);
        CHECK(largestCurveGap(c, *o) <= 1e-12);
        const geom::Curve back = fromOcct(*o);
        CHECK(exchange_test::largestGap(back.knots, c.knots) <= 1e-12);
        REQUIRE(back.points.size() == c.points.size());
        // Rational poles are unrolled through homogeneous coordinates: equal to rounding.
        for (std::size_t i = 0; i < c.points.size(); ++i)
            CHECK(glm::length(back.points[i] - c.points[i]) <= 1e-15);
        CHECK(exchange_test::largestGap(back.weights, c.weights) <= 1e-15);
        // Never: the same unclamped curve, not periodic, every pole kept.
        const auto open = toOcct(c, Periodicity::Never);
        CHECK_FALSE(open->IsPeriodic());
        CHECK(open->NbPoles() == 10);
        CHECK(largestCurveGap(c, *open) <= 1e-12);
    }
    // A closed curve whose last point does not repeat the first is not periodic.
    geom::Curve broken = geom::makePeriodicCurve(3, ring);
    broken.points.back().x += 1e-6;
    CHECK_FALSE(periodicByConstruction(broken));
    CHECK_FALSE(toOcct(broken)->IsPeriodic());
}

TEST_CASE("conversion: the transport's surfaces, periodic round the fuselage and nacelles only",
          "[exchange][conversion]") {
    for (const auto& c : exchange_test::transport().components) {
        INFO(c.name);
        CHECK_FALSE(periodicByConstruction(c.surface, false));
        CHECK(periodicByConstruction(c.surface, true) == c.closedW);
        const auto o = toOcct(c.surface);
        CHECK_FALSE(o->IsUPeriodic());
        CHECK(o->IsVPeriodic() == c.closedW);
        CHECK(std::size_t(o->NbVPoles()) == c.surface.countV - (c.closedW ? 3 : 0));
        CHECK(largestSurfaceGap(c.surface, *o) <= 1e-12);
        requireSameSurface(fromOcct(*o), c.surface);
        // Never: the wrapped form as it is.
        const auto open = toOcct(c.surface, Periodicity::Never);
        CHECK_FALSE(open->IsVPeriodic());
        CHECK(largestSurfaceGap(c.surface, *open) <= 1e-12);
    }
}

TEST_CASE("conversion: rational quadrics and an OpenCASCADE periodic surface with a double seam knot",
          "[exchange][conversion]") {
    for (const geom::Surface& s : {geom::makeSphere(2.5), geom::makeTorus(3, 1), geom::makeCylinder(1, 4)}) {
        const auto o = toOcct(s);
        CHECK(largestSurfaceGap(s, *o) <= 1e-12);
        requireSameSurface(fromOcct(*o), s, 0.0);
    }
    // Periodic in v with multiplicity 2 at the seam (C1 there): geom unrolls it as OpenCASCADE does.
    TColgp_Array2OfPnt poles(1, 4, 1, 6);
    for (int i = 1; i <= 4; ++i)
        for (int j = 1; j <= 6; ++j) poles(i, j) = gp_Pnt(i, std::cos(j), std::sin(j) * (1 + 0.1 * i));
    TColStd_Array1OfReal uk(1, 2), vk(1, 6);
    TColStd_Array1OfInteger um(1, 2), vm(1, 6);
    uk(1) = 0, uk(2) = 1, um(1) = um(2) = 4;
    for (int j = 1; j <= 6; ++j) vk(j) = (j - 1) * 0.2, vm(j) = 1;
    vm(1) = vm(6) = 2;
    const Handle(Geom_BSplineSurface) o = new Geom_BSplineSurface(poles, uk, vk, um, vm, 3, 3, false, true);
    const geom::Surface g = fromOcct(*o);
    CHECK(g.countV == 8);
    CHECK(largestSurfaceGap(g, *o) <= 1e-12);
    REQUIRE(periodicByConstruction(g, true));
    const auto again = toOcct(g);
    REQUIRE(again->IsVPeriodic());
    CHECK(again->NbVPoles() == 6);
    CHECK(again->VMultiplicity(1) == 2);
    CHECK(largestSurfaceGap(g, *again) <= 1e-12);
}

TEST_CASE("conversion: invalid B-splines are refused with geom's message", "[exchange][conversion]") {
    geom::Surface bad = exchange_test::transport().components[1].surface;
    std::swap(bad.knotsU[5], bad.knotsU[6]);
    CHECK_THROWS_AS(toOcct(bad), geom::GeometryError);
    geom::Curve c = geom::makeCircle({0, 0, 0}, {1, 0, 0}, {0, 1, 0}, 1);
    c.weights[2] = -1;
    CHECK_THROWS_WITH(toOcct(c), Catch::Contains("weight"));
    CHECK_THROWS_AS(polylineToOcct({{0, 0}}), geom::GeometryError);
}

}  // namespace test_occt_conversion
