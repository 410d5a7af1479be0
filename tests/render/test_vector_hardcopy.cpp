// The vector hardcopy (phigs_hardcopy) against the lavapipe picture of the same draw list: each
// scene is written as PDF, SVG and EPS on a page of one point per pixel, the PDF and SVG are
// rasterised (pdftoppm, rsvg-convert) and their drawn pixels must agree with the raster's within
// one pixel (at least 95 % both ways); the PDF must hold no raster image.
#include "RenderTestSupport.h"
#include "SceneMeshes.h"
#include "VectorRaster.h"
#include "VectorScenes.h"
#include "phigs/hardcopy/MeshOutline.h"
#include "phigs/hardcopy/VectorWorkstation.h"
#include "phigs/view/ViewMatrices.h"
#include "phigs/vk/ImageTarget.h"

#include "geom/Tessellate.h"

#include <cstdio>
#include <fstream>

namespace test_vector_hardcopy {

using namespace phigs;
using namespace phigs::hardcopy;
using namespace render_test;

namespace {

constexpr double kRequiredOverlap = 0.95;

/// Draws `list` on lavapipe (or `reference` when the raster needs another list for the same
/// picture) and as vector files, and compares; the figures go to output/vector/<name>.txt.
void compareWithLavapipe(const std::string& name, const DrawList& list, std::uint32_t width,
                         std::uint32_t height, const VectorOptions& options = {},
                         const DrawList* reference = nullptr) {
    vk::Context context(lavapipeWithValidation());
    Image raster;
    {
        vk::ImageTarget ws(context, width, height);
        raster = ws.draw(reference ? *reference : list);
    }
    requireNoValidationMessages(context);
    const auto dir = std::filesystem::path(PHIGS_TEST_OUTPUT_DIR) / "vector";
    std::filesystem::create_directories(dir);
    writePng(raster, dir / (name + "_lavapipe.png"));
    PageSetup page;
    page.paper = {double(width), double(height)};
    page.orientation = width >= height ? PageOrientation::Landscape : PageOrientation::Portrait;
    page.nominalPixel = 1.0;
    std::uintmax_t bytes[3] = {};
    const char* extensions[3] = {".pdf", ".svg", ".eps"};
    DescribeStats stats;
    for (int f = 0; f < 3; ++f) {
        const auto file = dir / (name + extensions[f]);
        VectorWorkstation vector(file, VectorFormat(f), page, options);
        vector.update(list);
        vector.close();
        bytes[f] = std::filesystem::file_size(file);
        stats = vector.lastStats();
    }
    CHECK(vector_test::pdfImageCount(dir / (name + ".pdf")) == 0);
    const Image pdf = vector_test::rasterisePdf(dir / (name + ".pdf"), width, height);
    const Image svg = vector_test::rasteriseSvg(dir / (name + ".svg"), width, height);
    const vector_test::Overlap pdfOverlap = vector_test::drawnOverlap(raster, pdf, list.background);
    const vector_test::Overlap svgOverlap = vector_test::drawnOverlap(raster, svg, list.background);
    char line[320];
    std::snprintf(
        line, sizeof line,
        "%s: PDF %.4f / %.4f, SVG %.4f / %.4f (raster in vector / vector in raster); drawn %zu, %zu, "
        "%zu; bytes PDF %ju SVG %ju EPS %ju; facets %zu -> %zu (%zu splits), %zu occluders\n",
        name.c_str(), pdfOverlap.aInB, pdfOverlap.bInA, svgOverlap.aInB, svgOverlap.bInA, pdfOverlap.drawnA,
        pdfOverlap.drawnB, svgOverlap.drawnB, bytes[0], bytes[1], bytes[2], stats.facets.input,
        stats.facets.output, stats.facets.splits, stats.occluders);
    std::ofstream(dir / (name + ".txt")) << line;
    INFO(line);
    CHECK(pdfOverlap.drawnA > 100);
    CHECK(pdfOverlap.worst() >= kRequiredOverlap);
    CHECK(svgOverlap.worst() >= kRequiredOverlap);
}

DrawPolyline line(std::vector<glm::dvec3> points, glm::vec3 colour, LineType type, float width) {
    DrawPolyline p;
    p.points = std::move(points);
    p.style = LineStyle{colour, type, width};
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

/// The raster's picture of a hidden-line drawing: the surfaces in the background colour, unlit,
/// hiding by the depth buffer, with their iso-lines and their patch boundaries as polylines.
DrawList hiddenLineReference(const DrawList& list) {
    DrawList reference = list;
    for (const DrawItem& item : list.items) {
        const auto* mesh = primitiveIf<DrawMesh>(item.primitive);
        if (!mesh) continue;
        for (const auto& chain : chainEdges(patchBoundaryEdges(*mesh->mesh, mesh->surface.get()))) {
            DrawPolyline boundary;
            std::vector<glm::dvec3> points;
            for (std::uint32_t i : chain) points.push_back(glm::dvec3(mesh->mesh->positions[i]));
            boundary.points = points;
            boundary.style.edit().colour = mesh->interior->colour;
            DrawItem copy = item;
            copy.primitive = boundary;
            reference.items.push_back(copy);
        }
    }
    for (DrawItem& item : reference.items)
        if (holdsPrimitive<DrawMesh>(item.primitive)) {
            DrawMesh& mesh = editPrimitive<DrawMesh>(item.primitive);
            mesh.interior.edit().colour = reference.background;
            mesh.interior.edit().reflectance = ReflectanceModel::None;
        }
    return reference;
}

}  // namespace

TEST_CASE("vector hardcopy against lavapipe: polylines, line types and widths", "[render][hardcopy]") {
    DrawList list = emptyScene();
    const LineType types[] = {LineType::Solid, LineType::Dashed, LineType::Dotted, LineType::DashDotted};
    for (int t = 0; t < 4; ++t)
        for (int w = 0; w < 3; ++w) {
            const double y = 0.92 - (t * 3 + w) * 0.075;
            list.items.push_back(item(line({{0.05, y, 0.5}, {0.6, y, 0.5}, {0.95, y - 0.05, 0.5}},
                                           {1.0f, 0.9f - 0.2f * t, 0.3f * w}, types[t], float(1 << w))));
        }
    compareWithLavapipe("polylines", list, 256, 256);
}

TEST_CASE("vector hardcopy against lavapipe: polymarkers", "[render][hardcopy]") {
    DrawList list = emptyScene();
    const MarkerType types[] = {MarkerType::Dot, MarkerType::Plus, MarkerType::Asterisk, MarkerType::Circle,
                                MarkerType::Cross};
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
    compareWithLavapipe("polymarkers", list, 256, 256);
}

TEST_CASE("vector hardcopy against lavapipe: fill areas and sets, hollow, solid, hatch, edges",
          "[render][hardcopy]") {
    DrawList list = emptyScene();
    list.items.push_back(item(fill({rectangle(0.05, 0.55, 0.3, 0.95)}, InteriorStyle::Hollow, {1, 1, 0})));
    list.items.push_back(item(fill({rectangle(0.37, 0.55, 0.62, 0.95)}, InteriorStyle::Solid, {0, 0.8f, 1})));
    for (int h = 1; h <= 2; ++h) {
        DrawFillArea hatch = fill({rectangle(0.69, 0.75 - (h - 1) * 0.2, 0.95, 0.95 - (h - 1) * 0.2)},
                                  InteriorStyle::Hatch, {1, 0.5f, 0.2f});
        hatch.interior.edit().styleIndex = h == 1 ? 3 : 5;
        list.items.push_back(item(hatch));
    }
    DrawFillArea u = fill({{{0.05, 0.05, 0.5},
                            {0.45, 0.05, 0.5},
                            {0.45, 0.45, 0.5},
                            {0.35, 0.45, 0.5},
                            {0.35, 0.15, 0.5},
                            {0.15, 0.15, 0.5},
                            {0.15, 0.45, 0.5},
                            {0.05, 0.45, 0.5}}},
                          InteriorStyle::Solid, {0.9f, 0.2f, 0.6f});
    u.edges = EdgeStyle{true, {1, 1, 1}, LineType::Dashed, 2.0f};
    list.items.push_back(item(u));
    DrawFillArea holes = fill(
        {rectangle(0.55, 0.05, 0.95, 0.45), rectangle(0.6, 0.1, 0.72, 0.4), rectangle(0.78, 0.1, 0.9, 0.4)},
        InteriorStyle::Solid, {0.3f, 1.0f, 0.3f});
    holes.edges = EdgeStyle{true, {1, 0, 0}, LineType::Solid, 1.0f};
    list.items.push_back(item(holes));
    compareWithLavapipe("fill_areas", list, 256, 256);
}

TEST_CASE("vector hardcopy against lavapipe: stroke text and annotation text", "[render][hardcopy]") {
    DrawList list = emptyScene();
    auto text = [&](std::string s, glm::dvec3 at, auto&& adjust) {
        DrawText t;
        t.text = std::move(s);
        t.position = at;
        t.style.edit().height = 0.06;
        adjust(t);
        list.items.push_back(item(t));
    };
    text("PHIGS", {0.05, 0.85, 0.5}, [](DrawText&) {});
    text("wide", {0.55, 0.85, 0.5}, [](DrawText& t) { t.style.edit().expansion = 1.6f; });
    text("UP", {0.1, 0.15, 0.5}, [](DrawText& t) { t.style.edit().upVector = {-1, 1}; });
    text("DOWN", {0.9, 0.75, 0.5}, [](DrawText& t) {
        t.style.edit().path = TextPath::Down;
        t.style.edit().height = 0.04;
    });
    text("centred", {0.5, 0.55, 0.5}, [](DrawText& t) {
        t.style.edit().horizontal = HorizontalAlignment::Centre;
        t.style.edit().vertical = VerticalAlignment::Half;
    });
    DrawText note;
    note.text = "note";
    note.annotation = true;
    note.position = {0.3, 0.3, 0.5};
    note.annotationOffset = {0.05, -0.1, 0};
    note.style.edit().height = 0.05;
    list.items.push_back(item(note));
    compareWithLavapipe("text", list, 256, 256);
}

TEST_CASE("vector hardcopy against lavapipe: a NURBS curve tessellated to the page tolerance",
          "[render][hardcopy]") {
    DrawList list = emptyScene();
    auto curve = std::make_shared<const geom::Curve>(3, std::vector<double>{0, 0, 0, 0, 1, 2, 3, 3, 3, 3},
                                                     std::vector<glm::dvec3>{{0.1, 0.1, 0.5},
                                                                             {0.2, 0.9, 0.5},
                                                                             {0.5, -0.3, 0.5},
                                                                             {0.8, 1.1, 0.5},
                                                                             {0.9, 0.5, 0.5},
                                                                             {0.6, 0.2, 0.5}});
    DrawCurve drawn;
    drawn.curve = curve;
    drawn.points = geom::tessellate(*curve, 1e-4);  // the raster's polyline, finer than a pixel
    drawn.style = LineStyle{{0.4f, 1.0f, 0.8f}, LineType::Solid, 2.0f};
    list.items.push_back(item(drawn));
    compareWithLavapipe("nurbs_curve", list, 256, 256);
}

TEST_CASE("vector hardcopy against lavapipe: NURBS surfaces shaded, facets depth sorted",
          "[render][hardcopy]") {
    vector_test::SurfaceScene scene(WorkstationType::OffscreenImage);
    compareWithLavapipe("surfaces_shaded", scene.ws->display(), 512, 384);
}

TEST_CASE("vector hardcopy against lavapipe: NURBS surfaces as a hidden-line drawing", "[render][hardcopy]") {
    vector_test::SurfaceScene scene(WorkstationType::OffscreenImage);
    const DrawList& list = scene.ws->display();
    const DrawList reference = hiddenLineReference(list);
    VectorOptions options;
    options.surfaces = SurfaceDrawing::HiddenLine;
    compareWithLavapipe("surfaces_hidden_line", list, 512, 384, options, &reference);
}

TEST_CASE("vector hardcopy against lavapipe: four views, one in perspective, with their clip limits",
          "[render][hardcopy]") {
    DrawList list = emptyScene();
    list.views.clear();
    list.hiddenSurfaceRemoval = true;
    Light ambient;
    ambient.colour = glm::vec3(0.3f);
    Light key;
    key.type = LightType::Directional;
    key.direction = glm::normalize(glm::dvec3(-1, -2, -3));
    list.lightSets.push_back({ambient, key});
    auto body = sphere({0, 0, 0}, 1.0f, 24, 12, 4);
    for (auto& p : body->positions) p *= glm::vec3(0.9f, 0.3f, 0.2f);
    const glm::dvec3 vpns[4] = {{0, 0, 1}, {0, -1, 0}, {1, 0, 0}, {1, -1, 1}};
    const glm::dvec3 vups[4] = {{0, 1, 0}, {0, 0, 1}, {0, 0, 1}, {0, 0, 1}};
    const glm::dvec2 corners[4] = {{0, 0.5}, {0.5, 0.5}, {0, 0}, {0.5, 0}};
    for (int v = 0; v < 4; ++v) {
        ViewMapping mapping;
        mapping.windowMin = glm::dvec2(-1.3), mapping.windowMax = glm::dvec2(1.3);
        mapping.viewportMin = {corners[v] + 0.01, 0.0};
        mapping.viewportMax = {corners[v] + 0.49, 1.0};
        mapping.backPlaneDistance = -2.0, mapping.frontPlaneDistance = 2.0;
        if (v == 3) {
            mapping.projection = ProjectionType::Perspective;
            mapping.projectionReferencePoint = {0, 0, 6};
        }
        DrawView view;
        view.orientation = evaluateViewOrientationMatrix({0, 0, 0}, vpns[v], vups[v]);
        view.mapping = evaluateViewMappingMatrix(mapping);
        view.clipMin = mapping.viewportMin;
        view.clipMax = mapping.viewportMax;
        list.views.push_back(view);
        const glm::vec3 colours[3] = {{1, 0.2f, 0.2f}, {0.2f, 1, 0.2f}, {0.3f, 0.5f, 1}};
        for (int a = 0; a < 3; ++a) {
            glm::dvec3 end(0.0);
            end[a] = 1.2;
            list.items.push_back(item(line({glm::dvec3(0.0), end}, colours[a], LineType::Solid, 2.0f), v));
        }
        DrawMesh m;
        m.mesh = body;
        m.interior.edit().style = InteriorStyle::Solid;
        m.interior.edit().colour = {0.8f, 0.8f, 0.8f};
        m.interior.edit().shading = ShadingMethod::Normal;
        m.interior.edit().reflectance = ReflectanceModel::Diffuse;
        m.isoLineStyle = LineStyle{{1, 1, 0}, LineType::Dashed, 1.0f};
        DrawItem i = item(m, v);
        i.context.edit().lightSet = 0;
        list.items.push_back(i);
        list.items.push_back(item(line({{-5, -5, -5}, {5, 5, 5}}, {1, 0.5f, 0}, LineType::Solid, 1.0f), v));
    }
    compareWithLavapipe("four_views", list, 256, 256);
}

}  // namespace test_vector_hardcopy
