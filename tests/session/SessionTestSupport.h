#pragma once
// Support for the session tests: a session on a small screen (320 x 240, the display surface's
// 4:3) driven line by line (so a test can compute where to pick from the views it set up), its
// pictures through vk::WorkstationDisplay on one shared lavapipe context, and comparison with
// reference images in tests/data/session.

#include "../render/RenderTestSupport.h"
#include "acsynt/session/Session.h"
#include "geom/Evaluate.h"
#include "phigs/input/ScriptInputSource.h"
#include "phigs/input/WindowEventMapper.h"
#include "phigs/vk/Context.h"
#include "phigs/vk/WorkstationDisplay.h"

#include <catch2/catch.hpp>

#include <cstdio>
#include <deque>
#include <filesystem>
#include <memory>
#include <string>

namespace session_test {

constexpr int width = 320, height = 240;

/// The one Vulkan context of the test program (lavapipe, validation on).
inline phigs::vk::Context& context() {
    static phigs::vk::Context shared(render_test::lavapipeWithValidation());
    return shared;
}

/// Shows a session's workstation offscreen on the small screen.
inline std::unique_ptr<phigs::vk::WorkstationDisplay> displayOf(acsynt::Session& session) {
    phigs::vk::DisplaySettings surface;
    surface.width = width;
    surface.height = height;
    return std::make_unique<phigs::vk::WorkstationDisplay>(session.workstation(), context(), surface);
}

/// An input source fed one script line at a time; it never runs dry (the test decides the end).
class LineSource : public phigs::InputSource {
public:
    void push(const std::string& line) {
        phigs::ScriptInputSource parsed(line, "test", acsynt::Session::directives());
        for (const auto& a : parsed.actions()) pending_.push_back(a);
    }
    /// An action as a window delivers it (no script line in between).
    void push(const phigs::InputAction& action) { pending_.push_back(action); }
    std::optional<phigs::InputAction> next(std::chrono::milliseconds) override {
        if (pending_.empty()) return std::nullopt;
        phigs::InputAction a = pending_.front();
        pending_.pop_front();
        return a;
    }
    bool exhausted() const override { return false; }
    std::string position() const override { return "test"; }
    bool empty() const { return pending_.empty(); }
    /// Keys typed as a window's keyboard types them (not yet accepted: no Enter).
    void type(const std::string& text) {
        for (char c : text) keys_.handle(phigs::window_event::Character{char32_t(c)});
    }
    phigs::StringEcho stringEcho() const override { return keys_.stringEcho(); }
    void startString(const std::string& text) override { keys_.startString(text); }

private:
    std::deque<phigs::InputAction> pending_;
    phigs::WindowEventMapper keys_;
};

inline std::filesystem::path outputDirectory(const std::string& name) {
    return std::filesystem::path(PHIGS_TEST_OUTPUT_DIR) / "session" / name;
}

/// A session on the small screen whose snapshots go to the output directory `name`.
struct Driver {
    explicit Driver(const std::string& name) : session(settings(name), source), display(displayOf(session)) {
        session.setSnapshot([this](const std::filesystem::path& file) { phigs::writePng(picture(), file); });
    }

    static acsynt::SessionSettings settings(const std::string& name) {
        acsynt::SessionSettings s;
        s.width = width;
        s.height = height;
        s.outputDirectory = outputDirectory(name);
        s.searchPath.push_back(std::filesystem::path(PHIGS_TEST_DATA_DIR) / "session");
        return s;
    }

    /// Delivers the lines one after the other, each handled before the next.
    void run(std::initializer_list<std::string> lines) {
        for (const std::string& line : lines) {
            source.push(line);
            while (!source.empty() && session.step(std::chrono::milliseconds(0))) {
            }
        }
    }
    /// A pick at the pixel where a world point shows in `view`.
    void pickAt(const glm::dvec3& world, int view) {
        const glm::dvec2 p = session.pixelOf(world, view);
        run({"pick " + std::to_string(p.x) + " " + std::to_string(p.y)});
    }
    phigs::Image picture() {
        display->update();
        render_test::requireNoValidationMessages(context());
        return display->image();
    }
    bool logHasError() const {
        for (const auto& line : session.log())
            if (line.rfind("ERROR: ", 0) == 0) return true;
        return false;
    }

    LineSource source;
    acsynt::Session session;
    std::unique_ptr<phigs::vk::WorkstationDisplay> display;
};

/// Compares with tests/data/session/<name>.png (PHIGS_UPDATE_REFERENCES=1 rewrites it).
inline void compareWithReference(const phigs::Image& image, const std::string& name) {
    const auto reference = std::filesystem::path(PHIGS_TEST_DATA_DIR) / "session" / (name + ".png");
    const auto out = std::filesystem::path(PHIGS_TEST_OUTPUT_DIR) / "session";
    std::filesystem::create_directories(out);
    phigs::writePng(image, out / (name + ".png"));
    const char* update = std::getenv("PHIGS_UPDATE_REFERENCES");
    if (update && std::string(update) == "1") {
        phigs::writePng(image, reference);
        WARN("reference rewritten: " << reference.string());
        return;
    }
    INFO("reference " << reference.string() << " (PHIGS_UPDATE_REFERENCES=1 regenerates it)");
    REQUIRE(std::filesystem::exists(reference));
    const phigs::Image expected = phigs::readPng(reference);
    REQUIRE(expected.width == image.width);
    REQUIRE(expected.height == image.height);
    phigs::Image diff;
    const std::size_t differing = render_test::differingPixels(image, expected, 24, &diff);
    const auto allowed = std::size_t(0.003 * image.width * image.height);
    if (differing > allowed) phigs::writePng(diff, out / (name + "_diff.png"));
    INFO(differing << " pixels differ, " << allowed << " allowed");
    CHECK(differing <= allowed);
}

/// The index of the component named `name` in `model`; fails the test when there is none.
inline int componentIndex(const acsynt::Model& model, const std::string& name) {
    for (std::size_t i = 0; i < model.components.size(); ++i)
        if (model.components[i].name == name) return int(i);
    FAIL("no component " << name);
    return -1;
}
/// The same in the session's current model.
inline int componentIndex(const acsynt::Session& s, const std::string& name) {
    return componentIndex(s.models().current(), name);
}
/// Picks the current model's component `name` at its surface point (u, w), pick device 1.
inline void pickOn(Driver& d, const std::string& name, double u, double w) {
    const acsynt::Model& m = d.session.models().current();
    d.pickAt(geom::evaluate(m.components[std::size_t(componentIndex(m, name))].surface, u, w), 1);
}

/// The script line `valuator D V` that sets the marker's u (D = 1) or w (D = 2), the component's
/// own parameters, at `fraction` of the reference patch's span.
inline std::string markerValuator(const acsynt::Session& s, int device, double fraction) {
    REQUIRE(s.reference());
    const acsynt::ReferencePoint& r = *s.reference();
    const acsynt::Patch& p =
        s.models().current().components[std::size_t(r.component)].patches.patches[std::size_t(r.patch - 1)];
    const double v = device == 1 ? p.u0 + fraction * (p.u1 - p.u0) : p.w0 + fraction * (p.w1 - p.w0);
    char text[64];
    std::snprintf(text, sizeof text, "valuator %d %.17g", device, v);
    return text;
}

}  // namespace session_test
