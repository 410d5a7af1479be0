// The toolkit put together: structures in the store, posted on a model workstation, drawn by
// the Vulkan backend (vk::WorkstationDisplay) and picked through the logical input devices
// (the workstation's input devices on a script source). The pixel found in the rendered image must be
// the pixel the pick resolves: one WorkstationMapping serves both.
#include "RenderTestSupport.h"
#include "phigs/Phigs.h"
#include "phigs/input/ScriptInputSource.h"
#include "phigs/view/ViewMatrices.h"
#include "phigs/vk/WorkstationDisplay.h"

#include "geom/Evaluate.h"

#include <cstdio>
#include <optional>

namespace test_workstation_display {

using namespace phigs;
using namespace render_test;

namespace {

/// A bicubic Bézier patch over x in [0, 0.8], y in [0, 0.6] (x, y affine in u, v by the linear
/// precision of the control grid) with a bumpy z, so the exact pick has real work to do.
geom::Surface bumpyPatch() {
    std::vector<glm::dvec3> points;
    const double bumps[4][4] = {
        {0.0, 0.2, -0.1, 0.0}, {0.1, 0.5, 0.4, -0.2}, {-0.2, 0.3, 0.5, 0.1}, {0.0, -0.1, 0.2, 0.0}};
    for (int i = 0; i < 4; ++i)
        for (int j = 0; j < 4; ++j) points.push_back({0.8 * i / 3.0, 0.6 * j / 3.0, bumps[i][j]});
    return geom::Surface(3, 3, {0, 0, 0, 0, 1, 1, 1, 1}, {0, 0, 0, 0, 1, 1, 1, 1}, 4, 4, points);
}

struct PixelBox {
    glm::dvec2 min{1e30}, max{-1e30}, sum{0.0};
    std::size_t count = 0;
    glm::dvec2 centroid() const { return sum / double(count); }
};

/// Where the pixels of (about) one colour lie in the image; pixel centres at (i + 0.5, j + 0.5).
PixelBox pixelsOf(const Image& image, glm::ivec3 rgb) {
    PixelBox box;
    for (std::uint32_t y = 0; y < image.height; ++y)
        for (std::uint32_t x = 0; x < image.width; ++x) {
            const std::uint8_t* p = image.pixel(x, y);
            if (std::abs(p[0] - rgb.x) > 40 || std::abs(p[1] - rgb.y) > 40 || std::abs(p[2] - rgb.z) > 40)
                continue;
            const glm::dvec2 centre(x + 0.5, y + 0.5);
            box.min = glm::min(box.min, centre);
            box.max = glm::max(box.max, centre);
            box.sum += centre;
            ++box.count;
        }
    return box;
}

std::string pickLine(glm::dvec2 pixel) {
    char line[96];
    std::snprintf(line, sizeof line, "pick %.17g %.17g\n", pixel.x, pixel.y);
    return line;
}

/// The scene: structure 1 (names {1}) holds a red square with pick id 5, then executes
/// structure 2 (names {1, 2} there) with pick id 6; structure 2 holds the green patch with pick
/// id 7. View 1 maps world [-1, 1]^2 onto NPC [0.1, 0.9]^2.
struct Scene {
    Phigs phigs;
    Workstation* ws = nullptr;
    geom::Surface patch = bumpyPatch();

    Scene() {
        phigs.open();
        auto& store = phigs.store();
        store.openStructure(1);
        store.insert(addNamesToSet({1}));                                                        // 1
        store.insert(pickId(5));                                                                 // 2
        store.insert(IndexAttribute{ElementType::InteriorStyle, 1});                             // 3 solid
        store.insert(ColourAttribute{ElementType::InteriorColour, Colour::fromRgb({1, 0, 0})});  // 4
        store.insert(viewIndex(1));                                                              // 5
        store.insert(fillArea3({{-0.8, -0.8, 0}, {-0.4, -0.8, 0}, {-0.4, -0.4, 0}, {-0.8, -0.4, 0}}));  // 6
        store.insert(pickId(6));                                                                        // 7
        store.insert(executeStructure(2));                                                              // 8
        store.closeStructure();
        store.openStructure(2);
        store.insert(addNamesToSet({2}));                                                        // 1
        store.insert(ColourAttribute{ElementType::InteriorColour, Colour::fromRgb({0, 1, 0})});  // 2
        store.insert(pickId(7));                                                                 // 3
        store.insert(NurbsSurfaceElement{patch, {}});                                            // 4
        store.closeStructure();

        ws = &phigs.openWorkstation(1, WorkstationType::OffscreenImage);
        ViewMapping mapping;
        mapping.windowMin = {-1, -1};
        mapping.windowMax = {1, 1};
        mapping.viewportMin = {0.1, 0.1, 0.0};
        mapping.viewportMax = {0.9, 0.9, 1.0};
        mapping.projectionReferencePoint = {0, 0, 5};
        mapping.frontPlaneDistance = 1;
        mapping.backPlaneDistance = -1;
        ws->setViewRepresentation(1, {evaluateViewOrientationMatrix({0, 0, 0}, {0, 0, 1}, {0, 1, 0}),
                                      evaluateViewMappingMatrix(mapping)});
        ws->postStructure(1, 0.5);
        ws->input().setPickFilter(1, {1}, {});  // starts empty (ISO 9592): nothing pickable
    }

