#include "geom/exchange/OcctConversion.h"

#include "geom/GeometryError.h"

#include <BSplCLib.hxx>
#include <Standard_Failure.hxx>
#include <TColStd_Array1OfInteger.hxx>
#include <TColStd_Array1OfReal.hxx>
#include <TColStd_Array2OfReal.hxx>
#include <TColgp_Array1OfPnt.hxx>
#include <TColgp_Array1OfPnt2d.hxx>
#include <TColgp_Array2OfPnt.hxx>

#include <algorithm>
#include <cmath>
#include <optional>
#include <span>
#include <string>

namespace geom::exchange {

namespace {

/// One direction's knots as OpenCASCADE keeps them.
struct DistinctKnots {
    std::vector<double> values;
    std::vector<int> mults;
    std::size_t poles = 0;  ///< the pole count in that direction (each pole once when periodic)
};

TColStd_Array1OfReal realArray(const std::vector<double>& v) {
    TColStd_Array1OfReal a(1, int(v.size()));
    for (std::size_t i = 0; i < v.size(); ++i) a(int(i) + 1) = v[i];
    return a;
}

TColStd_Array1OfInteger intArray(const std::vector<int>& v) {
    TColStd_Array1OfInteger a(1, int(v.size()));
    for (std::size_t i = 0; i < v.size(); ++i) a(int(i) + 1) = v[i];
    return a;
}

/// Distinct values and multiplicities of a flat knot vector (repeats in geom are exact copies).
DistinctKnots distinct(std::span<const double> flat, std::size_t poles) {
    DistinctKnots k;
    for (double t : flat) {
        if (!k.values.empty() && t == k.values.back()) {
            ++k.mults.back();
        } else {
            k.values.push_back(t);
            k.mults.push_back(1);
        }
    }
    k.poles = poles;
    return k;
}

/// The knots of the domain [t_p, t_count] with their whole multiplicities, where OpenCASCADE's
/// periodic knot sequence of them is `flat` (within 1e-12 of the domain width); else nullopt.
std::optional<DistinctKnots> periodicKnots(std::span<const double> flat, int degree, std::size_t count) {
    const double a = flat[std::size_t(degree)], b = flat[count], width = b - a;
    DistinctKnots k;
    for (double t : flat) {
        if (t < a || t > b) continue;
        if (!k.values.empty() && t == k.values.back())
            ++k.mults.back();
        else {
            k.values.push_back(t);
            k.mults.push_back(1);
        }
    }
    if (k.values.size() < 2 || k.mults.front() != k.mults.back() || k.mults.front() > degree)
        return std::nullopt;
    for (std::size_t i = 1; i + 1 < k.mults.size(); ++i)
        if (k.mults[i] > degree) return std::nullopt;
    std::size_t sum = 0;
    for (std::size_t i = 0; i + 1 < k.mults.size(); ++i) sum += std::size_t(k.mults[i]);
    k.poles = sum;
    if (sum < 2 || sum + std::size_t(degree) + 1 != count + std::size_t(k.mults.front())) return std::nullopt;
    const TColStd_Array1OfReal values = realArray(k.values);
    const TColStd_Array1OfInteger mults = intArray(k.mults);
    const int length = BSplCLib::KnotSequenceLength(mults, degree, true);
    if (length != int(flat.size())) return std::nullopt;
    TColStd_Array1OfReal sequence(1, length);
    BSplCLib::KnotSequence(values, mults, degree, true, sequence);
    for (int i = 0; i < length; ++i)
        if (!(std::abs(sequence(i + 1) - flat[std::size_t(i)]) <= 1e-12 * width)) return std::nullopt;
    return k;
}

double netSize(const std::vector<glm::dvec3>& points) {
    double size = 0;
    for (const auto& p : points) size = std::max({size, std::abs(p.x), std::abs(p.y), std::abs(p.z)});
    return 1.0 + size;
}

/// Points (and weights) `period` apart along one index are equal, for every pair that wraps.
bool wraps(const std::vector<glm::dvec3>& points, const std::vector<double>& weights, std::size_t count,
           std::size_t period, std::size_t stride, std::size_t rows, std::size_t rowStride) {
    const double tolerance = 1e-12 * netSize(points);
    for (std::size_t r = 0; r < rows; ++r)
        for (std::size_t i = period; i < count; ++i) {
            const std::size_t a = r * rowStride + (i - period) * stride, b = r * rowStride + i * stride;
            const glm::dvec3 d = points[a] - points[b];
            if (!(std::max({std::abs(d.x), std::abs(d.y), std::abs(d.z)}) <= tolerance)) return false;
            if (!weights.empty() && !(std::abs(weights[a] - weights[b]) <= 1e-12 * weights[a])) return false;
        }
    return true;
}

std::optional<DistinctKnots> periodicCurve(const Curve& c) {
    auto k = periodicKnots(c.knots, c.degree, c.points.size());
    if (k && wraps(c.points, c.weights, c.points.size(), k->poles, 1, 1, 0)) return k;
    return std::nullopt;
}

std::optional<DistinctKnots> periodicSurface(const Surface& s, bool alongV) {
    const int degree = alongV ? s.degreeV : s.degreeU;
    const std::size_t count = alongV ? s.countV : s.countU;
    auto k = periodicKnots(alongV ? s.knotsV : s.knotsU, degree, count);
    if (!k) return std::nullopt;
    const bool ok = alongV ? wraps(s.points, s.weights, s.countV, k->poles, 1, s.countU, s.countV)
                           : wraps(s.points, s.weights, s.countU, k->poles, s.countV, s.countV, 1);
    return ok ? k : std::nullopt;
}

gp_Pnt pnt(const glm::dvec3& p) {
    return gp_Pnt(p.x, p.y, p.z);
}

std::vector<double> flatKnots(const TColStd_Array1OfReal& knots, const TColStd_Array1OfInteger& mults,
                              int degree) {
    TColStd_Array1OfReal sequence(1, BSplCLib::KnotSequenceLength(mults, degree, false));
    BSplCLib::KnotSequence(knots, mults, degree, false, sequence);
    return {sequence.begin(), sequence.end()};
}

[[noreturn]] void rethrow(const Standard_Failure& e, const char* where) {
    throw GeometryError(std::string(where) + ": OpenCASCADE refused the B-spline: " +
                        (e.GetMessageString() ? e.GetMessageString() : e.DynamicType()->Name()));
}

}  // namespace

bool periodicByConstruction(const Curve& curve) {
    validate(curve, "periodicByConstruction");
    return periodicCurve(curve).has_value();
}

bool periodicByConstruction(const Surface& surface, bool alongV) {
    validate(surface, "periodicByConstruction");
    return periodicSurface(surface, alongV).has_value();
}

opencascade::handle<Geom_BSplineCurve> toOcct(const Curve& curve, Periodicity periodicity) {
    validate(curve, "toOcct");
    std::optional<DistinctKnots> k;
    if (periodicity == Periodicity::Detect) k = periodicCurve(curve);
    const bool periodic = k.has_value();
    if (!periodic) k = distinct(curve.knots, curve.points.size());
    TColgp_Array1OfPnt poles(1, int(k->poles));
    TColStd_Array1OfReal weights(1, int(k->poles));
    for (std::size_t i = 0; i < k->poles; ++i) {
        poles(int(i) + 1) = pnt(curve.points[i]);
        weights(int(i) + 1) = curve.weight(i);
    }
    try {
        if (curve.rational())
            return new Geom_BSplineCurve(poles, weights, realArray(k->values), intArray(k->mults),
                                         curve.degree, periodic);
        return new Geom_BSplineCurve(poles, realArray(k->values), intArray(k->mults), curve.degree, periodic);
    } catch (const Standard_Failure& e) {
        rethrow(e, "toOcct");
    }
}

opencascade::handle<Geom_BSplineSurface> toOcct(const Surface& surface, Periodicity periodicity) {
    validate(surface, "toOcct");
    std::optional<DistinctKnots> ku, kv;
    if (periodicity == Periodicity::Detect) {
        ku = periodicSurface(surface, false);
        kv = periodicSurface(surface, true);
    }
    const bool periodicU = ku.has_value(), periodicV = kv.has_value();
    if (!periodicU) ku = distinct(surface.knotsU, surface.countU);
    if (!periodicV) kv = distinct(surface.knotsV, surface.countV);
    TColgp_Array2OfPnt poles(1, int(ku->poles), 1, int(kv->poles));
    TColStd_Array2OfReal weights(1, int(ku->poles), 1, int(kv->poles));
    for (std::size_t i = 0; i < ku->poles; ++i)
        for (std::size_t j = 0; j < kv->poles; ++j) {
            poles(int(i) + 1, int(j) + 1) = pnt(surface.point(i, j));
            weights(int(i) + 1, int(j) + 1) = surface.weight(i, j);
        }
    try {
        if (surface.rational())
            return new Geom_BSplineSurface(poles, weights, realArray(ku->values), realArray(kv->values),
                                           intArray(ku->mults), intArray(kv->mults), surface.degreeU,
                                           surface.degreeV, periodicU, periodicV);
        return new Geom_BSplineSurface(poles, realArray(ku->values), realArray(kv->values),
                                       intArray(ku->mults), intArray(kv->mults), surface.degreeU,
                                       surface.degreeV, periodicU, periodicV);
    } catch (const Standard_Failure& e) {
        rethrow(e, "toOcct");
    }
}

opencascade::handle<Geom2d_BSplineCurve> polylineToOcct(const std::vector<glm::dvec2>& points) {
    if (points.size() < 2) throw GeometryError("polylineToOcct: a polyline needs 2 points or more");
    const int n = int(points.size());
    TColgp_Array1OfPnt2d poles(1, n);
    TColStd_Array1OfReal knots(1, n);
    TColStd_Array1OfInteger mults(1, n);
    for (int i = 0; i < n; ++i) {
        const glm::dvec2& p = points[std::size_t(i)];
        if (!std::isfinite(p.x) || !std::isfinite(p.y))
            throw GeometryError("polylineToOcct: point " + std::to_string(i) + " is not finite");
        poles(i + 1) = gp_Pnt2d(p.x, p.y);
        knots(i + 1) = i;
        mults(i + 1) = i == 0 || i == n - 1 ? 2 : 1;
    }
    return new Geom2d_BSplineCurve(poles, knots, mults, 1);
}

Curve fromOcct(const Geom_BSplineCurve& source) {
    opencascade::handle<Geom_BSplineCurve> c =
        opencascade::handle<Geom_BSplineCurve>::DownCast(source.Copy());
    if (c->IsPeriodic()) c->SetNotPeriodic();  // OpenCASCADE's own unrolling: poles wrap, knots periodic
    std::vector<glm::dvec3> points;
    std::vector<double> weights;
    for (int i = 1; i <= c->NbPoles(); ++i) {
        const gp_Pnt& p = c->Pole(i);
        points.emplace_back(p.X(), p.Y(), p.Z());
        if (c->IsRational()) weights.push_back(c->Weight(i));
    }
    return Curve(c->Degree(), flatKnots(c->Knots(), c->Multiplicities(), c->Degree()), std::move(points),
                 std::move(weights));
}

Surface fromOcct(const Geom_BSplineSurface& source) {
    opencascade::handle<Geom_BSplineSurface> s =
        opencascade::handle<Geom_BSplineSurface>::DownCast(source.Copy());
    if (s->IsUPeriodic()) s->SetUNotPeriodic();
    if (s->IsVPeriodic()) s->SetVNotPeriodic();
    const bool rational = s->IsURational() || s->IsVRational();
    std::vector<glm::dvec3> points;
    std::vector<double> weights;
    for (int i = 1; i <= s->NbUPoles(); ++i)
        for (int j = 1; j <= s->NbVPoles(); ++j) {
            const gp_Pnt& p = s->Pole(i, j);
            points.emplace_back(p.X(), p.Y(), p.Z());
            if (rational) weights.push_back(s->Weight(i, j));
        }
    return Surface(s->UDegree(), s->VDegree(), flatKnots(s->UKnots(), s->UMultiplicities(), s->UDegree()),
                   flatKnots(s->VKnots(), s->VMultiplicities(), s->VDegree()), std::size_t(s->NbUPoles()),
                   std::size_t(s->NbVPoles()), std::move(points), std::move(weights));
}

}  // namespace geom::exchange
