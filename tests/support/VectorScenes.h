#pragma once

// Scenes shared by the vector hardcopy tests (tests/hardcopy, GPU-free) and their comparison with
// the lavapipe picture (tests/render): NURBS surfaces through the store and traversal, so the
// draw list holds what an application's would (tessellation, uv, iso-curves, the exact surface).

#include "phigs/Phigs.h"
#include "phigs/store/Element.h"
#include "phigs/view/ViewMatrices.h"
#include "phigs/ws/Workstation.h"

#include "geom/Surface.h"

#include <glm/geometric.hpp>

#include <cmath>
#include <vector>

namespace vector_test {

/// A bicubic B-spline surface with `pieces` x `pieces` Bézier pieces over [x0, x1] x [y0, y1]
/// (x and y affine in u and v: control points at the Greville abscissae), height z plus a bump.
inline geom::Surface wavySurface(double x0, double y0, double x1, double y1, double z, double bump,
                                 int pieces) {
    std::vector<double> knots{0, 0, 0, 0};
    for (int k = 1; k < pieces; ++k) knots.push_back(double(k) / pieces);
    knots.insert(knots.end(), {1, 1, 1, 1});
    const std::size_t n = std::size_t(pieces) + 3;
    std::vector<double> greville;
    for (std::size_t i = 0; i < n; ++i)
        greville.push_back((knots[i + 1] + knots[i + 2] + knots[i + 3]) / 3.0);
    std::vector<glm::dvec3> points;
    for (std::size_t i = 0; i < n; ++i)
        for (std::size_t j = 0; j < n; ++j) {
            const double u = greville[i], v = greville[j];
            points.push_back({x0 + (x1 - x0) * u, y0 + (y1 - y0) * v,
                              z + bump * std::sin(3.14159265 * u) * std::sin(3.14159265 * v)});
        }
    return geom::Surface(3, 3, knots, knots, n, n, points);
}

/// PHIGS and one workstation showing two surfaces, a small one in front of a larger one, each
/// with iso-curves, lit by the default ambient light and one directional light, hidden-surface
/// removal on. View 1 looks at the world box [0, 1]^3 from above and to the right of +z, tilted
/// enough that the front surface hides curved parts of the back one's lines.
struct SurfaceScene {
    static constexpr glm::dvec3 kBackColour{0.9, 0.3, 0.2}, kBackLines{1.0, 0.6, 0.2};
    static constexpr glm::dvec3 kFrontColour{0.2, 0.8, 0.3}, kFrontLines{0.6, 1.0, 0.6};
    /// The front surface covers [kFrontMin, kFrontMax]^2 in world x and y.
    static constexpr double kFrontMin = 0.3, kFrontMax = 0.7;

    phigs::Phigs phigs;
    phigs::Workstation* ws = nullptr;
    geom::Surface front = wavySurface(kFrontMin, kFrontMin, kFrontMax, kFrontMax, 0.7, 0.05, 1);

    explicit SurfaceScene(phigs::WorkstationType type,
                          phigs::ShadingMethod shading = phigs::ShadingMethod::Normal) {
        using namespace phigs;
        phigs.open();
        auto& store = phigs.store();
        store.openStructure(1);
        store.insert(viewIndex(1));
        store.insert(SurfaceCharacteristicsAttribute{3, 0, 3, 3});
        store.insert(IndexAttribute{ElementType::InteriorStyle, int(InteriorStyle::Solid)});
        store.insert(IndexAttribute{ElementType::InteriorShadingMethod, int(shading)});
        store.insert(
            IndexAttribute{ElementType::InteriorReflectanceEquation, int(ReflectanceModel::Diffuse)});
        store.insert(LightSourceStateAttribute{{1, 2}, {}});
        addSurface(store, wavySurface(0.1, 0.1, 0.9, 0.9, 0.3, 0.1, 2), kBackColour, kBackLines);
        addSurface(store, front, kFrontColour, kFrontLines);
        store.closeStructure();
        ws = &phigs.openWorkstation(1, type);
        ViewMapping mapping;
        mapping.windowMin = glm::dvec2(-0.75), mapping.windowMax = glm::dvec2(0.75);
        mapping.backPlaneDistance = -1.0, mapping.frontPlaneDistance = 1.0;
        ws->setViewRepresentation(
            1, {evaluateViewOrientationMatrix({0.5, 0.5, 0.5}, {0.35, -0.7, 1.0}, {0, 1, 0}),
                evaluateViewMappingMatrix(mapping)});
        Light key;
        key.type = LightType::Directional;
        key.direction = glm::normalize(glm::dvec3(-1, -1, -2));
        ws->setLightSourceRepresentation(2, key);
        ws->setHlhsrMode(1);
        ws->postStructure(1, 0.5);
    }

    static void addSurface(phigs::StructureStore& store, geom::Surface surface, glm::dvec3 colour,
                           glm::dvec3 lines) {
        using namespace phigs;
        store.insert(ColourAttribute{ElementType::InteriorColour, Colour::fromRgb(colour)});
        store.insert(ColourAttribute{ElementType::PolylineColour, Colour::fromRgb(lines)});
        NurbsSurfaceElement element;
        element.surface = std::move(surface);
        store.insert(element);
    }
};

}  // namespace vector_test
