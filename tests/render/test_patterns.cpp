// Interior style PATTERN on lavapipe: the pattern box of the reference point, reference vectors
// and size (modelling coordinates) tiles fill areas and meshes with the pattern's cells.
#include "RenderTestSupport.h"
#include "phigs/vk/ImageTarget.h"

#include <glm/gtc/matrix_transform.hpp>

#include <random>

namespace test_patterns {

using namespace phigs;
using namespace render_test;

namespace {

constexpr std::uint32_t kSize = 192;

const glm::vec3 kPalette[] = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {1, 1, 0}, {0, 1, 1}, {1, 0, 1}, {1, 1, 1}};

/// A random pattern of 1..4 x 1..4 cells from the palette.
DrawPattern randomPattern(std::mt19937& random) {
    DrawPattern p;
    p.columns = std::uniform_int_distribution<int>(1, 4)(random);
    p.rows = std::uniform_int_distribution<int>(1, 4)(random);
    p.colours.clear();
    std::uniform_int_distribution<int> pick(0, 6);
    for (int k = 0; k < p.columns * p.rows; ++k) p.colours.push_back(kPalette[pick(random)]);
    return p;
}

/// A random placement: reference point anywhere near the square, vectors at any angle (not
/// orthogonal, with z components the projection onto the plane z = const drops), cells of
/// 14 to 30 pixels.
PatternPlacement randomPlacement(std::mt19937& random, const DrawPattern& pattern) {
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    PatternPlacement p;
    p.referencePoint = {unit(random), unit(random), unit(random) - 0.5};
    const double a = 6.283185307 * unit(random), skew = 1.5708 + 0.6 * (unit(random) - 0.5);
    const double zx = 0.4 * (unit(random) - 0.5), zy = 0.4 * (unit(random) - 0.5);
    p.vectorX = glm::dvec3(std::cos(a), std::sin(a), zx) * (0.5 + 2 * unit(random));
    p.vectorY = glm::dvec3(std::cos(a + skew), std::sin(a + skew), zy) * (0.5 + 2 * unit(random));
    const double cell = (14.0 + 16.0 * unit(random)) / kSize;
    // The projection shortens each vector's box edge by its z share: size it so cells stay large.
    p.size = {cell * pattern.columns / glm::length(glm::dvec2(glm::normalize(p.vectorX))),
              cell * pattern.rows / glm::length(glm::dvec2(glm::normalize(p.vectorY)))};
    return p;
}

/// The cell (column, fraction) pair the standard's mapping gives a modelling point on the plane
/// z = const: the box edges projected onto the plane (z dropped), the point solved in them.
struct Expected {
    glm::vec3 colour;
    bool wellInside;
};
Expected expectedCell(const DrawPattern& pattern, const PatternPlacement& p, glm::dvec2 x) {
    const glm::dvec2 a = glm::dvec2(glm::normalize(p.vectorX)) * p.size.x;
    const glm::dvec2 b = glm::dvec2(glm::normalize(p.vectorY)) * p.size.y;
    const glm::dvec2 d = x - glm::dvec2(p.referencePoint);
    const double det = a.x * b.y - a.y * b.x;
    const double s = (d.x * b.y - d.y * b.x) / det * pattern.columns;
    const double t = (a.x * d.y - a.y * d.x) / det * pattern.rows;
    auto wrap = [](double v, int n) { return ((int(std::floor(v)) % n) + n) % n; };
    auto inside = [](double v) {
        const double f = v - std::floor(v);
        return f > 0.2 && f < 0.8;
    };
    return {pattern.colours[std::size_t(wrap(t, pattern.rows) * pattern.columns + wrap(s, pattern.columns))],
            inside(s) && inside(t)};
}

DrawMesh quadMesh(double x0, double y0, double x1, double y1, double z) {
    auto mesh = std::make_shared<MeshData>();
    mesh->positions = {{x0, y0, z}, {x1, y0, z}, {x1, y1, z}, {x0, y1, z}};
    mesh->triangles = {0, 1, 2, 0, 2, 3};
    DrawMesh m;
    m.mesh = mesh;
    return m;
}

}  // namespace

