// acsynt: the ACSYNT-like design program. Replays a session script headless (pictures through
// the Vulkan offscreen workstation) or runs interactively in a GLFW window; either way the
// session can be recorded as a script.
#include "acsynt/session/Session.h"
#include "phigs/input/ScriptInputSource.h"
#include "phigs/vk/Context.h"
#include "phigs/vk/WorkstationDisplay.h"

#ifdef ACSYNT_HAVE_WINDOW
#include "phigs/vk/WindowWorkstation.h"
#include "phigs/window/GlfwInputSource.h"
#endif

#include <getopt.h>

#include <cstdio>
#include <fstream>
#include <iostream>
#include <optional>

namespace {

struct Options {
    std::string script;
    std::filesystem::path output = "out";
    std::string record;
    bool window = false;
    int width = 1024, height = 768;
};

void usage(std::ostream& out) {
    out << "usage: acsynt --script FILE [--output DIR] [--record FILE] [--size WxH]\n"
           "       acsynt --window [--output DIR] [--record FILE] [--size WxH]\n"
           "  --script FILE  replay a session script headless (lavapipe), writing its snapshots\n"
           "  --output DIR   where pictures, summary.txt, acsynt.log and saved files go (default out)\n"
           "  --record FILE  write the session as a script that replays it\n"
           "  --window       interactive session in a GLFW window\n"
           "  --size WxH     screen size in pixels, 4:3 like the display surface (default 1024x768)\n";
}

std::optional<Options> parse(int argc, char** argv) {
    static const option longOptions[] = {{"script", required_argument, nullptr, 's'},
                                         {"output", required_argument, nullptr, 'o'},
                                         {"record", required_argument, nullptr, 'r'},
                                         {"window", no_argument, nullptr, 'w'},
                                         {"size", required_argument, nullptr, 'z'},
                                         {"help", no_argument, nullptr, 'h'},
                                         {nullptr, 0, nullptr, 0}};
    Options o;
    int c;
    while ((c = getopt_long(argc, argv, "s:o:r:wz:h", longOptions, nullptr)) != -1) {
        switch (c) {
            case 's':
                o.script = optarg;
                break;
            case 'o':
                o.output = optarg;
                break;
            case 'r':
                o.record = optarg;
                break;
            case 'w':
                o.window = true;
                break;
            case 'z':
                if (std::sscanf(optarg, "%dx%d", &o.width, &o.height) != 2 || o.width < 160 ||
                    o.height < 120 || o.width > 1024 || o.height > 768) {
                    std::cerr << "acsynt: --size wants WxH within 160x120 .. 1024x768, not '" << optarg
                              << "'\n";
                    return std::nullopt;
                }
                break;
            case 'h':
                usage(std::cout);
                std::exit(0);
            default:
                usage(std::cerr);
                return std::nullopt;
        }
    }
    if (optind < argc || (o.script.empty() && !o.window)) {
        usage(std::cerr);
        return std::nullopt;
    }
    return o;
}

void finish(acsynt::Session& session, const Options& o) {
    std::filesystem::create_directories(o.output);
    const auto summary = o.output / "summary.txt";
    std::ofstream(summary) << session.summary();
    const auto log = o.output / "acsynt.log";
    std::ofstream out(log);
    for (const auto& line : session.log()) out << line << "\n";
    if (!o.record.empty()) std::ofstream(o.record) << session.recording();
    for (const auto& p : session.pictures()) std::cout << p.string() << "\n";
    std::cout << summary.string() << "\n" << log.string() << "\n";
    if (!o.record.empty()) std::cout << o.record << "\n";
}

}  // namespace

int main(int argc, char** argv) {
    const auto options = parse(argc, argv);
    if (!options) return 2;
    acsynt::SessionSettings settings;
    settings.width = options->width;
    settings.height = options->height;
    settings.outputDirectory = options->output;
    try {
        if (!options->window) {
            auto script = phigs::ScriptInputSource::fromFile(options->script, acsynt::Session::directives());
            acsynt::Session session(settings, script);
            phigs::vk::ContextSettings defaults;
            defaults.validation = false;
            phigs::vk::DisplaySettings surface;
            surface.width = std::uint32_t(settings.width);
            surface.height = std::uint32_t(settings.height);
            phigs::vk::WorkstationDisplay display(
                session.workstation(), phigs::vk::ContextSettings::fromEnvironment(defaults), surface);
            session.setSnapshot([&](const std::filesystem::path& file) {
                display.update();
                phigs::writePng(display.image(), file);
            });
            session.run();
            finish(session, *options);
            return 0;
        }
#ifdef ACSYNT_HAVE_WINDOW
        settings.workstationType = phigs::WorkstationType::Window;
        phigs::vk::Context context(phigs::vk::WindowWorkstation::contextSettings());
        phigs::vk::WindowWorkstation window(context, std::uint32_t(settings.width),
                                            std::uint32_t(settings.height), "ACSYNT B-SPLINE MODULE");
        phigs::GlfwInputSource source(window.window());
        acsynt::Session session(settings, source);
        session.setSnapshot([&](const std::filesystem::path& file) {
            phigs::Image image;
            window.draw(session.picture(), &image);
            phigs::writePng(image, file);
        });
        session.setPresenter([&](const phigs::DrawList& list) { window.draw(list); });
        window.draw(session.picture());
        while (!window.shouldClose() && session.step(std::chrono::milliseconds(30))) {
        }
        finish(session, *options);
        return 0;
#else
        std::cerr << "acsynt: built without the GLFW window source\n";
        return 2;
#endif
    } catch (const std::exception& e) {
        std::cerr << "acsynt: " << e.what() << "\n";
        return 1;
    }
}
