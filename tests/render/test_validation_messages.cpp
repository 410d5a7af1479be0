// The validation layer's messages: collected for tests (which fail on any), and printed as they
// arrive when ContextSettings::printMessages is on (the program with PHIGS_VK_VALIDATION=1).
#include "RenderTestSupport.h"

#include <cstdlib>
#include <iostream>
#include <sstream>

namespace test_validation_messages {

using namespace phigs;
using namespace render_test;

namespace {

/// A buffer of size 0 is invalid usage the layer reports (VUID-VkBufferCreateInfo-size-00912).
void misuse(vk::Context& context) {
    VkBufferCreateInfo info{};
    info.sType = VK_STRUCTURE_TYPE_BUFFER_CREATE_INFO;
    info.size = 0;
    info.usage = VK_BUFFER_USAGE_VERTEX_BUFFER_BIT;
    info.sharingMode = VK_SHARING_MODE_EXCLUSIVE;
    VkBuffer buffer = VK_NULL_HANDLE;
    if (vkCreateBuffer(context.device(), &info, nullptr, &buffer) == VK_SUCCESS && buffer)
        vkDestroyBuffer(context.device(), buffer, nullptr);
}

}  // namespace

TEST_CASE("validation: printMessages prints every message as it arrives, and tests still see them",
          "[render][validation]") {
    std::ostringstream printed;
    std::streambuf* before = std::cerr.rdbuf(printed.rdbuf());
    std::vector<std::string> messages;
    {
        vk::ContextSettings settings = lavapipeWithValidation();
        settings.printMessages = true;
        vk::Context context(settings);
        misuse(context);
        messages = context.validationMessages();
        context.clearValidationMessages();
    }
    std::cerr.rdbuf(before);
    REQUIRE_FALSE(messages.empty());
    for (const std::string& message : messages) {
        INFO(message);
        CHECK(printed.str().find("Vulkan validation " + message) != std::string::npos);
    }

    // Without printMessages (the default) nothing is printed; the messages are collected.
    std::ostringstream quiet;
    before = std::cerr.rdbuf(quiet.rdbuf());
    {
        vk::Context context(lavapipeWithValidation());
        misuse(context);
        CHECK_FALSE(context.validationMessages().empty());
        context.clearValidationMessages();
    }
    std::cerr.rdbuf(before);
    CHECK(quiet.str().empty());
}

TEST_CASE("validation: PHIGS_VK_VALIDATION 0 or 1 turns the layer off or on over a program's default",
          "[render][validation]") {
    const char* saved = std::getenv("PHIGS_VK_VALIDATION");
    const std::string savedValue = saved ? saved : "";
    vk::ContextSettings programDefault;
    programDefault.validation = false;  // what the acsynt program starts from
    unsetenv("PHIGS_VK_VALIDATION");
    CHECK_FALSE(vk::ContextSettings::fromEnvironment(programDefault).validation);
    setenv("PHIGS_VK_VALIDATION", "1", 1);
    CHECK(vk::ContextSettings::fromEnvironment(programDefault).validation);
    setenv("PHIGS_VK_VALIDATION", "0", 1);
    CHECK_FALSE(vk::ContextSettings::fromEnvironment(lavapipeWithValidation()).validation);
    // Anything else is refused by name: "off" or "" must not turn the layer on.
    for (const char* other : {"off", "", "true", "2", "yes"}) {
        setenv("PHIGS_VK_VALIDATION", other, 1);
        CHECK_THROWS_WITH(vk::ContextSettings::fromEnvironment(programDefault),
                          Catch::Contains("PHIGS_VK_VALIDATION must be '0' or '1'"));
    }
    if (saved)
        setenv("PHIGS_VK_VALIDATION", savedValue.c_str(), 1);
    else
        unsetenv("PHIGS_VK_VALIDATION");
}

}  // namespace test_validation_messages
