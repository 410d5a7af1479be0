// Primitives carrying per-vertex data: colours blended across a fill area set with data and a
// mesh (draw lists built by hand), and the PHIGS PLUS triangle strip, quadrilateral mesh and
// cell array going through the store and traversal; compared with reference images.
#include "RenderTestSupport.h"
#include "phigs/Phigs.h"
#include "phigs/vk/ImageTarget.h"

namespace test_vertex_data {

using namespace phigs;
using namespace render_test;

namespace {

constexpr std::uint32_t kSize = 128;

/// The pixel of NPC (x, y) on a hand-built list drawn on kSize x kSize pixels.
Rgb pixelAt(const Image& image, double x, double y) {
    return at(image, std::uint32_t(x * kSize), std::uint32_t((1 - y) * kSize));
}

}  // namespace

TEST_CASE("vertex colours: a fill area set with data and a mesh blend the colours of their vertices",
          "[render][primitives]") {
    vk::Context context(lavapipeWithValidation());
    {
        vk::ImageTarget ws(context, kSize, kSize);
        DrawList list = emptyScene();
        // A square with a square hole, red and green along the bottom, blue and white on top; the
        // hole's corners are yellow, which blends in around the hole.
        DrawFillArea frame;
        frame.contours = {{{0.05, 0.05, 0.5}, {0.45, 0.05, 0.5}, {0.45, 0.95, 0.5}, {0.05, 0.95, 0.5}},
                          {{0.15, 0.4, 0.5}, {0.35, 0.4, 0.5}, {0.35, 0.6, 0.5}, {0.15, 0.6, 0.5}}};
        frame.vertexColours = {{{1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {1, 1, 1}},
                               {{1, 1, 0}, {1, 1, 0}, {1, 1, 0}, {1, 1, 0}}};
        frame.interior.edit().style = InteriorStyle::Solid;
        frame.interior.edit().colour = {0.5f, 0.5f, 0.5f};  // must not show: the vertices have colours
        list.items.push_back(item(frame));
        // A mesh of two triangles: black, red, yellow, green at its corners.
        auto mesh = std::make_shared<MeshData>();
        mesh->positions = {
            {0.55f, 0.05f, 0.5f}, {0.95f, 0.05f, 0.5f}, {0.95f, 0.95f, 0.5f}, {0.55f, 0.95f, 0.5f}};
        mesh->colours = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}};
        mesh->triangles = {0, 1, 2, 0, 2, 3};
        DrawMesh quad;
        quad.mesh = mesh;
        quad.interior.edit().style = InteriorStyle::Solid;
        quad.interior.edit().colour = {0.5f, 0.5f, 0.5f};
        list.items.push_back(item(quad));

        const Image image = ws.draw(list);
        CHECK(near(pixelAt(image, 0.07, 0.07), 255, 0, 0, 24));      // near the red corner
        CHECK(near(pixelAt(image, 0.43, 0.07), 0, 255, 0, 24));      // near the green corner
        CHECK(near(pixelAt(image, 0.43, 0.93), 0, 0, 255, 24));      // near the blue corner
        CHECK(near(pixelAt(image, 0.07, 0.93), 255, 255, 255, 24));  // near the white corner
        CHECK(near(pixelAt(image, 0.25, 0.5), 25, 25, 25));          // the hole shows the background
        CHECK(near(pixelAt(image, 0.25, 0.38), 255, 255, 0, 40));    // just below the hole's yellow edge
        CHECK(near(pixelAt(image, 0.57, 0.07), 0, 0, 0, 24));
        CHECK(near(pixelAt(image, 0.93, 0.07), 255, 0, 0, 24));
        CHECK(near(pixelAt(image, 0.93, 0.93), 255, 255, 0, 24));
        CHECK(near(pixelAt(image, 0.57, 0.93), 0, 255, 0, 24));
        CHECK(near(pixelAt(image, 0.75, 0.5), 128, 128, 0, 32));  // the centre: the mean of the diagonal
        compareWithReference(image, "vertex_colours");
    }
    requireNoValidationMessages(context);
}

