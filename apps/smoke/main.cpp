// phigs-smoke: renders the known triangle headless (lavapipe by default), writes it as a PNG and
// prints the file's path. It proves the tool chain end to end until the ACSYNT demo replaces it.
// With --scene FILE.png it also draws a small PHIGS scene through the real renderer.
#include "phigs/image/Image.h"
#include "phigs/vk/Context.h"
#include "phigs/vk/ImageTarget.h"
#include "phigs/vk/OffscreenTarget.h"
#include "phigs/vk/SmokeRenderer.h"

#include <filesystem>
#include <iostream>
#include <string_view>

namespace {

/// A fill area set with a hole and edges, stroke text and markers: the renderer's main families.
phigs::DrawList demoScene() {
    using namespace phigs;
    DrawList list;
    list.views.push_back(DrawView{});
    list.background = {0.05f, 0.05f, 0.15f};
    DrawFillArea frame;
    frame.contours = {{{0.1, 0.1, 0.5}, {0.9, 0.1, 0.5}, {0.9, 0.7, 0.5}, {0.1, 0.7, 0.5}},
                      {{0.3, 0.25, 0.5}, {0.7, 0.25, 0.5}, {0.5, 0.55, 0.5}}};
    frame.interior.edit().style = InteriorStyle::Solid;
    frame.interior.edit().colour = {1.0f, 0.5f, 0.0f};
    frame.edges.edit().visible = true;
    frame.edges.edit().width = 2.0f;
    DrawItem fill;
    fill.primitive = frame;
    list.items.push_back(fill);
    DrawText title;
    title.text = "PHIGS on Vulkan";
    title.position = {0.5, 0.8, 0.5};
    title.style.edit().height = 0.06;
    title.style.edit().horizontal = HorizontalAlignment::Centre;
    DrawItem text;
    text.primitive = title;
    list.items.push_back(text);
    DrawPolymarker stars;
    stars.points = {{0.2, 0.9, 0.5}, {0.8, 0.9, 0.5}};
    stars.style.edit().scale = 3.0f;
    DrawItem markers;
    markers.primitive = stars;
    list.items.push_back(markers);
    return list;
}

}  // namespace

int main(int argc, char** argv) {
    std::filesystem::path output = "out/smoke.png";
    std::filesystem::path scene;
    for (int i = 1; i < argc; ++i) {
        const std::string_view arg = argv[i];
        if (arg == "--output" && i + 1 < argc) {
            output = argv[++i];
        } else if (arg == "--scene" && i + 1 < argc) {
            scene = argv[++i];
        } else {
            std::cerr << "usage: phigs-smoke [--output FILE.png] [--scene FILE.png]\n";
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
        if (!scene.empty()) {
            vk::ImageTarget workstation(context, 256, 256);
            if (scene.has_parent_path()) std::filesystem::create_directories(scene.parent_path());
            workstation.drawToPng(demoScene(), scene);
        }
        for (const auto& message : context.validationMessages())
            std::cerr << "validation " << message << '\n';
        if (!context.validationMessages().empty()) return 1;
        if (output.has_parent_path()) std::filesystem::create_directories(output.parent_path());
        writePng(image, output);
        std::cout << "device: " << context.properties().deviceName << '\n';
        std::cout << std::filesystem::absolute(output).string() << '\n';
        if (!scene.empty()) std::cout << std::filesystem::absolute(scene).string() << '\n';
    } catch (const std::exception& e) {
        std::cerr << "phigs-smoke: " << e.what() << '\n';
        return 1;
    }
    return 0;
}