    /// NPC of a world point through view 1.
    glm::dvec3 npcOf(glm::dvec3 world) {
        const DrawView& v = ws->display().views.at(1);
        const glm::dvec4 h = v.mapping * v.orientation * glm::dvec4(world, 1.0);
        return glm::dvec3(h) / h.w;
    }
};

}  // namespace

TEST_CASE("workstation display: a posted network rendered offscreen is picked at its pixels",
          "[render][wiring]") {
    Scene scene;
    vk::DisplaySettings settings;
    settings.width = 256;  // the 1024 x 768 display surface at a quarter of a pixel per unit
    settings.height = 192;
    vk::WorkstationDisplay display(*scene.ws, lavapipeWithValidation(), settings);
    REQUIRE(display.update());
    const Image& image = display.image();
    REQUIRE(image.width == 256);
    REQUIRE(image.height == 192);
    writePng(image, std::filesystem::path(PHIGS_TEST_OUTPUT_DIR) / "workstation_display.png");
    const WorkstationMapping mapping = display.mapping();
    CHECK(mapping.pixelsPerDevice == Approx(0.25));

    // The red square: the image puts it where the mapping says.
    const PixelBox red = pixelsOf(image, {255, 0, 0});
    REQUIRE(red.count > 100);
    const glm::dvec2 redMin = mapping.toPixels(scene.npcOf({-0.8, -0.4, 0}));  // top left in pixels
    const glm::dvec2 redMax = mapping.toPixels(scene.npcOf({-0.4, -0.8, 0}));
    CHECK(std::abs(red.min.x - redMin.x) <= 1.0);
    CHECK(std::abs(red.min.y - redMin.y) <= 1.0);
    CHECK(std::abs(red.max.x - redMax.x) <= 1.0);
    CHECK(std::abs(red.max.y - redMax.y) <= 1.0);

    // The green patch: its box in the image is the projection of its corners.
    const PixelBox green = pixelsOf(image, {0, 255, 0});
    REQUIRE(green.count > 100);
    const glm::dvec2 greenMin = mapping.toPixels(scene.npcOf({0.0, 0.6, 0}));
    const glm::dvec2 greenMax = mapping.toPixels(scene.npcOf({0.8, 0.0, 0}));
    CHECK(std::abs(green.min.x - greenMin.x) <= 1.0);
    CHECK(std::abs(green.min.y - greenMin.y) <= 1.0);
    CHECK(std::abs(green.max.x - greenMax.x) <= 1.0);
    CHECK(std::abs(green.max.y - greenMax.y) <= 1.0);

    // A known surface point's pixel is green in the image...
    const glm::dvec2 uv(0.3, 0.65);
    const glm::dvec3 onSurface = geom::evaluate(scene.patch, uv.x, uv.y);
    const glm::dvec2 surfacePixel = mapping.toPixels(scene.npcOf(onSurface));
    const std::uint8_t* p = image.pixel(std::uint32_t(surfacePixel.x), std::uint32_t(surfacePixel.y));
    CHECK(p[1] > 200);
    CHECK(p[0] < 60);

    // ...and the picks through the input devices, at the red square's centroid found in the
    // image and at that surface pixel, name the right paths, pick ids and (u, v).
    ScriptInputSource script(pickLine(red.centroid()) + pickLine(surfacePixel), "e2e.txt");
    InputQueue queue;
    scene.ws->connectInput(script, queue);

    auto [status, measure] = scene.ws->input().request(InputClass::Pick, 1);
    REQUIRE(status == InputStatus::Ok);
    CHECK(std::get<PickMeasure>(measure).path == std::vector<PickPathItem>{{1, 6, 5}});
    // The pick echo: the display highlights the picked square (60 % toward yellow) and
    // re-uploads no geometry for it.
    REQUIRE(scene.ws->lastPickEcho().size() == 1);
    display.setEcho(scene.ws->lastPickEcho());
    REQUIRE(display.update());
    CHECK(display.renderer().lastFrame().buffersCreated == 0);
    const glm::dvec2 centre = red.centroid();
    CHECK(shows(display.image(), centre, {1.0, 0.6, 0.0}, 16));
    display.setEcho({});
    REQUIRE(display.update());
    CHECK(shows(display.image(), centre, {1.0, 0.0, 0.0}));

    auto [status2, measure2] = scene.ws->input().request(InputClass::Pick, 1);
    REQUIRE(status2 == InputStatus::Ok);
    const PickMeasure& surfacePick = std::get<PickMeasure>(measure2);
    CHECK(surfacePick.path == std::vector<PickPathItem>{{1, 8, 6}, {2, 4, 7}});
    REQUIRE(surfacePick.surface);
    CHECK(surfacePick.surface->uv.x == Approx(uv.x).margin(1e-6));
    CHECK(surfacePick.surface->uv.y == Approx(uv.y).margin(1e-6));
    CHECK(glm::length(surfacePick.surface->point - onSurface) < 1e-6);

    requireNoValidationMessages(display.context());
}

TEST_CASE("workstation display: a pick device with its own filter picks on its own traversal",
          "[render][wiring]") {
    Scene scene;
    vk::DisplaySettings settings;
    settings.width = 128;
    settings.height = 96;
    vk::WorkstationDisplay display(*scene.ws, lavapipeWithValidation(), settings);
    REQUIRE(display.update());
    const WorkstationMapping mapping = display.mapping();
    const glm::dvec3 onSurface = geom::evaluate(scene.patch, 0.5, 0.5);
    const glm::dvec2 pixel = mapping.toPixels(scene.npcOf(onSurface));
    ScriptInputSource script(pickLine(pixel) + pickLine(pixel), "filter.txt");
    InputQueue queue;
    scene.ws->connectInput(script, queue);
    // The patch has names {1, 2}: excluding 2 makes it unpickable for this device only.
    scene.ws->input().setPickFilter(1, {1}, {2});
    CHECK(scene.ws->input().request(InputClass::Pick, 1).first == InputStatus::None);
    scene.ws->input().setPickFilter(1, {1}, {});
    CHECK(scene.ws->input().request(InputClass::Pick, 1).first == InputStatus::Ok);
    // The displayed picture was not touched by the pick traversals.
    CHECK(scene.ws->display().items.size() == 2);
    requireNoValidationMessages(display.context());
}

TEST_CASE("workstation display: an unchanged workstation uploads nothing, an edit only what it touched",
          "[render][wiring]") {
    Scene scene;
    vk::Context context(lavapipeWithValidation());
    {
        vk::DisplaySettings settings;
        settings.width = 64;
        settings.height = 48;
        vk::WorkstationDisplay display(*scene.ws, context, settings);
        display.update();
        CHECK(display.renderer().lastFrame().uploads > 0);
        const Image first = display.image();
        display.update();
        CHECK(display.renderer().lastFrame().uploads == 0);
        CHECK(display.renderer().lastFrame().buffersCreated == 0);
        CHECK(display.image().rgba == first.rgba);
        // Freed images come back at the next picture: the same pixels, the buffers kept.
        display.releaseImages();
        CHECK(display.image().rgba.empty());
        display.update();
        CHECK(display.renderer().lastFrame().uploads == 0);
        CHECK(display.image().rgba == first.rgba);
        // Recolour the square (element 4 of structure 1): the patch's mesh stays on the GPU.
        auto& store = scene.phigs.store();
        store.openStructure(1);
        store.setElementPointer(4);
        store.setEditMode(EditMode::Replace);
        store.insert(ColourAttribute{ElementType::InteriorColour, Colour::fromRgb({0, 0, 1})});
        store.closeStructure();
        display.update();
        CHECK(display.renderer().lastFrame().buffersCreated == 1);  // the square's new vertices
        CHECK(display.image().rgba != first.rgba);
    }
    requireNoValidationMessages(context);
}

TEST_CASE("workstation display: a hardcopy workstation writes its picture on update", "[render][wiring]") {
    Scene scene;
    Workstation& hardcopy = scene.phigs.openWorkstation(2, WorkstationType::Hardcopy);
    hardcopy.postStructure(2, 0.5);
    const auto file = std::filesystem::path(PHIGS_TEST_OUTPUT_DIR) / "workstation_hardcopy.png";
    std::filesystem::remove(file);
    vk::DisplaySettings settings;
    settings.width = 140;  // A4 landscape (3508 x 2480) at 1/25 scale
    settings.height = 99;
    settings.file = file;
    vk::WorkstationDisplay display(hardcopy, lavapipeWithValidation(), settings);
    display.update();
    const Image written = readPng(file);
    CHECK(written.width == 140);
    CHECK(written.rgba == display.image().rgba);
    CHECK(pixelsOf(written, {0, 255, 0}).count > 50);  // the patch, drawn in view 0 here
    vk::DisplaySettings missing;
    CHECK_THROWS_WITH(vk::WorkstationDisplay(hardcopy, display.context(), missing),
                      Catch::Matchers::Contains("needs a file"));
    requireNoValidationMessages(display.context());
}

}  // namespace test_workstation_display
