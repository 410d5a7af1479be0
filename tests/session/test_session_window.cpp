// The interactive session in a GLFW window under a virtual X server (started by the test): clicks
// on the menu panel, on the surface and on the pad, typed text and a slider drag drive DEFINE
// POINT through the window input source, exactly as the window's callbacks deliver them.
#include "SessionTestSupport.h"

#ifdef ACSYNT_HAVE_WINDOW

#include "geom/Evaluate.h"
#include "phigs/vk/Context.h"
#include "phigs/vk/WindowWorkstation.h"
#include "phigs/window/GlfwInputSource.h"

#include <signal.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

extern char** environ;

namespace {

/// An Xvfb server on a free display number for the lifetime of the object.
class VirtualDisplay {
public:
    VirtualDisplay() {
        int fds[2];
        REQUIRE(pipe(fds) == 0);
        const std::string fd = std::to_string(fds[1]);
        const char* argv[] = {"Xvfb",       "-displayfd", fd.c_str(), "-screen", "0",
                              "640x480x24", "-nolisten",  "tcp",      nullptr};
        posix_spawn_file_actions_t actions;
        posix_spawn_file_actions_init(&actions);
        posix_spawn_file_actions_addclose(&actions, fds[0]);
        const int rc =
            posix_spawnp(&pid_, "Xvfb", &actions, nullptr, const_cast<char* const*>(argv), environ);
        posix_spawn_file_actions_destroy(&actions);
        close(fds[1]);
        REQUIRE(rc == 0);  // install the Debian package 'xvfb'
        std::string number;
        char c;
        while (read(fds[0], &c, 1) == 1 && c != '\n') number += c;
        close(fds[0]);
        REQUIRE(!number.empty());
        previous_ = std::getenv("DISPLAY") ? std::getenv("DISPLAY") : "";
        setenv("DISPLAY", (":" + number).c_str(), 1);
    }
    ~VirtualDisplay() {
        if (previous_.empty())
            unsetenv("DISPLAY");
        else
            setenv("DISPLAY", previous_.c_str(), 1);
        if (pid_ > 0) {
            kill(pid_, SIGTERM);
            waitpid(pid_, nullptr, 0);
        }
    }

private:
    pid_t pid_ = -1;
    std::string previous_;
};

}  // namespace

TEST_CASE("interactive session in a window: menu clicks, surface clicks, pad and slider drive DEFINE POINT") {
    using namespace phigs::window_event;
    VirtualDisplay display;
    phigs::vk::ContextSettings base;
    base.device = phigs::vk::DevicePreference::Lavapipe;
    base.validation = false;
    phigs::vk::Context context(phigs::vk::WindowWorkstation::contextSettings(base));
    phigs::vk::WindowWorkstation window(context, session_test::width, session_test::height, "acsynt test");
    phigs::GlfwInputSource source(window.window());
    acsynt::Session session(session_test::Driver::settings("window"), source);
    int frames = 0;
    session.setPresenter([&](const phigs::DrawList& list) {
        window.draw(list);
        ++frames;
    });
    const acsynt::ScreenLayout& layout = session.layout();

    auto settle = [&] {
        for (int i = 0; i < 6; ++i) session.step(std::chrono::milliseconds(5));
    };
    auto click = [&](glm::dvec2 p) {
        source.post(ButtonPress{Button::Left, p, false});
        source.post(ButtonRelease{Button::Left, p});
        settle();
    };
    auto menu = [&](const std::string& item) {
        const auto& items = session.menuItems();
        const auto it = std::find(items.begin(), items.end(), item);
        REQUIRE(it != items.end());
        const phigs::ChoicePanel panel{1, layout.menuFor(items.size()).echoVolume(), items};
        const auto [a, b] = panel.row(int(it - items.begin()) + 1);
        click((a + b) / 2.0);
    };
    auto type = [&](const std::string& text) {
        for (char c : text) source.post(Character{char32_t(c)});
        source.post(KeyPress{Key::Enter, 0});
        settle();
    };

    menu("FILE");
    CHECK(session.menuTitle() == "FILE");
    menu("READ_MODEL");
    CHECK(session.message() == "ENTER MODEL FILE NAME");
    type("transport.acm");
    REQUIRE(session.models().size() == 1);
    menu("RETURN");
    menu("CURVE_MAP");
    menu("DEFINE_POINT");
    CHECK(session.message() == "SELECT COMPONENT FOR MAPPING");

    const acsynt::Component& wing = session.models().current().components[1];
    REQUIRE(wing.name == "right_wing");
    const glm::dvec3 point = geom::evaluate(wing.surface, 0.5, 0.3);
    click(session.pixelOf(point, 1));
    CHECK(session.message() == "SELECT REFERENCE PATCH TO MAP");
    click(session.pixelOf(point, 1));
    CHECK(session.message() == "ACCEPT OR REJECT PATCH");
    menu("ACCEPT");
    REQUIRE(session.reference());
    const acsynt::Patch* patch = wing.patches.find(0.5, 0.3);
    REQUIRE(patch);
    CHECK(session.reference()->patch == patch->number);

    click(layout.padButton(5).centre());  // the centre button: the middle of the patch
    CHECK(session.reference()->u == Approx((patch->u0 + patch->u1) / 2));
    CHECK(session.reference()->w == Approx((patch->w0 + patch->w1) / 2));
    click(layout.padButton(6).centre());  // east: u up by an eighth
    CHECK(session.reference()->u == Approx((patch->u0 + patch->u1) / 2 + (patch->u1 - patch->u0) / 8));

    // A drag in the W slider: the value at the release point.
    const acsynt::PixelBox slider = layout.slider(2);
    const glm::dvec2 from{slider.x0 + 2, slider.centre().y},
        to{slider.x0 + 0.25 * (slider.x1 - slider.x0), slider.centre().y};
    source.post(ButtonPress{Button::Left, from, false});
    source.post(CursorMove{to});
    source.post(ButtonRelease{Button::Left, to});
    settle();
    const phigs::ValuatorSlider model{2, slider.echoVolume(), 0, 1};
    CHECK(session.reference()->w == Approx(patch->w0 + model.valueAt(to) * (patch->w1 - patch->w0)));

    click(layout.padButton(10).centre());  // DONE
    CHECK(session.message().rfind("REFERENCE POINT U = ", 0) == 0);
    CHECK(frames > 10);
    for (const auto& line : session.log()) {
        INFO(line);
        CHECK(line.rfind("ERROR: ", 0) != 0);
    }
}

#endif