TEST_CASE("triangle strip, quadrilateral mesh and cell array from the store, through traversal",
          "[render][primitives]") {
    vk::Context context(lavapipeWithValidation());
    {
        Phigs phigs;
        phigs.open();
        StructureStore& store = phigs.store();
        Workstation& model = phigs.openWorkstation(1, WorkstationType::OffscreenImage);
        model.setColourRepresentation(2, {1.0, 0.0, 0.0});
        model.setColourRepresentation(3, {0.0, 1.0, 0.0});
        model.setColourRepresentation(4, {0.0, 0.0, 1.0});
        model.setColourRepresentation(5, {1.0, 1.0, 0.0});
        store.openStructure(1);
        store.insert(IndexAttribute{ElementType::InteriorStyle, int(InteriorStyle::Solid)});
        store.insert(ColourAttribute{ElementType::InteriorColour, Colour::fromRgb({0.0, 0.6, 1.0})});
        // A strip of four triangles, zig-zagging up the left third, one colour for all (the
        // interior colour), so the alternating winding must not drop every other triangle.
        store.insert(TriangleStripElement{{{0.05, 0.05, 0.5},
                                           {0.3, 0.05, 0.5},
                                           {0.05, 0.5, 0.5},
                                           {0.3, 0.5, 0.5},
                                           {0.05, 0.95, 0.5},
                                           {0.3, 0.95, 0.5}},
                                          {},
                                          {}});
        // A 3 x 3 quadrilateral mesh in the middle third, vertex colours through the colour table:
        // red bottom row, green middle, blue top, interpolated (COLOUR shading; flat shading
        // would draw each facet in the interior colour).
        store.insert(IndexAttribute{ElementType::InteriorShadingMethod, int(ShadingMethod::Colour)});
        QuadrilateralMeshElement grid;
        grid.rows = 3, grid.columns = 3;
        for (int r = 0; r < 3; ++r)
            for (int c = 0; c < 3; ++c) {
                grid.points.push_back({0.37 + 0.13 * c, 0.05 + 0.45 * r, 0.5});
                grid.vertexColours.push_back(Colour::indexed(2 + r));
            }
        store.insert(grid);
        // A 2 x 2 cell array in the right third: red, green (bottom row), blue, yellow (top row).
        CellArrayElement cells;
        cells.p = {0.7, 0.05, 0.5}, cells.q = {0.95, 0.05, 0.5}, cells.r = {0.7, 0.95, 0.5};
        cells.columns = 2, cells.rows = 2;
        cells.colourIndices = {2, 3, 4, 5};
        store.insert(cells);
        store.closeStructure();
        model.postStructure(1, 0.5);
        const DrawList& list = model.display();
        REQUIRE(list.items.size() == 3);

        // The display surface is 1024 x 768 device units, NPC on its lower-left 768 x 768: on
        // 128 x 96 pixels, NPC (x, y) is pixel (96 x, 96 (1 - y)).
        vk::ImageTarget ws(context, 128, 96);
        const Image image = ws.draw(list);
        auto px = [&](double x, double y) {
            return at(image, std::uint32_t(x * 96), std::uint32_t((1 - y) * 96));
        };
        for (double y : {0.15, 0.3, 0.4, 0.6, 0.7, 0.85}) {  // both windings of the strip
            INFO("strip at y = " << y);
            CHECK(near(px(0.12, y), 0, 153, 255));
            CHECK(near(px(0.23, y), 0, 153, 255));
        }
        CHECK(near(px(0.5, 0.07), 255, 0, 0, 32));  // the mesh's red row
        CHECK(near(px(0.5, 0.5), 0, 255, 0, 32));   // green in the middle
        CHECK(near(px(0.5, 0.93), 0, 0, 255, 32));  // blue at the top
        const Rgb between = px(0.5, 0.275);         // halfway from red to green
        CHECK(near(between, 128, 128, 0, 40));
        CHECK(near(px(0.76, 0.25), 255, 0, 0));  // cells: flat colours, no blending
        CHECK(near(px(0.89, 0.25), 0, 255, 0));
        CHECK(near(px(0.76, 0.75), 0, 0, 255));
        CHECK(near(px(0.89, 0.75), 255, 255, 0));
        CHECK(near(px(0.82, 0.48), 255, 0, 0));  // just below the middle: still the bottom row
        compareWithReference(image, "store_meshes");

        // Changing a colour table entry the cells and the mesh use reaches both pictures.
        model.setColourRepresentation(2, {1.0, 0.0, 1.0});
        const Image recoloured = ws.draw(model.display());
        CHECK(near(at(recoloured, std::uint32_t(0.76 * 96), std::uint32_t(0.75 * 96)), 255, 0, 255));
        CHECK(near(at(recoloured, std::uint32_t(0.5 * 96), std::uint32_t(0.93 * 96)), 255, 0, 255, 32));
    }
    requireNoValidationMessages(context);
}

}  // namespace test_vertex_data
