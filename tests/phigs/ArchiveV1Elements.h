#pragma once

// Random elements holding only what archive format version 1 could say, of the four payloads
// that version 2 extended (fill area set 3 with data, triangle strip, quadrilateral mesh,
// parametric surface characteristics), mixed with a few others. The files in
// tests/data/archive_v1 were written from v1Archive(seed) by ArchiveFile::encode as it was
// at version 1; the test regenerates the same contents and reads the files back. Only the
// fields of version 1 are set, so this compiles against either version of Element.h, and
// only raw std::mt19937 outputs are used (no distributions), so every standard library draws
// the same contents.

#include "phigs/store/Element.h"

#include <cstdint>
#include <map>
#include <random>
#include <vector>

namespace phigs::testing::v1 {

/// An integer in [lo, hi].
inline int draw(std::mt19937& rng, int lo, int hi) {
    return lo + static_cast<int>(rng() % static_cast<std::uint32_t>(hi - lo + 1));
}
/// A real in [-100, 100) with all 32 bits of one draw, so it needs its shortest round-trip text.
inline double real(std::mt19937& rng) {
    return static_cast<double>(rng()) / 4294967296.0 * 200.0 - 100.0;
}
inline glm::dvec3 point(std::mt19937& rng) {
    const double x = real(rng), y = real(rng);
    return {x, y, real(rng)};
}
inline std::vector<glm::dvec3> points(std::mt19937& rng, int n) {
    std::vector<glm::dvec3> p;
    for (int i = 0; i < n; ++i) p.push_back(point(rng));
    return p;
}
inline Colour colour(std::mt19937& rng) {
    if (draw(rng, 0, 1)) return Colour::indexed(draw(rng, 0, 255));
    const double r = draw(rng, 0, 1000) / 1000.0, g = draw(rng, 0, 1000) / 1000.0;
    return Colour::fromRgb({r, g, draw(rng, 0, 1000) / 1000.0});
}
inline std::vector<Colour> colours(std::mt19937& rng, std::size_t n) {
    std::vector<Colour> c;
    for (std::size_t i = 0; i < n; ++i) c.push_back(colour(rng));
    return c;
}

inline FillAreaSetWithDataElement fillAreaSetWithData(std::mt19937& rng) {
    FillAreaSetWithDataElement e;
    const bool withColours = draw(rng, 0, 1), withNormals = draw(rng, 0, 1);
    for (int c = draw(rng, 1, 3); c > 0; --c) {
        e.contours.push_back(points(rng, draw(rng, 3, 6)));
        const int n = static_cast<int>(e.contours.back().size());
        if (withColours) e.vertexColours.push_back(colours(rng, static_cast<std::size_t>(n)));
        if (withNormals) e.vertexNormals.push_back(points(rng, n));
    }
    e.hasFacetColour = draw(rng, 0, 1);
    if (e.hasFacetColour) e.facetColour = colour(rng);
    e.hasFacetNormal = draw(rng, 0, 1);
    if (e.hasFacetNormal) e.facetNormal = point(rng);
    return e;
}
inline TriangleStripElement triangleStrip(std::mt19937& rng) {
    TriangleStripElement e;
    e.points = points(rng, draw(rng, 3, 8));
    if (draw(rng, 0, 1)) e.vertexColours = colours(rng, e.points.size());
    if (draw(rng, 0, 1)) e.vertexNormals = points(rng, static_cast<int>(e.points.size()));
    return e;
}
inline QuadrilateralMeshElement quadrilateralMesh(std::mt19937& rng) {
    QuadrilateralMeshElement e;
    e.rows = draw(rng, 2, 4), e.columns = draw(rng, 2, 4);
    const int n = e.rows * e.columns;
    e.points = points(rng, n);
    if (draw(rng, 0, 1)) e.vertexColours = colours(rng, static_cast<std::size_t>(n));
    if (draw(rng, 0, 1)) e.vertexNormals = points(rng, n);
    return e;
}
inline SurfaceCharacteristicsAttribute surfaceCharacteristics(std::mt19937& rng) {
    SurfaceCharacteristicsAttribute e;
    e.style = draw(rng, 1, 3);
    e.placement = draw(rng, 0, 1);
    e.curvesU = draw(rng, 0, 20), e.curvesV = draw(rng, 0, 20);
    return e;
}

/// One random element: mostly the four extended payloads, sometimes a label or a polyline
/// around them so that their records sit between others.
inline Element element(std::mt19937& rng) {
    switch (draw(rng, 0, 5)) {
        case 0:
            return fillAreaSetWithData(rng);
        case 1:
            return triangleStrip(rng);
        case 2:
            return quadrilateralMesh(rng);
        case 3:
            return surfaceCharacteristics(rng);
        case 4:
            return LabelElement{draw(rng, -1000, 1000)};
        default:
            return PolylineElement{points(rng, draw(rng, 0, 4)), false};
    }
}

/// The contents of one version-1 test archive: 1 to 4 structures of 4 to 12 elements, every
/// one of the four extended payloads at least once.
inline std::map<int, std::vector<Element>> archive(std::uint32_t seed) {
    std::mt19937 rng(seed);
    std::map<int, std::vector<Element>> contents;
    const int structures = draw(rng, 1, 4);
    for (int s = 0; s < structures; ++s) {
        auto& elements = contents[draw(rng, 1, 1000)];
        for (int n = draw(rng, 4, 12); n > 0; --n) elements.push_back(element(rng));
    }
    auto& first = contents.begin()->second;
    first.push_back(fillAreaSetWithData(rng)), first.push_back(triangleStrip(rng));
    first.push_back(quadrilateralMesh(rng)), first.push_back(surfaceCharacteristics(rng));
    return contents;
}

}  // namespace phigs::testing::v1
