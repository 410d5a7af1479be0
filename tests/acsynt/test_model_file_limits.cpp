// The aircraft description reader's limits, each just below (read and lofted) and just above
// (refused at the line that breaks it, quickly and in little memory), and the patch count the
// parser budgets with, against real lofts of random components.

#include "PeakMemory.h"
#include "acsynt/Model.h"
#include "acsynt/ModelFile.h"

#include <catch2/catch.hpp>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <random>
#include <sstream>
#include <string>

namespace test_model_file_limits {

using namespace acsynt;

namespace {

std::string fuselage(const std::string& name, int sections, int points) {
    std::ostringstream out;
    out << "component fuselage " << name << "\n  points " << points << "\n  sections " << sections << "\n";
    for (int i = 0; i < sections; ++i)
        out << "  station "
            << (i == 0              ? "nose"
                : i + 1 == sections ? "aft"
                                    : "mid")
            << " " << i * 0.5 << " 1 1 1 0 2\n";
    return out.str() + "end\n";
}

std::string wing(const std::string& name, int sections, int points, bool mirror = false) {
    std::ostringstream out;
    out << "component wing " << name << "\n  points " << points << "\n  sections " << sections
        << "\n  airfoil 2412\n  position 1 1 0\n  root_chord 2\n  span 5\n";
    if (mirror) out << "  mirror " << name << "_m\n";
    return out.str() + "end\n";
}

std::string nacelle(const std::string& name, int sections, int points) {
    std::ostringstream out;
    out << "component nacelle " << name << "\n  points " << points << "\n  sections " << sections
        << "\n  position 0 3 0\n";
    for (int i = 0; i < sections; ++i) out << "  profile " << i * 0.4 << " 0.6\n";
    return out.str() + "end\n";
}

const std::string header = "acsynt-model 1\nmodel limits\n";

AircraftDescription parse(const std::string& text) {
    std::istringstream in(text);
    return parseAircraftDescription(in, "limits.acm");
}

/// Parses `text` expecting a refusal whose message contains `expected`, fast and small.
void requireRefused(const std::string& text, const std::string& expected) {
    const std::string message = test_support::cheapRefusal<ModelFileError>([&] { parse(text); });
    INFO(message);
    CHECK(message.find(expected) != std::string::npos);
}

}  // namespace

TEST_CASE("model file: the patch count the parser budgets is the loft's, for random components",
          "[acsynt][limits]") {
    std::mt19937 random(20261202);
    for (int trial = 0; trial < 40; ++trial) {
        const int sections = std::uniform_int_distribution<int>(4, 24)(random);
        const int points = 2 * std::uniform_int_distribution<int>(2, 20)(random) + 1;
        const std::string text = header + fuselage("f", sections, points + 1) +
                                 wing("w", sections, points, true) + nacelle("n", sections, points - 1);
        const AircraftDescription d = parse(text);
        const Model m = buildModel(d, "limits.acm");
        std::size_t expected = 0;
        for (const ComponentDescription& c : d.components)
            expected += loftedPatchCount(c) * (c.mirrorName.empty() ? 1 : 2);
        INFO("sections " << sections << " points " << points);
        CHECK(m.patchCount() == expected);
    }
}

TEST_CASE("model file: the patch budget is met exactly and broken by the next component",
          "[acsynt][limits]") {
    // 126 x 65 = 8190 patches, plus a wing of 1 x 2 = 8192: read and lofted.
    const std::string full = header + fuselage("body", 129, 65) + wing("w1", 4, 5);
    const AircraftDescription d = parse(full);
    CHECK(buildModel(d, "limits.acm").patchCount() == kModelMaxPatches);
    // One more small wing breaks it, at that wing's 'end' line.
    const std::string over = full + wing("w2", 4, 5);
    const int endLine = int(std::count(over.begin(), over.end(), '\n'));
    requireRefused(over, "limits.acm:" + std::to_string(endLine) +
                             ": the components so far loft to 8194 patches; the limit is 8192 per model");
    // The mirror image counts too.
    requireRefused(header + fuselage("body", 129, 65) + wing("w1", 4, 5, true), "8194 patches");
    // The largest component the format allows (200 x 200) is refused before it is lofted.
    requireRefused(header + fuselage("huge", 200, 200), "39400 patches; the limit is 8192");
}

TEST_CASE("model file: components, bytes, lines, control characters and directories", "[acsynt][limits]") {
    std::string many = header;
    for (std::size_t i = 0; i < kModelMaxComponents; ++i) many += wing("w" + std::to_string(i), 4, 5);
    CHECK(parse(many).components.size() == kModelMaxComponents);
    requireRefused(many + wing("one_more", 4, 5), "more than 64 components");
    // Mirror images count: 31 mirrored wings and a plain one are 63 components; a mirrored one
    // more is refused at its line, a plain one makes 64.
    std::string mirrored = header;
    for (int i = 0; i < 31; ++i) mirrored += wing("m" + std::to_string(i), 4, 5, true);
    mirrored += wing("plain", 4, 5);
    CHECK(buildModel(parse(mirrored)).components.size() == kModelMaxComponents - 1);
    const auto componentLine = std::count(mirrored.begin(), mirrored.end(), '\n') + 1;
    requireRefused(mirrored + wing("one_more", 4, 5, true),
                   "limits.acm:" + std::to_string(componentLine) + ": more than 64 components with");
    CHECK(buildModel(parse(mirrored + wing("last", 4, 5))).components.size() == kModelMaxComponents);
    // Places lie within a million of the origin, whatever the keyword.
    const std::string far[] = {
        "component wing w\n  points 5\n  sections 4\n  airfoil 2412\n  position 1 1e7 0\n",
        "component fuselage f\n  points 5\n  sections 4\n  station nose -2e6 1 1 1 0 2\n",
        "component fuselage f\n  points 5\n  sections 4\n  station nose 0 1 1 1 1e300 2\n",
        "component nacelle n\n  points 5\n  sections 4\n  position 0 0 0\n  profile 1000001 1\n"};
    for (const std::string& text : far) requireRefused(header + text, "is outside [-1e+06, 1e+06]");

    requireRefused(header + "# " + std::string(kModelFileMaxLineLength, 'x') + "\n", "line longer than 4096");
    requireRefused(header + "component fuselage bo" + '\0' + "dy\n",
                   "limits.acm:3: control character 0x00 at column 22");

    const auto folder = std::filesystem::path(PHIGS_TEST_OUTPUT_DIR) / "model_limits";
    std::filesystem::create_directories(folder);
    try {
        readAircraftDescription(folder);
        FAIL("a directory was read as a model");
    } catch (const ModelFileError& e) {
        CHECK(e.reason().find("is a directory") != std::string::npos);
    }
    // A file over the byte limit is refused before it is read.
    const auto big = folder / "big.acm";
    {
        std::ofstream out(big);
        out << header << std::string(kModelFileMaxBytes, '#') << "\n";
    }
    const auto cost = test_support::measureWork([&] {
        try {
            readAircraftDescription(big);
            FAIL("an oversized file was read");
        } catch (const ModelFileError& e) {
            CHECK(e.line() == 0);
            CHECK(e.reason().find("the limit is 1048576") != std::string::npos);
        }
    });
    CHECK(cost.peakBytes < (16u << 20));
}

}  // namespace test_model_file_limits
