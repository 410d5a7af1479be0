#include "ErrorNumber.h"
#include "phigs/Phigs.h"
#include "phigs/ws/PredefinedRepresentations.h"
#include "phigs/ws/Realization.h"
#include "phigs/ws/WorkstationErrors.h"

#include <catch2/catch.hpp>

#include <random>

namespace test_ws_state {

using namespace phigs;
using phigs::test::errorOf;

namespace {

bool atOnce(DeferralMode d) {
    return d == DeferralMode::Asap || d == DeferralMode::Bnig || d == DeferralMode::Bnil;
}

/// What the standard says the workstation holds: requested values and the current ones.
struct Model {
    double requestedWindow = 1.0, currentWindow = 1.0;
    int requestedHlhsr = 0, currentHlhsr = 0;
    DeferralMode deferral = DeferralMode::Asap;
    ModificationMode modification = ModificationMode::Nive;
    bool effectiveAtOnce() const { return atOnce(deferral) || modification == ModificationMode::Uqum; }
    void commit() {
        currentWindow = requestedWindow;
        currentHlhsr = requestedHlhsr;
    }
};

}  // namespace

TEST_CASE("requested and current values follow the deferral and modification modes", "[ws][state]") {
    std::mt19937 random(20261203);
    for (int run = 0; run < 20; ++run) {
        Phigs phigs;
        phigs.open();
        Workstation& ws = phigs.openWorkstation(1, WorkstationType::Hardcopy);
        ws.postStructure(1, 0.5);
        ws.display();  // the first picture is made whatever the mode
        Model m;
        for (int step = 0; step < 40; ++step) {
            switch (random() % 5) {
                case 0: {
                    m.deferral = static_cast<DeferralMode>(random() % 5);
                    m.modification = static_cast<ModificationMode>(random() % 3);
                    ws.setDeferralState(m.deferral, m.modification);
                    if (m.effectiveAtOnce()) m.commit();
                    break;
                }
                case 1:
                    m.requestedWindow = 0.25 + 0.75 * double(random() % 100) / 100.0;
                    ws.setWorkstationWindow({0, 0, 0}, {m.requestedWindow, 1, 1});
                    if (m.effectiveAtOnce()) m.commit();
                    break;
                case 2:
                    m.requestedHlhsr = int(random() % 2);
                    ws.setHlhsrMode(m.requestedHlhsr);
                    if (m.effectiveAtOnce()) m.commit();
                    break;
                case 3:
                    if (random() % 2) {
                        ws.update(Regeneration::Perform);
                        m.commit();
                    } else {
                        ws.update(Regeneration::Postpone);  // no regeneration: nothing takes effect
                    }
                    break;
                default:
                    ws.redrawAllStructures();
                    m.commit();
                    break;
            }
            INFO("run " << run << " step " << step);
            CHECK(ws.current().windowMax.x == m.currentWindow);
            CHECK(ws.tables().windowMax.x == m.requestedWindow);
            CHECK(ws.current().hlhsrMode == m.currentHlhsr);
            CHECK(ws.transformationUpdatePending() == (m.currentWindow != m.requestedWindow));
            CHECK(ws.hlhsrUpdatePending() == (m.currentHlhsr != m.requestedHlhsr));
            if (atOnce(m.deferral)) CHECK(ws.visualState() == VisualState::Correct);
            // The picture is made from the current values.
            CHECK(ws.display().windowMax.x == ws.current().windowMax.x);
        }
    }
}

TEST_CASE("the visual state and the empty surface say what the display shows, drawn or not", "[ws][state]") {
    // Random mode switches, changes, postings and updates with no picture drawn between them: a
    // change made where changes show at once is on the display although the picture is only made
    // when drawn, so a later switch to a deferring mode has nothing deferred (it said DEFERRED).
    std::mt19937 random(20261205);
    for (int run = 0; run < 30; ++run) {
        Phigs phigs;
        phigs.open();
        Workstation& ws = phigs.openWorkstation(1, WorkstationType::Hardcopy);
        DeferralMode deferral = DeferralMode::Asap;
        ModificationMode modification = ModificationMode::Nive;
        bool deferred = false, simulated = false, posted = false, shownPosted = false;
        std::string trace;
        for (int step = 0; step < 40; ++step) {
            const bool atOnceNow = atOnce(deferral);
            auto change = [&] {
                if (atOnceNow) return;
                (modification == ModificationMode::Uqum ? simulated : deferred) = true;
            };
            const unsigned what = random() % 6;
            trace += " " + std::to_string(what);
            if (what == 0) {
                deferral = static_cast<DeferralMode>(random() % 5);
                modification = static_cast<ModificationMode>(random() % 3);
                ws.setDeferralState(deferral, modification);
                trace += "(" + std::to_string(int(deferral)) + std::to_string(int(modification)) + ")";
                if (atOnce(deferral)) deferred = simulated = false;
                // Quick update methods show what was deferred too, as a simulation.
                if (modification == ModificationMode::Uqum && deferred) deferred = false, simulated = true;
            } else if (what == 1) {
                ws.setWorkstationWindow({0, 0, 0}, {0.5 + 0.25 * double(random() % 3), 1, 1});
                change();
            } else if (what == 2) {
                posted = !posted;
                if (posted)
                    ws.postStructure(1, 0.5);
                else
                    ws.unpostAllStructures();
                change();
            } else if (what == 3) {
                const bool perform = random() % 2;
                ws.update(perform ? Regeneration::Perform : Regeneration::Postpone);
                if (perform) deferred = simulated = false;
            } else if (what == 4) {
                ws.redrawAllStructures();
                deferred = simulated = false;
            }
            // Shown at once, simulated at once, or (nothing deferred) shown already.
            if (atOnce(deferral) || modification == ModificationMode::Uqum || !deferred) shownPosted = posted;
            VisualState expected = VisualState::Correct;
            if (!atOnce(deferral) && deferred)
                expected =
                    modification == ModificationMode::Uqum ? VisualState::Simulated : VisualState::Deferred;
            else if (!atOnce(deferral) && simulated)
                expected = VisualState::Simulated;
            INFO("run " << run << " step " << step << trace);
            CHECK(ws.visualState() == expected);
            CHECK(ws.surfaceEmpty() == !shownPosted);
        }
    }
}

TEST_CASE("WAIT with NIVE or UWOR defers a change, UQUM simulates it, UPDATE performs it", "[ws][state]") {
    for (ModificationMode mode : {ModificationMode::Nive, ModificationMode::Uwor, ModificationMode::Uqum}) {
        Phigs phigs;
        phigs.open();
        Workstation& ws = phigs.openWorkstation(1, WorkstationType::Hardcopy);
        ws.postStructure(1, 0.5);
        ws.display();
        ws.setDeferralState(DeferralMode::Wait, mode);
        ViewRepresentation view;
        view.mapping[0][0] = 0.5;
        ws.setViewRepresentation(1, view);
        const bool simulated = mode == ModificationMode::Uqum;
        CHECK(ws.viewUpdatePending(1) == !simulated);
        CHECK(ws.current().views.defined(1) == simulated);
        CHECK(ws.visualState() == (simulated ? VisualState::Simulated : VisualState::Deferred));
        CHECK(ws.newFrameNecessary());
        ws.display();
        CHECK(ws.viewUpdatePending(1) == !simulated);  // showing does not perform a deferred change
        ws.update(Regeneration::Postpone);
        CHECK(ws.viewUpdatePending(1) == !simulated);
        ws.update(Regeneration::Perform);
        CHECK_FALSE(ws.viewUpdatePending(1));
        CHECK(ws.current().views.get(1).mapping[0][0] == 0.5);
        CHECK(ws.visualState() == VisualState::Correct);
        CHECK_FALSE(ws.newFrameNecessary());
        // Unposting empties the surface at once only where the change shows at once.
        ws.unpostAllStructures();
        CHECK(ws.surfaceEmpty() == simulated);
        ws.update(Regeneration::Perform);
        CHECK(ws.surfaceEmpty());
    }
}

TEST_CASE("a new workstation starts with its type's predefined representations", "[ws][state]") {
    Phigs phigs;
    phigs.open();
    Workstation& ws = phigs.openWorkstation(1, WorkstationType::SvgFile);
    const PredefinedRepresentations& p = predefinedRepresentations(WorkstationType::SvgFile);
    REQUIRE(p.polylines.size() == 5);
    for (std::size_t i = 0; i < p.polylines.size(); ++i)
        CHECK(ws.tables().polylines.get(int(i) + 1) == p.polylines[i]);
    for (std::size_t i = 0; i < p.edges.size(); ++i) CHECK(ws.tables().edges.get(int(i) + 1) == p.edges[i]);
    CHECK(ws.patterns().definedIndices() == std::vector<int>{1, 2});
    CHECK(*ws.patterns().find(1) == p.patterns[0]);
    CHECK(ws.colourModel() == 1);
    CHECK(ws.visualState() == VisualState::Correct);
    CHECK(ws.surfaceEmpty());
}

TEST_CASE("representation errors in the standard's order leave the tables unchanged", "[ws][state][errors]") {
    Phigs phigs;
    phigs.open();
    Workstation& ws = phigs.openWorkstation(1, WorkstationType::PdfFile);
    const PolylineBundle before = ws.tables().polylines.get(2);
    CHECK(errorOf([&] {
              ws.setPolylineRepresentation(0, {LineType(9), 1, Colour::indexed(-1)});
          }) == errors::BundleIndexBelowOne);
    CHECK(errorOf([&] {
              ws.setPolylineRepresentation(2, {LineType(9), 1, Colour::indexed(-1)});
          }) == errors::ColourIndexBelowZero);
    CHECK(errorOf([&] {
              ws.setPolylineRepresentation(2, {LineType(9), 1, Colour::indexed(1)});
          }) == errors::BadLineType);
    CHECK(ws.tables().polylines.get(2) == before);
    CHECK(errorOf([&] {
              ws.setTextRepresentation(2, {5, 2, 1, 0, Colour::indexed(1)});
          }) == errors::TextFontNotAvailable);
    CHECK(errorOf([&] {
              ws.setTextRepresentation(2, {1, 3, 1, 0, Colour::indexed(1)});
          }) == errors::TextFontNotAvailable);
    CHECK(errorOf([&] {
              ws.setEdgeRepresentation(2, {true, LineType(0), 1, Colour::indexed(1)});
          }) == errors::EdgeTypeNotAvailable);
    InteriorBundle pattern;
    pattern.style = InteriorStyle::Pattern;
    pattern.styleIndex = 0;
    CHECK(errorOf([&] { ws.setInteriorRepresentation(2, pattern); }) == errors::PatternIndexBelowOne);
    CHECK(errorOf([&] { ws.setPatternRepresentation(0, {}); }) == errors::PatternIndexBelowOne);
    CHECK(errorOf([&] {
              ws.setPatternRepresentation(3, PatternRepresentation::indexed(2, 2, {1, 1, 1}));
          }) == errors::BadPatternDimensions);
    CHECK(errorOf([&] { ws.setPatternRepresentation(3, PatternRepresentation::indexed(1, 1, {-2})); }) ==
          errors::ColourIndexBelowZero);
    for (int i = 3; i <= ws.description().patternTableSize; ++i) ws.setPatternRepresentation(i, {});
    CHECK(errorOf([&] { ws.setPatternRepresentation(99, {}); }) == errors::BundleTableFull);
    CHECK(ws.patterns().find(99) == nullptr);
    CHECK(errorOf([&] { ws.setColourModel(5); }) == errors::ColourModelNotAvailable);
    CHECK(ws.colourModel() == 1);
}

TEST_CASE("realized representations: widths and sizes within the facilities, stroke text", "[ws][state]") {
    std::mt19937 random(77);
    const WorkstationDescription d = describeWorkstationType(WorkstationType::OffscreenImage);
    const ColourTable colours;
    for (int i = 0; i < 200; ++i) {
        const double scale = std::ldexp(double(random() % 1000 + 1), -int(random() % 12));
        const int colour = int(random() % 20);
        const PolylineBundle line =
            realized(PolylineBundle{LineType::Solid, scale, Colour::indexed(colour)}, d, colours);
        INFO("scale " << scale << " colour " << colour);
        CHECK(line.width * d.primitives.nominalLineWidth >= d.primitives.minLineWidth - 1e-12);
        CHECK(line.width * d.primitives.nominalLineWidth <= d.primitives.maxLineWidth + 1e-12);
        if (scale * d.primitives.nominalLineWidth >= d.primitives.minLineWidth &&
            scale * d.primitives.nominalLineWidth <= d.primitives.maxLineWidth)
            CHECK(line.width == Approx(scale));
        CHECK(line.colour.index == (colour <= 7 ? colour : 1));
        const PolymarkerBundle marker =
            realized(PolymarkerBundle{MarkerType::Dot, scale, Colour::indexed(1)}, d, colours);
        CHECK(marker.scale * d.primitives.nominalMarkerSize <= d.primitives.maxMarkerSize + 1e-9);
        CHECK(marker.scale * d.primitives.nominalMarkerSize >= d.primitives.minMarkerSize - 1e-9);
        CHECK(realized(TextBundle{1, int(random() % 3), 1, 0, Colour::indexed(1)}, d, colours).precision ==
              2);
    }
    CHECK(realized(PatternRepresentation::indexed(2, 1, {3, 99}), colours) ==
          PatternRepresentation::indexed(2, 1, {3, 1}));
}

TEST_CASE("a pick traversal in a deferred state reads the views of the picture shown", "[ws][state]") {
    Phigs phigs;
    phigs.open();
    StructureStore& store = phigs.store();
    store.openStructure(1);
    store.insert(IndexAttribute{ElementType::ViewIndex, 1});
    store.insert(polyline3({{0, 0, 0}, {1, 1, 0}}));
    store.closeStructure();
    Workstation& ws = phigs.openWorkstation(1, WorkstationType::Hardcopy);
    ws.postStructure(1, 0.5);
    ViewRepresentation first;
    ws.setViewRepresentation(1, first);
    ws.display();
    ws.setDeferralState(DeferralMode::Wait, ModificationMode::Nive);
    ViewRepresentation second;
    second.mapping[0][0] = 0.5;
    ws.setViewRepresentation(1, second);
    const auto viewOf = [](const DrawList& list) { return list.views.at(1).mapping[0][0]; };
    CHECK(viewOf(ws.display()) == 1.0);
    CHECK(viewOf(ws.traverse({})) == 1.0);  // what is shown, not what is requested
    ws.update(Regeneration::Perform);
    CHECK(viewOf(ws.display()) == 0.5);
    CHECK(viewOf(ws.traverse({})) == 0.5);
}

}  // namespace test_ws_state
