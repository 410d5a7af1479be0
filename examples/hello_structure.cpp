// Example 1, hello structure: a polyline and a line of text in a structure, posted on an
// offscreen workstation, drawn by the Vulkan backend and written as a PNG file.
//
//     hello_structure [picture.png]
#include "phigs/Phigs.h"
#include "phigs/image/Image.h"
#include "phigs/vk/WorkstationDisplay.h"

#include <cstdio>
#include <exception>

int main(int argc, char** argv) {
    const char* file = argc > 1 ? argv[1] : "hello_structure.png";
    try {
        phigs::Phigs phigs;
        phigs.open();

        // Structure 1: a yellow zigzag and white text. With no view set, view 0 shows world
        // coordinates [0, 1] x [0, 1] as they are.
        phigs::StructureStore& store = phigs.store();
        store.openStructure(1);
        store.insert(
            phigs::ColourAttribute{phigs::ElementType::PolylineColour, phigs::Colour::fromRgb({1, 1, 0})});
        store.insert(phigs::RealAttribute{phigs::ElementType::LinewidthScaleFactor, 3.0});
        store.insert(
            phigs::polyline3({{0.1, 0.2, 0}, {0.3, 0.5, 0}, {0.5, 0.2, 0}, {0.7, 0.5, 0}, {0.9, 0.2, 0}}));
        store.insert(
            phigs::ColourAttribute{phigs::ElementType::TextColour, phigs::Colour::fromRgb({1, 1, 1})});
        store.insert(phigs::RealAttribute{phigs::ElementType::CharacterHeight, 0.08});
        store.insert(phigs::TextElement{{0.1, 0.7, 0}, {1, 0, 0}, {0, 1, 0}, "Hello, PHIGS", false});
        store.closeStructure();

        // An offscreen workstation shows the structure; its display draws it into an image.
        phigs::Workstation& ws = phigs.openWorkstation(1, phigs::WorkstationType::OffscreenImage);
        ws.postStructure(1, 0.5);
        phigs::vk::DisplaySettings settings;
        settings.width = 512;  // the 1024 x 768 display surface at half a pixel per unit
        settings.height = 384;
        phigs::vk::WorkstationDisplay display(ws, phigs::vk::ContextSettings::fromEnvironment(), settings);
        display.update();
        phigs::writePng(display.image(), file);
        std::printf("wrote %s (%u x %u)\n", file, display.width(), display.height());

        // Validation messages (the layer is on by default) mean a bug in the toolkit.
        const auto messages = display.context().validationMessages();
        for (const auto& message : messages) std::fprintf(stderr, "validation: %s\n", message.c_str());
        return messages.empty() ? 0 : 1;
    } catch (const std::exception& e) {
        std::fprintf(stderr, "hello_structure: %s\n", e.what());
        return 1;
    }
}
