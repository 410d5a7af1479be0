#include "phigs/input/ScriptInputSource.h"

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <random>

namespace test_input_script {

using namespace phigs;
using Catch::Matchers::Contains;

namespace {

std::string errorOf(const std::string& text, std::set<std::string> directives = {}) {
    try {
        ScriptInputSource s(text, "session.txt", std::move(directives));
    } catch (const ScriptError& e) {
        return e.what();
    }
    return "";
}

}  // namespace

TEST_CASE("input script: every action kind parses, comments and blank lines are skipped", "[input]") {
    const std::string text =
        "# a session\n"
        "pick 10 20\n"
        "\n"
        "locator 1.5 2.5 device 2   # trailing comment\n"
        "stroke 0 0 10 10 20 0\n"
        "valuator 3 0.25\n"
        "choice 2\n"
        "choice Wing device 4\n"
        "string   hello world  \n"
        "break\n"
        "wait\n"
        "snapshot front.png\n";
    ScriptInputSource s(text, "session.txt", {"snapshot"});
    const auto& a = s.actions();
    REQUIRE(a.size() == 10);
    CHECK(std::get<action::Pick>(a[0].what).position == glm::dvec2(10, 20));
    CHECK(a[0].line == 2);
    CHECK(std::get<action::Locate>(a[1].what).device == 2);
    CHECK(a[1].line == 4);
    CHECK(std::get<action::Stroke>(a[2].what).points.size() == 3);
    CHECK(std::get<action::Valuator>(a[3].what).device == 3);
    CHECK(std::get<action::Valuator>(a[3].what).value == 0.25);
    CHECK(std::get<action::Choice>(a[4].what).choice == 2);
    CHECK(std::get<action::Choice>(a[5].what).name == "Wing");
    CHECK(std::get<action::Choice>(a[5].what).device == 4);
    CHECK(std::get<action::String>(a[6].what).text == "hello world");
    CHECK(std::holds_alternative<action::Break>(a[7].what));
    CHECK(std::holds_alternative<action::Wait>(a[8].what));
    const auto& d = std::get<action::Directive>(a[9].what);
    CHECK(d.name == "snapshot");
    CHECK(d.arguments == std::vector<std::string>{"front.png"});
    CHECK(a[9].line == 12);
}

TEST_CASE("input script: bad lines are reported with file, line number and reason", "[input]") {
    CHECK_THAT(errorOf("pick 1 2\nfly 3\n"), Contains("session.txt:2:") && Contains("unknown action 'fly'"));
    CHECK_THAT(errorOf("\n\npick 10\n"), Contains("session.txt:3:") && Contains("pick X Y"));
    CHECK_THAT(errorOf("locator 1 abc\n"), Contains(":1:") && Contains("'abc' is not a finite number"));
    CHECK_THAT(errorOf("pick 1 nan\n"), Contains("not a finite number"));
    CHECK_THAT(errorOf("valuator 1\n"), Contains("valuator DEVICE VALUE"));
    CHECK_THAT(errorOf("valuator 0 0.5\n"), Contains("at least 1"));
    CHECK_THAT(errorOf("valuator 1.5 0.5\n"), Contains("not an integer"));
    CHECK_THAT(errorOf("stroke 1 2 3\n"), Contains("stroke X1 Y1"));
    CHECK_THAT(errorOf("choice\n"), Contains("choice N"));
    CHECK_THAT(errorOf("choice 2.5\n"), Contains("not an integer"));
    CHECK_THAT(errorOf("pick 1 2 device 0\n"), Contains("at least 1"));
    CHECK_THAT(errorOf("wait 3\n"), Contains("expected 'wait'"));
    CHECK_THAT(errorOf("snapshot x\n"), Contains("unknown action 'snapshot'"));
    CHECK(errorOf("snapshot x\n", {"snapshot"}).empty());
}

TEST_CASE("input script: a missing file names the file", "[input]") {
    CHECK_THROWS_WITH(ScriptInputSource::fromFile("/nonexistent/session.txt"),
                      Contains("/nonexistent/session.txt") && Contains("cannot open"));
}

TEST_CASE("input script: read from a file, replayed in order, then exhausted", "[input]") {
    const std::filesystem::path path = std::filesystem::path(PHIGS_TEST_OUTPUT_DIR) / "input_script.txt";
    {
        std::ofstream out(path);
        out << "choice 1\r\n\r\nstring ok\r\n";
    }
    auto s = ScriptInputSource::fromFile(path);
    CHECK_FALSE(s.exhausted());
    CHECK(s.next(std::chrono::milliseconds(0))->line == 1);
    CHECK(s.position() == path.string() + " line 1");
    CHECK(std::get<action::String>(s.next(std::chrono::milliseconds(0))->what).text == "ok");
    CHECK(s.exhausted());
    CHECK_THROWS_AS(s.next(std::chrono::milliseconds(0)), InputExhausted);
    CHECK_THROWS_WITH(s.next(std::chrono::milliseconds(0)), Contains("after line 3"));
}

TEST_CASE("input script: format writes lines the parser reads back to the same actions", "[input]") {
    const std::string text =
        "pick 10.5 20\nlocator 1 2 device 3\nstroke 0 0 1 1 device 2\nvaluator 2 -0.125\nchoice 3\n"
        "choice Tail device 2\nstring two words\nmove 4 5 device 2\nbreak\nwait\n";
    ScriptInputSource s(text, "a");
    std::string again;
    for (const auto& a : s.actions()) again += ScriptInputSource::format(a) + "\n";
    CHECK(again == text);
}

TEST_CASE("input script: a string line's text runs to the end of the line, '#' included", "[input]") {
    const std::string text =
        "string part#2.crv\n"
        "  string   a # b  \n"
        "# string commented out\n"
        "pick 1 2 # a comment still ends other lines\n"
        "string#not a string line\n";
    ScriptInputSource s(text, "session.txt");
    const auto& a = s.actions();
    REQUIRE(a.size() == 4);
    CHECK(std::get<action::String>(a[0].what).text == "part#2.crv");
    CHECK(std::get<action::String>(a[1].what).text == "a # b");
    CHECK(std::get<action::Pick>(a[2].what).position == glm::dvec2(1, 2));
    // "string#..." is no string verb: its '#' starts a comment and leaves the empty string.
    CHECK(errorOf("string#x\n").empty());
    CHECK(std::get<action::String>(a[3].what).text.empty());
}

TEST_CASE("input script: readsBack holds strings and choice names the line can hold, and only those",
          "[input]") {
    std::mt19937 random(20261207);
    const std::string alphabet = "ab #\t\x01\n.-9/\xc3\xbc";
    auto randomText = [&](std::size_t length) {
        std::string t;
        for (std::size_t i = 0; i < length; ++i)
            t += alphabet[std::uniform_int_distribution<std::size_t>(0, alphabet.size() - 1)(random)];
        return t;
    };
    auto hasControl = [](const std::string& t) {
        return std::any_of(t.begin(), t.end(), [](char c) { return (unsigned char)c < 0x20 && c != '\t'; });
    };
    auto blankEnd = [](const std::string& t) {
        return !t.empty() && (t.front() == ' ' || t.front() == '\t' || t.back() == ' ' || t.back() == '\t');
    };
    int held = 0, refused = 0;
    for (int trial = 0; trial < 2000; ++trial) {
        InputAction a;
        bool expected = false;
        const std::string t = randomText(std::size_t(trial % 9));
        if (trial % 2 == 0) {
            // A string: any text but a control character or a blank at an end ('#' too).
            a.what = action::String{t, 1};
            expected = !hasControl(t) && !blankEnd(t);
        } else {
            // A choice name: one word, no '#', not read as a number (none: choice number 0).
            a.what = action::Choice{0, 1, t};
            expected = t.empty() || (t.find_first_of(" \t#") == std::string::npos && !hasControl(t) &&
                                     t.find_first_not_of("+-0123456789.eE") != std::string::npos);
        }
        INFO("line: " << ScriptInputSource::format(a));
        const bool reads = ScriptInputSource::readsBack(a);
        CHECK(reads == expected);
        if (reads) {
            const ScriptInputSource parsed(ScriptInputSource::format(a), "format");
            REQUIRE(parsed.actions().size() == 1);
            CHECK(parsed.actions()[0].what == a.what);
        }
        (reads ? held : refused)++;
    }
    CHECK(held > 300);
    CHECK(refused > 300);
    InputAction other;
    other.what = action::String{"abc", 2};  // a string line has no device field
    CHECK_FALSE(ScriptInputSource::readsBack(other));
    InputAction tooLong;
    tooLong.what = action::String{std::string(ScriptInputSource::kMaxScriptLineLength, 'x'), 1};
    CHECK_FALSE(ScriptInputSource::readsBack(tooLong));
    InputAction notFinite;
    notFinite.what = action::Valuator{1, std::nan("")};
    CHECK_FALSE(ScriptInputSource::readsBack(notFinite));
    InputAction directive;
    directive.what = action::Directive{"snapshot", {"front#1.png"}};
    CHECK_FALSE(ScriptInputSource::readsBack(directive));
    directive.what = action::Directive{"snapshot", {"front.png"}};
    CHECK(ScriptInputSource::readsBack(directive));
}
}  // namespace test_input_script
