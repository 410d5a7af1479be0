// Bundle tables: polyline, polymarker, text and interior representations (with the PHIGS PLUS
// entries: general colours, approximation criteria) set on the workstation, selected by the
// bundle index elements and used only for the aspects whose source flag says BUNDLED.
#include "ErrorNumber.h"
#include "phigs/Phigs.h"
#include "phigs/ws/Realization.h"
#include "phigs/ws/WorkstationErrors.h"

#include <catch2/catch.hpp>

#include <random>

namespace test_bundles {

using namespace phigs;

namespace {

struct Scene {
    Phigs phigs;
    StructureStore* store = nullptr;
    Workstation* ws = nullptr;
    Scene() {
        phigs.open();
        store = &phigs.store();
        ws = &phigs.openWorkstation(1, WorkstationType::OffscreenImage);
        ws->setColourRepresentation(5, {0.25, 0.5, 0.75});
        ws->setColourRepresentation(6, {0.75, 0.25, 0.5});
    }
    const DrawList& show(std::initializer_list<Element> elements) {
        store->openStructure(1);
        for (const Element& e : elements) store->insert(e);
        store->closeStructure();
        ws->postStructure(1, 0.5);
        return ws->display();
    }
};

Element bundled(AspectId aspect) {
    return AsfAttribute{aspect, false};
}
Element individual(AspectId aspect) {
    return AsfAttribute{aspect, true};
}

const Element markers = polymarker3({{0.5, 0.5, 0}});
const Element square = fillArea3({{0.1, 0.1, 0}, {0.4, 0.1, 0}, {0.4, 0.4, 0}});
const Element words = TextElement{{0.1, 0.8, 0}, {1, 0, 0}, {0, 1, 0}, "AB", false};

const glm::vec3 colour5(0.25f, 0.5f, 0.75f);
const glm::vec3 colour6(0.75f, 0.25f, 0.5f);

}  // namespace

TEST_CASE("polymarker bundle: bundled aspects read the representation, individual ones do not",
          "[traverse][bundles]") {
    Scene s;
    s.ws->setPolymarkerRepresentation(3, {MarkerType::Circle, 2.5, Colour::indexed(5)});
    const DrawList& list = s.show({
        IndexAttribute{ElementType::MarkerType, int(MarkerType::Plus)},
        RealAttribute{ElementType::MarkerSizeScaleFactor, 0.5},
        ColourAttribute{ElementType::PolymarkerColour, Colour::indexed(6)},
        IndexAttribute{ElementType::PolymarkerIndex, 3},
        markers,  // all individual
        bundled(AspectId::MarkerType), bundled(AspectId::MarkerSizeScale),
        bundled(AspectId::PolymarkerColour),
        markers,  // all bundled
        individual(AspectId::MarkerSizeScale),
        markers,  // scale individual again
        IndexAttribute{ElementType::PolymarkerIndex, 7},
        markers,  // undefined bundle 7 reads as bundle 1
    });
    REQUIRE(list.items.size() == 4);
    auto style = [&](int i) { return std::get<DrawPolymarker>(list.items[i].primitive).style.get(); };
    CHECK(style(0).type == MarkerType::Plus);
    CHECK(style(0).scale == 0.5f);
    CHECK(style(0).colour == colour6);
    CHECK(style(1).type == MarkerType::Circle);
    CHECK(style(1).scale == 2.5f);
    CHECK(style(1).colour == colour5);
    CHECK(style(2).type == MarkerType::Circle);
    CHECK(style(2).scale == 0.5f);
    CHECK(style(3).type == MarkerType::Asterisk);  // bundle 1's defaults
    CHECK(style(3).colour == glm::vec3(1.0f));

    // A new representation reaches the bundled item at the next display, not the individual one.
    s.ws->setPolymarkerRepresentation(3, {MarkerType::Cross, 4.0, Colour::indexed(6)});
    const DrawList& again = s.ws->display();
    REQUIRE(again.items.size() == 4);
    CHECK(std::get<DrawPolymarker>(again.items[1].primitive).style->type == MarkerType::Cross);
    CHECK(std::get<DrawPolymarker>(again.items[1].primitive).style->scale == 4.0f);
    CHECK(std::get<DrawPolymarker>(again.items[0].primitive).style->type == MarkerType::Plus);
}

TEST_CASE("text bundle: font, expansion, spacing and colour from the representation when bundled",
          "[traverse][bundles]") {
    Scene s;
    s.ws->setTextRepresentation(2, {3, 2, 1.5, 0.25, Colour::indexed(5)});
    const DrawList& list = s.show({
        IndexAttribute{ElementType::TextFont, 2},
        RealAttribute{ElementType::CharacterExpansionFactor, 0.8},
        RealAttribute{ElementType::CharacterSpacing, 0.1},
        ColourAttribute{ElementType::TextColour, Colour::indexed(6)},
        IndexAttribute{ElementType::TextIndex, 2},
        words,
        bundled(AspectId::TextFont),
        bundled(AspectId::CharacterExpansion),
        bundled(AspectId::CharacterSpacing),
        bundled(AspectId::TextColour),
        words,
        individual(AspectId::TextColour),
        individual(AspectId::TextFont),
        words,
    });
    REQUIRE(list.items.size() == 3);
    auto style = [&](int i) { return primitiveAs<DrawText>(list.items[i].primitive).style.get(); };
    CHECK(style(0).font == 2);
    CHECK(style(0).expansion == 0.8f);
    CHECK(style(0).spacing == 0.1f);
    CHECK(style(0).colour == colour6);
    CHECK(style(1).font == 3);
    CHECK(style(1).expansion == 1.5f);
    CHECK(style(1).spacing == 0.25f);
    CHECK(style(1).colour == colour5);
    CHECK(style(2).font == 2);
    CHECK(style(2).colour == colour6);
    CHECK(style(2).expansion == 1.5f);  // still bundled
}

TEST_CASE("interior bundle: style, style index, colours, shading and reflectance when bundled",
          "[traverse][bundles]") {
    Scene s;
    InteriorBundle hatch;
    hatch.style = InteriorStyle::Hatch;
    hatch.styleIndex = 4;
    hatch.colour = Colour::indexed(5);
    hatch.backColour = Colour::fromRgb({0.0, 0.5, 0.0});
    hatch.shading = ShadingMethod::Normal;
    hatch.reflectance = ReflectanceModel::Specular;
    hatch.properties.ambient = 0.125;
    s.ws->setInteriorRepresentation(4, hatch);
    const DrawList& list = s.show({
        IndexAttribute{ElementType::InteriorStyle, int(InteriorStyle::Solid)},
        IndexAttribute{ElementType::InteriorStyleIndex, 2},
        ColourAttribute{ElementType::InteriorColour, Colour::indexed(6)},
        IndexAttribute{ElementType::InteriorIndex, 4},
        square,
        bundled(AspectId::InteriorStyle),
        bundled(AspectId::InteriorStyleIndex),
        bundled(AspectId::InteriorColour),
        bundled(AspectId::BackInteriorColour),
        bundled(AspectId::InteriorShading),
        bundled(AspectId::InteriorReflectance),
        bundled(AspectId::AreaProperties),
        square,
        individual(AspectId::InteriorStyle),
        individual(AspectId::InteriorColour),
        square,
    });
    REQUIRE(list.items.size() == 3);
    auto interior = [&](int i) { return primitiveAs<DrawFillArea>(list.items[i].primitive).interior.get(); };
    CHECK(interior(0).style == InteriorStyle::Solid);
    CHECK(interior(0).styleIndex == 2);
    CHECK(interior(0).colour == colour6);
    CHECK(interior(0).shading == ShadingMethod::None);
    CHECK(interior(1).style == InteriorStyle::Hatch);
    CHECK(interior(1).styleIndex == 4);
    CHECK(interior(1).colour == colour5);
    CHECK(interior(1).backColour == glm::vec3(0.0f, 0.5f, 0.0f));
    CHECK(interior(1).shading == ShadingMethod::Normal);
    CHECK(interior(1).reflectance == ReflectanceModel::Specular);
    CHECK(interior(1).properties.ambient == 0.125f);
    CHECK(interior(2).style == InteriorStyle::Solid);
    CHECK(interior(2).colour == colour6);
    CHECK(interior(2).styleIndex == 4);  // still bundled
}

TEST_CASE("polyline bundle (PHIGS PLUS): a direct colour and the curve approximation criteria when bundled",
          "[traverse][bundles]") {
    std::mt19937 random(19);
    const Element cubic =
        NurbsCurveElement{geom::Curve(3, {0, 0, 0, 0, 1, 1, 1, 1},
                                      {{0.1, 0.1, 0}, {0.3, 0.9, 0}, {0.6, 0.9, 0}, {0.9, 0.1, 0}}),
                          0, 0};
    const Element line = polyline3({{0.1, 0.5, 0}, {0.9, 0.5, 0}});
    for (int round = 0; round < 20; ++round) {
        Scene s;
        const int individualSegments = int(random() % 40) + 1, bundledSegments = int(random() % 40) + 1;
        const glm::dvec3 rgb(double(random() % 101) / 100, double(random() % 101) / 100, 0.5);
        PolylineBundle b{LineType::Dotted, 2.0, Colour::fromRgb(rgb)};
        b.shading = ShadingMethod::Colour;
        b.approximation = {ElementType::CurveApproximationCriteria, 2, double(bundledSegments),
                           double(bundledSegments)};
        s.ws->setPolylineRepresentation(3, b);
        const DrawList& list = s.show({
            IndexAttribute{ElementType::PolylineIndex, 3},
            ApproximationAttribute{ElementType::CurveApproximationCriteria, 2, double(individualSegments),
                                   double(individualSegments)},
            cubic,  // all individual
            bundled(AspectId::CurveApproximation),
            bundled(AspectId::PolylineColour),
            bundled(AspectId::LineType),
            cubic,
            line,
        });
        REQUIRE(list.items.size() == 3);
        const DrawCurve& first = primitiveAs<DrawCurve>(list.items[0].primitive);
        const DrawCurve& second = primitiveAs<DrawCurve>(list.items[1].primitive);
        INFO("segments " << individualSegments << " and " << bundledSegments);
        CHECK(first.points.size() == std::size_t(individualSegments) + 1);  // one span
        CHECK(first.style->colour == glm::vec3(1.0f));
        CHECK(second.points.size() == std::size_t(bundledSegments) + 1);
        CHECK(second.style->colour == glm::vec3(rgb));
        CHECK(second.style->type == LineType::Dotted);
        CHECK(std::get<DrawPolyline>(list.items[2].primitive).style->colour == glm::vec3(rgb));
    }
}

TEST_CASE("bundle colours are general colours: an index >= 0 or RGB within [0, 1], checked first",
          "[ws][bundles][errors]") {
    Scene s;
    const PolylineBundle before = s.ws->tables().polylines.get(2);
    using test::errorOf;
    CHECK(errorOf([&] {
              s.ws->setPolylineRepresentation(2, {LineType::Solid, 1, Colour::fromRgb({0.5, 1.25, 0})});
          }) == errors::BadDirectColour);
    PolylineBundle shaded;
    shaded.shading = ShadingMethod::DotProduct;  // polylines shade NONE or COLOUR only
    CHECK(errorOf([&] { s.ws->setPolylineRepresentation(2, shaded); }) ==
          errors::PolylineShadingNotAvailable);
    CHECK(s.ws->tables().polylines.get(2) == before);
    InteriorBundle interior;
    interior.backProperties.specularColour = Colour::indexed(-3);
    CHECK(errorOf([&] { s.ws->setInteriorRepresentation(2, interior); }) == errors::ColourIndexBelowZero);
    interior.backProperties.specularColour = Colour::fromRgb({0, 0, -0.5});
    CHECK(errorOf([&] { s.ws->setInteriorRepresentation(2, interior); }) == errors::BadDirectColour);
    interior.backProperties.specularColour = Colour::indexed(9);
    interior.backShading = ShadingMethod(7);
    CHECK(errorOf([&] { s.ws->setInteriorRepresentation(2, interior); }) ==
          errors::InteriorShadingNotAvailable);
    interior.backShading = ShadingMethod::Colour;
    interior.reflectance = ReflectanceModel(0);
    CHECK(errorOf([&] { s.ws->setInteriorRepresentation(2, interior); }) == errors::ReflectanceNotAvailable);
    interior.reflectance = ReflectanceModel::Diffuse;
    s.ws->setInteriorRepresentation(2, interior);
    CHECK(s.ws->tables().interiors.get(2) == interior);
    PatternRepresentation pattern{1, 2, {Colour::fromRgb({0.2, 0.4, 0.6}), Colour::fromRgb({1.5, 0, 0})}};
    CHECK(errorOf([&] { s.ws->setPatternRepresentation(3, pattern); }) == errors::BadDirectColour);
    pattern.colours[1] = Colour::indexed(40);
    s.ws->setPatternRepresentation(3, pattern);
    const PatternRepresentation drawn = realized(*s.ws->patterns().find(3), s.ws->tables().colours);
    CHECK(drawn.colours[0] == pattern.colours[0]);  // direct colours as given
    CHECK(drawn.colours[1] == Colour::indexed(1));  // an undefined index as 1
}

}  // namespace test_bundles
