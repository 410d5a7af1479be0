#include "ErrorNumber.h"
#include "InputFakes.h"

#include "phigs/core/Error.h"
#include "phigs/input/ScriptInputSource.h"
#include "phigs/input/WorkstationInput.h"

#include <catch2/catch.hpp>

#include <deque>
#include <random>
#include <string>

namespace test_input_devices {

using namespace phigs;
using phigs::test::errorOf;
using namespace std::chrono_literals;
using Catch::Matchers::Contains;
using phigs::test::FakeMeasurer;
using phigs::test::IdleSource;

namespace {

struct Rig {
    explicit Rig(const std::string& script, std::size_t capacity = 64)
        : source(script, "s.txt"), queue(capacity), input(1, source, measurer, queue) {}
    ScriptInputSource source;
    FakeMeasurer measurer;
    InputQueue queue;
    WorkstationInput input;
};

}  // namespace

TEST_CASE("input devices: REQUEST waits for its own device and returns its measure", "[input]") {
    Rig r("valuator 2 0.5\nlocator 12 34\nchoice 3\nstring hi there\nstroke 1 2 3 4\npick 5 6\n");
    // The valuator line reaches no waiting device and is noted as ignored.
    auto [status, measure] = r.input.request(InputClass::Locator, 1);
    CHECK(status == InputStatus::Ok);
    CHECK(std::get<LocatorMeasure>(measure).position == glm::dvec3(12, 34, 0));
    REQUIRE(r.input.ignoredActions().size() == 1);
    CHECK_THAT(r.input.ignoredActions()[0], Contains("s.txt line 1") && Contains("valuator 2 0.5"));

    auto choice = r.input.request(InputClass::Choice, 1);
    CHECK(choice.first == InputStatus::Ok);
    CHECK(std::get<ChoiceMeasure>(choice.second).choice == 3);
    CHECK(std::get<StringMeasure>(r.input.request(InputClass::String, 1).second).text == "hi there");
    CHECK(std::get<StrokeMeasure>(r.input.request(InputClass::Stroke, 1).second).points ==
          std::vector<glm::dvec3>{{1, 2, 0}, {3, 4, 0}});
    const auto pick = r.input.request(InputClass::Pick, 1);
    CHECK(pick.first == InputStatus::Ok);
    CHECK(std::get<PickMeasure>(pick.second).path == std::vector<PickPathItem>{{1, 5, 6}});
    CHECK_THROWS_AS(r.input.request(InputClass::Pick, 1), InputExhausted);
    CHECK(r.input.history().size() == 6);
}

TEST_CASE("input devices: a break ends a request with status NONE, a pick of nothing is NONE", "[input]") {
    Rig r("break\npick -1 0\n");
    CHECK(r.input.request(InputClass::Valuator, 1).first == InputStatus::None);
    CHECK(r.input.request(InputClass::Pick, 1).first == InputStatus::None);
}

TEST_CASE("input devices: valuator range and initial value", "[input]") {
    Rig r("valuator 1 7.5\nvaluator 1 11\n");
    DeviceInitialisation v;
    v.initial = ValuatorMeasure{5.0};
    v.valuatorLow = 0.0;
    v.valuatorHigh = 10.0;
    r.input.initialise(InputClass::Valuator, 1, v);
    CHECK(std::get<ValuatorMeasure>(r.input.device(InputClass::Valuator, 1).current).value == 5.0);
    CHECK(std::get<ValuatorMeasure>(r.input.request(InputClass::Valuator, 1).second).value == 7.5);
    CHECK_THROWS_WITH(r.input.request(InputClass::Valuator, 1),
                      Contains("s.txt line 2") && Contains("outside the range [0.000000, 10.000000]"));

    v.initial = ValuatorMeasure{12.0};
    CHECK(errorOf([&] { r.input.initialise(InputClass::Valuator, 1, v); }) == 261);
    v.valuatorHigh = -1.0;
    CHECK(errorOf([&] { r.input.initialise(InputClass::Valuator, 1, v); }) == 260);
    // A refused initialisation leaves the device as it was.
    CHECK(r.input.device(InputClass::Valuator, 1).setup.valuatorHigh == 10.0);
}

TEST_CASE("input devices: choice alternatives are chosen by number or by name", "[input]") {
    Rig r("choice Fuselage\nchoice 3\nchoice 0\nchoice 4\nchoice Engine\n");
    DeviceInitialisation c;
    c.initial = ChoiceMeasure{InputStatus::Ok, 1};
    c.choiceStrings = {"Wing", "Fuselage", "Tail"};
    r.input.initialise(InputClass::Choice, 1, c);
    CHECK(std::get<ChoiceMeasure>(r.input.request(InputClass::Choice, 1).second).choice == 2);
    CHECK(std::get<ChoiceMeasure>(r.input.request(InputClass::Choice, 1).second).choice == 3);
    CHECK(r.input.request(InputClass::Choice, 1).first == InputStatus::None);  // choice 0: no choice
    CHECK_THROWS_WITH(r.input.request(InputClass::Choice, 1),
                      Contains("line 4") && Contains("alternatives 1..3"));
    CHECK_THROWS_WITH(r.input.request(InputClass::Choice, 1),
                      Contains("line 5") && Contains("no alternative 'Engine'"));
    c.initial = ChoiceMeasure{InputStatus::Ok, 4};
    CHECK(errorOf([&] { r.input.initialise(InputClass::Choice, 1, c); }) == 261);
}

TEST_CASE("input devices: initialisation is checked against its class's rules", "[input]") {
    Rig r("");
    DeviceInitialisation s;
    s.initial = StringMeasure{"abcdef"};
    s.bufferSize = 4;
    CHECK(errorOf([&] { r.input.initialise(InputClass::String, 1, s); }) == 263);
    s.initial = LocatorMeasure{};
    CHECK(errorOf([&] { r.input.initialise(InputClass::String, 1, s); }) == 261);
    DeviceInitialisation k;
    k.initial = StrokeMeasure{0, {{0, 0, 0}, {1, 1, 1}}};
    k.bufferSize = 1;
    CHECK(errorOf([&] { r.input.initialise(InputClass::Stroke, 1, k); }) == 262);
    DeviceInitialisation e;
    e.initial = LocatorMeasure{};
    e.promptEchoType = 9;
    CHECK(errorOf([&] { r.input.initialise(InputClass::Locator, 1, e); }) == 253);
    e.promptEchoType = 1;
    e.echoVolume = {10, 5, 0, 1, 0, 1};
    CHECK(errorOf([&] { r.input.initialise(InputClass::Locator, 1, e); }) == 254);
    DeviceInitialisation p;
    p.initial = PickMeasure{};
    p.pickAperture = 0.0;
    CHECK(errorOf([&] { r.input.initialise(InputClass::Pick, 1, p); }) == 260);
    CHECK(errorOf([&] { r.input.initialise(InputClass::Pick, 2, p); }) == 250);  // one pick device
    CHECK(errorOf([&] { r.input.device(InputClass::Valuator, 13); }) == 250);

    p.pickAperture = 0.02;
    r.input.setMode(InputClass::Pick, 1, OperatingMode::Event);
    CHECK(errorOf([&] { r.input.initialise(InputClass::Pick, 1, p); }) == 251);
    CHECK(errorOf([&] { r.input.request(InputClass::Pick, 1); }) == 251);
    CHECK(errorOf([&] { r.input.sample(InputClass::Pick, 1); }) == 252);
}

TEST_CASE("input devices: the device state inquiry reports mode, echo, setup and filter", "[input]") {
    Rig r("");
    DeviceInitialisation p;
    p.initial = PickMeasure{};
    p.pathOrder = PathOrder::BottomFirst;
    p.pickAperture = 0.05;
    r.input.initialise(InputClass::Pick, 1, p);
    // ISO 9592: a pick filter starts with empty inclusion and exclusion sets.
    CHECK(r.input.device(InputClass::Pick, 1).pickInclusion.empty());
    CHECK(r.input.device(InputClass::Pick, 1).pickExclusion.empty());
    r.input.setPickFilter(1, {1, 2}, {3});
    r.input.setPickPathDepth(1, 2);
    r.input.setMode(InputClass::Pick, 1, OperatingMode::Sample, EchoSwitch::NoEcho);
    const InputDevice& d = r.input.device(InputClass::Pick, 1);
    CHECK(d.mode == OperatingMode::Sample);
    CHECK(d.echo == EchoSwitch::NoEcho);
    CHECK(d.setup.pathOrder == PathOrder::BottomFirst);
    CHECK(d.setup.pickAperture == 0.05);
    CHECK(d.pickInclusion == std::set<int>{1, 2});
    CHECK(d.pickExclusion == std::set<int>{3});
    CHECK(d.pickPathDepth == 2);
    CHECK(errorOf([&] { r.input.setPickPathDepth(1, -1); }) == 207);
}

TEST_CASE("input devices: SAMPLE reads the latest measure without waiting", "[input]") {
    Rig r("valuator 1 0.25\nvaluator 1 0.75\n");
    r.input.setMode(InputClass::Valuator, 1, OperatingMode::Sample);
    CHECK(std::get<ValuatorMeasure>(r.input.sample(InputClass::Valuator, 1)).value == 0.0);  // initial
    CHECK(r.input.pump(0ms) == WorkstationInput::Pumped::Delivered);
    CHECK(std::get<ValuatorMeasure>(r.input.sample(InputClass::Valuator, 1)).value == 0.25);
    r.input.pump(0ms);
    CHECK(std::get<ValuatorMeasure>(r.input.sample(InputClass::Valuator, 1)).value == 0.75);
    CHECK(r.queue.size() == 0);
}

TEST_CASE("input devices: EVENT mode queues reports, AWAIT EVENT and GET read them in order", "[input]") {
    Rig r("valuator 2 0.5\nchoice 2\nstring abc\n");
    r.input.setMode(InputClass::Valuator, 2, OperatingMode::Event);
    r.input.setMode(InputClass::Choice, 1, OperatingMode::Event);
    r.input.setMode(InputClass::String, 1, OperatingMode::Event);
    auto e = r.queue.awaitEvent(0ms);
    REQUIRE(e);
    CHECK(e->workstation == 1);
    CHECK(e->inputClass == InputClass::Valuator);
    CHECK(e->device == 2);
    CHECK(std::get<ValuatorMeasure>(r.queue.currentMeasure(InputClass::Valuator, "GET VALUATOR")).value ==
          0.5);
    CHECK(errorOf([&] { r.queue.currentMeasure(InputClass::Choice, "GET CHOICE"); }) == 259);
    e = r.queue.awaitEvent(0ms);
    REQUIRE(e);
    CHECK(e->inputClass == InputClass::Choice);
    e = r.queue.awaitEvent(0ms);
    REQUIRE(e);
    CHECK(std::get<StringMeasure>(e->measure).text == "abc");
}

TEST_CASE("input devices: one trigger gives simultaneous pick and locator events", "[input]") {
    Rig r("pick 7 8\nlocator 1 1\n");
    r.input.setMode(InputClass::Pick, 1, OperatingMode::Event);
    r.input.setMode(InputClass::Locator, 1, OperatingMode::Event);
    auto first = r.queue.awaitEvent(0ms);
    REQUIRE(first);
    CHECK(first->inputClass == InputClass::Pick);
    CHECK(first->moreSimultaneous);
    CHECK(r.queue.moreSimultaneousEvents());
    auto second = r.queue.awaitEvent(0ms);
    REQUIRE(second);
    CHECK(second->inputClass == InputClass::Locator);
    CHECK(std::get<LocatorMeasure>(second->measure).position == glm::dvec3(7, 8, 0));
    CHECK_FALSE(second->moreSimultaneous);
    CHECK_FALSE(r.queue.moreSimultaneousEvents());
    auto third = r.queue.awaitEvent(0ms);
    REQUIRE(third);
    CHECK_FALSE(third->moreSimultaneous);
}

TEST_CASE("input devices: a full queue overflows, loses the trigger's events and says which", "[input]") {
    Rig r("choice 1\nchoice 2\npick 3 4\nchoice 3\n", 3);
    std::vector<int> warnings;
    r.queue.setWarningSink([&](const Error& e) { warnings.push_back(e.number()); });
    r.input.setMode(InputClass::Choice, 1, OperatingMode::Event);
    r.input.setMode(InputClass::Pick, 1, OperatingMode::Event);
    r.input.setMode(InputClass::Locator, 1, OperatingMode::Event);
    CHECK(errorOf([&] { r.queue.inquireOverflow(); }) == 257);
    for (int i = 0; i < 3; ++i) r.input.pump(0ms);
    // choice 1, choice 2 fit; the pick and its locator (two events) do not: neither is queued.
    CHECK(r.queue.size() == 2);
    CHECK(warnings == std::vector<int>{256});
    const QueueOverflow o = r.queue.inquireOverflow();
    CHECK(o.workstation == 1);
    CHECK(o.inputClass == InputClass::Pick);
    CHECK(o.device == 1);
    CHECK(errorOf([&] { r.queue.inquireOverflow(); }) == 257);  // cleared by the inquiry
    r.input.pump(0ms);
    CHECK(r.queue.size() == 2);  // choice 3 would fit, but the queue is closed until emptied
    CHECK(warnings == std::vector<int>{256});
    CHECK_THROWS_AS(InputQueue(0), std::invalid_argument);
}

TEST_CASE("input devices: an overflowed queue takes events again once AWAIT EVENT finds it empty",
          "[input]") {
    // Random event streams against a model of the rule: full -> closed; AWAIT on empty -> open.
    std::mt19937 rng(20261205);
    for (int round = 0; round < 200; ++round) {
        const std::size_t capacity = 1 + rng() % 5;
        std::string script;
        std::vector<std::string> lines;
        for (int i = 0; i < 40; ++i) script += "choice " + std::to_string(1 + i % 9) + "\n";
        Rig r(script, capacity);
        int warnings = 0;
        r.queue.setWarningSink([&](const Error&) { ++warnings; });
        r.input.setMode(InputClass::Choice, 1, OperatingMode::Event);
        std::deque<int> model;
        bool closed = false;
        int expectedWarnings = 0, next = 0;
        for (int step = 0; step < 40; ++step) {
            if (rng() % 3 == 0) {
                const bool wasEmpty = model.empty();
                const auto event = r.queue.awaitEvent(0ms);
                // With the queue empty, AWAIT EVENT opens it and pumps the script: one line.
                if (wasEmpty) {
                    closed = false;
                    if (next < 40) {
                        ++next;
                        REQUIRE(event);
                        CHECK(std::get<ChoiceMeasure>(event->measure).choice == 1 + (next - 1) % 9);
                    }
                    continue;
                }
                REQUIRE(event);
                CHECK(std::get<ChoiceMeasure>(event->measure).choice == model.front());
                model.pop_front();
            } else if (next < 40) {
                r.input.pump(0ms);
                const int choice = 1 + next % 9;
                ++next;
                if (closed) continue;
                if (model.size() == capacity) {
                    closed = true;
                    ++expectedWarnings;
                    continue;
                }
                model.push_back(choice);
            }
            REQUIRE(r.queue.size() == model.size());
        }
        CHECK(warnings == expectedWarnings);
    }
}

TEST_CASE("input devices: the overflow of a workstation closed since is error 258", "[input]") {
    FakeMeasurer measurer;
    InputQueue queue(1);
    ScriptInputSource first("choice 1\nchoice 2\n", "a.txt");
    {
        WorkstationInput closing(1, first, measurer, queue);
        closing.setMode(InputClass::Choice, 1, OperatingMode::Event);
        closing.pump(0ms);
        closing.pump(0ms);  // overflows: the queue holds one
        CHECK(queue.size() == 1);
    }  // workstation 1 closes: its events go, the overflow record stays
    CHECK(queue.size() == 0);
    CHECK(errorOf([&] { queue.inquireOverflow(); }) == 258);
    CHECK(errorOf([&] { queue.inquireOverflow(); }) == 257);  // 258 cleared it
}

TEST_CASE("input devices: every choice device refuses choices beyond its alternatives", "[input]") {
    // Numbered alternatives (no strings) end at the workstation's most, named ones at their count;
    // both for INITIALIZE (261) and for what the source sends (the action's error).
    std::mt19937 rng(5122026);
    for (int round = 0; round < 40; ++round) {
        const int named = static_cast<int>(rng() % 4) == 0 ? 0 : 1 + static_cast<int>(rng() % 70);
        DeviceInitialisation c;
        for (int i = 0; i < named; ++i) c.choiceStrings.push_back("alternative " + std::to_string(i + 1));
        const int count = named == 0 ? kMaxChoiceAlternatives : named;
        const int beyond = count + 1 + static_cast<int>(rng() % 1000);
        INFO("round " << round << ": " << count << " alternatives, choice " << beyond);
        Rig r("choice " + std::to_string(count) + "\nchoice " + std::to_string(beyond) + "\n");
        c.initial = ChoiceMeasure{InputStatus::Ok, beyond};
        CHECK(errorOf([&] { r.input.initialise(InputClass::Choice, 1, c); }) == 261);
        c.initial = ChoiceMeasure{InputStatus::Ok, count};
        r.input.initialise(InputClass::Choice, 1, c);
        CHECK(std::get<ChoiceMeasure>(r.input.request(InputClass::Choice, 1).second).choice == count);
        CHECK_THROWS_WITH(r.input.request(InputClass::Choice, 1),
                          Contains("line 2") && Contains("alternatives 1.." + std::to_string(count)));
    }
}

TEST_CASE("input devices: an operator's action no device can take is ignored and the request waits on",
          "[input]") {
    // A function key past a choice device's alternatives, a valuator value out of range, a name no
    // alternative has: from a window each is ignored (and said so); a pending request of any
    // device goes on to the operator's next action. The same lines from a script are errors.
    std::mt19937 rng(712);
    for (int round = 0; round < 30; ++round) {
        IdleSource window;
        FakeMeasurer measurer;
        InputQueue queue;
        WorkstationInput input(1, window, measurer, queue);
        DeviceInitialisation choices;
        choices.choiceStrings = {"a", "b", "c", "d"};
        choices.initial = ChoiceMeasure{InputStatus::Ok, 1};
        input.initialise(InputClass::Choice, 1, choices);
        const bool requestChoice = rng() % 2 == 0;
        const int stray = static_cast<int>(rng() % 3);
        InputAction bad;
        bad.fromOperator = true;
        bad.text = "stray";
        if (stray == 0) bad.what = action::Choice{5 + static_cast<int>(rng() % 20), 1, {}};
        if (stray == 1) bad.what = action::Valuator{1, 2.0 + static_cast<double>(rng() % 10)};
        if (stray == 2) bad.what = action::Choice{0, 1, "z"};
        InputAction good;
        good.fromOperator = true;
        if (requestChoice)
            good.what = action::Choice{3, 1, {}};
        else
            good.what = action::Valuator{1, 0.25};
        window.actions = {bad, good};
        INFO("round " << round << ", stray " << stray << (requestChoice ? ", choice" : ", valuator"));
        if (requestChoice) {
            const auto [status, measure] = input.request(InputClass::Choice, 1);
            CHECK(status == InputStatus::Ok);
            CHECK(std::get<ChoiceMeasure>(measure).choice == 3);
        } else {
            const auto [status, measure] = input.request(InputClass::Valuator, 1);
            CHECK(status == InputStatus::Ok);
            CHECK(std::get<ValuatorMeasure>(measure).value == 0.25);
        }
        CHECK_FALSE(input.ignoredActions().empty());
        // From a script the same action is the line's error.
        bad.fromOperator = false;
        window.actions = {bad};
        CHECK_THROWS_AS(input.request(requestChoice ? InputClass::Choice : InputClass::Valuator, 1),
                        ScriptError);
    }
}

TEST_CASE("input devices: what a window's operator did before AWAIT or FLUSH EVENTS is queued first",
          "[input]") {
    // ISO 9592: FLUSH DEVICE EVENTS removes the events already made, and the queue overflows
    // when the operator made more than it holds. A script's lines happen as they are read.
    const auto choice = [](int c) {
        InputAction a;
        a.fromOperator = true;
        a.what = action::Choice{c, 1, {}};
        return a;
    };
    for (const bool live : {true, false}) {
        INFO((live ? "window" : "script-like source"));
        {
            IdleSource source;
            source.isLive = live;
            FakeMeasurer measurer;
            InputQueue queue;
            WorkstationInput input(1, source, measurer, queue);
            input.setMode(InputClass::Choice, 1, OperatingMode::Event);
            source.actions = {choice(1), choice(2)};
            queue.flush(1, InputClass::Choice, 1);
            const auto e = queue.awaitEvent(0ms);
            CHECK(e.has_value() == !live);
        }
        {
            std::mt19937 rng(live ? 3 : 4);
            const int made = 65 + static_cast<int>(rng() % 100);
            IdleSource source;
            source.isLive = live;
            FakeMeasurer measurer;
            InputQueue queue(64);
            WorkstationInput input(1, source, measurer, queue);
            input.setMode(InputClass::Choice, 1, OperatingMode::Event);
            for (int i = 0; i < made; ++i) source.actions.push_back(choice(1 + i % 4));
            REQUIRE(queue.awaitEvent(0ms));
            INFO(made << " choices made");
            if (live)
                CHECK(queue.inquireOverflow().device == 1);
            else
                CHECK(errorOf([&] { queue.inquireOverflow(); }) == 257);
        }
    }
}

TEST_CASE("input devices: a new source on the same queue keeps the queued events and overflow", "[input]") {
    // Only leaving the queue (closing the workstation) removes its events; attaching another
    // script to an open workstation must not.
    std::mt19937 rng(20261205);
    for (int round = 0; round < 60; ++round) {
        const std::size_t capacity = 1 + rng() % 8;
        const int lines = static_cast<int>(rng() % 12);
        std::string script;
        for (int i = 0; i < lines; ++i) script += "choice " + std::to_string(1 + i) + "\n";
        Rig r(script, capacity);
        r.input.setMode(InputClass::Choice, 1, OperatingMode::Event);
        for (int i = 0; i < lines; ++i) r.input.pump(0ms);
        const std::size_t queued = r.queue.size();
        INFO("round " << round << ": capacity " << capacity << ", " << lines << " events");
        REQUIRE(queued == std::min<std::size_t>(capacity, std::size_t(lines)));
        ScriptInputSource next("choice 50\n", "next.txt");
        r.input.connect(next, r.queue);
        CHECK(r.queue.size() == queued);
        if (std::size_t(lines) > capacity) {
            const QueueOverflow o = r.queue.inquireOverflow();  // not 258: the workstation is open
            CHECK(o.workstation == 1);
            CHECK(o.device == 1);
        }
        for (std::size_t i = 0; i < queued; ++i) {
            const auto event = r.queue.awaitEvent(0ms);
            REQUIRE(event);
            CHECK(std::get<ChoiceMeasure>(event->measure).choice == int(i) + 1);
        }
        // Then the new source's line.
        const auto last = r.queue.awaitEvent(0ms);
        REQUIRE(last);
        CHECK(std::get<ChoiceMeasure>(last->measure).choice == 50);
    }
}

TEST_CASE("input devices: FLUSH DEVICE EVENTS removes one device's reports", "[input]") {
    Rig r("choice 1\nvaluator 1 0.5\nchoice 2 device 2\nchoice 3\n");
    r.input.setMode(InputClass::Choice, 1, OperatingMode::Event);
    r.input.setMode(InputClass::Choice, 2, OperatingMode::Event);
    r.input.setMode(InputClass::Valuator, 1, OperatingMode::Event);
    for (int i = 0; i < 4; ++i) r.input.pump(0ms);
    CHECK(r.queue.size() == 4);
    r.queue.flush(1, InputClass::Choice, 1);
    CHECK(r.queue.size() == 2);
    CHECK(r.queue.awaitEvent(0ms)->inputClass == InputClass::Valuator);
    CHECK(r.queue.awaitEvent(0ms)->device == 2);
}

TEST_CASE("input devices: AWAIT EVENT times out on a script 'wait' and on an idle source", "[input]") {
    Rig r("valuator 1 0.5\nwait\nchoice 1\n");
    r.input.setMode(InputClass::Valuator, 1, OperatingMode::Sample);
    r.input.setMode(InputClass::Choice, 1, OperatingMode::Event);
    // The sample line is consumed, the wait line ends the await with no event.
    CHECK_FALSE(r.queue.awaitEvent(10s).has_value());
    CHECK(std::get<ValuatorMeasure>(r.input.sample(InputClass::Valuator, 1)).value == 0.5);
    CHECK(errorOf([&] { r.queue.currentMeasure(InputClass::Valuator, "GET VALUATOR"); }) == 259);
    CHECK(r.queue.awaitEvent(10s)->inputClass == InputClass::Choice);

    IdleSource idle;
    FakeMeasurer measurer;
    InputQueue queue;
    WorkstationInput window(2, idle, measurer, queue);
    window.setMode(InputClass::Choice, 1, OperatingMode::Event);
    CHECK_FALSE(queue.awaitEvent(0ms).has_value());
    CHECK(idle.polls >= 1);
    InputAction a;
    a.what = action::Choice{2, 1, {}};
    idle.actions.push_back(a);
    const auto e = queue.awaitEvent(1s);
    REQUIRE(e);
    CHECK(e->workstation == 2);
}

TEST_CASE("input devices: two workstations share the queue, closing one flushes its events", "[input]") {
    ScriptInputSource a("choice 1\n", "a"), b("choice 2\n", "b");
    FakeMeasurer measurer;
    InputQueue queue;
    WorkstationInput first(1, a, measurer, queue);
    {
        WorkstationInput second(2, b, measurer, queue);
        first.setMode(InputClass::Choice, 1, OperatingMode::Event);
        second.setMode(InputClass::Choice, 1, OperatingMode::Event);
        first.pump(0ms);
        second.pump(0ms);
        CHECK(queue.size() == 2);
    }
    CHECK(queue.size() == 1);
    CHECK(queue.awaitEvent(0ms)->workstation == 1);
}

TEST_CASE("input devices: directives go to the application's handler", "[input]") {
    ScriptInputSource s("snapshot a.png\nchoice 1\n", "s", {"snapshot"});
    FakeMeasurer measurer;
    InputQueue queue;
    WorkstationInput input(1, s, measurer, queue);
    std::vector<std::string> seen;
    input.setDirectiveHandler([&](const action::Directive& d, const InputAction& a) {
        seen.push_back(d.name + " " + d.arguments.at(0) + " @" + std::to_string(a.line));
    });
    CHECK(input.request(InputClass::Choice, 1).first == InputStatus::Ok);
    CHECK(seen == std::vector<std::string>{"snapshot a.png @1"});
}

TEST_CASE("input devices: strings and strokes are cut to the buffer size", "[input]") {
    Rig r("string abcdefgh\nstroke 0 0 1 1 2 2 3 3\n");
    DeviceInitialisation s;
    s.initial = StringMeasure{};
    s.bufferSize = 3;
    r.input.initialise(InputClass::String, 1, s);
    DeviceInitialisation k;
    k.initial = StrokeMeasure{};
    k.bufferSize = 2;
    r.input.initialise(InputClass::Stroke, 1, k);
    CHECK(std::get<StringMeasure>(r.input.request(InputClass::String, 1).second).text == "abc");
    CHECK(std::get<StrokeMeasure>(r.input.request(InputClass::Stroke, 1).second).points.size() == 2);
}

TEST_CASE("input devices: a string is cut between UTF-8 characters, never through one", "[input]") {
    // Characters of 1 to 4 bytes in random strings and buffer sizes: the measure is the longest
    // start of the text within the buffer that ends on a character boundary.
    const std::string characters[] = {"a", "\xC3\xA9", "\xE2\x82\xAC",
                                      "\xF0\x9F\x98\x80"};  // a e-acute euro emoji
    std::mt19937 random(7);
    for (int trial = 0; trial < 300; ++trial) {
        std::vector<std::size_t> ends;  // byte offsets where a character ends
        std::string text;
        for (int n = 1 + int(random() % 8); n > 0; --n) {
            text += characters[random() % 4];
            ends.push_back(text.size());
        }
        Rig r("string " + text + "\n");
        DeviceInitialisation s;
        s.initial = StringMeasure{};
        s.bufferSize = 1 + random() % (text.size() + 2);
        r.input.initialise(InputClass::String, 1, s);
        const std::string got = std::get<StringMeasure>(r.input.request(InputClass::String, 1).second).text;
        std::size_t want = 0;
        for (std::size_t e : ends)
            if (e <= s.bufferSize) want = e;
        CHECK(got == text.substr(0, want));
    }
}

TEST_CASE("input devices: pointer motion moves a sampled locator and triggers nothing", "[input]") {
    Rig r("move 3 4\nmove 5 6\nlocator 7 8\n");
    CHECK(r.input.pump(0ms) == WorkstationInput::Pumped::Nothing);  // nobody samples: dropped
    CHECK(r.input.ignoredActions().empty());
    CHECK(r.input.history().empty());
    r.input.setMode(InputClass::Locator, 1, OperatingMode::Sample);
    CHECK(r.input.pump(0ms) == WorkstationInput::Pumped::Delivered);
    CHECK(std::get<LocatorMeasure>(r.input.sample(InputClass::Locator, 1)).position == glm::dvec3(5, 6, 0));
    r.input.setMode(InputClass::Locator, 1, OperatingMode::Event);
    CHECK(r.queue.awaitEvent(0ms)->inputClass == InputClass::Locator);  // the locator line triggers
}

}  // namespace test_input_devices
