// Efficiency: buffers and pipelines are created once and reused while the input is unchanged; a
// frame with no edits uploads nothing; an edit uploads only what it changed.
#include "RenderTestSupport.h"
#include "SceneMeshes.h"
#include "phigs/vk/ImageTarget.h"

using namespace phigs;
using namespace render_test;

namespace {

DrawList editableScene(std::shared_ptr<const MeshData> mesh) {
    DrawList list = emptyScene();
    list.hiddenSurfaceRemoval = true;
    for (int k = 0; k < 3; ++k) {
        DrawPolyline l;
        l.points = {{0.1, 0.2 + 0.2 * k, 0.5}, {0.9, 0.2 + 0.2 * k, 0.5}};
        l.style.colour = {1, 1, 0};
        l.style.type = k == 2 ? LineType::Dashed : LineType::Solid;
        DrawItem i = item(l);
        i.source.path = {{1, k + 1, 0}};
        i.source.structureVersion = 1;
        list.items.push_back(i);
    }
    DrawMesh m;
    m.mesh = std::move(mesh);
    m.interior.style = InteriorStyle::Solid;
    list.items.push_back(item(m));
    DrawText t;
    t.text = "fixed";
    t.position = {0.1, 0.85, 0.5};
    t.style.height = 0.05;
    list.items.push_back(item(t));
    return list;
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
            std::get<DrawPolyline>(list.items[1].primitive).points[1].y += 0.1;
            list.items[1].source.structureVersion = 2;
            ws.draw(list);
            CHECK(renderer.lastFrame().uploads == 1);
            CHECK(renderer.lastFrame().uploadedBytes == 2 * sizeof(render::RenderVertex));
            CHECK(renderer.lastFrame().buffersCreated == 1);
            CHECK(renderer.lastFrame().buffersDestroyed == 1);
        }
        SECTION("recolouring a polyline re-uploads its vertices only (colour is part of its key)") {
            std::get<DrawPolyline>(list.items[0].primitive).style.colour = {0, 1, 1};
            ws.draw(list);
            CHECK(renderer.lastFrame().buffersCreated == 1);  // its geometry key includes the style
            CHECK(renderer.lastFrame().uploads == 1);         // that buffer; colours are push constants
        }
        SECTION("changing the mesh's interior colour uploads nothing and draws the new colour") {
            std::get<DrawMesh>(list.items[3].primitive).interior.colour = {1, 0, 0};
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
            list.items[3].modelTransform[3][0] = 0.1;
            ws.draw(list);
            CHECK(renderer.lastFrame().uploads == 1);
            CHECK(renderer.lastFrame().uploadedBytes == 2 * 176);  // interior and iso-lines, adjacent
            CHECK(renderer.lastFrame().buffersCreated == 0);
        }
        SECTION("a new mesh pointer uploads its vertices and indices, and the old buffers are freed") {
            std::get<DrawMesh>(list.items[3].primitive).mesh = sphere({0.5f, 0.5f, 0.5f}, 0.25f, 16, 8, 2);
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
