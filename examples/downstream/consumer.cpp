// A downstream program: a filled square in a structure, drawn offscreen through the installed
// package, its centre pixel checked. Prints "consumer: ok" on success.
#include <phigs/Phigs.h>
#include <phigs/image/Image.h>
#include <phigs/vk/WorkstationDisplay.h>

#include <cstdio>
#include <exception>

int main(int argc, char** argv) {
    try {
        phigs::Phigs phigs;
        phigs.open();
        phigs::StructureStore& store = phigs.store();
        store.openStructure(1);
        store.insert(phigs::IndexAttribute{phigs::ElementType::InteriorStyle, 1});
        store.insert(
            phigs::ColourAttribute{phigs::ElementType::InteriorColour, phigs::Colour::fromRgb({0, 0, 1})});
        store.insert(phigs::fillArea3({{0.25, 0.25, 0}, {0.75, 0.25, 0}, {0.75, 0.75, 0}, {0.25, 0.75, 0}}));
        store.closeStructure();
        // Elements compare with the defaulted operator== of C++20, which the package enables.
        const bool same = store.elementAt(1, 1) ==
                          phigs::Element{phigs::IndexAttribute{phigs::ElementType::InteriorStyle, 1}};

        phigs::Workstation& ws = phigs.openWorkstation(1, phigs::WorkstationType::OffscreenImage);
        ws.postStructure(1, 0.5);
        phigs::vk::DisplaySettings settings;
        settings.width = 256, settings.height = 192;
        phigs::vk::WorkstationDisplay display(ws, phigs::vk::ContextSettings::fromEnvironment(), settings);
        display.update();
        if (argc > 1) phigs::writePng(display.image(), argv[1]);
        // NPC (0.5, 0.5) is pixel (96, 96): the workstation window fills the lower-left 192 x 192.
        const std::uint8_t* p = display.image().pixel(96, 96);
        const bool blue = p[0] < 30 && p[1] < 30 && p[2] > 220;
        const bool clean = display.context().validationMessages().empty();
        std::printf("consumer: %s (element compare %d, centre pixel %d %d %d, validation %s)\n",
                    same && blue && clean ? "ok" : "FAILED", same, p[0], p[1], p[2],
                    clean ? "clean" : "messages");
        return same && blue && clean ? 0 : 1;
    } catch (const std::exception& e) {
        std::fprintf(stderr, "consumer: %s\n", e.what());
        return 1;
    }
}
