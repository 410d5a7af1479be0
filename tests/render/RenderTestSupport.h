#pragma once

// Shared by the render tests: a lavapipe context with validation, scene helpers, and the tolerant
// comparison with reference images in tests/data/render (PHIGS_UPDATE_REFERENCES=1 rewrites them).

#include "phigs/image/Image.h"
#include "phigs/traverse/DrawList.h"
#include "phigs/vk/Context.h"

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <string>

namespace render_test {

inline phigs::vk::ContextSettings lavapipeWithValidation() {
    phigs::vk::ContextSettings settings;
    settings.device = phigs::vk::DevicePreference::Lavapipe;
    settings.validation = true;
    return settings;
}

inline void requireNoValidationMessages(const phigs::vk::Context& context) {
    const auto messages = context.validationMessages();
    for (const auto& message : messages) UNSCOPED_INFO(message);
    REQUIRE(messages.empty());
}

/// A draw list with one identity view (world = NPC) and a dark grey background.
inline phigs::DrawList emptyScene() {
    phigs::DrawList list;
    list.views.push_back(phigs::DrawView{});
    list.background = {0.1f, 0.1f, 0.1f};
    return list;
}

/// A solid fill area over [x0, x1] x [y0, y1] at depth z, counter-clockwise seen from +z.
inline phigs::DrawFillArea solidRectangle(double x0, double y0, double x1, double y1, double z,
                                          glm::vec3 colour) {
    phigs::DrawFillArea f;
    f.contours = {{{x0, y0, z}, {x1, y0, z}, {x1, y1, z}, {x0, y1, z}}};
    f.interior.edit().style = phigs::InteriorStyle::Solid;
    f.interior.edit().colour = colour;
    return f;
}

template <class Primitive>
phigs::DrawItem item(Primitive primitive, int view = 0) {
    phigs::DrawItem i;
    i.primitive = std::move(primitive);
    i.context.edit().viewIndex = view;
    return i;
}

/// Pixels whose largest channel difference exceeds `threshold`.
inline std::size_t differingPixels(const phigs::Image& a, const phigs::Image& b, int threshold,
                                   phigs::Image* diff = nullptr) {
    if (diff) *diff = phigs::Image(a.width, a.height);
    std::size_t count = 0;
    for (std::uint32_t y = 0; y < a.height; ++y)
        for (std::uint32_t x = 0; x < a.width; ++x) {
            const std::uint8_t *p = a.pixel(x, y), *q = b.pixel(x, y);
            int worst = 0;
            for (int c = 0; c < 3; ++c) worst = std::max(worst, std::abs(int(p[c]) - int(q[c])));
            if (worst > threshold) ++count;
            if (diff) {
                std::uint8_t* d = diff->pixel(x, y);
                d[0] = worst > threshold ? 255 : std::uint8_t(p[0] / 4);
                d[1] = worst > threshold ? 0 : std::uint8_t(p[1] / 4);
                d[2] = worst > threshold ? 0 : std::uint8_t(p[2] / 4);
                d[3] = 255;
            }
        }
    return count;
}

/// Compares with tests/data/render/<name>.png: a pixel differs when a channel is off by more than
/// `threshold`; at most `allowedFraction` of the pixels may differ. On failure the picture and a
/// diff (differing pixels red) go to PHIGS_TEST_OUTPUT_DIR.
inline void compareWithReference(const phigs::Image& image, const std::string& name, int threshold = 24,
                                 double allowedFraction = 0.003) {
    const auto reference = std::filesystem::path(PHIGS_TEST_DATA_DIR) / "render" / (name + ".png");
    const auto out = std::filesystem::path(PHIGS_TEST_OUTPUT_DIR);
    std::filesystem::create_directories(out);
    phigs::writePng(image, out / (name + ".png"));
    const char* update = std::getenv("PHIGS_UPDATE_REFERENCES");
    if (update && std::string(update) == "1") {
        std::filesystem::create_directories(reference.parent_path());
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
    const std::size_t differing = differingPixels(image, expected, threshold, &diff);
    const auto allowed = std::size_t(allowedFraction * image.width * image.height);
    if (differing > allowed) phigs::writePng(diff, out / (name + "_diff.png"));
    INFO(differing << " pixels differ, " << allowed << " allowed; see "
                   << (out / (name + "_diff.png")).string());
    CHECK(differing <= allowed);
}

/// Colour of a pixel (x right, y down) as ints.
struct Rgb {
    int r, g, b;
};
inline Rgb at(const phigs::Image& image, std::uint32_t x, std::uint32_t y) {
    const std::uint8_t* p = image.pixel(x, y);
    return {p[0], p[1], p[2]};
}
inline bool near(Rgb c, int r, int g, int b, int tolerance = 8) {
    return std::abs(c.r - r) <= tolerance && std::abs(c.g - g) <= tolerance && std::abs(c.b - b) <= tolerance;
}
/// Whether the pixel holding position `p` (pixels, y down) shows the colour `rgb` (0..1 each).
inline bool shows(const phigs::Image& image, glm::dvec2 p, glm::dvec3 rgb, int tolerance = 12) {
    const Rgb c = at(image, std::uint32_t(p.x), std::uint32_t(p.y));
    return near(c, int(std::lround(rgb.x * 255)), int(std::lround(rgb.y * 255)),
                int(std::lround(rgb.z * 255)), tolerance);
}

}  // namespace render_test
