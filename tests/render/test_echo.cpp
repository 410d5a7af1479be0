// Choice panels and valuator sliders drawn as PHIGS structures (buildChoicePanel,
// buildValuatorSlider), posted on an offscreen workstation, and clicked through a session
// script: a pick inside a panel row chooses it, inside a slider sets the value.
#include "RenderTestSupport.h"
#include "phigs/Phigs.h"
#include "phigs/input/ScriptInputSource.h"
#include "phigs/vk/WorkstationDisplay.h"
#include "phigs/ws/EchoStructures.h"

namespace test_echo {

using namespace phigs;
using namespace render_test;

namespace {

std::size_t pixelsLike(const Image& image, glm::dvec2 from, glm::dvec2 to, glm::dvec3 rgb) {
    std::size_t n = 0;
    for (double y = from.y; y < to.y; ++y)
        for (double x = from.x; x < to.x; ++x) n += shows(image, {x, y}, rgb);
    return n;
}

}  // namespace

TEST_CASE("echo structures: a menu panel and a slider are drawn by the toolkit and clicked by a script",
          "[render][echo]") {
    Phigs phigs;
    phigs.open();
    Workstation& ws = phigs.openWorkstation(1, WorkstationType::OffscreenImage);
    vk::DisplaySettings settings;
    settings.width = 256;
    settings.height = 192;
    vk::WorkstationDisplay display(ws, lavapipeWithValidation(), settings);

    // Rows of 20 pixels: Wing (10..30), Tail (30..50), Body (50..70); the slider runs from
    // x = 100 (0) to 180 (10). The workstation window (NPC's unit square) shows as the left
    // 192 x 192 pixels: echo areas must lie there to be seen.
    ScriptInputSource script("pick 50 45\npick 160 160\nlocator 60 62\n", "echo.txt");
    InputQueue queue;
    ws.connectInput(script, queue);
    WorkstationInput& input = ws.input();
    input.initialise(InputClass::Choice, 1,
                     choicePanelInitialisation({"Wing", "Tail", "Body"}, {10, 90, 10, 70, 0, 1}));
    input.initialise(InputClass::Valuator, 1,
                     valuatorSliderInitialisation(0, 10, 5, {100, 180, 150, 170, 0, 1}));
    const EchoLayout layout = input.echoLayout();
    REQUIRE(layout.panels.size() == 1);
    REQUIRE(layout.sliders.size() == 1);

    const EchoStyle style;
    auto show = [&](int choice, double value) {
        buildChoicePanel(phigs.store(), 100, layout.panels[0], choice, display.mapping(), style);
        buildValuatorSlider(phigs.store(), 101, layout.sliders[0], value, "Span", display.mapping(), style);
        ws.postStructure(100, 1.0);
        ws.postStructure(101, 1.0);
        REQUIRE(display.update());
        return display.image();
    };
    const Image before = show(1, 5.0);
    writePng(before, std::filesystem::path(PHIGS_TEST_OUTPUT_DIR) / "echo_before.png");
    CHECK(shows(before, {14, 20}, style.current));  // Wing is current
    CHECK(shows(before, {14, 40}, style.box));      // Tail is not
    CHECK(shows(before, {14, 60}, style.box));
    CHECK(shows(before, {140, 160}, style.current));  // the knob at 5
    CHECK(shows(before, {110, 160}, style.track));
    CHECK(shows(before, {5, 5}, glm::dvec3(0.0)));  // outside: the background
    // Every row carries its name in stroke text: text-coloured pixels inside the boxes.
    CHECK(pixelsLike(before, {30, 32}, {70, 48}, style.text) > 20);
    CHECK(pixelsLike(before, {30, 12}, {70, 28}, style.currentText) > 20);
    // The label and value above the slider.
    CHECK(pixelsLike(before, {100, 125}, {180, 150}, style.text) > 20);

    // The script's clicks: Tail, 7.5, and a locator press on Body.
    auto [status, measure] = input.request(InputClass::Choice, 1);
    CHECK(status == InputStatus::Ok);
    CHECK(std::get<ChoiceMeasure>(measure).choice == 2);
    auto [valueStatus, valueMeasure] = input.request(InputClass::Valuator, 1);
    CHECK(valueStatus == InputStatus::Ok);
    CHECK(std::get<ValuatorMeasure>(valueMeasure).value == Approx(7.5));
    auto [bodyStatus, bodyMeasure] = input.request(InputClass::Choice, 1);
    CHECK(bodyStatus == InputStatus::Ok);
    CHECK(std::get<ChoiceMeasure>(bodyMeasure).choice == 3);

    // The application shows the new state: the highlight and the knob move, nothing else.
    const Image after = show(2, 7.5);
    writePng(after, std::filesystem::path(PHIGS_TEST_OUTPUT_DIR) / "echo_after.png");
    CHECK(shows(after, {14, 20}, style.box));
    CHECK(shows(after, {14, 40}, style.current));
    CHECK(shows(after, {160, 160}, style.current));
    CHECK(shows(after, {140, 160}, style.track));

    // Building while a structure is open is refused (error 6) and changes nothing.
    phigs.store().openStructure(7);
    try {
        buildChoicePanel(phigs.store(), 100, layout.panels[0], 3, display.mapping(), style);
        FAIL("no error");
    } catch (const Error& e) {
        CHECK(e.number() == errors::NotStructureClosed);
    }
    phigs.store().closeStructure();
    REQUIRE(display.update());
    CHECK(display.image().rgba == after.rgba);
    requireNoValidationMessages(display.context());
}

}  // namespace test_echo