TEST_CASE("patterns: pixels take the colour of the pattern cell the placement puts under them",
          "[render][pattern]") {
    vk::Context context(lavapipeWithValidation());
    {
        vk::ImageTarget ws(context, kSize, kSize);
        std::mt19937 random(41);
        std::uniform_real_distribution<double> unit(0.0, 1.0);
        int checked = 0;
        for (int trial = 0; trial < 8; ++trial) {
            INFO("trial " << trial);
            DrawList list = emptyScene();
            const DrawPattern pattern = randomPattern(random);
            const int index = 1 + trial % 3;
            list.patterns[index] = pattern;
            // A modelling transform that rotates, scales and moves the square in its plane.
            const double angle = unit(random) - 0.5, scale = 0.8 + 0.4 * unit(random);
            glm::dmat4 model = glm::translate(glm::dmat4(1.0), glm::dvec3(0.5, 0.5, 0.0)) *
                               glm::rotate(glm::dmat4(1.0), angle, glm::dvec3(0, 0, 1)) *
                               glm::scale(glm::dmat4(1.0), glm::dvec3(scale, scale, 1.0)) *
                               glm::translate(glm::dmat4(1.0), glm::dvec3(-0.5, -0.5, 0.0));
            InteriorStyleSet interior;
            interior.style = InteriorStyle::Pattern;
            interior.styleIndex = index;
            interior.colour = {0.5f, 0.5f, 0.5f};
            interior.pattern = randomPlacement(random, pattern);
            DrawItem drawn;
            if (trial % 2 == 0) {
                DrawFillArea f = solidRectangle(0.15, 0.15, 0.85, 0.85, 0.5, {0.5f, 0.5f, 0.5f});
                f.interior = interior;
                drawn = item(f);
            } else {
                DrawMesh m = quadMesh(0.15, 0.15, 0.85, 0.85, 0.5);
                m.interior = interior;
                drawn = item(m);
            }
            drawn.context.edit().modelTransform = model;
            list.items.push_back(drawn);
            const Image image = ws.draw(list);
            const glm::dmat4 toModel = glm::inverse(model);
            int sampled = 0, mismatched = 0;
            for (int k = 0; k < 400; ++k) {
                const std::uint32_t px = std::uint32_t(unit(random) * kSize);
                const std::uint32_t py = std::uint32_t(unit(random) * kSize);
                const glm::dvec2 npc((px + 0.5) / kSize, 1.0 - (py + 0.5) / kSize);
                const glm::dvec2 m = glm::dvec2(toModel * glm::dvec4(npc, 0.5, 1.0));
                if (m.x < 0.17 || m.x > 0.83 || m.y < 0.17 || m.y > 0.83) continue;  // off the square
                const Expected e = expectedCell(pattern, interior.pattern, m);
                if (!e.wellInside) continue;
                ++sampled;
                if (!shows(image, {px, py}, glm::dvec3(e.colour))) {
                    ++mismatched;
                    UNSCOPED_INFO("pixel " << px << "," << py);
                }
            }
            CHECK(sampled > 40);
            CHECK(mismatched == 0);
            checked += sampled;
        }
        CHECK(checked > 400);
    }
    requireNoValidationMessages(context);
}

TEST_CASE("patterns: an undefined pattern index draws pattern 1, no pattern table draws solid",
          "[render][pattern]") {
    vk::Context context(lavapipeWithValidation());
    {
        vk::ImageTarget ws(context, 64, 64);
        DrawList list = emptyScene();
        DrawFillArea f = solidRectangle(0.0, 0.0, 1.0, 1.0, 0.5, {0.5f, 0.5f, 0.5f});
        f.interior.edit().style = InteriorStyle::Pattern;
        f.interior.edit().styleIndex = 7;
        f.interior.edit().pattern.size = {2.0, 2.0};  // one cell covers the whole picture
        list.items.push_back(item(f));
        const Image solid = ws.draw(list);
        CHECK(near(at(solid, 32, 32), 128, 128, 128));
        list.patterns[1] = DrawPattern{1, 1, {glm::vec3(0, 1, 0)}};
        const Image one = ws.draw(list);
        CHECK(near(at(one, 32, 32), 0, 255, 0));
        // Hollow, solid, hatch and empty interiors ignore the pattern table.
        list.items[0] = item(solidRectangle(0.0, 0.0, 1.0, 1.0, 0.5, {0.5f, 0.5f, 0.5f}));
        CHECK(near(at(ws.draw(list), 32, 32), 128, 128, 128));
    }
    requireNoValidationMessages(context);
}

}  // namespace test_patterns
