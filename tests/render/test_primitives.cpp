// One small scene per 2D primitive family and attribute group, compared with reference images.
#include "RenderTestSupport.h"
#include "SceneMeshes.h"
#include "phigs/vk/ImageTarget.h"

namespace test_primitives {

using namespace phigs;
using namespace render_test;

namespace {

DrawPolyline line(std::vector<glm::dvec3> points, glm::vec3 colour, LineType type, float width) {
    DrawPolyline p;
    p.points = std::move(points);
    p.style.edit().colour = colour;
    p.style.edit().type = type;
    p.style.edit().width = width;
    return p;
}

DrawFillArea fill(std::vector<std::vector<glm::dvec3>> contours, InteriorStyle style, glm::vec3 colour) {
    DrawFillArea f;
    f.contours = std::move(contours);
    f.interior.edit().style = style;
    f.interior.edit().colour = colour;
    return f;
}

std::vector<glm::dvec3> rectangle(double x0, double y0, double x1, double y1) {
    return {{x0, y0, 0.5}, {x1, y0, 0.5}, {x1, y1, 0.5}, {x0, y1, 0.5}};
}

}  // namespace

TEST_CASE("polylines: the four PHIGS line types at widths 1, 2 and 4", "[render][primitives]") {
    vk::Context context(lavapipeWithValidation());
    {
        vk::ImageTarget ws(context, 256, 256);
        DrawList list = emptyScene();
        const LineType types[] = {LineType::Solid, LineType::Dashed, LineType::Dotted, LineType::DashDotted};
        const float widths[] = {1.0f, 2.0f, 4.0f};
        for (int t = 0; t < 4; ++t)
            for (int w = 0; w < 3; ++w) {
                const double y = 0.92 - (t * 3 + w) * 0.075;
                list.items.push_back(item(line({{0.05, y, 0.5}, {0.6, y, 0.5}, {0.95, y - 0.05, 0.5}},
                                               {1.0f, 0.9f - 0.2f * t, 0.3f * w}, types[t], widths[w])));
            }
        const Image image = ws.draw(list);
        // A solid line is continuous; a dashed one has gaps along its length.
        int solidLit = 0, dashedLit = 0;
        for (std::uint32_t x = 20; x < 140; ++x) {
            solidLit += at(image, x, std::uint32_t((1 - 0.92) * 256)).r > 128;
            dashedLit += at(image, x, std::uint32_t((1 - (0.92 - 3 * 0.075)) * 256)).r > 128;
        }
        CHECK(solidLit == 120);
        CHECK(dashedLit > 60);
        CHECK(dashedLit < 100);
        compareWithReference(image, "polylines");
    }
    requireNoValidationMessages(context);
}

TEST_CASE("mesh iso-lines take the PHIGS line types, their dashes measured in pixels",
          "[render][primitives]") {
    vk::Context context(lavapipeWithValidation());
    {
        vk::ImageTarget ws(context, 256, 256);
        // A flat grid in modelling units 0..2, scaled by 0.5 to world 0..1 (the dashes must not
        // follow the modelling units), with one iso-line along its middle row.
        const int n = 16;
        auto mesh = grid(0.2, 0.2, 1.8, 1.8, 1.0, n);
        std::vector<std::uint32_t> row;
        for (int i = 0; i <= n; ++i) row.push_back(std::uint32_t((n / 2) * (n + 1) + i));
        mesh->isoLines.push_back(row);
        auto draw = [&](LineType type) {
            DrawList list = emptyScene();
            DrawMesh m;
            m.mesh = mesh;
            m.interior.edit().style = InteriorStyle::Solid;
            m.interior.edit().colour = {0.3f, 0.3f, 0.3f};
            m.isoLineStyle.edit().colour = {1, 1, 0};
            m.isoLineStyle.edit().type = type;
            DrawItem i = item(m);
            i.context.edit().modelTransform = glm::dmat4(glm::dvec4(0.5, 0, 0, 0), glm::dvec4(0, 0.5, 0, 0),
                                                         glm::dvec4(0, 0, 0.5, 0), glm::dvec4(0, 0, 0, 1));
            list.items.push_back(i);
            list.hiddenSurfaceRemoval = true;
            return ws.draw(list);
        };
        // The runs of yellow pixels along the line (world y = 0.5, x from 0.1 to 0.9).
        auto runs = [](const Image& image) {
            std::vector<int> lengths;
            int run = 0, lit = 0;
            for (std::uint32_t x = 30; x < 226; ++x) {
                bool yellow = false;
                for (std::uint32_t y = 126; y <= 130; ++y) {
                    const Rgb c = at(image, x, y);
                    yellow = yellow || (c.r > 200 && c.g > 200 && c.b < 80);
                }
                lit += yellow;
                if (yellow) {
                    ++run;
                } else if (run > 0) {
                    lengths.push_back(run);
                    run = 0;
                }
            }
            if (run > 0) lengths.push_back(run);
            return std::pair{lit, lengths};
        };
        const auto [solidLit, solidRuns] = runs(draw(LineType::Solid));
        CHECK(solidLit == 196);
        CHECK(solidRuns.size() == 1);
        const Image dashedImage = draw(LineType::Dashed);
        const auto [dashedLit, dashedRuns] = runs(dashedImage);
        // 12 pixels on, 6 off: about two thirds lit, the inner dashes 12 pixels long.
        CHECK(dashedLit > 196 * 0.55);
        CHECK(dashedLit < 196 * 0.78);
        REQUIRE(dashedRuns.size() >= 8);
        for (std::size_t k = 1; k + 1 < dashedRuns.size(); ++k) CHECK(std::abs(dashedRuns[k] - 12) <= 1);
        const auto [dottedLit, dottedRuns] = runs(draw(LineType::Dotted));
        CHECK(dottedLit < 196 / 2);  // 2 on, 4 off
        CHECK(dottedRuns.size() > dashedRuns.size() * 2);
        compareWithReference(dashedImage, "iso_line_types");
    }
    requireNoValidationMessages(context);
}

TEST_CASE("polymarkers: the five marker types at three scales", "[render][primitives]") {
    vk::Context context(lavapipeWithValidation());
    {
        vk::ImageTarget ws(context, 256, 256);
        DrawList list = emptyScene();
        const MarkerType types[] = {MarkerType::Dot, MarkerType::Plus, MarkerType::Asterisk,
                                    MarkerType::Circle, MarkerType::Cross};
        for (int t = 0; t < 5; ++t) {
            DrawPolymarker m;
            m.style.edit().type = types[t];
            m.style.edit().colour = {0.3f + 0.15f * t, 1.0f, 1.0f - 0.2f * t};
            for (int s = 0; s < 3; ++s) {
                m.points = {{0.2 + 0.3 * s, 0.85 - 0.17 * t, 0.5}};
                m.style.edit().scale = 1.0f + 1.5f * s;
                list.items.push_back(item(m));
            }
        }
        const Image image = ws.draw(list);
        // A plus at scale 4 reaches 14 pixels either side of its centre; a cross leaves the centre row empty
        // there.
        const std::uint32_t cx = std::uint32_t(0.8 * 256), plusY = std::uint32_t((1 - 0.68) * 256);
        CHECK(at(image, cx + 12, plusY).g > 200);
        CHECK(at(image, cx, plusY - 12).g > 200);
        const std::uint32_t crossY = std::uint32_t((1 - (0.85 - 0.68)) * 256);
        CHECK(at(image, cx + 12, crossY).g < 60);
        CHECK(at(image, cx + 10, crossY - 10).g > 200);
        compareWithReference(image, "polymarkers");
    }
    requireNoValidationMessages(context);
}

TEST_CASE("fill areas: hollow, solid, hatch, a concave outline and a set with holes, with edges",
          "[render][primitives]") {
    vk::Context context(lavapipeWithValidation());
    {
        vk::ImageTarget ws(context, 256, 256);
        DrawList list = emptyScene();
        list.items.push_back(
            item(fill({rectangle(0.05, 0.55, 0.3, 0.95)}, InteriorStyle::Hollow, {1, 1, 0})));
        list.items.push_back(
            item(fill({rectangle(0.37, 0.55, 0.62, 0.95)}, InteriorStyle::Solid, {0, 0.8f, 1})));
        for (int h = 1; h <= 2; ++h) {
            DrawFillArea hatch = fill({rectangle(0.69, 0.75 - (h - 1) * 0.2, 0.95, 0.95 - (h - 1) * 0.2)},
                                      InteriorStyle::Hatch, {1, 0.5f, 0.2f});
            hatch.interior.edit().styleIndex = h == 1 ? 3 : 5;
            list.items.push_back(item(hatch));
        }
        // A concave "U" with visible dashed edges.
        DrawFillArea u = fill({{{0.05, 0.05, 0.5},
                                {0.45, 0.05, 0.5},
                                {0.45, 0.45, 0.5},
                                {0.35, 0.45, 0.5},
                                {0.35, 0.15, 0.5},
                                {0.15, 0.15, 0.5},
                                {0.15, 0.45, 0.5},
                                {0.05, 0.45, 0.5}}},
                              InteriorStyle::Solid, {0.9f, 0.2f, 0.6f});
        u.edges.edit().visible = true;
        u.edges.edit().colour = {1, 1, 1};
        u.edges.edit().type = LineType::Dashed;
        u.edges.edit().width = 2.0f;
        list.items.push_back(item(u));
        // A fill area set: a square with two square holes.
        DrawFillArea holes = fill({rectangle(0.55, 0.05, 0.95, 0.45), rectangle(0.6, 0.1, 0.72, 0.4),
                                   rectangle(0.78, 0.1, 0.9, 0.4)},
                                  InteriorStyle::Solid, {0.3f, 1.0f, 0.3f});
        holes.edges.edit().visible = true;
        holes.edges.edit().colour = {1, 0, 0};
        list.items.push_back(item(holes));
        const Image image = ws.draw(list);
        auto px = [&](double x, double y) {
            return at(image, std::uint32_t(x * 256), std::uint32_t((1 - y) * 256));
        };
        CHECK(near(px(0.17, 0.75), 25, 25, 25));   // hollow: inside is background
        CHECK(near(px(0.5, 0.75), 0, 204, 255));   // solid
        CHECK(near(px(0.25, 0.30), 25, 25, 25));   // the notch of the U is empty
        CHECK(near(px(0.1, 0.3), 230, 51, 153));   // the U's left arm is filled
        CHECK(near(px(0.66, 0.25), 25, 25, 25));   // a hole
        CHECK(near(px(0.75, 0.25), 76, 255, 76));  // between the holes
        compareWithReference(image, "fill_areas");
    }
    requireNoValidationMessages(context);
}

TEST_CASE("text: stroke text with height, up vector, path, alignment and expansion, annotation text",
          "[render][primitives]") {
    vk::Context context(lavapipeWithValidation());
    {
        vk::ImageTarget ws(context, 256, 256);
        DrawList list = emptyScene();
        auto text = [&](std::string s, glm::dvec3 at, auto&& adjust) {
            DrawText t;
            t.text = std::move(s);
            t.position = at;
            t.style.edit().height = 0.06;
            t.style.edit().colour = {1, 1, 1};
            adjust(t);
            list.items.push_back(item(t));
        };
        text("PHIGS", {0.05, 0.85, 0.5}, [](DrawText&) {});
        text("wide", {0.55, 0.85, 0.5}, [](DrawText& t) {
            t.style.edit().expansion = 1.6f;
            t.style.edit().colour = {1, 0.6f, 0.2f};
        });
        text("UP", {0.1, 0.15, 0.5}, [](DrawText& t) {
            t.style.edit().upVector = {-1, 1};
            t.style.edit().colour = {0.4f, 1, 0.4f};
        });
        text("DOWN", {0.9, 0.75, 0.5}, [](DrawText& t) {
            t.style.edit().path = TextPath::Down;
            t.style.edit().height = 0.04;
            t.style.edit().colour = {0.4f, 0.7f, 1};
        });
        text("centred", {0.5, 0.55, 0.5}, [](DrawText& t) {
            t.style.edit().horizontal = HorizontalAlignment::Centre;
            t.style.edit().vertical = VerticalAlignment::Half;
            t.style.edit().colour = {1, 1, 0};
        });
        text("<-left", {0.8, 0.4, 0.5}, [](DrawText& t) {
            t.style.edit().path = TextPath::Left;
            t.style.edit().height = 0.04;
        });
        DrawText note;
        note.text = "note";
        note.annotation = true;
        note.position = {0.3, 0.3, 0.5};
        note.annotationOffset = {0.05, -0.1, 0};
        note.style.edit().height = 0.05;
        note.style.edit().colour = {1, 0.3f, 0.3f};
        list.items.push_back(item(note));
        DrawPolymarker reference;
        reference.points = {{0.5, 0.55, 0.5}, {0.3, 0.3, 0.5}};
        reference.style.edit().type = MarkerType::Plus;
        reference.style.edit().colour = {1, 0, 1};
        list.items.push_back(item(reference));
        const Image image = ws.draw(list);
        compareWithReference(image, "text");
    }
    requireNoValidationMessages(context);
}

}  // namespace test_primitives
