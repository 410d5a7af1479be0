#include "ErrorNumber.h"
#include "RandomElements.h"
#include "phigs/Phigs.h"

#include <catch2/catch.hpp>

#include <filesystem>
#include <fstream>
#include <sstream>

namespace test_archive {

using namespace phigs;
using phigs::test::errorOf;

namespace {

std::filesystem::path outputFile(const std::string& name) {
    std::filesystem::path p = std::filesystem::path(PHIGS_TEST_OUTPUT_DIR) / name;
    std::filesystem::remove(p);
    return p;
}

std::map<int, std::vector<Element>> snapshot(const StructureStore& store) {
    std::map<int, std::vector<Element>> out;
    for (int id : store.structureIds())
        for (int n = 1; n <= store.elementCount(id); ++n) out[id].push_back(store.elementAt(id, n));
    for (int id : store.structureIds()) out[id];
    return out;
}

void buildRandomNetwork(StructureStore& store, std::mt19937& rng, int structures) {
    for (int id = 1; id <= structures; ++id) {
        store.openStructure(id);
        int n = testing::randomInt(rng, 0, 25);
        for (int i = 0; i < n; ++i) store.insert(testing::randomElement(rng, id, structures));
        store.closeStructure();
    }
}

std::string readFile(const std::filesystem::path& p) {
    std::ifstream in(p, std::ios::binary);
    std::stringstream s;
    s << in.rdbuf();
    return s.str();
}

void writeFile(const std::filesystem::path& p, const std::string& text) {
    std::ofstream out(p, std::ios::binary | std::ios::trunc);
    out << text;
}

}  // namespace

TEST_CASE("archive round trip of random networks with every element type", "[archive]") {
    std::mt19937 rng(7);
    for (int trial = 0; trial < 20; ++trial) {
        auto path = outputFile("roundtrip.phar");
        Phigs phigs;
        phigs.open();
        buildRandomNetwork(phigs.store(), rng, testing::randomInt(rng, 1, 12));
        auto before = snapshot(phigs.store());
        phigs.openArchiveFile(1, path);
        phigs.archiveAllStructures(1);
        phigs.closeArchiveFile(1);
        CHECK_FALSE(std::filesystem::exists(path.string() + ".tmp"));
        phigs.store().deleteAllStructures();
        phigs.openArchiveFile(2, path);
        CHECK(phigs.archiveContents(2).size() == before.size());
        phigs.retrieveAllStructures(2);
        phigs.closeArchiveFile(2);
        auto after = snapshot(phigs.store());
        REQUIRE(after.size() == before.size());
        for (const auto& [id, elements] : before) {
            REQUIRE(after[id].size() == elements.size());
            for (std::size_t i = 0; i < elements.size(); ++i) {
                INFO("structure " << id << " element " << i + 1 << " "
                                  << elementTypeName(elementType(elements[i])));
                REQUIRE(after[id][i] == elements[i]);
            }
        }
    }
}

TEST_CASE("encoding is exact: reals and strings survive bit for bit", "[archive]") {
    std::map<int, std::vector<Element>> contents;
    contents[3] = {PolylineElement{{{0.1, 1e-300, -7.0 / 3.0}, {1e300, 0.0, -0.0}}, false},
                   ApplicationDataElement{std::string("a\0b c\nd", 7)},
                   TextElement{{}, {1, 0, 0}, {0, 1, 0}, "", true}};
    std::string text = ArchiveFile::encode(contents);
    CHECK(text.starts_with("PHIGS-ARCHIVE 3\nSTRUCTURE 3 3\nPOLYLINE_3 2 0.1 1e-300"));
    CHECK(ArchiveFile::decode(text, "memory", nullptr) == contents);
}

TEST_CASE("a truncated archive is refused naming the file and line, the store unchanged",
          "[archive][errors]") {
    std::mt19937 rng(11);
    auto path = outputFile("truncated.phar");
    Phigs phigs;
    phigs.open();
    buildRandomNetwork(phigs.store(), rng, 6);
    phigs.openArchiveFile(1, path);
    phigs.archiveAllStructures(1);
    phigs.closeArchiveFile(1);
    const std::string good = readFile(path);
    phigs.store().openStructure(99);
    phigs.store().insert(label(5));
    phigs.store().closeStructure();
    const auto before = snapshot(phigs.store());
    for (int trial = 0; trial < 200; ++trial) {
        // Cut at 0 the file is empty: a new archive (below).
        std::size_t cut =
            static_cast<std::size_t>(testing::randomInt(rng, 1, static_cast<int>(good.size()) - 2));
        writeFile(path, good.substr(0, cut));
        try {
            phigs.openArchiveFile(3, path);
            FAIL("a truncated archive was opened, cut at " << cut);
        } catch (const Error& e) {
            CHECK(e.number() == errors::NotAnArchive);
            CHECK(e.function() == "OPEN ARCHIVE FILE");
            CHECK(e.detail().find(path.string() + ": line ") == 0);
        }
        REQUIRE_FALSE(phigs.anyArchiveOpen());
    }
    CHECK(snapshot(phigs.store()) == before);
}

TEST_CASE("an existing empty file opens as a new archive", "[archive]") {
    auto path = outputFile("empty.phar");
    writeFile(path, "");
    Phigs phigs;
    phigs.open();
    phigs.store().openStructure(1);
    phigs.store().insert(label(7));
    phigs.store().closeStructure();
    phigs.openArchiveFile(1, path);
    CHECK(phigs.archiveContents(1).empty());
    phigs.archiveAllStructures(1);
    phigs.closeArchiveFile(1);
    phigs.openArchiveFile(2, path);
    CHECK(phigs.archiveContents(2) == std::vector<int>{1});
}

TEST_CASE("RETRIEVE STRUCTURE NETWORKS leaves a structure the archive only references alone", "[archive]") {
    auto path = outputFile("references.phar");
    std::filesystem::remove(path);
    Phigs phigs;
    phigs.open();
    StructureStore& store = phigs.store();
    store.openStructure(1);
    store.insert(executeStructure(5));
    store.closeStructure();
    phigs.openArchiveFile(1, path);
    phigs.archiveStructures(1, {1});  // 5 is referenced, not archived
    store.deleteAllStructures();
    store.openStructure(5);
    store.insert(label(55));
    store.closeStructure();
    // Not a conflict, by the inquiries or the retrieval, under every resolution; 5 keeps its label.
    CHECK(phigs.conflictingStructuresInNetwork(1, 1, NetworkSource::Archive).empty());
    for (ConflictResolution r :
         {ConflictResolution::Abandon, ConflictResolution::Update, ConflictResolution::Maintain}) {
        phigs.setConflictResolution(ConflictResolution::Update, r);
        phigs.retrieveStructureNetworks(1, {1});
        CHECK(store.elementCount(1) == 1);
        CHECK(store.elementCount(5) == 1);
        store.deleteStructure(1);
    }
    // A root the archive lacks: error 201 for the archive's network, as for the store's.
    try {
        phigs.conflictingStructuresInNetwork(1, 99, NetworkSource::Archive);
        FAIL("no error for a root the archive lacks");
    } catch (const Error& e) {
        CHECK(e.number() == errors::StructureDoesNotExist);
    }
}

TEST_CASE("a corrupt archive is refused: 300 random single-byte changes are each detected",
          "[archive][errors]") {
    std::mt19937 rng(13);
    auto path = outputFile("corrupt.phar");
    Phigs phigs;
    phigs.open();
    buildRandomNetwork(phigs.store(), rng, 5);
    phigs.openArchiveFile(1, path);
    phigs.archiveAllStructures(1);
    phigs.closeArchiveFile(1);
    const std::string good = readFile(path);
    const auto before = snapshot(phigs.store());
    for (int trial = 0; trial < 300; ++trial) {
        std::string bad = good;
        std::size_t at =
            static_cast<std::size_t>(testing::randomInt(rng, 0, static_cast<int>(good.size()) - 2));
        char replacement = static_cast<char>(testing::randomInt(rng, 32, 126));
        if (bad[at] == replacement) continue;
        bad[at] = replacement;
        writeFile(path, bad);
        CHECK(errorOf([&] { phigs.openArchiveFile(3, path); }) == errors::NotAnArchive);
    }
    writeFile(path, "not an archive at all\n");
    CHECK(errorOf([&] { phigs.openArchiveFile(3, path); }) == errors::NotAnArchive);
    CHECK(snapshot(phigs.store()) == before);
    CHECK(phigs.errorLog().entries().back().detail.find("line 1") != std::string::npos);
}

TEST_CASE("archive conflict resolution: maintain, abandon, update", "[archive]") {
    auto path = outputFile("conflicts.phar");
    Phigs phigs;
    phigs.open();
    StructureStore& store = phigs.store();
    auto put = [&](int id, int value) {
        store.emptyStructure(id);
        store.openStructure(id);
        store.insert(label(value));
        store.closeStructure();
    };
    auto labelOf = [&](int id) { return std::get<LabelElement>(store.elementAt(id, 1)).label; };
    put(1, 10);
    put(2, 20);
    phigs.openArchiveFile(1, path);
    phigs.archiveStructures(1, {1, 2});
    put(1, 11);
    put(3, 30);
    CHECK(phigs.conflictingStructures(1) == std::vector<int>{1, 2});

    SECTION("archival") {
        phigs.setConflictResolution(ConflictResolution::Abandon, ConflictResolution::Abandon);
        CHECK(errorOf([&] { phigs.archiveStructures(1, {1, 3}); }) == errors::ArchiveNameConflict);
        CHECK(phigs.archiveContents(1) == std::vector<int>{1, 2});  // nothing written, not even 3
        phigs.setConflictResolution(ConflictResolution::Maintain, ConflictResolution::Abandon);
        phigs.archiveStructures(1, {1, 3});
        CHECK(phigs.archiveContents(1) == std::vector<int>{1, 2, 3});
        store.deleteAllStructures();
        phigs.retrieveStructures(1, {1});
        CHECK(labelOf(1) == 10);  // the archive kept its copy
        phigs.setConflictResolution(ConflictResolution::Update, ConflictResolution::Update);
        put(1, 12);
        phigs.archiveStructures(1, {1});
        put(1, 0);
        phigs.retrieveStructures(1, {1});
        CHECK(labelOf(1) == 12);
    }
    SECTION("retrieval") {
        auto before = snapshot(store);
        phigs.setConflictResolution(ConflictResolution::Update, ConflictResolution::Abandon);
        CHECK(errorOf([&] { phigs.retrieveStructures(1, {1, 2}); }) == errors::ArchiveNameConflict);
        CHECK(snapshot(store) == before);
        phigs.setConflictResolution(ConflictResolution::Update, ConflictResolution::Maintain);
        phigs.retrieveStructures(1, {1});
        CHECK(labelOf(1) == 11);
        phigs.setConflictResolution(ConflictResolution::Update, ConflictResolution::Update);
        phigs.retrieveStructures(1, {1, 7});  // 7 is not in the archive: created empty, warning 408
        CHECK(labelOf(1) == 10);
        CHECK(store.structureStatus(7) == StructureStatus::Empty);
        CHECK(phigs.errorLog().entries().back().number == errors::MissingInArchiveCreatedEmpty);
    }
}

TEST_CASE("archive networks, delete from archive, conflicts in a network", "[archive]") {
    auto path = outputFile("networks.phar");
    Phigs phigs;
    phigs.open();
    StructureStore& store = phigs.store();
    store.openStructure(1);
    store.insert(executeStructure(2));
    store.closeStructure();
    store.openStructure(2);
    store.insert(executeStructure(3));
    store.closeStructure();
    store.openStructure(4);
    store.closeStructure();
    phigs.openArchiveFile(5, path);
    CHECK(phigs.openArchiveIds() == std::vector<int>{5});
    phigs.archiveStructureNetworks(5, {2});
    CHECK(phigs.archiveContents(5) == std::vector<int>{2, 3});
    phigs.archiveStructures(5, {4, 42});  // 42 does not exist: warning 200
    CHECK(phigs.errorLog().entries().back().number == errors::IgnoringMissingStructures);
    CHECK(phigs.conflictingStructuresInNetwork(5, 1, NetworkSource::Css) == std::vector<int>{2, 3});
    phigs.deleteStructureNetworksFromArchive(5, {2});
    CHECK(phigs.archiveContents(5) == std::vector<int>{4});
    phigs.deleteAllStructuresFromArchive(5);
    CHECK(phigs.archiveContents(5).empty());
    CHECK(errorOf([&] { phigs.openArchiveFile(5, path); }) == errors::ArchiveIdInUse);
    CHECK(errorOf([&] { phigs.closeArchiveFile(6); }) == errors::ArchiveNotOpen);
    phigs.closeArchiveFile(5);
    CHECK(errorOf([&] { phigs.openArchiveFile(6, "/nonexistent-dir/x.phar"); }) == errors::ArchiveCannotOpen);
}

TEST_CASE("retrieving a network that would be cyclic is refused and changes nothing", "[archive][errors]") {
    auto path = outputFile("cyclic.phar");
    Phigs phigs;
    phigs.open();
    StructureStore& store = phigs.store();
    store.openStructure(1);
    store.insert(executeStructure(2));
    store.closeStructure();
    phigs.openArchiveFile(1, path);
    phigs.archiveStructures(1, {1});
    store.deleteAllStructures();
    store.openStructure(2);
    store.insert(executeStructure(1));  // the archive's 1 executes 2: retrieving 1 would close a cycle
    store.closeStructure();
    auto before = snapshot(store);
    phigs.setConflictResolution(ConflictResolution::Update, ConflictResolution::Update);
    CHECK(errorOf([&] { phigs.retrieveStructures(1, {1}); }) == errors::StructureCycle);
    CHECK(snapshot(store) == before);
}

TEST_CASE("retrieve paths to ancestors and descendants read the archive's network, as the store's inquiries",
          "[archive]") {
    auto path = outputFile("paths.phar");
    Phigs phigs;
    phigs.open();
    StructureStore& store = phigs.store();
    // 1 executes 2 twice and 4; 2 executes 3; 4 executes 3 and 5; 6 stands alone.
    const std::map<int, std::vector<int>> network{{1, {2, 2, 4}}, {2, {3}}, {3, {}},
                                                  {4, {3, 5}},    {5, {}},  {6, {}}};
    for (const auto& [id, children] : network) {
        store.openStructure(id);
        store.insert(LabelElement{id});
        for (int child : children) store.insert(executeStructure(child));
        store.closeStructure();
    }
    using Key = std::tuple<int, StructurePathOrder, int>;
    std::map<Key, std::vector<StructurePath>> ancestors, descendants;
    for (const auto& entry : network)
        for (auto order : {StructurePathOrder::TopFirst, StructurePathOrder::BottomFirst})
            for (int depth : {0, 1, 2}) {
                const Key key{entry.first, order, depth};
                ancestors[key] = store.pathsToAncestors(entry.first, order, depth);
                descendants[key] = store.pathsToDescendants(entry.first, order, depth);
            }
    CHECK(ancestors[{3, StructurePathOrder::TopFirst, 0}] ==
          std::vector<StructurePath>{
              {{1, 2}, {2, 2}, {3, 0}}, {{1, 3}, {2, 2}, {3, 0}}, {{1, 4}, {4, 2}, {3, 0}}});
    phigs.openArchiveFile(1, path);
    phigs.archiveAllStructures(1);
    store.deleteAllStructures();

    for (const auto& [key, paths] : ancestors) {
        const auto [id, order, depth] = key;
        INFO("structure " << id << " depth " << depth);
        CHECK(phigs.retrievePathsToAncestors(1, id, order, depth) == paths);
        CHECK(phigs.retrievePathsToDescendants(1, id, order, depth) == descendants[key]);
    }
    CHECK(store.structureIds().empty());  // the store is not touched

    const std::size_t warnings = phigs.errorLog().entries().size();
    CHECK(phigs.retrievePathsToAncestors(1, 42, StructurePathOrder::TopFirst, 0).empty());
    CHECK(phigs.errorLog().entries().size() == warnings + 1);
    CHECK(phigs.errorLog().entries().back().number == errors::MissingInArchive);
    CHECK(phigs.retrievePathsToDescendants(1, 42, StructurePathOrder::TopFirst, 0).empty());
    CHECK(errorOf([&] { phigs.retrievePathsToDescendants(1, 1, StructurePathOrder::TopFirst, -1); }) ==
          errors::NegativePathDepth);
    CHECK(errorOf([&] { phigs.retrievePathsToAncestors(2, 1, StructurePathOrder::TopFirst, 0); }) ==
          errors::ArchiveNotOpen);
    phigs.closeArchiveFile(1);

    // A hand-made archive whose network is cyclic (this toolkit never writes one) is reported, not
    // walked for ever.
    auto cyclicPath = outputFile("paths_cyclic.phar");
    writeFile(cyclicPath, ArchiveFile::encode({{7, {executeStructure(8)}}, {8, {executeStructure(7)}}}));
    phigs.openArchiveFile(2, cyclicPath);
    CHECK(errorOf([&] { phigs.retrievePathsToDescendants(2, 7, StructurePathOrder::TopFirst, 0); }) ==
          errors::StructureCycle);
    CHECK(errorOf([&] { phigs.retrievePathsToAncestors(2, 7, StructurePathOrder::TopFirst, 0); }) ==
          errors::StructureCycle);
    phigs.closeArchiveFile(2);
}

}  // namespace test_archive
