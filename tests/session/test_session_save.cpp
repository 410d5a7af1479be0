// SAVE MODEL writes the current model as it is (reduced surfaces, mapped curves) and READ MODEL
// gives it back bit for bit; a name already loaded is read under a new name, said on the line.
#include "SessionTestSupport.h"

#include <unistd.h>

#include "acsynt/ModelFile.h"
#include "acsynt/session/ModelStateFile.h"
#include "geom/Evaluate.h"

#include <algorithm>
#include <fstream>
#include <sstream>

namespace test_session_save {

using session_test::Driver;

using session_test::componentIndex;
using session_test::pickOn;

namespace {

/// The transport with its fuselage reduced and the logo mapped on the reduced model's wing.
void reduceAndMap(Driver& d) {
    d.run({"choice FILE", "choice READ_MODEL", "string transport.acm", "choice RETURN", "choice VIEW",
           "choice FOUR_VIEWS", "choice RETURN", "choice SURF_REDN", "choice BY_TOLERANCE",
           "choice REDUCE_U&W"});
    pickOn(d, "fuselage", 0.5, 0.5);
    d.run({"string 0.01", "choice RETURN"});
    REQUIRE(d.session.models().current().name == "transport_R1");
    d.run({"choice CURVE_MAP", "choice LOAD_CURVE", "string acslogo.crv 1", "choice DEFINE_POINT"});
    pickOn(d, "right_wing", 0.5, 0.38);
    pickOn(d, "right_wing", 0.5, 0.38);
    d.run({"choice ACCEPT", "choice DONE device 2", "choice MAP_CURVE", "choice RETURN"});
    REQUIRE(d.session.mappings().size() == 1);
    REQUIRE(d.session.mappings()[0].model == "transport_R1");
}

void requireSameModel(const acsynt::Model& a, const acsynt::Model& b) {
    REQUIRE(a.components.size() == b.components.size());
    for (std::size_t c = 0; c < a.components.size(); ++c) {
        const acsynt::Component& x = a.components[c];
        const acsynt::Component& y = b.components[c];
        INFO("component " << x.name);
        CHECK(x.name == y.name);
        CHECK(x.kind == y.kind);
        CHECK(x.colour == y.colour);
        CHECK(x.closedU == y.closedU);
        CHECK(x.closedW == y.closedW);
        CHECK(x.surface.degreeU == y.surface.degreeU);
        CHECK(x.surface.degreeV == y.surface.degreeV);
        CHECK(x.surface.knotsU == y.surface.knotsU);  // bit for bit
        CHECK(x.surface.knotsV == y.surface.knotsV);
        CHECK(x.surface.countU == y.surface.countU);
        CHECK(x.surface.countV == y.surface.countV);
        CHECK(x.surface.points == y.surface.points);
        CHECK(x.surface.weights == y.surface.weights);
        CHECK(x.patches.patches.size() == y.patches.patches.size());
    }
}

void requireSameMapping(const acsynt::MappingRecord& a, const acsynt::MappingRecord& b) {
    CHECK(a.component == b.component);
    CHECK(a.curveFile == b.curveFile);
    CHECK(a.reference.component == b.reference.component);
    CHECK(a.reference.patch == b.reference.patch);
    CHECK(a.reference.u == b.reference.u);
    CHECK(a.reference.w == b.reference.w);
    CHECK(a.parts == b.parts);
    CHECK(a.loops == b.loops);
    CHECK(a.boundaryWalks == b.boundaryWalks);
    CHECK(a.loopsPerPart == b.loopsPerPart);
    CHECK(a.polylines == b.polylines);
    CHECK(a.uvPolylines == b.uvPolylines);
    REQUIRE(a.partReports.size() == b.partReports.size());
    for (std::size_t i = 0; i < a.partReports.size(); ++i) {
        CHECK(a.partReports[i].name == b.partReports[i].name);
        CHECK(a.partReports[i].outcome == b.partReports[i].outcome);
        CHECK(a.partReports[i].loops == b.partReports[i].loops);
        CHECK(a.partReports[i].boundaryWalks == b.partReports[i].boundaryWalks);
        CHECK(a.partReports[i].reason == b.partReports[i].reason);
    }
}

}  // namespace

TEST_CASE("SAVE MODEL: a reduced model with a mapped logo reads back bit for bit, renamed beside itself") {
    Driver d("save_model");
    const auto out = session_test::outputDirectory("save_model");
    std::filesystem::remove_all(out);
    reduceAndMap(d);
    const acsynt::Model saved = d.session.models().current();
    const acsynt::MappingRecord mapping = d.session.mappings()[0];
    d.run({"choice FILE", "choice SAVE_MODEL", "string reduced.acs"});
    CHECK(d.session.message() == "MODEL transport_R1 SAVED TO " + (out / "reduced.acs").string() +
                                     ": 8 COMPONENTS, 1 MAPPED CURVES");

    // The name is loaded: read back as transport_R1_2, said on the message line.
    d.run({"choice READ_MODEL", "string " + (out / "reduced.acs").string()});
    CHECK(d.session.message() ==
          "MODEL transport_R1 READ AS transport_R1_2 (transport_R1 IS LOADED): 8 COMPONENTS, " +
              std::to_string(saved.patchCount()) + " PATCHES, 1 MAPPED CURVES");
    REQUIRE(d.session.models().size() == 3);
    CHECK(d.session.models().current().name == "transport_R1_2");
    requireSameModel(saved, d.session.models().current());
    REQUIRE(d.session.mappings().size() == 2);
    CHECK(d.session.mappings()[1].model == "transport_R1_2");
    requireSameMapping(mapping, d.session.mappings()[1]);

    // Saved again from the copy read back: the same text (nothing drifts through a round trip).
    d.run({"choice SAVE_MODEL", "string again.acs"});
    std::ostringstream first, second;
    first << std::ifstream(out / "reduced.acs").rdbuf();
    second << std::ifstream(out / "again.acs").rdbuf();
    const std::string a = first.str(), b = second.str();
    CHECK(a.substr(a.find('\n', a.find("model "))) == b.substr(b.find('\n', b.find("model "))));

    // With the original deleted, the file reads back under its own name.
    d.run({"choice RETURN", "choice MODELS", "choice PREVIOUS_MODEL", "choice DELETE_MODEL", "choice RETURN",
           "choice FILE", "choice READ_MODEL", "string " + (out / "reduced.acs").string()});
    CHECK(d.session.message().rfind("MODEL transport_R1 READ: 8 COMPONENTS", 0) == 0);
    CHECK(d.session.models().current().name == "transport_R1");
    requireSameModel(saved, d.session.models().current());
    CHECK_FALSE(d.logHasError());
}

TEST_CASE("SAVE MODEL: a mapping carried through a reduction names the reduced surface's patch") {
    // The logo mapped on the fuselage, then the fuselage reduced: the carried mapping's reference
    // point keeps its (u, w), and its patch number is the reduced surface's patch there. The old
    // number named another patch, or one past the last, and the saved file was refused.
    Driver d("save_model_carried");
    const auto out = session_test::outputDirectory("save_model_carried");
    std::filesystem::remove_all(out);
    d.run({"choice FILE", "choice READ_MODEL", "string transport.acm", "choice RETURN", "choice VIEW",
           "choice FOUR_VIEWS", "choice RETURN", "choice CURVE_MAP", "choice LOAD_CURVE",
           "string acslogo.crv 1", "choice DEFINE_POINT"});
    pickOn(d, "fuselage", 0.8, 0.3);
    pickOn(d, "fuselage", 0.8, 0.3);
    d.run({"choice ACCEPT", "choice DONE device 2", "choice MAP_CURVE", "choice RETURN", "choice SURF_REDN",
           "choice BY_TOLERANCE", "choice REDUCE_U&W"});
    pickOn(d, "fuselage", 0.5, 0.5);
    d.run({"string 0.01", "choice RETURN"});
    REQUIRE(d.session.mappings().size() == 2);
    const acsynt::MappingRecord& before = d.session.mappings()[0];
    const acsynt::MappingRecord carried = d.session.mappings()[1];
    REQUIRE(carried.model == "transport_R1");
    const acsynt::Component& fuselage = *d.session.models().current().find("fuselage");
    CHECK(carried.reference.u == before.reference.u);
    CHECK(carried.reference.w == before.reference.w);
    REQUIRE(carried.reference.patch >= 1);
    REQUIRE(std::size_t(carried.reference.patch) <= fuselage.patches.size());
    CHECK(fuselage.patches.patches[std::size_t(carried.reference.patch) - 1].contains(carried.reference.u,
                                                                                      carried.reference.w));
    INFO("patch " << before.reference.patch << " of "
                  << d.session.models().at(0).find("fuselage")->patches.size() << " -> "
                  << carried.reference.patch << " of " << fuselage.patches.size());
    CHECK(fuselage.patches.size() < d.session.models().at(0).find("fuselage")->patches.size());
    // The carried curve is the reduced model's first: drawn in the first colour, as on the original
    // (the colour went by the curve's place among every model's curves).
    auto mappedColours = [&] {
        std::vector<glm::dvec3> colours;
        const phigs::ElementArena& e =
            d.session.phigs().store().structure(acsynt::structures::mapped).elements;
        for (std::size_t i = 0; i < e.size(); ++i)
            if (const auto* c = e.get<phigs::ColourAttribute>(i)) colours.push_back(c->colour.rgb);
        return colours;
    };
    CHECK(mappedColours() == std::vector<glm::dvec3>{glm::dvec3(0.1, 0.3, 1.0)});
    d.run({"choice FILE", "choice SAVE_MODEL", "string carried.acs", "choice READ_MODEL",
           "string " + (out / "carried.acs").string()});
    REQUIRE(d.session.mappings().size() == 3);
    requireSameMapping(carried, d.session.mappings()[2]);
    CHECK_FALSE(d.logHasError());
}

TEST_CASE("READ MODEL: a damaged saved model is refused by file and line, the models stay as they were") {
    Driver d("save_model_bad");
    const auto out = session_test::outputDirectory("save_model_bad");
    std::filesystem::remove_all(out);
    d.run({"choice FILE", "choice READ_MODEL", "string fighter.acm", "choice SAVE_MODEL", "string good.acs"});
    std::ostringstream text;
    text << std::ifstream(out / "good.acs").rdbuf();
    const std::string good = text.str();
    // Cut at several places, a number spoiled, a wrong version.
    std::vector<std::string> bad;
    for (double f : {0.1, 0.5, 0.9, 0.999})
        bad.push_back(good.substr(0, std::size_t(f * double(good.size()))));
    std::string spoiled = good;
    spoiled.replace(spoiled.find("\np ") + 3, 4, "zz z");
    bad.push_back(spoiled);
    bad.push_back("acsynt-surfaces 9\n" + good.substr(good.find('\n') + 1));
    for (std::size_t i = 0; i < bad.size(); ++i) {
        const auto file = out / ("bad" + std::to_string(i) + ".acs");
        std::ofstream(file) << bad[i];
        d.run({"choice READ_MODEL", "string " + file.string()});
        INFO("file " << i << ": " << d.session.message());
        CHECK(d.session.message().find(file.string() + ":") != std::string::npos);
        CHECK(d.session.models().size() == 1);
    }
}

TEST_CASE("READ MODEL: numbers a model cannot hold are refused at their line, the models stay") {
    // A pole at 2^1000 loaded and made every view fail; a loop vertex or reference point outside
    // the surface's domain, or a patch it does not have, were taken and failed later (a reduction
    // then made its model and dropped the curves).
    Driver d("save_model_range");
    const auto out = session_test::outputDirectory("save_model_range");
    std::filesystem::remove_all(out);
    reduceAndMap(d);
    d.run({"choice FILE", "choice SAVE_MODEL", "string good.acs"});
    std::ostringstream text;
    text << std::ifstream(out / "good.acs").rdbuf();
    const std::string good = text.str();
    auto replaceWord = [&](const std::string& lineStart, std::size_t word, const std::string& value) {
        std::string t = good;
        const std::size_t line = t.find("\n" + lineStart) + 1;
        std::size_t at = line;
        for (std::size_t k = 0; k < word; ++k) at = t.find(' ', at) + 1;
        t.replace(at, t.find_first_of(" \n", at) - at, value);
        return t;
    };
    const std::size_t models = d.session.models().size();
    const std::vector<std::pair<std::string, std::string>> bad{
        {replaceWord("p ", 1, "0x1p+1000"), "is beyond 1000000000"},
        {replaceWord("v ", 1, "0x1p+3"), "is outside right_wing's parameter domain"},
        {replaceWord("reference ", 2, "99999"), "is not a count from 0 to"},
        {replaceWord("reference ", 3, "0x1.8p+1"), "the reference point"},
        // A colour past 1, and words a line does not take, anywhere, were read as if right.
        {replaceWord("colour ", 2, "0x1.4p+2"), "the colour component '0x1.4p+2' is not from 0 to 1"},
        {replaceWord("model ", 2, "8 trailing"), "'model' takes 2 values, not 3"},
        {replaceWord("surface ", 5, "0 0"), "'surface' takes 5 values, not 6"},
        {replaceWord("reference ", 4, "0x1p-1 extra"), "'reference' takes 4 values, not 5"},
        {good + "end\n", "'end' after the model's 'end'"},
        // Fields that contradict each other: a reference point on another component than the
        // mapping's, or outside the patch it names; a loop vertex off the surface at its (u, w);
        // a direction said to be closed whose ends are apart.
        {replaceWord("reference ", 1, "0"), "the reference point is on fuselage, the mapping on right_wing"},
        {replaceWord("reference ", 3, "0x0p+0"), "is outside patch"},
        {replaceWord("v ", 3, "0x1p+10"), "is not on right_wing at"},
        {replaceWord("component ", 3, "1"), "is said to be closed in u, but its u ends are apart"},
    };
    for (std::size_t i = 0; i < bad.size(); ++i) {
        const auto file = out / ("range" + std::to_string(i) + ".acs");
        std::ofstream(file) << bad[i].first;
        d.run({"choice READ_MODEL", "string " + file.string()});
        INFO("file " << i << ": " << d.session.message());
        CHECK(d.session.message().find(file.string() + ":") != std::string::npos);
        CHECK(d.session.message().find(bad[i].second) != std::string::npos);
        CHECK(d.session.models().size() == models);
    }
}

TEST_CASE("READ MODEL: a saved model over the patch limit is refused at the component that passes it") {
    // One bicubic component of 94 x 94 points is 91 x 91 = 8,281 patches, over 8,192: refused
    // at its knots, before its points are read (a net within the point limit may be gigabytes of
    // patches), not at a line after every component was read.
    auto component = [](const std::string& name, std::size_t n) {
        std::ostringstream out;
        out << "component " << name << " wing 0 0\ncolour 0x1p-1 0x1p-1 0x1p-1\nsurface 3 3 " << n << " " << n
            << " 0\n";
        for (const char* key : {"knots_u", "knots_w"}) {
            out << key << " " << n + 4;
            for (std::size_t k = 0; k < n + 4; ++k)
                out << " " << (k < 4 ? 0.0 : k >= n ? double(n - 3) : double(k - 3));
            out << "\n";
        }
        for (std::size_t i = 0; i < n; ++i)
            for (std::size_t j = 0; j < n; ++j) out << "p " << i << " " << j << " " << (i * j) % 7 << "\n";
        return out.str();
    };
    const std::string big = component("big", 94), small = component("small", 5);
    const std::string text = "acsynt-surfaces 1\nmodel m 2\n" + big + small + "end\n";
    const int bigKnotsLine = 2 + 5;  // heading, model, component, colour, surface, knots_u, knots_w
    std::istringstream in(text);
    try {
        acsynt::parseModelState(in, "big.acs");
        FAIL("a model of 8,306 patches was read");
    } catch (const acsynt::ModelFileError& e) {
        CHECK(e.reason().find("more than 8192 patches") != std::string::npos);
        CHECK(e.line() == bigKnotsLine);
    }
    // Within the limit (86 x 86 = 7,396 patches, and 4 more) it reads.
    std::istringstream fits("acsynt-surfaces 1\nmodel m 2\n" + component("big", 89) + small + "end\n");
    CHECK(acsynt::parseModelState(fits, "fits.acs").model.patchCount() == 86 * 86 + 4);
}

TEST_CASE(
    "READ MODEL: a saved model takes 1 to 64 components, as READ MODEL of a description and IMPORT do") {
    // A count of 0 was read (and the empty model made current, its views' window not finite),
    // and 65-128 were read into models that EXPORT writes and IMPORT refuses.
    Driver d("save_component_count");
    const auto out = session_test::outputDirectory("save_component_count");
    std::filesystem::create_directories(out);
    const std::size_t models = d.session.models().size();
    for (const char* count : {"0", "65", "128"}) {
        const auto file = out / (std::string("count") + count + ".acs");
        std::ofstream(file) << "acsynt-surfaces 1\nmodel m " << count << "\nend\n";
        d.run({"choice FILE", "choice READ_MODEL", "string " + file.string()});
        INFO(count << ": " << d.session.message());
        CHECK(d.session.message().find(file.string() + ":2:") != std::string::npos);
        CHECK(d.session.models().size() == models);
        d.run({"choice RETURN"});
    }
    d.run({"choice FILE", "choice READ_MODEL", "string transport.acm", "choice SAVE_MODEL", "string one.acs",
           "choice READ_MODEL", "string " + (out / "one.acs").string(), "choice RETURN"});
    CHECK(d.session.models().size() == models + 2);
}

TEST_CASE("SAVE MODEL, ARCHIVE: a failed write keeps the previous file, an archive is replaced whole") {
    Driver d("save_whole");
    const auto out = session_test::outputDirectory("save_whole");
    std::filesystem::remove_all(out);
    auto text = [](const std::filesystem::path& file) {
        std::ostringstream all;
        all << std::ifstream(file).rdbuf();
        return all.str();
    };
    d.run(
        {"choice FILE", "choice READ_MODEL", "string transport.acm", "choice SAVE_MODEL", "string keep.acs"});
    const std::string kept = text(out / "keep.acs");
    REQUIRE(kept.find("model transport") != std::string::npos);
    // Read back by its bare name: not where files are read from, and the message says where it is.
    d.run({"choice READ_MODEL", "string keep.acs"});
    CHECK(d.session.message() ==
          "FILE keep.acs IS NOT IN THE WORKING DIRECTORY OR THE DATA FOLDERS; THE "
          "OUTPUT DIRECTORY HAS IT: NAME IT " +
              (out / "keep.acs").string());

    // The write fails (a file has the name of its temporary folder): the old file stays whole
    // and no partial file is left.
    const std::filesystem::path blocker = out / (".keep.acs.writing-" + std::to_string(::getpid()));
    std::ofstream(blocker) << "x";
    d.run({"choice READ_MODEL", "string fighter.acm", "choice SAVE_MODEL", "string keep.acs"});
    CHECK(d.session.message() == "CANNOT WRITE " + (out / "keep.acs").string());
    CHECK(text(out / "keep.acs") == kept);
    std::filesystem::remove(blocker);
    for (const auto& entry : std::filesystem::directory_iterator(out))
        CHECK(entry.path().filename().string().find(".writing") == std::string::npos);
    // Names with a leading "./" are the session's own files too.
    d.run({"choice SAVE_MODEL", "string ./acsynt.log"});
    CHECK(d.session.message().find("IS THE SESSION'S OWN") != std::string::npos);

    // The session's own summary and log are refused as names.
    for (const char* reserved : {"summary.txt", "acsynt.log"}) {
        d.run({"choice SAVE_MODEL", std::string("string ") + reserved});
        CHECK(d.session.message().find("IS THE SESSION'S OWN") != std::string::npos);
        CHECK_FALSE(std::filesystem::exists(out / reserved));
    }

    // ARCHIVE into a file holding another model's archive replaces it: the count is this
    // model's network, and RETRIEVE takes it back.
    d.run({"choice ARCHIVE", "string model.phar"});
    const std::string fighter = d.session.message();
    d.run({"choice RETURN", "choice MODELS", "choice PREVIOUS_MODEL", "choice RETURN", "choice FILE",
           "choice ARCHIVE", "string model.phar"});
    REQUIRE(d.session.models().current().name == "transport");
    const phigs::StructureStore& store = d.session.phigs().store();
    const std::size_t network = store.network(acsynt::structures::modelRoot).size();
    CHECK(d.session.message() ==
          "ARCHIVED " + std::to_string(network) + " STRUCTURES TO " + (out / "model.phar").string());
    CHECK(d.session.message() != fighter);
    d.run({"choice RETRIEVE", "string " + (out / "model.phar").string()});
    CHECK(d.session.message() ==
          "RETRIEVED " + std::to_string(network) + " STRUCTURES FROM " + (out / "model.phar").string());
}

}  // namespace test_session_save
