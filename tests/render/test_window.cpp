// The window workstation under a virtual X server: open, draw a known scene, read the presented
// image back, compare with the offscreen picture of the same list, resize, close. The test starts
// its own Xvfb, so it needs no display set up beforehand.
#include "RenderTestSupport.h"
#include "VirtualDisplay.h"
#include "phigs/vk/ImageTarget.h"
#include "phigs/vk/WindowTarget.h"
#include "phigs/window/GlfwWindow.h"

#include <unistd.h>

namespace test_window {

using namespace phigs;
using namespace render_test;

namespace {

DrawList knownScene() {
    DrawList list = emptyScene();
    list.background = {0.0f, 0.0f, 0.3f};
    DrawFillArea f;
    f.contours = {{{0.1, 0.1, 0.5}, {0.9, 0.1, 0.5}, {0.5, 0.9, 0.5}}};
    f.interior.edit().style = InteriorStyle::Solid;
    f.interior.edit().colour = {1.0f, 0.5f, 0.0f};
    list.items.push_back(item(f));
    DrawPolymarker m;
    m.points = {{0.5, 0.4, 0.5}};
    m.style.edit().type = MarkerType::Circle;
    m.style.edit().scale = 4.0f;
    list.items.push_back(item(m));
    return list;
}

}  // namespace

TEST_CASE("window: a window target presents the same picture as the offscreen one", "[render][window]") {
    VirtualDisplay display;
    GlfwWindow window(200, 160, "phigs window test");
    std::vector<std::string> shutdownLog;
    vk::ContextSettings settings = vk::WindowTarget::contextSettings(window, lavapipeWithValidation());
    settings.messageLog = &shutdownLog;
    {
        vk::Context context(settings);
        REQUIRE(context.isLavapipe());
        {
            const DrawList list = knownScene();
            Image offscreen;
            {
                vk::ImageTarget ws(context, 200, 160);
                offscreen = ws.draw(list);
            }
            vk::WindowTarget target(context, window);
            Image presented;
            REQUIRE(target.draw(list, &presented));
            REQUIRE(presented.width == 200);
            REQUIRE(presented.height == 160);
            CHECK(differingPixels(presented, offscreen, 2) == 0);
            CHECK(near(at(presented, 100, 100), 255, 128, 0, 2));
            CHECK(near(at(presented, 5, 5), 0, 0, 76, 2));
            // An unchanged second frame in the window uploads nothing either.
            REQUIRE(target.draw(list));
            CHECK(target.renderer().lastFrame().uploads == 0);

            // Resize: the swapchain follows and the picture is drawn at the new size.
            const std::uint64_t damage = window.damage();
            window.resize(120, 100);
            Image resized;
            for (int attempt = 0; attempt < 20 && resized.width != 120; ++attempt) {
                window.pollEvents();
                REQUIRE(target.draw(list, &resized));
                usleep(20000);
            }
            CHECK(window.damage() > damage);  // the window says its picture was lost
            CHECK(resized.width == 120);
            CHECK(resized.height == 100);
            CHECK(near(at(resized, 60, 60), 255, 128, 0, 2));

            CHECK_FALSE(window.shouldClose());
            window.requestClose();
            CHECK(window.shouldClose());
        }
        requireNoValidationMessages(context);
    }
    // Destroying the device and instance after the window reports nothing left alive.
    for (const auto& message : shutdownLog) UNSCOPED_INFO(message);
    CHECK(shutdownLog.empty());
}

}  // namespace test_window
