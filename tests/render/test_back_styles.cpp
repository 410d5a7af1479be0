// PHIGS PLUS back faces drawn by their own attributes: with face distinguishing on, each side of a
// fill area or mesh takes its own interior style (a SOLID, HATCH or PATTERN back under a HOLLOW or
// EMPTY front too), style index and shading method, on lavapipe and in the vector hardcopy (PDF,
// rasterised). Random squares turned either way, random styles per side, several seeded trials.
#include "RenderTestSupport.h"
#include "VectorRaster.h"
#include "phigs/hardcopy/VectorWorkstation.h"
#include "phigs/vk/ImageTarget.h"

#include <glm/gtc/matrix_transform.hpp>

#include <array>
#include <filesystem>
#include <random>
#include <string>

namespace test_back_styles {

using namespace phigs;
using namespace render_test;

namespace {

constexpr std::uint32_t kSize = 256;
constexpr int kColumns = 4, kRows = 3;
constexpr double kHalf = 0.09;  // half the side of a square, world (= NPC) units

const glm::vec3 kBackground{0.1f, 0.1f, 0.1f};
const glm::vec3 kFront{0.1f, 0.85f, 0.2f}, kBack{0.9f, 0.15f, 0.8f};
// Patterns 1 and 2: two colours each, seen by no other part of the picture.
const glm::vec3 kPatternColours[2][2] = {{{1.0f, 0.9f, 0.1f}, {0.1f, 0.2f, 1.0f}},
                                         {{0.1f, 0.95f, 0.95f}, {1.0f, 0.5f, 0.0f}}};

/// A square's turn: yaw about y, then pitch about x before it; its front is +z turned so.
struct Turn {
    double yaw = 0.0, pitch = 0.0;
    glm::dmat3 matrix() const {
        const glm::dmat4 r = glm::rotate(glm::dmat4(1.0), yaw, glm::dvec3(0, 1, 0)) *
                             glm::rotate(glm::dmat4(1.0), pitch, glm::dvec3(1, 0, 0));
        return glm::dmat3(r);
    }
    bool facesViewer() const { return (matrix() * glm::dvec3(0, 0, 1)).z > 0.0; }
};

/// A random turn showing either side well: yaw within 55 degrees of 0 or of 180, pitch within 15.
Turn randomTurn(std::mt19937& random) {
    std::uniform_real_distribution<double> unit(-1.0, 1.0);
    Turn t;
    t.yaw = 0.96 * unit(random) + (random() % 2 ? 3.14159265 : 0.0);
    t.pitch = 0.26 * unit(random);
    return t;
}

glm::dvec3 cellCentre(int k) {
    return {0.125 + 0.25 * (k % kColumns), 0.18 + 0.32 * (k / kColumns), 0.5};
}

/// The world point of local square coordinates (lx, ly in [-1, 1]) in cell k.
glm::dvec3 local(int k, const Turn& turn, double lx, double ly) {
    return cellCentre(k) + turn.matrix() * glm::dvec3(lx * kHalf, ly * kHalf, 0.0);
}

glm::ivec2 pixelOf(const glm::dvec3& world) {
    return {int(world.x * kSize), int((1.0 - world.y) * kSize)};
}

DrawList baseScene() {
    DrawList list = emptyScene();
    list.background = kBackground;
    for (int p = 0; p < 2; ++p) {
        DrawPattern pattern;
        pattern.columns = 2;
        pattern.rows = 2;
        pattern.colours = {kPatternColours[p][0], kPatternColours[p][1], kPatternColours[p][1],
                           kPatternColours[p][0]};
        list.patterns[p + 1] = pattern;
    }
    return list;
}

/// Shares of a window's pixels nearest each candidate colour and within `within` of it.
std::vector<double> shares(const Image& image, glm::ivec2 centre, int half,
                           const std::vector<glm::vec3>& candidates, float within) {
    std::vector<double> counts(candidates.size(), 0.0);
    int total = 0;
    for (int y = centre.y - half; y <= centre.y + half; ++y)
        for (int x = centre.x - half; x <= centre.x + half; ++x) {
            const Rgb c = at(image, std::uint32_t(x), std::uint32_t(y));
            const glm::vec3 v(c.r / 255.0f, c.g / 255.0f, c.b / 255.0f);
            std::size_t best = 0;
            for (std::size_t i = 1; i < candidates.size(); ++i)
                if (glm::length(v - candidates[i]) < glm::length(v - candidates[best])) best = i;
            if (glm::length(v - candidates[best]) < within) counts[best] += 1.0;
            ++total;
        }
    for (double& c : counts) c /= double(total);
    return counts;
}

/// One side's interior style and index.
struct Side {
    InteriorStyle style = InteriorStyle::Solid;
    int index = 1;
};

Side randomSide(std::mt19937& random) {
    const InteriorStyle styles[] = {InteriorStyle::Hollow, InteriorStyle::Solid, InteriorStyle::Pattern,
                                    InteriorStyle::Hatch, InteriorStyle::Empty};
    Side s;
    s.style = styles[random() % 5];
    s.index = s.style == InteriorStyle::Hatch ? 1 + int(random() % 6) : 1 + int(random() % 2);
    return s;
}

/// A square of the style test: its turn, sides, face distinguishing, and whether it is a mesh.
struct StyledSquare {
    Turn turn;
    Side front, back;
    bool distinguish = true, mesh = false;
};

InteriorStyleSet interiorOf(const StyledSquare& s) {
    InteriorStyleSet in;
    in.style = s.front.style;
    in.styleIndex = s.front.index;
    in.colour = kFront;
    in.backColour = kBack;
    in.distinguishBackFaces = s.distinguish;
    in.back.style = s.back.style;
    in.back.styleIndex = s.back.index;
    in.pattern.size = {0.06, 0.06};  // cells of 0.03: about 8 pixels
    return in;
}

DrawItem squareItem(int k, const StyledSquare& s) {
    const std::array<glm::dvec3, 4> corners = {local(k, s.turn, -1, -1), local(k, s.turn, 1, -1),
                                               local(k, s.turn, 1, 1), local(k, s.turn, -1, 1)};
    if (s.mesh) {
        auto data = std::make_shared<MeshData>();
        for (const glm::dvec3& c : corners) data->positions.push_back(glm::vec3(c));
        data->triangles = {0, 1, 2, 0, 2, 3};
        DrawMesh m;
        m.mesh = data;
        m.interior = interiorOf(s);
        return item(m);
    }
    DrawFillArea f;
    f.contours = {{corners.begin(), corners.end()}};
    f.interior = interiorOf(s);
    return item(f);
}

/// Checks the window in the square's upper left quarter (clear of its outline and of a mesh's
/// diagonal edge) against the style of the side the square shows.
void checkSquare(const Image& image, int trial, int k, const StyledSquare& s, const char* target) {
    const bool backShown = !s.turn.facesViewer();
    const bool own = backShown && s.distinguish;
    const Side side = own ? s.back : s.front;
    const std::vector<glm::vec3> candidates = {kBackground,
                                               kFront,
                                               kBack,
                                               kPatternColours[0][0],
                                               kPatternColours[0][1],
                                               kPatternColours[1][0],
                                               kPatternColours[1][1]};
    // Blends (anti-aliased borders in the PDF raster) count for no colour, except in `nearest`:
    // a hatch line of the PDF is mostly blends.
    const glm::ivec2 centre = pixelOf(local(k, s.turn, -0.5, 0.5));
    const std::vector<double> share = shares(image, centre, 4, candidates, 0.2f);
    const std::vector<double> nearest = shares(image, centre, 4, candidates, 2.0f);
    const double mine = share[own ? 2 : 1], other = share[own ? 1 : 2];
    INFO(target << " trial " << trial << " square " << k << ": front style " << int(s.front.style)
                << " index " << s.front.index << ", back style " << int(s.back.style) << " index "
                << s.back.index << ", distinguish " << s.distinguish << ", mesh " << s.mesh << ", shows its "
                << (backShown ? "back" : "front") << "; shares background " << share[0] << " front "
                << share[1] << " back " << share[2] << " pattern 1 " << share[3] + share[4] << " pattern 2 "
                << share[5] + share[6]);
    switch (side.style) {
        case InteriorStyle::Solid:
            CHECK(mine > 0.9);
            break;
        case InteriorStyle::Hollow:
        case InteriorStyle::Empty:
            CHECK(share[0] > 0.9);
            break;
        case InteriorStyle::Hatch:
            CHECK(nearest[own ? 2 : 1] > 0.04);
            CHECK(mine < 0.7);
            CHECK(share[0] > 0.25);
            CHECK(other < 0.02);
            break;
        case InteriorStyle::Pattern: {
            const std::size_t first = side.index == 1 ? 3 : 5;
            // Cell borders blend in the PDF raster; the other side's colour never shows.
            CHECK(share[first] + share[first + 1] > 0.7);
            CHECK(other < 0.02);
            CHECK(share[first] > 0.05);
            CHECK(share[first + 1] > 0.05);
            break;
        }
    }
}

/// The picture as the vector hardcopy's PDF, rasterised at one pixel per point.
Image hardcopyRaster(const DrawList& list, const std::string& name) {
    const auto dir = std::filesystem::path(PHIGS_TEST_OUTPUT_DIR) / "back_styles";
    std::filesystem::create_directories(dir);
    hardcopy::PageSetup page;
    page.paper = {double(kSize), double(kSize)};
    page.nominalPixel = 1.0;
    const auto file = dir / (name + ".pdf");
    {
        hardcopy::VectorWorkstation vector(file, hardcopy::VectorFormat::Pdf, page, {});
        vector.update(list);
        vector.close();
    }
    return vector_test::rasterisePdf(file, kSize, kSize);
}

}  // namespace

TEST_CASE("back faces: each side by its own interior style and index, on lavapipe and in PDF",
          "[render][shading][hardcopy]") {
    std::mt19937 random(19);
    vk::Context context(lavapipeWithValidation());
    for (int trial = 0; trial < 4; ++trial) {
        DrawList list = baseScene();
        std::vector<StyledSquare> squares;
        for (int k = 0; k < kColumns * kRows; ++k) {
            StyledSquare s;
            s.turn = randomTurn(random);
            s.front = randomSide(random);
            s.back = randomSide(random);
            s.distinguish = random() % 4 != 0;
            s.mesh = random() % 2 == 0;
            squares.push_back(s);
            list.items.push_back(squareItem(k, s));
        }
        Image raster;
        {
            vk::ImageTarget ws(context, kSize, kSize);
            raster = ws.draw(list);
        }
        const Image pdf = hardcopyRaster(list, "styles_" + std::to_string(trial));
        const auto dir = std::filesystem::path(PHIGS_TEST_OUTPUT_DIR) / "back_styles";
        writePng(raster, dir / ("styles_" + std::to_string(trial) + "_lavapipe.png"));
        for (int k = 0; k < kColumns * kRows; ++k) {
            checkSquare(raster, trial, k, squares[std::size_t(k)], "lavapipe");
            checkSquare(pdf, trial, k, squares[std::size_t(k)], "PDF");
        }
    }
    requireNoValidationMessages(context);
}

namespace {

/// A lit square mesh of the shading test: a 4 x 4 grid whose vertex normals lean toward +y with
/// height (local), both sides SOLID, each side's shading method its own.
DrawItem shadedSquare(int k, const Turn& turn, ShadingMethod front, ShadingMethod back, bool distinguish) {
    constexpr int n = 4;
    auto data = std::make_shared<MeshData>();
    const glm::dmat3 r = turn.matrix();
    for (int j = 0; j <= n; ++j)
        for (int i = 0; i <= n; ++i) {
            const double lx = -1.0 + 2.0 * i / n, ly = -1.0 + 2.0 * j / n;
            data->positions.push_back(glm::vec3(local(k, turn, lx, ly)));
            const double lean = 0.5 * (ly + 1.0);  // 0 at the bottom, 1 at the top
            data->normals.push_back(glm::vec3(r * glm::normalize(glm::dvec3(0.0, 1.1 * lean, 1.0))));
        }
    for (int j = 0; j < n; ++j)
        for (int i = 0; i < n; ++i) {
            const std::uint32_t a = std::uint32_t(j * (n + 1) + i), b = a + 1, c = a + n + 2, d = a + n + 1;
            data->triangles.insert(data->triangles.end(), {a, b, c, a, c, d});
        }
    DrawMesh m;
    m.mesh = data;
    InteriorStyleSet& in = m.interior.edit();
    in.style = InteriorStyle::Solid;
    in.colour = {0.9f, 0.9f, 0.9f};
    in.backColour = {0.9f, 0.9f, 0.9f};
    in.shading = front;
    in.reflectance = ReflectanceModel::Diffuse;
    in.properties.ambient = 0.2f;
    in.properties.diffuse = 0.8f;
    in.distinguishBackFaces = distinguish;
    in.back.style = InteriorStyle::Solid;
    in.back.shading = back;
    in.back.reflectance = ReflectanceModel::Diffuse;
    in.backProperties = in.properties;
    DrawItem i = item(m);
    i.context.edit().lightSet = 0;
    return i;
}

/// The mean red of a 7 x 7 window.
double meanRed(const Image& image, glm::ivec2 centre) {
    double sum = 0.0;
    for (int y = centre.y - 3; y <= centre.y + 3; ++y)
        for (int x = centre.x - 3; x <= centre.x + 3; ++x)
            sum += at(image, std::uint32_t(x), std::uint32_t(y)).r;
    return sum / 49.0;
}

}  // namespace

TEST_CASE("back faces: each side by its own shading method, on lavapipe and in PDF",
          "[render][shading][hardcopy]") {
    std::mt19937 random(23);
    vk::Context context(lavapipeWithValidation());
    const ShadingMethod methods[] = {ShadingMethod::None, ShadingMethod::Colour, ShadingMethod::Normal};
    for (int trial = 0; trial < 3; ++trial) {
        DrawList list = baseScene();
        Light ambient;
        ambient.type = LightType::Ambient;
        Light key;
        key.type = LightType::Directional;
        key.direction = {0, 0, -1};  // from the viewer
        list.lightSets.push_back({ambient, key});
        struct Case {
            Turn turn;
            ShadingMethod front, back;
            bool distinguish;
        };
        std::vector<Case> cases;
        for (int k = 0; k < kColumns * kRows; ++k) {
            Case c{randomTurn(random), methods[random() % 3], methods[random() % 3], random() % 4 != 0};
            cases.push_back(c);
            list.items.push_back(shadedSquare(k, c.turn, c.front, c.back, c.distinguish));
        }
        Image raster;
        {
            vk::ImageTarget ws(context, kSize, kSize);
            raster = ws.draw(list);
        }
        const Image pdf = hardcopyRaster(list, "shading_" + std::to_string(trial));
        for (int k = 0; k < kColumns * kRows; ++k) {
            const Case& c = cases[std::size_t(k)];
            const bool backShown = !c.turn.facesViewer();
            const ShadingMethod method = backShown && c.distinguish ? c.back : c.front;
            using Target = std::pair<const Image*, const char*>;
            for (const auto& [image, target] : {Target{&raster, "lavapipe"}, Target{&pdf, "PDF"}}) {
                const double low = meanRed(*image, pixelOf(local(k, c.turn, 0.0, -0.5)));
                const double high = meanRed(*image, pixelOf(local(k, c.turn, 0.0, 0.5)));
                INFO(target << " trial " << trial << " square " << k << ": front shading " << int(c.front)
                            << ", back shading " << int(c.back) << ", distinguish " << c.distinguish
                            << ", shows its " << (backShown ? "back" : "front") << "; red low " << low
                            << " high " << high);
                CHECK(low > 40.0);  // lit, not background
                if (method == ShadingMethod::None)
                    CHECK(std::abs(high - low) < 3.0);  // flat: one colour per facet plane
                else
                    CHECK(std::abs(high - low) > 8.0);  // interpolated: the normals' lean shows
            }
        }
    }
    requireNoValidationMessages(context);
}

}  // namespace test_back_styles
