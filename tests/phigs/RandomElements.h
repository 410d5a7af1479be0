#pragma once

// Random structure elements of every payload family and type, for round-trip tests.

#include "phigs/store/Element.h"

#include <random>

namespace phigs::testing {

inline double randomReal(std::mt19937& rng) {
    return std::uniform_real_distribution<double>(-100.0, 100.0)(rng);
}
inline int randomInt(std::mt19937& rng, int lo, int hi) {
    return std::uniform_int_distribution<int>(lo, hi)(rng);
}
inline glm::dvec3 randomPoint(std::mt19937& rng) {
    return {randomReal(rng), randomReal(rng), randomReal(rng)};
}
inline std::vector<glm::dvec3> randomPoints(std::mt19937& rng, int n) {
    std::vector<glm::dvec3> p;
    for (int i = 0; i < n; ++i) p.push_back(randomPoint(rng));
    return p;
}
/// A point list's length: empty often, a few points mostly, now and then hundreds.
inline int randomPointCount(std::mt19937& rng) {
    const int kind = randomInt(rng, 0, 15);
    return kind < 2 ? 0 : kind < 15 ? randomInt(rng, 1, 6) : randomInt(rng, 100, 400);
}
inline Colour randomColour(std::mt19937& rng) {
    if (randomInt(rng, 0, 1)) return Colour::indexed(randomInt(rng, 0, 20));
    return Colour::fromRgb({randomInt(rng, 0, 10) / 10.0, 0.25, 1.0 / 3.0});
}
inline geom::Curve randomCurve(std::mt19937& rng, bool rational) {
    int degree = randomInt(rng, 1, 3);
    int n = degree + 1 + randomInt(rng, 0, 3);
    std::vector<double> knots(static_cast<std::size_t>(degree + 1), 0.0);
    for (int i = 1; i < n - degree; ++i) knots.push_back(i);
    knots.insert(knots.end(), static_cast<std::size_t>(degree + 1), double(n - degree));
    std::vector<double> weights;
    if (rational)
        for (int i = 0; i < n; ++i) weights.push_back(0.5 + randomInt(rng, 0, 10) / 7.0);
    return geom::Curve(degree, knots, randomPoints(rng, n), weights);
}
inline geom::Surface randomSurface(std::mt19937& rng) {
    geom::Curve a = randomCurve(rng, false), b = randomCurve(rng, false);
    std::size_t nu = a.points.size(), nv = b.points.size();
    return geom::Surface(a.degree, b.degree, a.knots, b.knots, nu, nv,
                         randomPoints(rng, static_cast<int>(nu * nv)));
}

/// One of the three pattern elements, each with only its own fields set.
inline PatternAttribute randomPattern(std::mt19937& rng) {
    using T = ElementType;
    const T types[] = {T::PatternSize, T::PatternReferencePoint, T::PatternReferencePointAndVectors};
    PatternAttribute e{types[randomInt(rng, 0, 2)]};
    if (e.type == T::PatternSize) {
        e.size = {randomReal(rng), randomReal(rng)};
        return e;
    }
    e.referencePoint = randomPoint(rng);
    if (e.type == T::PatternReferencePoint) {
        e.referencePoint.z = 0;
        return e;
    }
    e.vectorX = randomPoint(rng), e.vectorY = randomPoint(rng);
    return e;
}

/// A random element; executes refer to structures in [1, maxId] greater than `self` so that
/// networks built this way are acyclic.
inline Element randomElement(std::mt19937& rng, int self, int maxId) {
    using T = ElementType;
    bool twoD = randomInt(rng, 0, 1) == 1;
    switch (randomInt(rng, 0, 31)) {
        case 0:
            return PolylineElement{randomPoints(rng, randomPointCount(rng)), twoD};
        case 1:
            return PolymarkerElement{randomPoints(rng, randomPointCount(rng)), twoD};
        case 2:
            return FillAreaElement{randomPoints(rng, randomPointCount(rng)), twoD};
        case 3:
            return FillAreaSetElement{{randomPoints(rng, 4), randomPoints(rng, 3)}, twoD};
        case 4:
            return TextElement{randomPoint(rng), {1, 0, 0}, {0, 1, 0}, "text with spaces\nand 12:34", twoD};
        case 5:
            return AnnotationTextElement{randomPoint(rng), randomPoint(rng), "", twoD};
        case 6:
            return CellArrayElement{randomPoint(rng), randomPoint(rng), randomPoint(rng), 2, 1, {3, 4}, twoD};
        case 7:
            return NurbsCurveElement{randomCurve(rng, randomInt(rng, 0, 1) == 1), 0.0, 0.0};
        case 8: {
            NurbsSurfaceElement s{randomSurface(rng), {}};
            if (randomInt(rng, 0, 1)) s.trimLoops.push_back({randomCurve(rng, false)});
            if (!s.trimLoops.empty() && randomInt(rng, 0, 1))
                s.trimDisplay = {
                    {randomInt(rng, 0, 1) == 1, randomInt(rng, 1, 8), randomInt(rng, 1, 40) / 4.0}};
            return s;
        }
        case 9: {
            FillAreaSetWithDataElement f;
            f.contours = {randomPoints(rng, 3)};
            f.vertexColours = {{randomColour(rng), randomColour(rng), randomColour(rng)}};
            f.hasFacetNormal = true;
            f.facetNormal = {0, 0, 1};
            if (randomInt(rng, 0, 1)) f.edgeFlags = {{randomInt(rng, 0, 1), randomInt(rng, 0, 1), 1}};
            return f;
        }
        case 10: {
            TriangleStripElement e{randomPoints(rng, 4), {}, randomPoints(rng, 4)};
            if (randomInt(rng, 0, 1)) e.facetColours = {randomColour(rng), randomColour(rng)};
            if (randomInt(rng, 0, 1)) e.facetNormals = randomPoints(rng, 2);
            return e;
        }
        case 11: {
            QuadrilateralMeshElement e{2, 2, randomPoints(rng, 4), {}, {}};
            if (randomInt(rng, 0, 1)) e.facetColours = {randomColour(rng)};
            if (randomInt(rng, 0, 1)) e.facetNormals = randomPoints(rng, 1);
            return e;
        }
        case 12: {
            static const T types[] = {T::PolylineIndex, T::Linetype,        T::MarkerType,
                                      T::TextFont,      T::InteriorStyle,   T::EdgeFlag,
                                      T::ViewIndex,     T::PickId,          T::HlhsrIdentifier,
                                      T::DepthCueIndex, T::FaceCullingMode, T::InteriorShadingMethod};
            const T type = types[randomInt(rng, 0, 11)];
            // Bundle indices start at 1, view and depth cue indices at 0 (ISO 9592 refuses less).
            const int lowest = type == T::PolylineIndex                           ? 1
                               : type == T::ViewIndex || type == T::DepthCueIndex ? 0
                                                                                  : -3;
            return IndexAttribute{type, randomInt(rng, lowest, 9)};
        }
        case 13:
            return RealAttribute{randomInt(rng, 0, 1) ? T::CharacterHeight : T::LinewidthScaleFactor,
                                 randomReal(rng)};
        case 14:
            return ColourAttribute{randomInt(rng, 0, 1) ? T::InteriorColour : T::EdgeColour,
                                   randomColour(rng)};
        case 15:
            return UpVectorAttribute{T::AnnotationTextCharacterUpVector, {randomReal(rng), 1.0}};
        case 16:
            return AlignmentAttribute{T::TextAlignment, randomInt(rng, 0, 3), randomInt(rng, 0, 5)};
        case 17:
            return AreaPropertiesAttribute{T::BackAreaProperties, 0.1, 0.2, 0.3, randomColour(rng), 5.0, 0.5};
        case 18:
            return AsfAttribute{static_cast<AspectId>(randomInt(rng, 0, int(AspectId::Count_) - 1)), twoD};
        case 19:
            return ApproximationAttribute{T::SurfaceApproximationCriteria, 2, 4.0, 3.0};
        case 20: {
            if (randomInt(rng, 0, 1)) return SurfaceCharacteristicsAttribute{3, 0, 2, 5};
            SurfaceCharacteristicsAttribute e{randomInt(rng, 4, 5), 0, 0, 0};
            e.origin = randomPoint(rng), e.direction = randomPoint(rng);
            for (int k = randomInt(rng, 0, 4); k > 0; --k) e.levels.push_back(randomReal(rng));
            return e;
        }
        case 21:
            return LightSourceStateAttribute{{1, 2}, {3}};
        case 22: {
            glm::dmat4 m(1.0);
            m[3] = glm::dvec4(randomPoint(rng), 1.0);
            return TransformElement{
                twoD ? T::GlobalModellingTransformation3 : T::LocalModellingTransformation3, m,
                static_cast<Composition>(randomInt(rng, 0, 2))};
        }
        case 23:
            return ModelClipElement{2, {{randomPoint(rng), {0, 0, 1}}}, twoD};
        case 24:
            return RestoreModelClipElement{};
        case 25:
            return NameSetElement{twoD, {randomInt(rng, 0, 63), randomInt(rng, 0, 63)}};
        case 26:
            if (self < maxId) return ExecuteStructureElement{randomInt(rng, self + 1, maxId)};
            return LabelElement{randomInt(rng, -5, 5)};
        case 27:
            return LabelElement{randomInt(rng, -5, 5)};
        case 28:  // an identifier this implementation does not register: stored as given
            return GdpElement{randomInt(rng, 1, 1000), randomPoints(rng, randomInt(rng, 0, 4)),
                              std::string("gdp\0record", 10), twoD};
        case 29:
            return GseElement{randomInt(rng, -1000, 1000), std::string("gse\nrecord")};
        case 30:
            return randomPattern(rng);
        default:
            return ApplicationDataElement{std::string("\0binary\n bytes", 14)};
    }
}

}  // namespace phigs::testing
