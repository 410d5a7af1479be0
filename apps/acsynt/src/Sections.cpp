#include "acsynt/Sections.h"

#include <cmath>
#include <numbers>

namespace acsynt {
namespace {

double radians(double degrees) {
    return degrees * std::numbers::pi / 180.0;
}

/// |s|^power with the sign of s: the super-ellipse coordinate.
double signedPower(double s, double power) {
    return std::copysign(std::pow(std::abs(s), power), s);
}

SectionGrid fuselageSections(const FuselageShape& f, std::size_t points) {
    SectionGrid g{f.stations.size(), points, true, {}};
    g.points.reserve(g.sectionCount * points);
    for (const FuselageStation& s : f.stations) {
        const double power = 2.0 / s.exponent;
        for (std::size_t j = 0; j < points; ++j) {
            const double phi = 2.0 * std::numbers::pi * static_cast<double>(j) / static_cast<double>(points);
            const double c = -std::cos(phi);  // -1 at the bottom, +1 at the top
            const double height = c < 0.0 ? s.lowerHeight : s.upperHeight;
            g.points.push_back({s.x, -s.halfWidth * signedPower(std::sin(phi), power),
                                s.zCentre + height * signedPower(c, power)});
        }
    }
    return g;
}

SectionGrid nacelleSections(const NacelleShape& n, std::size_t points) {
    SectionGrid g{n.profile.size(), points, true, {}};
    g.points.reserve(g.sectionCount * points);
    for (const NacelleStation& s : n.profile)
        for (std::size_t j = 0; j < points; ++j) {
            const double phi = 2.0 * std::numbers::pi * static_cast<double>(j) / static_cast<double>(points);
            g.points.push_back(n.position +
                               glm::dvec3(s.x, -s.radius * std::sin(phi), -s.radius * std::cos(phi)));
        }
    return g;
}

SectionGrid liftingSurfaceSections(const LiftingSurfaceShape& w, ComponentKind kind, std::size_t points) {
    const std::size_t count = static_cast<std::size_t>(w.sections);
    SectionGrid g{count, points, false, {}};
    g.points.reserve(count * points);
    const std::vector<glm::dvec2> root = naca4Contour(w.rootAirfoil, points);
    const std::vector<glm::dvec2> tip = naca4Contour(w.tipAirfoil, points);
    // The span direction leaves the root at the dihedral angle; a vertical tail starts from +z.
    const double roll =
        kind == ComponentKind::VerticalTail ? radians(90.0 - w.dihedral) : radians(w.dihedral);
    const double cr = std::cos(roll), sr = std::sin(roll);
    const double sweep = std::tan(radians(w.sweep));
    for (std::size_t i = 0; i < count; ++i) {
        const double eta = static_cast<double>(i) / static_cast<double>(count - 1);
        const double chord = w.rootChord * (1.0 + (w.taper - 1.0) * eta);
        const double along = eta * w.span;
        const double leadingEdge = along * sweep;
        const double pitch = radians(w.incidence + w.twist * eta);
        const double cp = std::cos(pitch), sp = std::sin(pitch);
        for (std::size_t j = 0; j < points; ++j) {
            const glm::dvec2 a = (1.0 - eta) * root[j] + eta * tip[j];
            // Incidence turns the section about its quarter chord, leading edge up.
            const double dx = (a.x - 0.25) * chord, dz = a.y * chord;
            const double x = leadingEdge + 0.25 * chord + dx * cp + dz * sp;
            const double z = -dx * sp + dz * cp;
            g.points.push_back(w.position + glm::dvec3(x, along * cr - z * sr, along * sr + z * cr));
        }
    }
    return g;
}

}  // namespace

SectionGrid componentSections(const ComponentDescription& c) {
    const std::size_t points = static_cast<std::size_t>(c.points);
    if (const auto* f = std::get_if<FuselageShape>(&c.shape)) return fuselageSections(*f, points);
    if (const auto* n = std::get_if<NacelleShape>(&c.shape)) return nacelleSections(*n, points);
    return liftingSurfaceSections(std::get<LiftingSurfaceShape>(c.shape), c.kind, points);
}

SectionGrid mirrored(const SectionGrid& grid) {
    SectionGrid m = grid;
    const std::size_t n = grid.pointsPerSection;
    for (std::size_t i = 0; i < grid.sectionCount; ++i)
        for (std::size_t j = 0; j < n; ++j) {
            // Closed sections keep their seam point first; open ones simply run backwards.
            const std::size_t from = grid.closedAround ? (n - j) % n : n - 1 - j;
            glm::dvec3 p = grid.at(i, from);
            p.y = -p.y;
            m.points[i * n + j] = p;
        }
    return m;
}

}  // namespace acsynt
