#include "geom/curvemap/SurfaceDomain.h"

#include "geom/Evaluate.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>

namespace geom::curvemap {

namespace {

double surfaceSize(const Surface& s) {
    glm::dvec3 lo(1e300), hi(-1e300);
    for (const glm::dvec3& p : s.points) {
        lo = glm::min(lo, p);
        hi = glm::max(hi, p);
    }
    return std::max(glm::length(hi - lo), 1e-300);
}

double wrapInto(double x, double a, double b) {
    const double p = b - a;
    double r = std::fmod(x - a, p);
    if (r < 0) r += p;
    return a + r;
}

}  // namespace

glm::dvec2 SurfaceDomain::wrap(const glm::dvec2& uv) const {
    return {closedU ? wrapInto(uv.x, u0, u1) : uv.x, closedW ? wrapInto(uv.y, w0, w1) : uv.y};
}

glm::dvec2 SurfaceDomain::unwrapNear(const glm::dvec2& uv, const glm::dvec2& near) const {
    glm::dvec2 r = uv;
    if (closedU) r.x += std::round((near.x - uv.x) / periodU()) * periodU();
    if (closedW) r.y += std::round((near.y - uv.y) / periodW()) * periodW();
    return r;
}

bool closesInU(const Surface& s, double tolerance) {
    validate(s, "closesInU");
    const double limit = tolerance * surfaceSize(s);
    for (int i = 0; i <= 16; ++i) {
        const double v = s.domainStartV() + (s.domainEndV() - s.domainStartV()) * i / 16.0;
        if (glm::length(evaluate(s, s.domainStartU(), v) - evaluate(s, s.domainEndU(), v)) > limit)
            return false;
    }
    return true;
}

bool closesInV(const Surface& s, double tolerance) {
    validate(s, "closesInV");
    const double limit = tolerance * surfaceSize(s);
    for (int i = 0; i <= 16; ++i) {
        const double u = s.domainStartU() + (s.domainEndU() - s.domainStartU()) * i / 16.0;
        if (glm::length(evaluate(s, u, s.domainStartV()) - evaluate(s, u, s.domainEndV())) > limit)
            return false;
    }
    return true;
}

SurfaceDomain surfaceDomain(const Surface& s, std::optional<bool> closedU, std::optional<bool> closedW) {
    validate(s, "surfaceDomain");
    SurfaceDomain d;
    d.u0 = s.domainStartU();
    d.u1 = s.domainEndU();
    d.w0 = s.domainStartV();
    d.w1 = s.domainEndV();
    d.closedU = closedU ? *closedU : closesInU(s);
    d.closedW = closedW ? *closedW : closesInV(s);
    return d;
}

}  // namespace geom::curvemap
