#include "phigs/core/ColourModels.h"
#include "phigs/store/ArchiveFile.h"
#include "phigs/view/RealizedLighting.h"
#include "phigs/view/WorkstationTables.h"

#include <catch2/catch.hpp>

#include <glm/common.hpp>
#include <glm/geometric.hpp>

#include <cmath>
#include <random>

namespace test_colour_models {

using namespace phigs;

namespace {

bool near(const glm::dvec3& a, const glm::dvec3& b, double eps = 1e-9) {
    return glm::all(glm::lessThanEqual(glm::abs(a - b), glm::dvec3(eps)));
}

glm::dvec3 randomUnit(std::mt19937& rng) {
    std::uniform_real_distribution<double> u(0.0, 1.0);
    return {u(rng), u(rng), u(rng)};
}

/// HSV to RGB as Foley et al. (1990) give it, by hue sector: the reference the tests compare with.
glm::dvec3 sectorHsv(double h, double s, double v) {
    const double f6 = h * 6.0;
    const int sector = static_cast<int>(std::floor(f6)) % 6;
    const double f = f6 - std::floor(f6);
    const double p = v * (1 - s), q = v * (1 - s * f), t = v * (1 - s * (1 - f));
    switch (sector) {
        case 0:
            return {v, t, p};
        case 1:
            return {q, v, p};
        case 2:
            return {p, v, t};
        case 3:
            return {p, q, v};
        case 4:
            return {t, p, v};
        default:
            return {v, p, q};
    }
}

}  // namespace

TEST_CASE("colour models: HSV and HLS are exact inverses of RGB", "[colour]") {
    std::mt19937 rng(20261203);
    std::uniform_real_distribution<double> u(0.0, 1.0);
    for (int i = 0; i < 2000; ++i) {
        const glm::dvec3 rgb = randomUnit(rng);
        for (ColourModel m : {ColourModel::Hsv, ColourModel::Hls, ColourModel::Cieluv}) {
            const glm::dvec3 c = fromRgb(m, rgb);
            CHECK(near(toRgb(m, c), rgb, 1e-12));
            if (m != ColourModel::Cieluv) CHECK(glm::all(glm::greaterThanEqual(c, glm::dvec3(0.0))));
            if (m != ColourModel::Cieluv) CHECK(glm::all(glm::lessThan(c, glm::dvec3(1.0 + 1e-12))));
        }
        // A canonical HSV / HLS colour (defined hue) comes back as given.
        const glm::dvec3 hsv{u(rng) * 0.999, 0.01 + 0.99 * u(rng), 0.01 + 0.99 * u(rng)};
        CHECK(near(fromRgb(ColourModel::Hsv, toRgb(ColourModel::Hsv, hsv)), hsv, 1e-9));
        CHECK(near(toRgb(ColourModel::Hsv, hsv), sectorHsv(hsv.x, hsv.y, hsv.z), 1e-12));
        const glm::dvec3 hls{u(rng) * 0.999, 0.01 + 0.98 * u(rng), 0.01 + 0.99 * u(rng)};
        CHECK(near(fromRgb(ColourModel::Hls, toRgb(ColourModel::Hls, hls)), hls, 1e-9));
        // HLS and HSV name the same colours: HLS lightness l, saturation s is HSV value
        // l + s min(l, 1 - l) (Foley et al. 1990, 13.3.5).
        const double v = hls.y + hls.z * std::min(hls.y, 1.0 - hls.y);
        const double sv = v > 0 ? 2.0 * (1.0 - hls.y / v) : 0.0;
        CHECK(near(toRgb(ColourModel::Hls, hls), toRgb(ColourModel::Hsv, {hls.x, sv, v}), 1e-12));
    }
    // Primaries and greys.
    CHECK(near(toRgb(ColourModel::Hsv, {0.0, 1, 1}), {1, 0, 0}));
    CHECK(near(toRgb(ColourModel::Hsv, {1.0 / 3, 1, 1}), {0, 1, 0}));
    CHECK(near(toRgb(ColourModel::Hls, {2.0 / 3, 0.5, 1}), {0, 0, 1}));
    CHECK(near(fromRgb(ColourModel::Hsv, {0.4, 0.4, 0.4}), {0, 0, 0.4}));
    CHECK(near(fromRgb(ColourModel::Hls, {0.4, 0.4, 0.4}), {0, 0.4, 0}));
}

TEST_CASE("colour models: CIELUV against the D65 reference white", "[colour]") {
    const glm::dvec3 white = fromRgb(ColourModel::Cieluv, glm::dvec3(1.0));
    CHECK(std::abs(white.x - 0.1978) < 1e-4);
    CHECK(std::abs(white.y - 0.4683) < 1e-4);
    CHECK(std::abs(white.z - 1.0) < 1e-6);
    // Black keeps the white point's chromaticity; a grey is white's chromaticity at its luminance.
    CHECK(near(fromRgb(ColourModel::Cieluv, glm::dvec3(0.0)), {white.x, white.y, 0.0}));
    std::mt19937 rng(4711);
    std::uniform_real_distribution<double> u(0.0, 1.0);
    for (int i = 0; i < 500; ++i) {
        const double y = u(rng);
        CHECK(near(fromRgb(ColourModel::Cieluv, glm::dvec3(y)), {white.x, white.y, y}, 1e-12));
        CHECK(near(toRgb(ColourModel::Cieluv, {white.x, white.y, y}), glm::dvec3(y), 1e-12));
        // Y is luminance: BT.709 weights of the RGB.
        const glm::dvec3 rgb = randomUnit(rng);
        CHECK(std::abs(fromRgb(ColourModel::Cieluv, rgb).z - glm::dot(rgb, {0.2126, 0.7152, 0.0722})) <
              1e-12);
    }
    // Outside the gamut: drawn clamped; v' = 0 is black.
    const glm::dvec3 out = clampedRgb(ColourModel::Cieluv, {0.6, 0.1, 1.0});
    CHECK(glm::all(glm::greaterThanEqual(out, glm::dvec3(0.0))));
    CHECK(glm::all(glm::lessThanEqual(out, glm::dvec3(1.0))));
    CHECK(near(toRgb(ColourModel::Cieluv, {0.3, 0.0, 1.0}), glm::dvec3(0.0)));
}

TEST_CASE("colour models: table entries keep their model, draw as clamped RGB", "[colour]") {
    std::mt19937 rng(99);
    ColourTable table(64);
    for (int i = 0; i < 300; ++i) {
        const auto model = static_cast<ColourModel>(1 + i % 4);
        const glm::dvec3 c = randomUnit(rng);
        const int index = 8 + i % 50;
        table.set(index, c, nullptr, model);
        const Colour given = table.given(index);
        CHECK(given.model == model);
        CHECK(given.rgb == c);
        CHECK(near(table.get(index), clampedRgb(model, c)));
        CHECK(near(table.resolve(Colour::indexed(index)), table.get(index)));
        CHECK(near(table.resolve(Colour::inModel(model, c)), clampedRgb(model, c)));
    }
    CHECK(Colour::inModel(ColourModel::Hsv, {0.5, 0.5, 0.5}) !=
          Colour::inModel(ColourModel::Hls, {0.5, 0.5, 0.5}));
}

TEST_CASE("colour models: direct colours keep their model through an archive", "[colour][archive]") {
    std::mt19937 rng(5);
    for (int i = 0; i < 50; ++i) {
        const auto model = static_cast<ColourModel>(1 + i % 4);
        const Colour colour = Colour::inModel(model, randomUnit(rng));
        const std::map<int, std::vector<Element>> contents{
            {1,
             {ColourAttribute{ElementType::InteriorColour, colour},
              ColourAttribute{ElementType::EdgeColour, Colour::indexed(i)}}}};
        const auto back = ArchiveFile::decode(ArchiveFile::encode(contents), "test", nullptr);
        REQUIRE(back.at(1).size() == 2);
        CHECK(back.at(1)[1] == contents.at(1)[1]);
        const auto* a = std::get_if<ColourAttribute>(&back.at(1)[0]);
        REQUIRE(a);
        CHECK(a->colour.model == model);
        CHECK(near(a->colour.rgb, colour.rgb, 1e-15));
    }
}

TEST_CASE("realized lights and depth cues differ from the set values exactly where the rule says",
          "[colour][lights]") {
    std::mt19937 rng(31);
    std::uniform_real_distribution<double> u(-1.0, 2.0);
    auto f = [&] { return static_cast<float>(u(rng)); };
    for (int i = 0; i < 1000; ++i) {
        Light l;
        l.type = static_cast<LightType>(1 + i % 4);
        l.colour = {f(), f(), f()};
        l.position = {u(rng), u(rng), u(rng)};
        l.direction = i % 7 == 0 ? glm::dvec3(0.0) : glm::dvec3(u(rng), u(rng), u(rng));
        l.attenuation = {f(), f()};
        l.concentration = f() * 100.0f;
        l.spreadAngle = f() * 3.0f;
        const Light r = realized(l);
        for (int k = 0; k < 3; ++k)
            CHECK(r.colour[k] == (l.colour[k] < 0 ? 0.0f : l.colour[k] > 1 ? 1.0f : l.colour[k]));
        CHECK(r.type == l.type);
        CHECK(r.position == l.position);
        CHECK(std::abs(glm::length(r.direction) - 1.0) < 1e-12);
        if (l.direction == glm::dvec3(0.0)) CHECK(r.direction == glm::dvec3(0, 0, -1));
        for (int k = 0; k < 2; ++k) CHECK(r.attenuation[k] == std::max(l.attenuation[k], 0.0f));
        CHECK(r.concentration == std::clamp(l.concentration, 0.0f, 128.0f));
        CHECK(r.spreadAngle == std::clamp(l.spreadAngle, 0.0f, 3.14159265f));
        CHECK((r == l) == (l.colour == glm::clamp(l.colour, 0.0f, 1.0f) && glm::length(l.direction) == 1.0 &&
                           l.attenuation == glm::max(l.attenuation, 0.0f) && l.concentration >= 0 &&
                           l.concentration <= 128 && l.spreadAngle >= 0 && l.spreadAngle <= 3.14159265f));

        DepthCue d;
        d.enabled = i % 2;
        d.frontPlane = u(rng), d.backPlane = u(rng);
        d.frontScale = f(), d.backScale = f();
        d.colour = {f(), f(), f()};
        const DepthCue c = realized(d);
        const double front = std::clamp(d.frontPlane, 0.0, 1.0), back = std::clamp(d.backPlane, 0.0, 1.0);
        const float fs = std::clamp(d.frontScale, 0.0f, 1.0f), bs = std::clamp(d.backScale, 0.0f, 1.0f);
        CHECK(c.enabled == d.enabled);
        CHECK(c.frontPlane >= c.backPlane);
        if (front >= back) {
            CHECK((c.frontPlane == front && c.backPlane == back && c.frontScale == fs && c.backScale == bs));
        } else {
            CHECK((c.frontPlane == back && c.backPlane == front && c.frontScale == bs && c.backScale == fs));
        }
        CHECK(c.colour == glm::clamp(d.colour, 0.0f, 1.0f));
    }
}

}  // namespace test_colour_models
