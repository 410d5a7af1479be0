// Bad input that once broke a session: a refused element half-rewrote a structure and left it
// open; huge curve scales ran curve mapping out of memory; files named by a script escaped the
// output directory. Each now fails the one line, leaves everything as it was, and is counted.
#include "SessionTestSupport.h"

#include "acsynt/session/ModelPicture.h"
#include "geom/Evaluate.h"
#include "phigs/core/Error.h"

#include <chrono>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>

namespace test_session_bounds {

using session_test::Driver;

namespace {

bool sameElements(const phigs::StructureStore& store, int id, const std::vector<phigs::Element>& expected) {
    if (store.elementCount(id) != int(expected.size())) return false;
    for (std::size_t i = 0; i < expected.size(); ++i)
        if (!(store.elementAt(id, int(i) + 1) == expected[i])) return false;
    return true;
}

/// CURVE MAP with `curve` loaded, DEFINE POINT on the right wing's middle, DONE.
void placeCurve(Driver& d, const std::string& curve) {
    d.run({"choice FILE", "choice READ_MODEL", "string transport.acm", "choice RETURN", "choice CURVE_MAP",
           "choice LOAD_CURVE", "string " + curve, "choice DEFINE_POINT"});
    const auto& components = d.session.models().current().components;
    std::size_t wing = 0;
    while (components[wing].name != "right_wing") ++wing;
    const glm::dvec3 p = geom::evaluate(components[wing].surface, 0.5, 0.38);
    d.pickAt(p, 1);
    d.pickAt(p, 1);
    d.run({"choice ACCEPT", "choice DONE device 2"});
    REQUIRE(d.session.reference());
}

}  // namespace

TEST_CASE("a structure rewrite is all or nothing: a refused element leaves it as it was and closed") {
    phigs::StructureStore store;
    const std::vector<phigs::Element> before{phigs::polyline3({{0, 0, 0}, {1, 0, 0}}),
                                             phigs::executeStructure(8)};
    acsynt::rewriteStructure(store, 7, before);
    REQUIRE(sameElements(store, 7, before));
    const double nan = std::numeric_limits<double>::quiet_NaN();
    const std::vector<std::vector<phigs::Element>> refused{
        {phigs::polyline3({{0, 0, 0}, {2, 0, 0}}), phigs::polyline3({{0, 0, 0}, {nan, 0, 0}})},
        {phigs::polyline3({{0, 0, 0}, {1e308, 0, 0}}), phigs::polyline3({{0, 0, 0}, {HUGE_VAL, 0, 0}})},
        {phigs::executeStructure(7)},  // itself
    };
    for (const auto& elements : refused) {
        CHECK_THROWS_AS(acsynt::rewriteStructure(store, 7, elements), phigs::Error);
        CHECK(sameElements(store, 7, before));
        CHECK_FALSE(store.isStructureOpen());
    }
    // 8 executing 7 would close a cycle through 7's reference to 8.
    CHECK_THROWS_AS(acsynt::rewriteStructure(store, 8, {phigs::executeStructure(7)}), phigs::Error);
    CHECK(store.elementCount(8) == 0);
    // A structure left open by someone else is not touched either.
    store.openStructure(9);
    CHECK_THROWS_AS(acsynt::rewriteStructure(store, 7, {}), phigs::Error);
    CHECK(sameElements(store, 7, before));
}

TEST_CASE("curve scales that overflow or dwarf the surface fail their line quickly, the session goes on") {
    Driver d("bounds_scale");
    d.run({"choice FILE", "choice READ_MODEL", "string transport.acm", "choice RETURN", "choice CURVE_MAP",
           "choice LOAD_CURVE", "string acslogo.crv 1e308"});
    CHECK(d.session.message().find("IS TOO LARGE") != std::string::npos);
    CHECK(d.session.failedLines() == 1);
    // Finite but past a million model units (the model's own bound), or below a micro-unit.
    for (const char* scale : {"1e300", "1e7", "1e-300", "1e-9"}) {
        d.run({"choice LOAD_CURVE", std::string("string acslogo.crv ") + scale});
        CHECK(d.session.message().find(scale[2] == '-' ? "IS TOO SMALL" : "IS TOO LARGE") !=
              std::string::npos);
    }
    CHECK(d.session.failedLines() == 5);
    // Words after the scale, or a scale that is not a number, are refused rather than ignored.
    d.run({"choice LOAD_CURVE", "string acslogo.crv notanumber"});
    CHECK(d.session.message().find("BAD INPUT IN CURVE MAP") != std::string::npos);
    d.run({"choice LOAD_CURVE", "string acslogo.crv 0.45 abc"});
    CHECK(d.session.message().find("BAD INPUT IN CURVE MAP") != std::string::npos);
    CHECK(d.session.failedLines() == 7);
    // A scale after a path past the string device's default 256 bytes is read (it was cut off,
    // and the curve loaded at scale 1 without a word).
    std::string longPath;
    for (int k = 0; k < 130; ++k) longPath += "./";
    d.run({"choice LOAD_CURVE", "string " + longPath + "acslogo.crv 1e7"});
    CHECK(d.session.message().find("IS TOO LARGE") != std::string::npos);
    CHECK(d.session.failedLines() == 8);
    // Points no curve passes through (two the same): the file and the part's line, as for the
    // file's other faults (it named only the part).
    const auto twice = session_test::outputDirectory("bounds_scale_files") / "twice.crv";
    std::filesystem::create_directories(twice.parent_path());
    std::ofstream(twice) << "CURVE INPUT FILE\n5\nP\nData-Points:\n0 0 0\n0 0 0\n1 0 0\n1 1 0\n0 0 0\n"
                            "Continuities:\n2\n2\n2\n2\n2\nConstraints:\nNone\n";
    d.run({"choice LOAD_CURVE", "string " + twice.string()});
    CHECK(d.session.message().rfind(twice.string() + ":2: curve part 'P': ", 0) == 0);
    CHECK(d.session.failedLines() == 9);

    // Within that bound, yet past what MAP CURVE takes on a wing (a hundred times its size).
    for (const char* scale : {"1e5", "5e4"}) {
        Driver big(std::string("bounds_scale_") + scale);
        placeCurve(big, std::string("acslogo.crv ") + scale);
        // DONE drew the placed curve into the overlay structure, closed.
        CHECK_FALSE(big.session.phigs().store().isStructureOpen());
        const std::size_t failedBefore = big.session.failedLines();
        for (const char* item : {"choice MAP_PREVIEW", "choice MAP_CURVE"}) {
            const auto start = std::chrono::steady_clock::now();
            big.run({item});
            CHECK(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count() < 5.0);
            CHECK(big.session.message().find("times the surface") != std::string::npos);
        }
        CHECK(big.session.failedLines() == failedBefore + 2);
        CHECK(big.session.mappings().empty());
        CHECK_FALSE(big.session.phigs().store().isStructureOpen());
        // The session still answers: a menu change works and shows no error.
        big.run({"choice RETURN"});
        CHECK(big.session.menuTitle() == "MAIN");
        big.picture();
    }
}

TEST_CASE("files a script names stay inside the output directory") {
    Driver d("bounds_paths");
    const auto outside = session_test::outputDirectory("bounds_paths").parent_path() / "escaped.txt";
    std::filesystem::remove(outside);
    d.run({"summary ../escaped", "summary /tmp/acsynt_escaped", "summary fine"});
    CHECK_FALSE(std::filesystem::exists(outside));
    CHECK(std::filesystem::exists(session_test::outputDirectory("bounds_paths") / "fine.txt"));
    CHECK(d.session.failedLines() == 2);
    d.run(
        {"choice FILE", "choice READ_MODEL", "string transport.acm", "choice SAVE_MODEL", "string ../x.acm"});
    CHECK(d.session.message().find("INSIDE THE OUTPUT DIRECTORY") != std::string::npos);
    CHECK_FALSE(std::filesystem::exists(outside.parent_path() / "x.acm"));
    d.run({"choice SAVE_MODEL", "string saved/copy.acm"});
    CHECK(std::filesystem::exists(session_test::outputDirectory("bounds_paths") / "saved" / "copy.acm"));
    CHECK(d.session.failedLines() == 3);
    // Nor through a symbolic link, to a folder or as the file; one that stays inside is followed.
    const auto out = session_test::outputDirectory("bounds_paths");
    const auto away = out.parent_path() / "bounds_paths_away";
    std::filesystem::remove_all(away);
    std::filesystem::create_directories(away);
    for (const char* link : {"link", "linked.acm", "inner"}) std::filesystem::remove(out / link);
    std::filesystem::create_directory_symlink(away, out / "link");
    std::filesystem::create_symlink(away / "linked.acm", out / "linked.acm");
    std::filesystem::create_directory_symlink(out / "saved", out / "inner");
    d.run({"choice SAVE_MODEL", "string link/x.acm", "choice SAVE_MODEL", "string linked.acm",
           "summary link/s"});
    CHECK(d.session.failedLines() == 6);
    CHECK(std::filesystem::is_empty(away));
    d.run({"choice SAVE_MODEL", "string inner/y.acm"});
    CHECK(d.session.failedLines() == 6);
    CHECK(std::filesystem::exists(out / "saved" / "y.acm"));
    // A directory named as an archive or a curve file is called one.
    const std::string folder = session_test::outputDirectory("bounds_paths").string();
    d.run({"choice RETRIEVE", "string " + folder});
    CHECK(d.session.message().find("IS A DIRECTORY") != std::string::npos);
    d.run({"choice RETURN", "choice CURVE_MAP", "choice LOAD_CURVE", "string " + folder});
    CHECK(d.session.message().find("is a directory") != std::string::npos);
    CHECK(d.session.failedLines() == 8);
    // A name longer than any file system's is refused by its length, not by a filesystem error
    // (the string device keeps all the 304 characters typed, as much as a script line holds).
    const std::string longName(300, 'a');
    d.run({"choice RETURN", "choice FILE", "choice SAVE_MODEL", "string " + longName + ".acs"});
    CHECK(d.session.message().find("IS 304 CHARACTERS LONG: A FILE NAME HOLDS AT MOST 255") !=
          std::string::npos);
    d.run({"choice READ_MODEL", "string " + longName});
    CHECK(d.session.message().find("INPUT FILE NAME 'aaaa") != std::string::npos);
    CHECK(d.session.failedLines() == 10);
}

TEST_CASE("an output file needs a name before its extension") {
    // `summary .` wrote '..txt' and `snapshot .png` '.png.png', hidden files.
    Driver d("bounds_dot_names");
    const auto out = session_test::outputDirectory("bounds_dot_names");
    d.run({"summary .", "snapshot .png", "choice FILE", "choice READ_MODEL", "string fighter.acm",
           "choice SAVE_MODEL", "string .acs"});
    CHECK(d.session.message() == "OUTPUT FILE '.acs' HAS NO NAME BEFORE ITS EXTENSION");
    CHECK(d.session.failedLines() == 3);
    for (const char* hidden : {"..txt", ".png.png", ".png", ".acs"})
        CHECK_FALSE(std::filesystem::exists(out / hidden));
    d.run({"summary a.b", "snapshot x"});
    CHECK(d.session.failedLines() == 3);
}

}  // namespace test_session_bounds
