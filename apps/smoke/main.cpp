// phigs-smoke: renders the known triangle headless (lavapipe by default), writes it as a PNG and
// prints the file's path. It proves the tool chain end to end until the ACSYNT demo replaces it.
#include "phigs/image/Image.h"
#include "phigs/vk/Context.h"
#include "phigs/vk/OffscreenTarget.h"
#include "phigs/vk/SmokeRenderer.h"

#include <filesystem>
#include <iostream>
#include <string_view>

int main(int argc, char** argv) {
    std::filesystem::path output = "out/smoke.png";
    for (int i = 1; i < argc; ++i) {
        const std::string_view arg = argv[i];
        if (arg == "--output" && i + 1 < argc) {
            output = argv[++i];
        } else {
            std::cerr << "usage: phigs-smoke [--output FILE.png]\n";
            return 2;
        }
    }
    try {
        using namespace phigs;
        vk::Context context(vk::ContextSettings::fromEnvironment());
        Image image;
        {
            vk::OffscreenTarget target(context, 256, 256);
            vk::SmokeRenderer renderer(context, target);
            image = renderer.render(vk::SmokeTriangle{});
        }
        for (const auto& message : context.validationMessages())
            std::cerr << "validation " << message << '\n';
        if (!context.validationMessages().empty()) return 1;
        if (output.has_parent_path()) std::filesystem::create_directories(output.parent_path());
        writePng(image, output);
        std::cout << "device: " << context.properties().deviceName << '\n';
        std::cout << std::filesystem::absolute(output).string() << '\n';
    } catch (const std::exception& e) {
        std::cerr << "phigs-smoke: " << e.what() << '\n';
        return 1;
    }
    return 0;
}
