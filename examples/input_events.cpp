// Example 4, input in event mode: the six logical input devices (locator, stroke, valuator,
// choice, pick, string) of a workstation are set to EVENT mode, a session script plays the
// operator, and AWAIT EVENT takes the reports from the input queue in order. In a window,
// phigs::GlfwInputSource takes the script's place and nothing else changes.
//
//     input_events [SCRIPT]     the script file to replay (default: the one below)
#include "phigs/Phigs.h"
#include "phigs/input/ScriptInputSource.h"

#include <chrono>
#include <cstdio>
#include <exception>

namespace {

// Pixels from the top left of the 1024 x 768 display surface; NPC [0, 1]^2 covers its
// lower-left 768 x 768 pixels, so pixel (x, y) is NPC (x / 768, (768 - y) / 768).
const char* const kScript =
    "locator 192 576\n"             // NPC (0.25, 0.25)
    "stroke 0 768 384 384 768 0\n"  // NPC (0, 0), (0.5, 0.5), (1, 1)
    "valuator 1 7.5\n"
    "choice Tail\n"
    "pick 384 384\n"  // the middle of the square
    "string hello, input\n";

void print(const phigs::EventReport& event) {
    std::printf("%-8s device %d: ", phigs::nameOf(event.inputClass), event.device);
    std::visit(
        [](const auto& m) {
            using M = std::decay_t<decltype(m)>;
            if constexpr (std::is_same_v<M, phigs::LocatorMeasure>)
                std::printf("view %d, (%.3f, %.3f)\n", m.viewIndex, m.position.x, m.position.y);
            else if constexpr (std::is_same_v<M, phigs::StrokeMeasure>) {
                std::printf("view %d,", m.viewIndex);
                for (const auto& p : m.points) std::printf(" (%.3f, %.3f)", p.x, p.y);
                std::printf("\n");
            } else if constexpr (std::is_same_v<M, phigs::ValuatorMeasure>)
                std::printf("%.3f\n", m.value);
            else if constexpr (std::is_same_v<M, phigs::ChoiceMeasure>)
                std::printf("alternative %d\n", m.choice);
            else if constexpr (std::is_same_v<M, phigs::PickMeasure>) {
                std::printf("path");
                for (const auto& item : m.path)
                    std::printf(" (%d, %d, %d)", item.structureId, item.elementNumber, item.pickId);
                std::printf("\n");
            } else
                std::printf("\"%s\"\n", m.text.c_str());
        },
        event.measure);
}

}  // namespace

int main(int argc, char** argv) {
    using namespace std::chrono_literals;
    try {
        phigs::Phigs phigs;
        phigs.open();
        // Something to pick: a square with pick id 3 and name 1 in the middle of the picture.
        phigs::StructureStore& store = phigs.store();
        store.openStructure(1);
        store.insert(phigs::IndexAttribute{phigs::ElementType::InteriorStyle, 1});
        store.insert(phigs::pickId(3));
        store.insert(phigs::addNamesToSet({1}));
        store.insert(phigs::fillArea3({{0.4, 0.4, 0}, {0.6, 0.4, 0}, {0.6, 0.6, 0}, {0.4, 0.6, 0}}));
        store.closeStructure();
        phigs::Workstation& ws = phigs.openWorkstation(1, phigs::WorkstationType::OffscreenImage);
        ws.postStructure(1, 0.5);

        phigs::ScriptInputSource script = argc > 1 ? phigs::ScriptInputSource::fromFile(argv[1])
                                                   : phigs::ScriptInputSource(kScript, "script");
        phigs::InputQueue queue;
        ws.connectInput(script, queue);
        phigs::WorkstationInput& input = ws.input();
        // A pick filter starts empty (ISO 9592), so nothing is pickable until it includes a name.
        input.setPickFilter(1, {1}, {});

        // The choice device names its alternatives; the valuator ranges over [0, 10].
        phigs::DeviceInitialisation choice;
        choice.initial = phigs::ChoiceMeasure{phigs::InputStatus::Ok, 1};
        choice.choiceStrings = {"Wing", "Tail", "Body"};
        input.initialise(phigs::InputClass::Choice, 1, choice);
        phigs::DeviceInitialisation valuator;
        valuator.initial = phigs::ValuatorMeasure{5.0};
        valuator.valuatorLow = 0.0, valuator.valuatorHigh = 10.0;
        input.initialise(phigs::InputClass::Valuator, 1, valuator);

        for (phigs::InputClass device :
             {phigs::InputClass::Locator, phigs::InputClass::Stroke, phigs::InputClass::Valuator,
              phigs::InputClass::Choice, phigs::InputClass::Pick, phigs::InputClass::String})
            input.setMode(device, 1, phigs::OperatingMode::Event);

        // AWAIT EVENT until the script has nothing more to say. One action may trigger several
        // devices: the pick's click also places the locator, and the two reports are
        // simultaneous events (INQUIRE MORE SIMULTANEOUS EVENTS says so after the first).
        int events = 0;
        while (queue.size() > 0 || !script.exhausted()) {
            const auto event = queue.awaitEvent(100ms);
            if (!event) continue;
            const bool more = queue.moreSimultaneousEvents();
            print(*event);
            if (more) std::printf("         (more simultaneous events follow)\n");
            ++events;
        }
        std::printf("%d events\n", events);
        return events == 7 ? 0 : 1;
    } catch (const std::exception& e) {
        std::fprintf(stderr, "input_events: %s\n", e.what());
        return 1;
    }
}
