// Facet colours of a triangle strip and a quadrilateral mesh, and the per-edge visibility of a
// fill area set with data, from the store through traversal onto lavapipe: each facet flat in
// its own colour, and only the flagged edges drawn.
#include "RenderTestSupport.h"
#include "phigs/Phigs.h"
#include "phigs/vk/ImageTarget.h"

namespace test_facet_data {

using namespace phigs;
using namespace render_test;

TEST_CASE("facet colours colour their facets flat, edges whose flag is off are not drawn",
          "[render][primitives]") {
    vk::Context context(lavapipeWithValidation());
    {
        Phigs phigs;
        phigs.open();
        StructureStore& store = phigs.store();
        Workstation& model = phigs.openWorkstation(1, WorkstationType::OffscreenImage);
        model.setColourRepresentation(2, {1.0, 0.0, 0.0});
        store.openStructure(1);
        store.insert(IndexAttribute{ElementType::InteriorStyle, int(InteriorStyle::Solid)});
        store.insert(ColourAttribute{ElementType::InteriorColour, Colour::fromRgb({0.5, 0.5, 0.5})});
        // A strip of four triangles up the left third: red (indexed), green, blue, yellow.
        TriangleStripElement strip{{{0.05, 0.05, 0.5},
                                    {0.3, 0.05, 0.5},
                                    {0.05, 0.5, 0.5},
                                    {0.3, 0.5, 0.5},
                                    {0.05, 0.95, 0.5},
                                    {0.3, 0.95, 0.5}},
                                   {},
                                   {}};
        strip.facetColours = {Colour::indexed(2), Colour::fromRgb({0, 1, 0}), Colour::fromRgb({0, 0, 1}),
                              Colour::fromRgb({1, 1, 0})};
        store.insert(strip);
        // A 3 x 3 quadrilateral mesh in the middle third: four quadrilaterals, four colours.
        QuadrilateralMeshElement grid;
        grid.rows = 3, grid.columns = 3;
        for (int r = 0; r < 3; ++r)
            for (int c = 0; c < 3; ++c) grid.points.push_back({0.37 + 0.13 * c, 0.05 + 0.45 * r, 0.5});
        grid.facetColours = {Colour::fromRgb({1, 0, 1}), Colour::fromRgb({0, 1, 1}),
                             Colour::fromRgb({1, 1, 1}), Colour::fromRgb({1, 0.5, 0})};
        store.insert(grid);
        // A square in the right third, edges thick and white: bottom and top on, left and right off.
        store.insert(IndexAttribute{ElementType::EdgeFlag, 1});
        store.insert(RealAttribute{ElementType::EdgewidthScaleFactor, 5.0});
        store.insert(ColourAttribute{ElementType::EdgeColour, Colour::fromRgb({1, 1, 1})});
        FillAreaSetWithDataElement square;
        square.contours = {{{0.7, 0.2, 0.5}, {0.95, 0.2, 0.5}, {0.95, 0.8, 0.5}, {0.7, 0.8, 0.5}}};
        square.edgeFlags = {{1, 0, 1, 0}};
        store.insert(square);
        store.closeStructure();
        model.postStructure(1, 0.5);
        const DrawList& list = model.display();

        // NPC (x, y) is pixel (96 x, 96 (1 - y)) on 128 x 96 pixels (see test_vertex_data).
        vk::ImageTarget ws(context, 128, 96);
        const Image image = ws.draw(list);
        auto px = [&](double x, double y) {
            return at(image, std::uint32_t(x * 96), std::uint32_t((1 - y) * 96));
        };
        // strip triangle k: k even below the diagonal from (0.05, y0 + 0.45) to (0.3, y0), k odd above
        CHECK(near(px(0.1, 0.1), 255, 0, 0));    // triangle 0
        CHECK(near(px(0.25, 0.42), 0, 255, 0));  // triangle 1
        CHECK(near(px(0.1, 0.55), 0, 0, 255));   // triangle 2
        CHECK(near(px(0.25, 0.87), 255, 255, 0));
        CHECK(near(px(0.43, 0.27), 255, 0, 255));  // quadrilateral (0, 0)
        CHECK(near(px(0.57, 0.27), 0, 255, 255));  // (0, 1)
        CHECK(near(px(0.43, 0.73), 255, 255, 255));
        CHECK(near(px(0.57, 0.73), 255, 128, 0, 24));
        CHECK(near(px(0.82, 0.5), 128, 128, 128, 24));   // the square's inside
        CHECK(near(px(0.82, 0.2), 255, 255, 255, 48));   // its bottom edge: on
        CHECK(near(px(0.82, 0.8), 255, 255, 255, 48));   // its top edge: on
        CHECK(near(px(0.705, 0.5), 128, 128, 128, 24));  // its left edge: off, the inside shows
        CHECK(near(px(0.945, 0.5), 128, 128, 128, 24));  // its right edge: off
    }
    requireNoValidationMessages(context);
}

TEST_CASE("level curves of a NURBS surface are drawn in the polyline attributes", "[render][primitives]") {
    vk::Context context(lavapipeWithValidation());
    {
        Phigs phigs;
        phigs.open();
        StructureStore& store = phigs.store();
        Workstation& model = phigs.openWorkstation(1, WorkstationType::OffscreenImage);
        store.openStructure(1);
        store.insert(IndexAttribute{ElementType::InteriorStyle, int(InteriorStyle::Solid)});
        store.insert(ColourAttribute{ElementType::InteriorColour, Colour::fromRgb({0.5, 0.5, 0.5})});
        store.insert(ColourAttribute{ElementType::PolylineColour, Colour::fromRgb({1, 0, 0})});
        store.insert(RealAttribute{ElementType::LinewidthScaleFactor, 3.0});
        // Planes x = 0.3 and x = 0.6 (modelling coordinates) across a flat patch.
        SurfaceCharacteristicsAttribute levels{4, 0, 0, 0};
        levels.origin = {0.1, 0, 0}, levels.direction = {0.1, 0, 0}, levels.levels = {2, 5};
        store.insert(levels);
        store.insert(NurbsSurfaceElement{
            geom::Surface(1, 1, {0, 0, 1, 1}, {0, 0, 1, 1}, 2, 2,
                          {{0.1, 0.1, 0.5}, {0.1, 0.9, 0.5}, {0.9, 0.1, 0.5}, {0.9, 0.9, 0.5}}),
            {}});
        store.closeStructure();
        model.postStructure(1, 0.5);
        vk::ImageTarget ws(context, 128, 96);
        const Image image = ws.draw(model.display());
        auto px = [&](double x, double y) {
            return at(image, std::uint32_t(x * 96), std::uint32_t((1 - y) * 96));
        };
        for (double y : {0.2, 0.5, 0.8}) {
            INFO("y = " << y);
            CHECK(near(px(0.3, y), 255, 0, 0, 48));
            CHECK(near(px(0.6, y), 255, 0, 0, 48));
            CHECK(near(px(0.45, y), 128, 128, 128, 24));
            CHECK(near(px(0.75, y), 128, 128, 128, 24));
        }
    }
    requireNoValidationMessages(context);
}

}  // namespace test_facet_data
