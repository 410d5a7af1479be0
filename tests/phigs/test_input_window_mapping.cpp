#include "phigs/input/WindowEventMapper.h"

#include <catch2/catch.hpp>

namespace test_input_window_mapping {

using namespace phigs;
using namespace phigs::window_event;

TEST_CASE("input window: clicks become pick and locator actions", "[input]") {
    WindowEventMapper m;
    auto a = m.handle(ButtonPress{Button::Left, {12, 34}, false});
    REQUIRE(a);
    CHECK(std::get<action::Pick>(a->what).position == glm::dvec2(12, 34));
    a = m.handle(ButtonPress{Button::Right, {5, 6}, false});
    REQUIRE(a);
    CHECK(std::get<action::Locate>(a->what).position == glm::dvec2(5, 6));
    CHECK_FALSE(m.handle(ButtonPress{Button::Middle, {5, 6}, false}));
    CHECK_FALSE(m.handle(ButtonRelease{Button::Left, {12, 34}}));
    const auto move = m.handle(CursorMove{{1, 1}});
    REQUIRE(move);
    CHECK(std::get<action::Move>(move->what).position == glm::dvec2(1, 1));
}

TEST_CASE("input window: a shift drag becomes a stroke, thinned by the spacing", "[input]") {
    WindowEventMapper m;
    CHECK_FALSE(m.handle(ButtonPress{Button::Left, {0, 0}, true}));
    CHECK(m.stroking());
    CHECK_FALSE(m.handle(CursorMove{{1, 0}}));  // closer than 2 pixels: dropped
    CHECK_FALSE(m.handle(CursorMove{{3, 0}}));
    CHECK_FALSE(m.handle(CursorMove{{6, 4}}));
    const auto a = m.handle(ButtonRelease{Button::Left, {10, 4}});
    REQUIRE(a);
    CHECK(std::get<action::Stroke>(a->what).points ==
          std::vector<glm::dvec2>{{0, 0}, {3, 0}, {6, 4}, {10, 4}});
    CHECK_FALSE(m.stroking());
}

TEST_CASE("input window: typed text with edits becomes a string on Enter", "[input]") {
    WindowEventMapper m;
    for (char32_t c : std::u32string(U"wingx")) CHECK_FALSE(m.handle(Character{c}));
    CHECK_FALSE(m.handle(KeyPress{Key::Backspace}));
    CHECK_FALSE(m.handle(Character{U'\u00e9'}));  // two UTF-8 bytes
    CHECK(m.pendingText() == "wing\xc3\xa9");
    CHECK_FALSE(m.handle(KeyPress{Key::Backspace}));  // removes both bytes
    CHECK(m.pendingText() == "wing");
    const auto a = m.handle(KeyPress{Key::Enter});
    REQUIRE(a);
    CHECK(std::get<action::String>(a->what).text == "wing");
    CHECK(m.pendingText().empty());
    CHECK(m.stringEcho().edits == 9);  // 5 + 1 + 1 + 1 characters and edits, and the Enter
    CHECK_FALSE(m.stringEcho().cancelled);
}

TEST_CASE("input window: Escape breaks, function keys choose", "[input]") {
    WindowEventMapper m;
    m.handle(Character{U'a'});
    auto a = m.handle(KeyPress{Key::Escape});
    REQUIRE(a);
    CHECK(std::holds_alternative<action::Break>(a->what));
    CHECK(m.pendingText().empty());
    CHECK(m.stringEcho().cancelled);  // the echo area says so until the next character
    m.handle(Character{U'b'});
    CHECK_FALSE(m.stringEcho().cancelled);
    CHECK(m.pendingText() == "b");
    a = m.handle(KeyPress{Key::Function, 3});
    REQUIRE(a);
    CHECK(std::get<action::Choice>(a->what).choice == 3);
    CHECK_FALSE(m.handle(KeyPress{Key::Function, 0}));
}

}  // namespace test_input_window_mapping
