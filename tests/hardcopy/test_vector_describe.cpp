// The describe step of the vector hardcopy without files: clipping to views and model clipping
// volumes, vertex-coloured dashed lines whose dashes run on across their colour pieces, NURBS curves to the
// page tolerance, facets split and ordered back to front, hidden lines removed, the raster's lighting, and
// mesh outlines.
#include "VectorRaster.h"
#include "VectorScenes.h"
#include "phigs/hardcopy/HomogeneousClipper.h"
#include "phigs/hardcopy/ItemProjector.h"
#include "phigs/hardcopy/MeshOutline.h"
#include "phigs/hardcopy/PageMapping.h"
#include "phigs/hardcopy/VectorDescriber.h"
#include "phigs/hardcopy/VectorWorkstation.h"

#include "geom/Evaluate.h"

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <random>

namespace test_vector_describe {

using namespace phigs;
using namespace phigs::hardcopy;

namespace {

/// A page of size x size points showing NPC [0, 1]^2 (page y down), one point per nominal pixel.
PageSetup squarePage(double size = 100) {
    PageSetup page;
    page.paper = {size, size};
    page.nominalPixel = 1.0;
    page.background = false;
    return page;
}

DrawList identityList() {
    DrawList list;
    list.views.push_back(DrawView{});
    return list;
}

template <class P>
DrawItem item(P primitive, int view = 0) {
    DrawItem i;
    i.primitive = std::move(primitive);
    i.context.edit().viewIndex = view;
    return i;
}

DrawFillArea solid(std::vector<glm::dvec3> contour, glm::vec3 colour) {
    DrawFillArea f;
    f.contours = {std::move(contour)};
    f.interior.edit().style = InteriorStyle::Solid;
    f.interior.edit().colour = colour;
    return f;
}

bool insideEvenOdd(const std::vector<std::vector<glm::dvec2>>& contours, glm::dvec2 p) {
    bool in = false;
    for (const auto& c : contours)
        for (std::size_t i = 0, j = c.size() - 1; i < c.size(); j = i++)
            if ((c[i].y > p.y) != (c[j].y > p.y) &&
                p.x < (c[j].x - c[i].x) * (p.y - c[i].y) / (c[j].y - c[i].y) + c[i].x)
                in = !in;
    return in;
}

/// The colour of the last fill painted over a page point (what shows there), or -1s.
glm::vec3 shownAt(const VectorPicture& picture, glm::dvec2 p) {
    for (auto op = picture.ops.rbegin(); op != picture.ops.rend(); ++op)
        if (const auto* fill = std::get_if<VectorFill>(&*op); fill && insideEvenOdd(fill->contours, p))
            return fill->colour;
    return glm::vec3(-1.0f);
}

std::vector<const VectorStroke*> strokes(const VectorPicture& picture, glm::vec3 colour) {
    std::vector<const VectorStroke*> out;
    for (const VectorOp& op : picture.ops)
        if (const auto* s = std::get_if<VectorStroke>(&op); s && glm::length(s->colour - colour) < 1e-3f)
            out.push_back(s);
    return out;
}

}  // namespace

TEST_CASE("vector describe: lines are cut at the view's clip limits, its depth limits and the model clip",
          "[hardcopy]") {
    DrawList list = identityList();
    DrawView clipped;
    clipped.clipMin = {0.25, 0.25, 0.4};
    clipped.clipMax = {0.75, 0.75, 1.0};
    list.views.push_back(clipped);
    DrawPolyline across;
    across.points = {{0.0, 0.5, 0.5}, {1.0, 0.5, 0.5}};
    list.items.push_back(item(across, 1));
    DrawPolyline deep;  // from z 0 to z 1 along x: only z >= 0.4 survives the back plane
    deep.points = {{0.3, 0.3, 0.0}, {0.7, 0.3, 1.0}};
    deep.style.edit().colour = {0, 1, 0};
    list.items.push_back(item(deep, 1));
    DrawPolyline cut;  // the model clipping volume keeps x <= 0.6
    cut.points = {{0.0, 0.9, 0.5}, {1.0, 0.9, 0.5}};
    cut.style.edit().colour = {0, 0, 1};
    DrawItem modelClipped = item(cut);
    modelClipped.context.edit().modelClipPlanes = {{-1, 0, 0, 0.6}};
    list.items.push_back(modelClipped);

    const VectorPicture picture = describePicture(list, squarePage());
    REQUIRE(picture.clips.size() == 2);
    CHECK(picture.clips[1].min.x == Approx(25));
    CHECK(picture.clips[1].max.y == Approx(75));
    const auto white = strokes(picture, {1, 1, 1});
    REQUIRE(white.size() == 1);
    CHECK(white[0]->points.front().x == Approx(25));
    CHECK(white[0]->points.back().x == Approx(75));
    CHECK(white[0]->points.front().y == Approx(50));
    const auto green = strokes(picture, {0, 1, 0});
    REQUIRE(green.size() == 1);
    CHECK(green[0]->points.front().x == Approx(46));  // z reaches 0.4 at 0.4 of the way
    const auto blue = strokes(picture, {0, 0, 1});
    REQUIRE(blue.size() == 1);
    CHECK(blue[0]->points.back().x == Approx(60));
    CHECK(blue[0]->clip == 0);
}

TEST_CASE(
    "vector describe: a NURBS curve is tessellated again until every chord is within the page tolerance",
    "[hardcopy]") {
    // A full circle as a rational quadratic NURBS (nine control points), radius 0.4 about (0.5, 0.5).
    const double w = std::sqrt(0.5);
    std::vector<glm::dvec3> points;
    const double corners[9][2] = {{1, 0},   {1, 1},  {0, 1},  {-1, 1}, {-1, 0},
                                  {-1, -1}, {0, -1}, {1, -1}, {1, 0}};
    for (const auto& c : corners) points.push_back({0.5 + 0.4 * c[0], 0.5 + 0.4 * c[1], 0.5});
    auto curve =
        std::make_shared<const geom::Curve>(2, std::vector<double>{0, 0, 0, 1, 1, 2, 2, 3, 3, 4, 4, 4},
                                            points, std::vector<double>{1, w, 1, w, 1, w, 1, w, 1});
    DrawCurve drawn;
    drawn.curve = curve;
    drawn.points = {points.front(), points.back()};  // what traversal gave matters no more
    DrawList list = identityList();
    list.items.push_back(item(drawn));
    VectorOptions options;
    options.curveTolerance = 0.01;
    const VectorPicture picture = describePicture(list, squarePage(1000), options);
    REQUIRE(picture.ops.size() == 1);
    const auto& stroke = std::get<VectorStroke>(picture.ops[0]);
    const glm::dvec2 centre(500, 500);
    double worstSagitta = 0.0;
    for (std::size_t i = 0; i + 1 < stroke.points.size(); ++i) {
        CHECK(std::abs(glm::length(stroke.points[i] - centre) - 400.0) < 1e-6);
        const glm::dvec2 middle = 0.5 * (stroke.points[i] + stroke.points[i + 1]);
        worstSagitta = std::max(worstSagitta, 400.0 - glm::length(middle - centre));
    }
    INFO(stroke.points.size() << " points, worst chord error " << worstSagitta << " pt");
    CHECK(worstSagitta <= 0.01);
    CHECK(stroke.points.size() > 100);  // traversal's 8 per span would give 33
    CHECK(glm::length(stroke.points.front() - stroke.points.back()) < 1e-9);
}

TEST_CASE("vector describe: a vertex-coloured dashed polyline keeps its dash phase across its pieces",
          "[hardcopy]") {
    std::mt19937 rng(7013);
    std::uniform_real_distribution<double> at(0.05, 0.95);
    std::uniform_real_distribution<float> unit(0.0f, 1.0f);
    for (int round = 0; round < 60; ++round) {
        DrawColouredPolyline line;
        std::vector<glm::dvec3> points;
        std::vector<glm::vec3> colours;
        const int n = 2 + int(rng() % 6);
        for (int i = 0; i < n; ++i) {
            points.push_back({at(rng), at(rng), 0.5});
            colours.push_back({unit(rng), unit(rng), unit(rng)});
        }
        line.line.points = points;
        line.colours = VertexColours{colours, rng() % 2 == 0};
        line.line.style.edit().type = static_cast<LineType>(2 + rng() % 3);
        DrawList list = identityList();
        list.items.push_back(item(line));
        const VectorPicture picture = describePicture(list, squarePage());
        // Page lengths along the line (one point per nominal pixel).
        std::vector<double> along{0.0};
        for (int i = 1; i < n; ++i)
            along.push_back(along.back() + 100.0 * glm::length(glm::dvec2(points[std::size_t(i)]) -
                                                               glm::dvec2(points[std::size_t(i - 1)])));
        double phase = 0.0;
        std::size_t pieces = 0;
        for (const VectorOp& op : picture.ops) {
            const auto* stroke = std::get_if<VectorStroke>(&op);
            if (!stroke) continue;
            ++pieces;
            REQUIRE_FALSE(stroke->dashes.empty());
            CHECK(stroke->dashOffset == Approx(phase).margin(1e-6));  // the dashes run on
            double length = 0.0;
            for (std::size_t k = 1; k < stroke->points.size(); ++k)
                length += glm::length(stroke->points[k] - stroke->points[k - 1]);
            // The colour at the piece's middle: the segment's first colour, or interpolated.
            const double middle = phase + length / 2;
            std::size_t k = 0;
            while (k + 2 < along.size() && along[k + 1] <= middle) ++k;
            const float t = float((middle - along[k]) / std::max(along[k + 1] - along[k], 1e-12));
            const glm::vec3 expected =
                line.colours.interpolated ? glm::mix(colours[k], colours[k + 1], t) : colours[k];
            CHECK(glm::length(stroke->colour - expected) < (line.colours.interpolated ? 2.0f / 255 : 1e-5f));
            phase += length;
        }
        CHECK(phase == Approx(along.back()).epsilon(1e-6));
        CHECK(pieces >= 1);
        if (!line.colours.interpolated) CHECK(pieces <= std::size_t(n - 1));
    }
}

TEST_CASE("vector describe: facets overlapping in depth are split and painted back to front", "[hardcopy]") {
    // Three bars in cyclic overlap: each lies over the next at one end and under it at the other,
    // so no order of whole facets is right.
    DrawList list = identityList();
    list.hiddenSurfaceRemoval = true;
    const glm::vec3 colours[3] = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
    for (int k = 0; k < 3; ++k) {
        const double a = 2.0943951 * k;
        const glm::dvec2 dir(std::cos(a), std::sin(a)), side(-dir.y, dir.x);
        const glm::dvec2 c(0.5, 0.5), start = c - 0.35 * dir - 0.12 * side,
                                      end = c + 0.35 * dir - 0.12 * side;
        const glm::dvec2 width = 0.12 * side;
        // Depth rises from 0.2 at the start to 0.8 at the end.
        list.items.push_back(
            item(solid({{start, 0.2}, {end, 0.8}, {end + width, 0.8}, {start + width, 0.2}}, colours[k])));
    }
    DescribeStats stats;
    const VectorPicture picture = describePicture(list, squarePage(), {}, &stats);
    CHECK(stats.hidden);
    CHECK(stats.facets.splits > 0);
    CHECK_FALSE(stats.facets.fellBack);
    // Where two bars cross, the one that is nearer there shows: test every pair's crossing.
    int checked = 0;
    for (int y = 1; y < 100; ++y)
        for (int x = 1; x < 100; ++x) {
            const glm::dvec2 page(x + 0.37, y + 0.61);
            const glm::dvec2 npc(page.x / 100.0, 1.0 - page.y / 100.0);
            double best = -1.0;
            int nearest = -1;
            bool nearEdge = false;
            for (int k = 0; k < 3; ++k) {
                const auto& f = primitiveAs<DrawFillArea>(list.items[std::size_t(k)].primitive);
                const auto& q = f.contours[0];
                const glm::dvec2 along = glm::dvec2(q[1] - q[0]), across = glm::dvec2(q[3] - q[0]);
                const glm::dvec2 d = npc - glm::dvec2(q[0]);
                const double s = glm::dot(d, along) / glm::dot(along, along);
                const double t = glm::dot(d, across) / glm::dot(across, across);
                const bool in = s > 0.02 && s < 0.98 && t > 0.02 && t < 0.98;
                nearEdge = nearEdge || (!in && s > -0.02 && s < 1.02 && t > -0.02 && t < 1.02);
                if (!in) continue;
                const double z = 0.2 + 0.6 * s;
                if (z > best) best = z, nearest = k;
            }
            if (nearest < 0 || nearEdge) continue;
            INFO("page point " << page.x << ", " << page.y << ": bar " << nearest << " nearest at depth "
                               << best);
            CHECK(shownAt(picture, page) == colours[nearest]);
            ++checked;
        }
    CHECK(checked > 500);
}

TEST_CASE("vector describe: shaded facets take the raster path's reflectance", "[hardcopy]") {
    DrawList list = identityList();
    Light ambient;
    ambient.colour = {0.5f, 0.5f, 0.5f};
    Light key;
    key.type = LightType::Directional;
    key.direction = glm::normalize(glm::dvec3(0, -1, -1));
    list.lightSets.push_back({ambient, key});
    DrawFillArea f =
        solid({{0.2, 0.2, 0.5}, {0.8, 0.2, 0.5}, {0.8, 0.8, 0.5}, {0.2, 0.8, 0.5}}, {0.2f, 0.6f, 1.0f});
    f.interior.edit().reflectance = ReflectanceModel::Diffuse;
    f.interior.edit().properties.ambient = 0.3f;
    f.interior.edit().properties.diffuse = 0.7f;
    DrawItem lit = item(f);
    lit.context.edit().lightSet = 0;
    list.items.push_back(lit);
    const VectorPicture picture = describePicture(list, squarePage());
    REQUIRE(picture.ops.size() == 1);
    const auto& fill = std::get<VectorFill>(picture.ops[0]);
    // ka La C + kd L C max(N . L, 0), N = +z, L = -direction.
    const float nl = float(glm::dot(glm::dvec3(0, 0, 1), -key.direction));
    const glm::vec3 expected = 0.3f * 0.5f * f.interior->colour + 0.7f * f.interior->colour * nl;
    CHECK(glm::length(fill.colour - expected) < 1e-5f);
    CHECK(fill.seamWidth == 0.0);  // one whole area: nothing to seam
}

TEST_CASE(
    "vector describe: a facet shows its vertex colours' mean and its depth cue in the rendering colour model",
    "[hardcopy][colour]") {
    std::mt19937 rng(20261205);
    std::uniform_real_distribution<float> unit(0.0f, 1.0f);
    const ColourModel models[] = {ColourModel::Rgb, ColourModel::Cieluv, ColourModel::Hsv, ColourModel::Hls};
    auto inModel = [](ColourModel m, glm::vec3 c) { return fromRgb(m, glm::dvec3(c)); };
    double rgbHsvApart = 0.0;
    for (int round = 0; round < 40; ++round) {
        const ColourModel model = models[round % 4];
        const bool cued = round % 8 >= 4;
        DrawList list = identityList();
        DrawFillArea f = solid({{0.2, 0.2, 0.5}, {0.8, 0.3, 0.5}, {0.4, 0.8, 0.5}}, glm::vec3(1.0f));
        f.vertexColours = {{}};
        glm::dvec3 sum(0.0), rgbSum(0.0), hsvSum(0.0);
        for (int k = 0; k < 3; ++k) {
            const glm::vec3 c{unit(rng), unit(rng), unit(rng)};
            f.vertexColours[0].push_back(c);
            sum += inModel(model, c) / 3.0, rgbSum += glm::dvec3(c) / 3.0;
            hsvSum += inModel(ColourModel::Hsv, c) / 3.0;
        }
        f.interior.edit().renderingModel = model;
        DrawItem i = item(f);
        glm::dvec3 expected = toRgb(model, sum);
        if (cued) {
            // A constant scale s: s C + (1 - s) cue colour, in the model.
            DepthCue cue;
            cue.enabled = true;
            cue.frontScale = cue.backScale = unit(rng);
            cue.colour = {unit(rng), unit(rng), unit(rng)};
            list.depthCues.push_back(cue);
            i.context.edit().depthCue = 0;
            const double s = cue.frontScale;
            const glm::vec3 shown = glm::clamp(glm::vec3(expected), glm::vec3(0.0f), glm::vec3(1.0f));
            expected = toRgb(model, s * inModel(model, shown) + (1.0 - s) * inModel(model, cue.colour));
        }
        list.items.push_back(i);
        const VectorPicture picture = describePicture(list, squarePage());
        REQUIRE(picture.ops.size() == 1);
        const auto& fill = std::get<VectorFill>(picture.ops[0]);
        const glm::vec3 clamped = glm::clamp(glm::vec3(expected), glm::vec3(0.0f), glm::vec3(1.0f));
        CHECK(glm::length(fill.colour - clamped) < 1e-5f);
        rgbHsvApart = std::max(rgbHsvApart, glm::length(rgbSum - toRgb(ColourModel::Hsv, hsvSum)));
    }
    CHECK(rgbHsvApart > 0.2);  // the models' means differ: the check tells them apart
}

TEST_CASE("vector describe: under hidden-surface removal lines and markers behind a facet are hidden",
          "[hardcopy]") {
    DrawList list = identityList();
    list.hiddenSurfaceRemoval = true;
    list.items.push_back(
        item(solid({{0.3, 0.3, 0.6}, {0.7, 0.3, 0.6}, {0.7, 0.7, 0.6}, {0.3, 0.7, 0.6}}, {0, 0, 1})));
    DrawPolyline behind;
    behind.points = {{0.1, 0.5, 0.4}, {0.9, 0.5, 0.4}};
    behind.style.edit().colour = {1, 0, 0};
    behind.style.edit().type = LineType::Dashed;
    list.items.push_back(item(behind));
    DrawPolyline front;
    front.points = {{0.5, 0.1, 0.8}, {0.5, 0.9, 0.8}};
    front.style.edit().colour = {0, 1, 0};
    list.items.push_back(item(front));
    DrawPolyline onTop;  // on the facet's plane: stays (the raster's depth bias)
    onTop.points = {{0.35, 0.35, 0.6}, {0.65, 0.65, 0.6}};
    onTop.style.edit().colour = {1, 1, 0};
    list.items.push_back(item(onTop));
    DrawPolymarker markers;
    markers.points = {{0.5, 0.4, 0.2}, {0.2, 0.2, 0.2}};
    markers.style.edit().colour = {1, 0, 1};
    markers.style.edit().type = MarkerType::Circle;
    list.items.push_back(item(markers));

    const VectorPicture picture = describePicture(list, squarePage());
    const auto red = strokes(picture, {1, 0, 0});
    REQUIRE(red.size() == 2);
    CHECK(red[0]->points.back().x == Approx(30));
    CHECK(red[1]->points.front().x == Approx(70));
    // The second run keeps the dash phase it had along the whole line.
    CHECK(red[1]->dashOffset == Approx(60));
    CHECK(strokes(picture, {0, 1, 0}).size() == 1);
    REQUIRE(strokes(picture, {1, 1, 0}).size() == 1);
    CHECK(glm::length(strokes(picture, {1, 1, 0})[0]->points.back() - glm::dvec2(65, 35)) < 1e-9);
    int circles = 0;
    for (const VectorOp& op : picture.ops)
        if (const auto* c = std::get_if<VectorCircle>(&op)) {
            ++circles;
            CHECK(c->centre.x == Approx(20));
        }
    CHECK(circles == 1);
}

TEST_CASE(
    "vector describe: hidden-line surfaces, a surface behind another leaves no line in the visible region",
    "[hardcopy]") {
    vector_test::SurfaceScene scene(WorkstationType::PdfFile);
    const DrawList& list = scene.ws->display();
    PageSetup page = squarePage(500);
    page.paper = {841.8898, 595.2756};
    VectorOptions options;
    options.surfaces = SurfaceDrawing::HiddenLine;
    DescribeStats stats;
    const VectorPicture picture = describePicture(list, page, options, &stats);
    CHECK(stats.hidden);
    CHECK(stats.occluders > 100);
    // The front surface's outline on the page (a height field seen from above: no fold), and a
    // test for points inside it by more than one nominal pixel.
    const PageMapping mapping(list, page);
    const DrawView& view = list.views[1];
    std::vector<glm::dvec2> outline;
    for (int side = 0; side < 4; ++side)
        for (int k = 0; k < 64; ++k) {
            const double s = k / 64.0, u = side == 0 ? s : side == 1 ? 1 : side == 2 ? 1 - s : 0;
            const double v = side == 0 ? 0 : side == 1 ? s : side == 2 ? 1 : 1 - s;
            const glm::dvec4 h =
                view.mapping * view.orientation * glm::dvec4(geom::evaluate(scene.front, u, v), 1.0);
            outline.push_back(glm::dvec2(mapping.toPage(glm::dvec3(h) / h.w)));
        }
    auto inFront = [&](glm::dvec2 p, double margin = 1.0) {
        double nearest = 1e300;
        for (std::size_t i = 0; i < outline.size(); ++i) {
            const glm::dvec2 a = outline[i], b = outline[(i + 1) % outline.size()];
            const double t = std::clamp(glm::dot(p - a, b - a) / glm::dot(b - a, b - a), 0.0, 1.0);
            nearest = std::min(nearest, glm::length(p - (a + t * (b - a))));
        }
        return insideEvenOdd({outline}, p) && nearest > margin;
    };
    std::size_t backStrokes = 0, frontStrokes = 0, pointsInside = 0;
    for (const VectorOp& op : picture.ops) {
        const auto* s = std::get_if<VectorStroke>(&op);
        if (!s) continue;
        const glm::dvec3 c(s->colour);
        const bool back = glm::length(c - vector_test::SurfaceScene::kBackColour) < 1e-3 ||
                          glm::length(c - vector_test::SurfaceScene::kBackLines) < 1e-3;
        (back ? backStrokes : frontStrokes)++;
        if (!back) continue;
        for (std::size_t i = 0; i + 1 < s->points.size(); ++i)
            for (int k = 0; k <= 8; ++k)
                pointsInside += inFront(s->points[i] + (s->points[i + 1] - s->points[i]) * (k / 8.0));
    }
    INFO(backStrokes << " runs of the back surface's lines, " << frontStrokes << " of the front's");
    CHECK(backStrokes > 8);
    CHECK(frontStrokes > 4);
    CHECK(pointsInside == 0);
    // No facet is painted: the surfaces only hide (nothing else could show through them).
    for (const VectorOp& op : picture.ops) CHECK_FALSE(std::holds_alternative<VectorFill>(op));

    // The same in the file a viewer shows: no pixel of the back surface's colours inside the front
    // one (two pixels from its outline for anti-aliasing), and plenty outside.
    const auto file = std::filesystem::path(PHIGS_TEST_OUTPUT_DIR) / "hardcopy" / "hidden_line.pdf";
    VectorWorkstation(file, VectorFormat::Pdf, page, options).update(list);
    CHECK(vector_test::pdfImageCount(file) == 0);
    const glm::dvec2 size = page.pageSize();
    const Image image = vector_test::rasterisePdf(file, std::uint32_t(size.x), std::uint32_t(size.y));
    std::size_t backInside = 0, backOutside = 0;
    for (std::uint32_t y = 0; y < image.height; ++y)
        for (std::uint32_t x = 0; x < image.width; ++x) {
            const std::uint8_t* p = image.pixel(x, y);
            // The back surface's lines are orange-red: much more red than green or blue.
            if (!(p[0] > 120 && p[0] > p[1] + 60 && p[0] > p[2] + 60)) continue;
            (inFront({x + 0.5, y + 0.5}, 2.0) ? backInside : backOutside)++;
        }
    CHECK(backInside == 0);
    CHECK(backOutside > 500);
}

TEST_CASE("vector describe: a mesh's triangles outside its view give nothing, every other one a facet",
          "[hardcopy]") {
    // Random triangle soups around a view with clip limits on all six sides, under random model
    // transforms: the facets are exactly the triangles whose clipped polygon is not empty, and a
    // mesh wholly outside the view (edges on) puts nothing on the page.
    for (std::uint32_t seed = 1; seed <= 20; ++seed) {
        std::mt19937 random(seed);
        std::uniform_real_distribution<double> coordinate(-0.3, 1.3), offset(-0.5, 0.5), scale(0.7, 1.3);
        DrawList list = identityList();
        DrawView clipped;
        clipped.clipMin = {0.25, 0.3, 0.2};
        clipped.clipMax = {0.75, 0.7, 0.9};
        list.views[0] = clipped;
        glm::dmat4 model(1.0);
        model[0][0] = scale(random), model[1][1] = scale(random), model[2][2] = scale(random);
        model[0][1] = 0.3 * offset(random);
        model[3] = glm::dvec4(0.3 * glm::dvec3(offset(random), offset(random), offset(random)), 1.0);
        auto mesh = std::make_shared<MeshData>();
        for (std::uint32_t t = 0; t < 300; ++t) {
            const glm::dvec3 corner(coordinate(random), coordinate(random), coordinate(random));
            for (int k = 0; k < 3; ++k)
                mesh->positions.push_back(
                    glm::vec3(corner + 0.4 * glm::dvec3(offset(random), offset(random), offset(random))));
            mesh->triangles.insert(mesh->triangles.end(), {3 * t, 3 * t + 1, 3 * t + 2});
        }
        auto outside = std::make_shared<MeshData>(*mesh);
        for (glm::vec3& p : outside->positions) p.x += 10.0f;  // right of the view, whatever the model
        for (const auto& data : {mesh, outside}) {
            DrawMesh m;
            m.mesh = data;
            m.interior.edit().style = InteriorStyle::Solid;
            m.edges.edit().visible = data == outside;
            DrawItem drawn = item(m);
            drawn.context.edit().modelTransform = ItemRef<glm::dmat4>(model);
            list.items.push_back(std::move(drawn));
        }
        std::size_t expected = 0;
        const std::vector<HalfSpace> volume = viewVolume(clipped, list);
        for (std::size_t t = 0; t < mesh->triangles.size(); t += 3) {
            std::vector<ClipVertex> polygon;
            for (std::size_t k = 0; k < 3; ++k)
                polygon.push_back(
                    {model * glm::dvec4(glm::dvec3(mesh->positions[mesh->triangles[t + k]]), 1.0)});
            expected += clipPolygon(polygon, volume).empty() ? 0 : 1;
        }
        const PageMapping mapping(list, squarePage());
        const ProjectedScene scene = projectScene(list, mapping, VectorOptions{});
        REQUIRE(expected > 10);
        CHECK(scene.parts.size() == expected);
        for (const ProjectedPart& part : scene.parts) {
            const auto* facet = std::get_if<ProjectedFacet>(&part);
            REQUIRE(facet);
            for (const auto& contour : facet->contours)
                for (const PagePoint& p : contour) {
                    // NPC x in [0.25, 0.75] and y in [0.3, 0.7] on a 100-point page with y down.
                    CHECK(p.x >= 25.0 - 1e-9);
                    CHECK(p.x <= 75.0 + 1e-9);
                    CHECK(p.y >= 30.0 - 1e-9);
                    CHECK(p.y <= 70.0 + 1e-9);
                }
        }
    }
}

TEST_CASE("mesh outline: patch boundaries on knot lines, borders, silhouettes and chains", "[hardcopy]") {
    // A 4 x 4 grid over uv [0, 1]^2 with a knot line at u = 0.5.
    MeshData mesh;
    const int n = 4;
    for (int i = 0; i <= n; ++i)
        for (int j = 0; j <= n; ++j) {
            mesh.positions.push_back({float(i), float(j), 0.0f});
            mesh.uv.push_back({float(i) / n, float(j) / n});
        }
    auto at = [&](int i, int j) { return std::uint32_t(i * (n + 1) + j); };
    for (int i = 0; i < n; ++i)
        for (int j = 0; j < n; ++j)
            mesh.triangles.insert(mesh.triangles.end(), {at(i, j), at(i + 1, j), at(i + 1, j + 1), at(i, j),
                                                         at(i + 1, j + 1), at(i, j + 1)});
    CHECK(facetEdges(mesh).size() == 2 * n * (n + 1) + n * n);
    // Cells of two triangles: no diagonals; the cells of the first column only, by their facing.
    mesh.trianglesPerFacet = 2;
    CHECK(facetEdges(mesh).size() == 2 * n * (n + 1));
    std::vector<int> cellFacing(2 * n * n, -1);
    for (int t = 0; t < 2 * n; ++t) cellFacing[std::size_t(t)] = 1;
    CHECK(facetEdges(mesh, cellFacing, 1).size() == 3 * n + 1);
    CHECK(facetEdges(mesh, cellFacing, -1).size() == 2 * n * (n + 1) - 2 * n - 1);
    // An edge-on cell (facing 0) shows its front, as the raster and the picker take it.
    for (int t = 0; t < 2 * n; ++t) cellFacing[std::size_t(t)] = 0;
    CHECK(facetEdges(mesh, cellFacing, 1).size() == 3 * n + 1);
    CHECK(facetEdges(mesh, cellFacing, -1).size() == 2 * n * (n + 1) - 2 * n - 1);
    mesh.trianglesPerFacet = 1;
    CHECK(patchBoundaryEdges(mesh, nullptr).size() == 4 * n);  // the border only
    std::vector<double> knots{0, 0, 0, 0, 0.5, 1, 1, 1, 1};
    const geom::Surface surface(3, 3, knots, {0, 0, 0, 0, 1, 1, 1, 1}, 5, 4, std::vector<glm::dvec3>(20));
    const auto boundaries = patchBoundaryEdges(mesh, &surface);
    CHECK(boundaries.size() == 4 * n + n);  // and the knot line u = 0.5
    const auto chains = chainEdges(boundaries);
    std::size_t chained = 0;
    for (const auto& c : chains) chained += c.size() - 1;
    CHECK(chained == boundaries.size());
    CHECK(chains.size() <= 3);
    // Facing flips between the two halves: the silhouette is the line between them.
    std::vector<int> facing;
    for (int i = 0; i < n; ++i)
        for (int j = 0; j < n; ++j) facing.insert(facing.end(), 2, i < n / 2 ? 1 : -1);
    const auto silhouette = silhouetteEdges(mesh, facing);
    CHECK(silhouette.size() == std::size_t(n));
    for (const MeshEdge& e : silhouette) CHECK(mesh.uv[e.first].x == 0.5f);
}

}  // namespace test_vector_describe
