// Model clipping volumes (DrawItem::modelClipPlanes): half spaces in world coordinates that
// the fragment shader applies to every primitive family; compared with a reference image.
#include "RenderTestSupport.h"
#include "SceneMeshes.h"
#include "phigs/vk/ImageTarget.h"

namespace test_model_clip {

using namespace phigs;
using namespace render_test;

TEST_CASE("model clipping: meshes, fill areas, polylines and markers keep only the clipping volume",
          "[render][views]") {
    vk::Context context(lavapipeWithValidation());
    {
        vk::ImageTarget ws(context, 256, 256);
        DrawList list = emptyScene();
        // A sphere cut by the plane x = 0.3: only its left half stays (its inside shows).
        DrawMesh ball;
        ball.mesh = sphere({0.3f, 0.7f, 0.5f}, 0.2f, 32, 16);
        ball.interior.edit().style = InteriorStyle::Solid;
        ball.interior.edit().colour = {0.2f, 0.5f, 1.0f};
        DrawItem clippedBall = item(ball);
        clippedBall.context.edit().modelClipPlanes = {{-1, 0, 0, 0.3}};
        list.items.push_back(clippedBall);
        // A square cut by two half spaces: x + y <= 1.5 and y >= 0.6.
        DrawFillArea square;
        square.contours = {{{0.55, 0.55, 0.5}, {0.95, 0.55, 0.5}, {0.95, 0.95, 0.5}, {0.55, 0.95, 0.5}}};
        square.interior.edit().style = InteriorStyle::Solid;
        square.interior.edit().colour = {1.0f, 0.3f, 0.1f};
        DrawItem clippedSquare = item(square);
        clippedSquare.context.edit().modelClipPlanes = {{-1, -1, 0, 1.5}, {0, 1, 0, -0.6}};
        list.items.push_back(clippedSquare);
        // A wide line kept between x = 0.2 and x = 0.8, under a modelling transform (the planes
        // are in world coordinates).
        DrawPolyline line;
        line.points = {{0.05, 0.0, 0.5}, {0.95, 0.0, 0.5}};
        line.style.edit().colour = {1.0f, 1.0f, 0.2f};
        line.style.edit().width = 5.0f;
        DrawItem clippedLine = item(line);
        clippedLine.context.edit().modelTransform = glm::dmat4(1.0);
        clippedLine.context.edit().modelTransform.edit()[3] = glm::dvec4(0.0, 0.3, 0.0, 1.0);
        clippedLine.context.edit().modelClipPlanes = {{1, 0, 0, -0.2}, {-1, 0, 0, 0.8}};
        list.items.push_back(clippedLine);
        // Markers at x = 0.1 .. 0.9, kept where x <= 0.5 (a marker is clipped by its position).
        DrawPolymarker markers;
        std::vector<glm::dvec3> markerPoints;
        for (int i = 1; i <= 9; ++i) markerPoints.push_back({0.1 * i, 0.1, 0.5});
        markers.points = markerPoints;
        markers.style.edit().type = MarkerType::Cross;
        markers.style.edit().scale = 2.0f;
        markers.style.edit().colour = {0.3f, 1.0f, 0.3f};
        DrawItem clippedMarkers = item(markers);
        clippedMarkers.context.edit().modelClipPlanes = {{-1, 0, 0, 0.5}};
        list.items.push_back(clippedMarkers);
        const Image image = ws.draw(list);
        auto px = [&](double x, double y) {
            return at(image, std::uint32_t(x * 256), std::uint32_t((1 - y) * 256));
        };
        const Rgb background = px(0.02, 0.98);
        CHECK(near(px(0.2, 0.7), 51, 128, 255));                               // left half of the ball
        CHECK(near(px(0.4, 0.7), background.r, background.g, background.b));   // right half clipped
        CHECK(near(px(0.6, 0.7), 255, 77, 26));                                // kept corner of the square
        CHECK(near(px(0.9, 0.9), background.r, background.g, background.b));   // beyond x + y = 1.5
        CHECK(near(px(0.7, 0.57), background.r, background.g, background.b));  // below y = 0.6
        CHECK(near(px(0.5, 0.3), 255, 255, 51));                               // the line's kept middle
        CHECK(near(px(0.1, 0.3), background.r, background.g, background.b));
        CHECK(near(px(0.9, 0.3), background.r, background.g, background.b));
        CHECK(near(px(0.3, 0.1), 77, 255, 77));  // a kept marker's centre
        CHECK(near(px(0.7, 0.1), background.r, background.g, background.b));
        compareWithReference(image, "model_clip");

        // Unchanged planes upload nothing; moving one changes the frame block only.
        ws.draw(list);
        CHECK(ws.renderer().lastFrame().uploads == 0);
        list.items[0].context.edit().modelClipPlanes = {{-1, 0, 0, 0.35}};
        ws.draw(list);
        CHECK(ws.renderer().lastFrame().buffersCreated == 0);
        CHECK(ws.renderer().lastFrame().uploads == 1);
    }
    requireNoValidationMessages(context);
}

TEST_CASE("model clipping: more distinct planes than the frame holds are refused by name",
          "[render][views]") {
    vk::Context context(lavapipeWithValidation());
    {
        vk::ImageTarget ws(context, 32, 32);
        DrawList list = emptyScene();
        for (int i = 0; i < 70; ++i) {
            DrawPolymarker m;
            m.points = {{0.5, 0.5, 0.5}};
            DrawItem it = item(m);
            it.context.edit().modelClipPlanes = {{1, 0, 0, -0.001 * i}};
            list.items.push_back(it);
        }
        CHECK_THROWS_WITH(ws.draw(list), Catch::Matchers::Contains("model clipping planes"));
        list.items.resize(64);
        CHECK_NOTHROW(ws.draw(list));
    }
    requireNoValidationMessages(context);
}

}  // namespace test_model_clip
