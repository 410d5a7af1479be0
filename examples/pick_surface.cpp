// Example 3, picking: a surface drawn offscreen is clicked at a pixel through the pick device,
// which answers the pick path (structure, element, pick id at each level) and the surface's
// (u, v) under the cursor. The click comes from a script line "pick X Y", as a window's mouse
// button would give it (phigs::GlfwInputSource in a window).
//
//     pick_surface [U V]      clicks the pixel where the surface point S(U, V) is drawn
#include "phigs/Phigs.h"
#include "phigs/input/ScriptInputSource.h"
#include "phigs/view/ViewMatrices.h"
#include "phigs/vk/WorkstationDisplay.h"

#include "geom/Evaluate.h"

#include <cstdio>
#include <cstdlib>
#include <exception>

namespace {

/// Structure 1 executes structure 2 (pick id 6); structure 2 holds the patch (pick id 7).
void buildStructures(phigs::StructureStore& store, const geom::Surface& patch) {
    // The patch inherits name 1, which main() puts in pick device 1's filter: a pick filter
    // starts empty (ISO 9592), and then nothing is pickable.
    store.openStructure(1);
    store.insert(phigs::viewIndex(1));         // element 1
    store.insert(phigs::pickId(6));            // element 2
    store.insert(phigs::addNamesToSet({1}));   // element 3
    store.insert(phigs::executeStructure(2));  // element 4
    store.closeStructure();
    store.openStructure(2);
    store.insert(phigs::IndexAttribute{phigs::ElementType::InteriorStyle, 1});  // 1: solid
    store.insert(
        phigs::ColourAttribute{phigs::ElementType::InteriorColour, phigs::Colour::fromRgb({0, 1, 0})});
    store.insert(phigs::pickId(7));                       // 3
    store.insert(phigs::NurbsSurfaceElement{patch, {}});  // 4
    store.closeStructure();
}

}  // namespace

int main(int argc, char** argv) {
    const glm::dvec2 target(argc > 2 ? std::atof(argv[1]) : 0.3, argc > 2 ? std::atof(argv[2]) : 0.65);
    try {
        phigs::Phigs phigs;
        phigs.open();

        // A bicubic Bézier patch over [0, 0.8] x [0, 0.6] with a bumpy height.
        const double bumps[4][4] = {
            {0.0, 0.2, -0.1, 0.0}, {0.1, 0.5, 0.4, -0.2}, {-0.2, 0.3, 0.5, 0.1}, {0.0, -0.1, 0.2, 0.0}};
        std::vector<glm::dvec3> points;
        for (int i = 0; i < 4; ++i)
            for (int j = 0; j < 4; ++j) points.push_back({0.8 * i / 3.0, 0.6 * j / 3.0, bumps[i][j]});
        const geom::Surface patch(3, 3, {0, 0, 0, 0, 1, 1, 1, 1}, {0, 0, 0, 0, 1, 1, 1, 1}, 4, 4, points);

        buildStructures(phigs.store(), patch);

        // View 1 maps world [-1, 1]^2 onto NPC [0.1, 0.9]^2, looking down -z.
        phigs::Workstation& ws = phigs.openWorkstation(1, phigs::WorkstationType::OffscreenImage);
        phigs::ViewMapping mapping;
        mapping.windowMin = {-1, -1};
        mapping.windowMax = {1, 1};
        mapping.viewportMin = {0.1, 0.1, 0.0};
        mapping.viewportMax = {0.9, 0.9, 1.0};
        mapping.projectionReferencePoint = {0, 0, 5};
        mapping.frontPlaneDistance = 1;
        mapping.backPlaneDistance = -1;
        const phigs::ViewRepresentation view{
            phigs::evaluateViewOrientationMatrix({0, 0, 0}, {0, 0, 1}, {0, 1, 0}),
            phigs::evaluateViewMappingMatrix(mapping)};
        ws.setViewRepresentation(1, view);
        ws.postStructure(1, 0.5);

        phigs::vk::DisplaySettings settings;
        settings.width = 256, settings.height = 192;
        phigs::vk::WorkstationDisplay display(ws, phigs::vk::ContextSettings::fromEnvironment(), settings);
        display.update();

        // The pixel of S(u, v): world -> NPC through view 1, NPC -> pixels through the display.
        const glm::dvec3 world = geom::evaluate(patch, target.x, target.y);
        const glm::dvec4 npc = view.mapping * view.orientation * glm::dvec4(world, 1.0);
        const glm::dvec2 pixel = display.mapping().toPixels(glm::dvec3(npc) / npc.w);
        char line[96];
        std::snprintf(line, sizeof line, "pick %.17g %.17g\n", pixel.x, pixel.y);
        std::printf("click at pixel (%.1f, %.1f)\n", pixel.x, pixel.y);

        // REQUEST PICK on pick device 1, fed by the script.
        phigs::ScriptInputSource script(line, "clicks");
        phigs::InputQueue queue;
        ws.connectInput(script, queue);
        ws.input().setPickFilter(1, {1}, {});
        auto [status, measure] = ws.input().request(phigs::InputClass::Pick, 1);
        const auto& pick = std::get<phigs::PickMeasure>(measure);
        if (status != phigs::InputStatus::Ok || pick.status != phigs::InputStatus::Ok) {
            std::printf("nothing picked\n");
            return 1;
        }
        std::printf("pick path (structure, element, pick id):");
        for (const phigs::PickPathItem& item : pick.path)
            std::printf(" (%d, %d, %d)", item.structureId, item.elementNumber, item.pickId);
        std::printf("\n");
        if (pick.surface)
            std::printf("surface (u, v) = (%.4f, %.4f) at (%.4f, %.4f, %.4f)\n", pick.surface->uv.x,
                        pick.surface->uv.y, pick.surface->point.x, pick.surface->point.y,
                        pick.surface->point.z);
        return 0;
    } catch (const std::exception& e) {
        std::fprintf(stderr, "pick_surface: %s\n", e.what());
        return 1;
    }
}
