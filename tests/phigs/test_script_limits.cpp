// The session script reader's limits, each just below (read) and just above (refused with file,
// line and the limit, quickly and in little memory).

#include "PeakMemory.h"
#include "phigs/input/ScriptInputSource.h"

#include <catch2/catch.hpp>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <functional>
#include <string>

namespace test_script_limits {

using namespace phigs;

namespace {

std::string refusal(const std::function<void()>& read) {
    return test_support::cheapRefusal<ScriptError>(read);
}

std::filesystem::path scratch(const std::string& name) {
    const auto dir = std::filesystem::path(PHIGS_TEST_OUTPUT_DIR) / "script_limits";
    std::filesystem::create_directories(dir);
    return dir / name;
}

}  // namespace

TEST_CASE("input script: lines up to the length limit parse, one byte more is refused", "[input][limits]") {
    const std::size_t limit = ScriptInputSource::kMaxScriptLineLength;
    const std::string longest = "string " + std::string(limit - 7, 'a');
    const ScriptInputSource fits("pick 1 2\n" + longest + "\n", "s.session");
    REQUIRE(fits.actions().size() == 2);
    CHECK(std::get<action::String>(fits.actions()[1].what).text.size() == limit - 7);
    const std::string message =
        refusal([&] { ScriptInputSource("pick 1 2\n" + longest + "a\n", "s.session"); });
    CHECK(message == "s.session:2: the line is 4097 bytes long; the limit is 4096");
}

TEST_CASE("input script: control characters are refused with their column, tab and CRLF are fine",
          "[input][limits]") {
    CHECK(ScriptInputSource("pick\t1 2\r\nwait\r\n", "s.session").actions().size() == 2);
    for (char c : {'\0', '\x01', '\x1b', '\x1f'}) {
        std::string text = "wait\nstring ab";  // appended in place: GCC 12 warns falsely on temporaries
        text += c;
        text += "cd\n";
        char code[8];
        std::snprintf(code, sizeof code, "0x%02x", unsigned(static_cast<unsigned char>(c)));
        CHECK(refusal([&] { ScriptInputSource(text, "s.session"); }) ==
              std::string("s.session:2: control character ") + code + " at column 10");
    }
}

TEST_CASE("input script: files up to the size limit read, larger ones and directories are refused",
          "[input][limits]") {
    const auto big = scratch("big.session");
    {
        // Comment lines up to exactly the limit: read (and parsed to no actions).
        std::ofstream out(big, std::ios::binary);
        const std::string line = "#" + std::string(1022, '.') + "\n";
        for (std::size_t written = 0; written < ScriptInputSource::kMaxScriptBytes; written += line.size())
            out << line;
    }
    REQUIRE(std::filesystem::file_size(big) == ScriptInputSource::kMaxScriptBytes);
    CHECK(ScriptInputSource::fromFile(big).actions().empty());
    {
        std::ofstream out(big, std::ios::binary | std::ios::app);
        out << "\n";
    }
    CHECK(refusal([&] { ScriptInputSource::fromFile(big); }).find("the limit is 16777216") !=
          std::string::npos);
    const auto folder = scratch("a_directory");
    std::filesystem::create_directories(folder);
    CHECK(refusal([&] { ScriptInputSource::fromFile(folder); }).find("is a directory") != std::string::npos);
    // A device that never ends is refused before it is read.
    if (std::filesystem::exists("/dev/zero"))
        CHECK(refusal([&] { ScriptInputSource::fromFile("/dev/zero"); }).find("is not a regular file") !=
              std::string::npos);
}

}  // namespace test_script_limits
