// Example 2, a shaded NURBS surface: a bicubic B-spline surface with lights, hidden surface
// removal and four views (front, top, side, oblique) in a window, one view in each quarter.
//
//     shaded_surface                 a window until it is closed
//     shaded_surface --frames N      N frames, then exit
//     shaded_surface --png FILE      also write the last frame as a PNG file
//     shaded_surface --headless      draw offscreen instead (no display needed)
#include "phigs/Phigs.h"
#include "phigs/image/Image.h"
#include "phigs/view/ViewMatrices.h"
#include "phigs/vk/WorkstationDisplay.h"
#include "phigs/window/GlfwWindow.h"

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <memory>
#include <string>

namespace {

/// A wave over [-1, 1] x [-1, 1]: 6 x 6 control points, cubic both ways, clamped knots.
geom::Surface waveSurface() {
    std::vector<glm::dvec3> points;
    for (int i = 0; i < 6; ++i)
        for (int j = 0; j < 6; ++j) {
            const double x = -1 + 0.4 * i, y = -1 + 0.4 * j;
            points.push_back({x, y, 0.35 * std::sin(2.5 * x) * std::cos(2.0 * y)});
        }
    const std::vector<double> knots = {0, 0, 0, 0, 1, 2, 3, 3, 3, 3};
    return geom::Surface(3, 3, knots, knots, 6, 6, points);
}

/// View `index` looks at the origin along -`normal` and shows world [-1.5, 1.5]^2 in one
/// quarter of NPC [0, 1] x [0, 0.75] (the workstation window set in main).
void setView(phigs::Workstation& ws, int index, glm::dvec3 normal, glm::dvec3 up, glm::dvec2 corner) {
    phigs::ViewMapping mapping;
    mapping.windowMin = {-1.5, -1.5};
    mapping.windowMax = {1.5, 1.5};
    mapping.viewportMin = {corner.x, corner.y, 0.0};
    mapping.viewportMax = {corner.x + 0.5, corner.y + 0.375, 1.0};
    mapping.projectionReferencePoint = {0, 0, 10};  // parallel projection along n
    mapping.frontPlaneDistance = 3;
    mapping.backPlaneDistance = -3;
    phigs::ViewRepresentation view;
    view.orientation = phigs::evaluateViewOrientationMatrix({0, 0, 0}, normal, up);
    view.mapping = phigs::evaluateViewMappingMatrix(mapping);
    view.clipMin = mapping.viewportMin;
    view.clipMax = mapping.viewportMax;
    ws.setViewRepresentation(index, view);
}

void buildStructures(phigs::StructureStore& store) {
    using namespace phigs;
    // Structure 2: the surface itself.
    store.openStructure(2);
    store.insert(NurbsSurfaceElement{waveSurface(), {}});
    store.closeStructure();

    // Structure 1: how to draw it (solid, shaded, lit), then the surface once through each view.
    store.openStructure(1);
    store.insert(IndexAttribute{ElementType::InteriorStyle, static_cast<int>(InteriorStyle::Solid)});
    store.insert(IndexAttribute{ElementType::InteriorShadingMethod, static_cast<int>(ShadingMethod::Colour)});
    store.insert(IndexAttribute{ElementType::InteriorReflectanceEquation,
                                static_cast<int>(ReflectanceModel::Specular)});
    AreaPropertiesAttribute properties;
    properties.ambient = 0.3, properties.diffuse = 0.7, properties.specular = 0.3,
    properties.specularExponent = 20;
    store.insert(properties);
    store.insert(ColourAttribute{ElementType::InteriorColour, Colour::fromRgb({1.0, 0.55, 0.1})});
    store.insert(LightSourceStateAttribute{{1, 2}, {}});  // ambient and sun from the light table
    for (int view = 1; view <= 4; ++view) {
        store.insert(viewIndex(view));
        store.insert(executeStructure(2));
    }
    store.closeStructure();
}

void setUpWorkstation(phigs::Workstation& ws) {
    // NPC [0, 1] x [0, 0.75] fills the 4:3 display surface.
    ws.setWorkstationWindow({0, 0, 0}, {1, 0.75, 1});
    ws.setWorkstationViewport({0, 0, 0}, {ws.displaySize().x, ws.displaySize().y, 1});
    ws.setHlhsrMode(1);  // hidden surface removal
    phigs::Light ambient;
    ambient.colour = glm::vec3(0.6f);
    ws.setLightSourceRepresentation(1, ambient);
    phigs::Light sun;
    sun.type = phigs::LightType::Directional;
    sun.direction = glm::normalize(glm::dvec3(-0.5, -0.6, -1.0));
    ws.setLightSourceRepresentation(2, sun);
    setView(ws, 1, {0, 0, 1}, {0, 1, 0}, {0.0, 0.375});     // top left: from above
    setView(ws, 2, {0, -1, 0.4}, {0, 0, 1}, {0.5, 0.375});  // top right: from the front, a little above
    setView(ws, 3, {1, 0, 0.4}, {0, 0, 1}, {0.0, 0.0});     // bottom left: from the side, a little above
    setView(ws, 4, {1, -1.5, 1.2}, {0, 0, 1}, {0.5, 0.0});  // bottom right: oblique
}

}  // namespace

int main(int argc, char** argv) {
    bool headless = false;
    long frames = 0;
    std::string png;
    for (int i = 1; i < argc; ++i) {
        const std::string arg = argv[i];
        if (arg == "--headless")
            headless = true;
        else if (arg == "--frames" && i + 1 < argc)
            frames = std::atol(argv[++i]);
        else if (arg == "--png" && i + 1 < argc)
            png = argv[++i];
        else {
            std::fprintf(stderr, "usage: shaded_surface [--headless] [--frames N] [--png FILE]\n");
            return 2;
        }
    }
    try {
        phigs::Phigs phigs;
        phigs.open();
        buildStructures(phigs.store());
        phigs::Workstation& ws = phigs.openWorkstation(
            1, headless ? phigs::WorkstationType::OffscreenImage : phigs::WorkstationType::Window);
        setUpWorkstation(ws);
        ws.postStructure(1, 0.5);

        std::unique_ptr<phigs::GlfwWindow> window;
        phigs::vk::DisplaySettings settings;
        settings.width = 640, settings.height = 480;
        if (!headless) {
            window = std::make_unique<phigs::GlfwWindow>(640, 480, "phigs: shaded surface, four views");
            settings.window = window.get();
            settings.readBack = !png.empty();
        }
        phigs::vk::WorkstationDisplay display(ws, phigs::vk::ContextSettings::fromEnvironment(), settings);
        long frame = 0;
        do {
            display.update();
            if (window) window->pollEvents();
            ++frame;
        } while (window && !window->shouldClose() && (frames == 0 || frame < frames));
        if (!png.empty()) {
            phigs::writePng(display.image(), png);
            std::printf("wrote %s\n", png.c_str());
        }
        std::printf("%ld frame(s) drawn in %u x %u pixels\n", frame, display.width(), display.height());
        const auto messages = display.context().validationMessages();
        for (const auto& message : messages) std::fprintf(stderr, "validation: %s\n", message.c_str());
        return messages.empty() ? 0 : 1;
    } catch (const std::exception& e) {
        std::fprintf(stderr, "shaded_surface: %s\n", e.what());
        return 1;
    }
}
