// The whole tool chain in one test: validation layer on, lavapipe chosen explicitly, a pipeline
// from embedded SPIR-V, an offscreen render, a readback, and pixels checked inside and outside.
#include "phigs/image/Image.h"
#include "phigs/vk/Context.h"
#include "phigs/vk/OffscreenTarget.h"
#include "phigs/vk/SmokeRenderer.h"

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <string>

namespace test_smoke {

using namespace phigs;

namespace {

vk::ContextSettings lavapipeWithValidation() {
    vk::ContextSettings settings;
    settings.device = vk::DevicePreference::Lavapipe;
    settings.validation = true;
    return settings;
}

void requireNoValidationMessages(const vk::Context& context) {
    const auto messages = context.validationMessages();
    for (const auto& message : messages) UNSCOPED_INFO(message);
    REQUIRE(messages.empty());
}

bool near(const std::uint8_t* px, int r, int g, int b) {
    return std::abs(px[0] - r) <= 1 && std::abs(px[1] - g) <= 1 && std::abs(px[2] - b) <= 1 && px[3] == 255;
}

}  // namespace

TEST_CASE("smoke: lavapipe renders the known triangle with no validation message", "[render][smoke]") {
    vk::Context context(lavapipeWithValidation());
    REQUIRE(context.isLavapipe());
    {
        vk::OffscreenTarget target(context, 64, 64);
        vk::SmokeRenderer renderer(context, target);
        vk::SmokeTriangle triangle;
        triangle.corners = {glm::vec2(0.0f, -0.8f), glm::vec2(0.8f, 0.8f), glm::vec2(-0.8f, 0.8f)};
        triangle.color = {1.0f, 0.5f, 0.0f, 1.0f};
        triangle.background = {0.0f, 0.0f, 0.2f, 1.0f};
        const Image image = renderer.render(triangle);
        REQUIRE(image.width == 64);
        REQUIRE(image.height == 64);

        // Inside: the centroid and points near each corner, pulled towards the centroid.
        CHECK(near(image.pixel(32, 37), 255, 128, 0));
        CHECK(near(image.pixel(32, 10), 255, 128, 0));
        CHECK(near(image.pixel(55, 55), 255, 128, 0));
        CHECK(near(image.pixel(8, 55), 255, 128, 0));
        // Outside: the image corners and the two flanks of the apex.
        for (auto [x, y] : {std::pair{0, 0}, {63, 0}, {0, 63}, {63, 63}, {10, 20}, {54, 20}, {32, 60}})
            CHECK(near(image.pixel(x, y), 0, 0, 51));
        // Every pixel whose centre lies more than half a pixel inside the triangle has its colour,
        // every pixel more than half a pixel outside has the background; only the rim may differ.
        const glm::vec2 px[3] = {(triangle.corners[0] + 1.0f) * 32.0f, (triangle.corners[1] + 1.0f) * 32.0f,
                                 (triangle.corners[2] + 1.0f) * 32.0f};
        int inside = 0, outside = 0;
        for (std::uint32_t y = 0; y < 64; ++y)
            for (std::uint32_t x = 0; x < 64; ++x) {
                const glm::vec2 c(x + 0.5f, y + 0.5f);
                float minDistance = 1e9f;
                for (int e = 0; e < 3; ++e) {
                    const glm::vec2 a = px[e], b = px[(e + 1) % 3];
                    const glm::vec2 d = b - a;
                    // Corners run clockwise on screen (y down), so inside is where this is positive.
                    const float distance = (d.x * (c.y - a.y) - d.y * (c.x - a.x)) / std::hypot(d.x, d.y);
                    minDistance = std::min(minDistance, distance);
                }
                if (minDistance > 0.5f) {
                    ++inside;
                    CHECK(near(image.pixel(x, y), 255, 128, 0));
                } else if (minDistance < -0.5f) {
                    ++outside;
                    CHECK(near(image.pixel(x, y), 0, 0, 51));
                }
            }
        CHECK(inside > 1000);
        CHECK(outside > 2000);

        const auto out = std::filesystem::path(PHIGS_TEST_OUTPUT_DIR) / "smoke_triangle.png";
        writePng(image, out);
        const Image back = readPng(out);
        REQUIRE(back.rgba == image.rgba);
    }
    requireNoValidationMessages(context);
}

TEST_CASE("smoke: the validation messenger really reports misuse", "[render][smoke]") {
    // A zero-sized buffer breaks VUID-VkBufferCreateInfo-size-00912; if this is not reported, a
    // clean run of the other render tests would prove nothing.
    vk::Context context(lavapipeWithValidation());
    VkBufferCreateInfo info{};
    info.sType = VK_STRUCTURE_TYPE_BUFFER_CREATE_INFO;
    info.size = 0;
    info.usage = VK_BUFFER_USAGE_TRANSFER_DST_BIT;
    VkBuffer buffer = VK_NULL_HANDLE;
    vkCreateBuffer(context.device(), &info, nullptr, &buffer);
    if (buffer) vkDestroyBuffer(context.device(), buffer, nullptr);
    const auto messages = context.validationMessages();
    REQUIRE_FALSE(messages.empty());
    CHECK(messages.front().find("size") != std::string::npos);
}

TEST_CASE("smoke: PNG reading names the file when it is not a PNG", "[render][smoke]") {
    const auto bad = std::filesystem::path(PHIGS_TEST_OUTPUT_DIR) / "not_a_png.png";
    {
        std::FILE* f = std::fopen(bad.c_str(), "wb");
        std::fputs("hello", f);
        std::fclose(f);
    }
    REQUIRE_THROWS_WITH(readPng(bad), Catch::Contains("not_a_png.png"));
}

}  // namespace test_smoke
