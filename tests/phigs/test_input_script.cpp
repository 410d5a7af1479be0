#include "phigs/input/ScriptInputSource.h"

#include <catch2/catch.hpp>

#include <filesystem>
#include <fstream>

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

}  // namespace test_input_script
