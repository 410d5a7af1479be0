// Efficiency: buffers and pipelines are created once and reused while the input is unchanged; a
// frame with no edits uploads nothing; an edit uploads only what it changed.
#include "RenderTestSupport.h"
#include "SceneMeshes.h"
#include "phigs/Phigs.h"
#include "phigs/render/ItemGeometry.h"
#include "phigs/vk/ImageTarget.h"
#include "phigs/vk/WorkstationDisplay.h"

#include <random>

namespace test_uploads {

using namespace phigs;
using namespace render_test;

namespace {

DrawList editableScene(std::shared_ptr<const MeshData> mesh) {
    DrawList list = emptyScene();
    list.hiddenSurfaceRemoval = true;
    for (int k = 0; k < 3; ++k) {
        DrawPolyline l;
        l.points = {{0.1, 0.2 + 0.2 * k, 0.5}, {0.9, 0.2 + 0.2 * k, 0.5}};
        l.style.edit().colour = {1, 1, 0};
        l.style.edit().type = k == 2 ? LineType::Dashed : LineType::Solid;
        DrawItem i = item(l);
        i.source = DrawSource({{1, k + 1, 0}}, 1);
        list.items.push_back(i);
    }
    DrawMesh m;
    m.mesh = std::move(mesh);
    m.interior.edit().style = InteriorStyle::Solid;
    list.items.push_back(item(m));
    DrawText t;
    t.text = "fixed";
    t.position = {0.1, 0.85, 0.5};
    t.style.edit().height = 0.05;
    list.items.push_back(item(t));
    return list;
}

/// A bicubic Bezier dome over cell k of a row of `count`, its top at 0.5 + `lift`.
NurbsSurfaceElement dome(int k, int count, double lift) {
    const double cell = 1.0 / count, x0 = k * cell;
    std::vector<glm::dvec3> points;
    for (int i = 0; i < 4; ++i)
        for (int j = 0; j < 4; ++j) {
            const bool inner = (i == 1 || i == 2) && (j == 1 || j == 2);
            points.push_back(
                {x0 + 0.9 * cell * i / 3.0, 0.3 + 0.4 * j / 3.0, 0.3 + lift + (inner ? 0.2 : 0.0)});
        }
    const std::vector<double> knots = {0, 0, 0, 0, 1, 1, 1, 1};
    return NurbsSurfaceElement{geom::Surface(3, 3, knots, knots, 4, 4, points), {}};
}

/// Each draw-list mesh of a picture by the structure that holds it (the path's last level).
std::map<int, std::shared_ptr<const MeshData>> meshesByStructure(const DrawList& picture) {
    std::map<int, std::shared_ptr<const MeshData>> meshes;
    for (const DrawItem& item : picture.items)
        if (const auto* m = primitiveIf<DrawMesh>(item.primitive))
            meshes[item.source.path().back().structureId] = m->mesh;
    return meshes;
}

std::uint64_t bufferBytes(const MeshData& mesh) {
    return render::meshVertices(mesh).size() * sizeof(render::RenderVertex) +
           render::meshIndices(mesh).indices.size() * sizeof(std::uint32_t);
}

}  // namespace

TEST_CASE("uploads: unchanged frames upload nothing, edits upload only what changed", "[render][uploads]") {
    vk::Context context(lavapipeWithValidation());
    {
        vk::ImageTarget ws(context, 128, 128);
        const vk::Renderer& renderer = ws.renderer();
        auto mesh = sphere({0.5f, 0.5f, 0.5f}, 0.2f, 16, 8, 2);
        DrawList list = editableScene(mesh);

        const Image first = ws.draw(list);
        const vk::RenderStats initial = renderer.lastFrame();
        CHECK(initial.uploads > 0);
        CHECK(initial.pipelinesCreated > 0);
        CHECK(initial.buffersCreated > 0);

        SECTION("an unchanged frame uploads and creates nothing and draws the same") {
            const Image again = ws.draw(list);
            CHECK(renderer.lastFrame().uploads == 0);
            CHECK(renderer.lastFrame().uploadedBytes == 0);
            CHECK(renderer.lastFrame().buffersCreated == 0);
            CHECK(renderer.lastFrame().pipelinesCreated == 0);
            CHECK(renderer.lastFrame().drawCalls == initial.drawCalls);
            CHECK(again.rgba == first.rgba);
            // A fresh copy of the same list (as a new traversal would give) is just as unchanged.
            const DrawList copy = editableScene(mesh);
            ws.draw(copy);
            CHECK(renderer.lastFrame().uploads == 0);
        }
        SECTION("moving one polyline re-uploads that polyline's vertices only") {
            auto& moved = std::get<DrawPolyline>(list.items[1].primitive).points;
            std::vector<glm::dvec3> points = moved;
            points[1].y += 0.1;
            moved = points;
            list.items[1].source = DrawSource(list.items[1].source.path(), 2);
            ws.draw(list);
            CHECK(renderer.lastFrame().uploads == 1);
            CHECK(renderer.lastFrame().uploadedBytes == 2 * sizeof(render::RenderVertex));
            CHECK(renderer.lastFrame().buffersCreated == 1);
            CHECK(renderer.lastFrame().buffersDestroyed == 1);
        }
        SECTION("recolouring a polyline re-uploads its vertices only (colour is part of its key)") {
            std::get<DrawPolyline>(list.items[0].primitive).style.edit().colour = {0, 1, 1};
            ws.draw(list);
            CHECK(renderer.lastFrame().buffersCreated == 1);  // its geometry key includes the style
            CHECK(renderer.lastFrame().uploads == 1);         // that buffer; colours are push constants
        }
        SECTION("changing the mesh's interior colour uploads nothing and draws the new colour") {
            editPrimitive<DrawMesh>(list.items[3].primitive).interior.edit().colour = {1, 0, 0};
            const Image red = ws.draw(list);
            CHECK(renderer.lastFrame().uploads == 0);
            CHECK(renderer.lastFrame().uploadedBytes == 0);
            CHECK(renderer.lastFrame().buffersCreated == 0);
            const Rgb centre = at(red, 64, 64);
            CHECK(centre.r > 100);
            CHECK(centre.g < 30);
            CHECK(at(first, 64, 64).g > 100);  // white before
        }
        SECTION("moving the mesh uploads its draw records only (the modelling matrix)") {
            list.items[3].context.edit().modelTransform.edit()[3][0] = 0.1;
            ws.draw(list);
            CHECK(renderer.lastFrame().uploads == 1);
            CHECK(renderer.lastFrame().uploadedBytes == 2 * 176);  // interior and iso-lines, adjacent
            CHECK(renderer.lastFrame().buffersCreated == 0);
        }
        SECTION("a new mesh pointer uploads its vertices and indices, and the old buffers are freed") {
            editPrimitive<DrawMesh>(list.items[3].primitive).mesh =
                sphere({0.5f, 0.5f, 0.5f}, 0.25f, 16, 8, 2);
            mesh.reset();
            ws.draw(list);
            CHECK(renderer.lastFrame().uploads == 2);
            CHECK(renderer.lastFrame().buffersCreated == 2);
            CHECK(renderer.lastFrame().buffersDestroyed == 2);
        }
        SECTION("a new view changes the frame block and re-measures patterned lines only") {
            list.views[0].mapping[3][0] = 0.05;
            ws.draw(list);
            CHECK(renderer.lastFrame().buffersCreated == 1);  // the dashed line
            CHECK(renderer.lastFrame().uploads == 2);         // its vertices and the frame block
        }
    }
    requireNoValidationMessages(context);
}

TEST_CASE("uploads: through the store, an unchanged frame uploads nothing and an edit only its structure",
          "[render][uploads]") {
    vk::Context context(lavapipeWithValidation());
    std::mt19937 random(20);
    for (int round = 0; round < 4; ++round) {
        // A root with the attributes executing `count` leaves, one surface each; one leaf edited.
        const int count = std::uniform_int_distribution<int>(2, 6)(random);
        const int edited = std::uniform_int_distribution<int>(0, count - 1)(random);
        CAPTURE(round, count, edited);
        Phigs phigs;
        phigs.open();
        StructureStore& store = phigs.store();
        store.openStructure(1);
        store.insert(IndexAttribute{ElementType::InteriorStyle, int(InteriorStyle::Solid)});
        store.insert(SurfaceCharacteristicsAttribute{3, 0, 3, 2});
        store.insert(ApproximationAttribute{ElementType::SurfaceApproximationCriteria, 2, 6, 4});
        for (int k = 0; k < count; ++k) store.insert(executeStructure(10 + k));
        store.closeStructure();
        for (int k = 0; k < count; ++k) {
            store.openStructure(10 + k);
            store.insert(dome(k, count, 0.0));
            store.closeStructure();
        }
        Workstation& ws = phigs.openWorkstation(1, WorkstationType::OffscreenImage);
        vk::DisplaySettings settings;
        settings.width = 96, settings.height = 64;
        vk::WorkstationDisplay display(ws, context, settings);
        ws.postStructure(1, 0.5);
        display.update();
        const vk::Renderer& renderer = display.renderer();
        REQUIRE(renderer.lastFrame().uploadedBytes > 0);
        const auto before = meshesByStructure(ws.shownPicture());
        REQUIRE(before.size() == std::size_t(count));

        const Image first = display.capture();
        CHECK(renderer.lastFrame().uploads == 0);
        CHECK(renderer.lastFrame().uploadedBytes == 0);
        CHECK(renderer.lastFrame().buffersCreated == 0);
        CHECK(display.image().rgba == first.rgba);

        store.openStructure(10 + edited);
        store.setEditMode(EditMode::Replace);
        store.setElementPointer(1);
        store.insert(dome(edited, count, 0.05));
        store.setEditMode(EditMode::Insert);
        store.closeStructure();
        display.update();
        const auto after = meshesByStructure(ws.shownPicture());
        for (int k = 0; k < count; ++k)
            CHECK((after.at(10 + k) == before.at(10 + k)) == (k != edited));  // the others are reused
        CHECK(renderer.lastFrame().uploads == 2);                             // its vertices and indices
        CHECK(renderer.lastFrame().uploadedBytes == bufferBytes(*after.at(10 + edited)));
        CHECK(renderer.lastFrame().buffersCreated == 2);
        CHECK(renderer.lastFrame().buffersDestroyed == 2);
        display.update();
        CHECK(renderer.lastFrame().uploadedBytes == 0);
    }
    requireNoValidationMessages(context);
}

}  // namespace test_uploads
