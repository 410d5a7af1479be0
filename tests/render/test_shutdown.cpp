// Clean shutdown: after every workstation type has drawn and been destroyed, destroying the
// device and instance reports no object still alive; and a leak would be reported.
#include "RenderTestSupport.h"
#include "phigs/vk/HardcopyTarget.h"
#include "phigs/vk/ImageTarget.h"

namespace test_shutdown {

using namespace phigs;
using namespace render_test;

TEST_CASE("shutdown: workstations and the context leave no Vulkan object behind", "[render][shutdown]") {
    std::vector<std::string> log;
    {
        vk::ContextSettings settings = lavapipeWithValidation();
        settings.messageLog = &log;
        vk::Context context(settings);
        DrawList list = emptyScene();
        DrawPolyline l;
        l.points = {{0.1, 0.1, 0.5}, {0.9, 0.9, 0.5}};
        list.items.push_back(item(l));
        {
            vk::ImageTarget ws(context, 64, 64);
            ws.draw(list);
            vk::HardcopyTarget hardcopy(context, 32, 32,
                                        std::filesystem::path(PHIGS_TEST_OUTPUT_DIR) / "shutdown.png");
            hardcopy.update(list);
        }
    }
    for (const auto& message : log) UNSCOPED_INFO(message);
    CHECK(log.empty());
}

TEST_CASE("shutdown: a leaked buffer is reported when the device is destroyed", "[render][shutdown]") {
    std::vector<std::string> log;
    {
        vk::ContextSettings settings = lavapipeWithValidation();
        settings.messageLog = &log;
        vk::Context context(settings);
        VkBufferCreateInfo info{};
        info.sType = VK_STRUCTURE_TYPE_BUFFER_CREATE_INFO;
        info.size = 64;
        info.usage = VK_BUFFER_USAGE_VERTEX_BUFFER_BIT;
        VkBuffer leaked = VK_NULL_HANDLE;
        REQUIRE(vkCreateBuffer(context.device(), &info, nullptr, &leaked) == VK_SUCCESS);
        REQUIRE(context.validationMessages().empty());
    }
    REQUIRE_FALSE(log.empty());
    CHECK(log.front().find("VkBuffer") != std::string::npos);
}

}  // namespace test_shutdown
