// The vector hardcopy of PHIGS PLUS facet data and edge flags, from the store through traversal:
// each facet of a strip in its facet colour, and only the flagged edges of a fill area set with
// data stroked.
#include "phigs/Phigs.h"
#include "phigs/hardcopy/VectorDescriber.h"

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

namespace test_vector_facets {

using namespace phigs;
using namespace phigs::hardcopy;

namespace {

/// The fills of `colour` and the centre of their corners (page coordinates).
std::vector<const VectorFill*> fillsOf(const VectorPicture& picture, glm::vec3 colour) {
    std::vector<const VectorFill*> out;
    for (const VectorOp& op : picture.ops)
        if (const auto* f = std::get_if<VectorFill>(&op); f && f->colour == colour) out.push_back(f);
    return out;
}
glm::dvec2 centre(const VectorFill& f) {
    glm::dvec2 sum(0.0);
    std::size_t n = 0;
    for (const auto& c : f.contours)
        for (const auto& p : c) sum += p, ++n;
    return sum / double(n);
}

/// The vector picture (a 100 x 100 page, no background) of structure 1 holding SOLID interiors
/// and `elements`, posted on an offscreen workstation in HLHSR mode `hlhsr`.
VectorPicture solidPicture(const std::vector<Element>& elements, int hlhsr = 0) {
    Phigs phigs;
    phigs.open();
    StructureStore& store = phigs.store();
    Workstation& model = phigs.openWorkstation(1, WorkstationType::OffscreenImage);
    store.openStructure(1);
    store.insert(IndexAttribute{ElementType::InteriorStyle, int(InteriorStyle::Solid)});
    for (const Element& e : elements) store.insert(e);
    store.closeStructure();
    model.setHlhsrMode(hlhsr);
    model.postStructure(1, 0.5);
    PageSetup page;
    page.paper = {100, 100};
    page.nominalPixel = 1.0;
    page.background = false;
    return describePicture(model.display(), page);
}

}  // namespace

TEST_CASE("vector describe: facet colours fill their facets, edges whose flag is off are not stroked",
          "[hardcopy]") {
    TriangleStripElement strip{
        {{0.05, 0.05, 0.5}, {0.45, 0.05, 0.5}, {0.05, 0.45, 0.5}, {0.45, 0.45, 0.5}}, {}, {}};
    strip.facetColours = {Colour::fromRgb({1, 0, 0}), Colour::fromRgb({0, 1, 0})};
    FillAreaSetWithDataElement square;
    square.contours = {{{0.55, 0.55, 0.5}, {0.95, 0.55, 0.5}, {0.95, 0.95, 0.5}, {0.55, 0.95, 0.5}}};
    square.edgeFlags = {{1, 0, 0, 0}};  // the bottom edge only
    const VectorPicture picture = solidPicture(
        {strip, IndexAttribute{ElementType::EdgeFlag, 1},
         ColourAttribute{ElementType::EdgeColour, Colour::fromRgb({1, 1, 0})},
         ColourAttribute{ElementType::InteriorColour, Colour::fromRgb({0.5, 0.5, 0.5})}, square});
    // The strip's two triangles in their facet colours: red lower left, green upper right (page y down).
    const auto red = fillsOf(picture, {1, 0, 0}), green = fillsOf(picture, {0, 1, 0});
    REQUIRE(red.size() == 1);
    REQUIRE(green.size() == 1);
    CHECK(centre(*red[0]).x < centre(*green[0]).x);
    CHECK(centre(*red[0]).y > centre(*green[0]).y);
    CHECK(fillsOf(picture, {1, 1, 1}).empty());  // the interior colour does not show
    // The square's edges: only its bottom one, the whole of it.
    const auto grey = fillsOf(picture, {0.5f, 0.5f, 0.5f});
    REQUIRE(grey.size() == 1);
    double bottom = -1e300, left = 1e300, right = -1e300;
    for (const auto& p : grey[0]->contours.at(0))
        bottom = std::max(bottom, p.y), left = std::min(left, p.x), right = std::max(right, p.x);
    double low = 1e300, high = -1e300;
    int stroked = 0;
    for (const VectorOp& op : picture.ops)
        if (const auto* s = std::get_if<VectorStroke>(&op); s && s->colour == glm::vec3(1, 1, 0))
            for (const glm::dvec2& p : s->points) {
                CHECK(std::abs(p.y - bottom) < 1e-6);  // on the bottom edge's line
                low = std::min(low, p.x), high = std::max(high, p.x);
                ++stroked;
            }
    CHECK(stroked >= 2);
    CHECK(std::abs(low - left) < 1e-6);
    CHECK(std::abs(high - right) < 1e-6);
}

TEST_CASE("vector describe: fill areas whose signed areas cancel are filled", "[hardcopy]") {
    // A bow-tie FILL AREA and a FILL AREA SET of two squares wound against each other: Newell's
    // normal cancels in both, the even-odd rule fills them, as the raster does.
    const VectorPicture picture = solidPicture(
        {ColourAttribute{ElementType::InteriorColour, Colour::fromRgb({1, 0, 0})},
         fillArea3({{0.05, 0.05, 0.5}, {0.45, 0.45, 0.5}, {0.45, 0.05, 0.5}, {0.05, 0.45, 0.5}}),
         ColourAttribute{ElementType::InteriorColour, Colour::fromRgb({0, 1, 0})},
         FillAreaSetElement{{{{0.55, 0.55, 0.5}, {0.7, 0.55, 0.5}, {0.7, 0.7, 0.5}, {0.55, 0.7, 0.5}},
                             {{0.8, 0.55, 0.5}, {0.8, 0.7, 0.5}, {0.95, 0.7, 0.5}, {0.95, 0.55, 0.5}}},
                            false}});
    CHECK_FALSE(fillsOf(picture, {1, 0, 0}).empty());
    CHECK_FALSE(fillsOf(picture, {0, 1, 0}).empty());
}

TEST_CASE("vector describe: fill areas whose signed areas cancel paint in depth order", "[hardcopy]") {
    // Two bow-ties over each other, tilted at random, the nearer one traversed first, hidden
    // surfaces removed: each has a plane (its lobes', not Newell's zero sum), so the farther one
    // is painted first.
    std::mt19937 random(20261207);
    std::uniform_real_distribution<double> tilt(-0.15, 0.15), shift(-0.1, 0.1);
    auto bowTie = [&](double depth, glm::dvec2 at) {
        const double tx = tilt(random), ty = tilt(random);
        std::vector<glm::dvec3> points;
        for (glm::dvec2 corner :
             {glm::dvec2(-1, -1), glm::dvec2(1, 1), glm::dvec2(1, -1), glm::dvec2(-1, 1)}) {
            const glm::dvec2 p = at + 0.25 * corner;
            points.emplace_back(p, depth + tx * (p.x - at.x) + ty * (p.y - at.y));
        }
        return fillArea3(points);
    };
    for (int trial = 0; trial < 20; ++trial) {
        const glm::dvec2 a(0.5 + shift(random), 0.5 + shift(random)),
            b(0.5 + shift(random), 0.5 + shift(random));
        const VectorPicture picture = solidPicture(
            {ColourAttribute{ElementType::InteriorColour, Colour::fromRgb({1, 0, 0})}, bowTie(0.8, a),
             ColourAttribute{ElementType::InteriorColour, Colour::fromRgb({0, 0, 1})}, bowTie(0.2, b)},
            1);
        std::size_t lastFar = 0, firstNear = picture.ops.size();
        for (std::size_t i = 0; i < picture.ops.size(); ++i)
            if (const auto* f = std::get_if<VectorFill>(&picture.ops[i])) {
                if (f->colour == glm::vec3(0, 0, 1)) lastFar = i;
                if (f->colour == glm::vec3(1, 0, 0)) firstNear = std::min(firstNear, i);
            }
        INFO("trial " << trial);
        REQUIRE(firstNear < picture.ops.size());
        CHECK(lastFar < firstNear);
    }
}

}  // namespace test_vector_facets
