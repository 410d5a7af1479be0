// Archive files under limits: a count is checked against the bytes left before room
// is made for its items, a file over the size limit is refused before it is read and never
// written, a refused retrieval leaves the store exactly as it was, writes are flushed to the
// disk, and a temporary file left by a killed write is removed when the archive is opened.

#include "ErrorNumber.h"
#include "phigs/Phigs.h"

#include <catch2/catch.hpp>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <sstream>

namespace test_archive_limits {

using namespace phigs;
using phigs::test::errorOf;

namespace {

std::filesystem::path outputFile(const std::string& name) {
    std::filesystem::path p = std::filesystem::path(PHIGS_TEST_OUTPUT_DIR) / name;
    std::filesystem::remove_all(p);
    std::filesystem::remove_all(p.string() + ".tmp");
    return p;
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

/// A line of /proc/self/status in KiB ("VmRSS", "VmHWM"), or -1.
long statusKiB(const std::string& key) {
    std::ifstream status("/proc/self/status");
    for (std::string line; std::getline(status, line);)
        if (line.rfind(key + ":", 0) == 0) return std::stol(line.substr(key.size() + 1));
    return -1;
}

/// Resets the peak resident size (VmHWM) to the current one; false where the kernel refuses.
bool resetPeakResident() {
    std::ofstream clear("/proc/self/clear_refs");
    clear << "5";
    clear.flush();
    return static_cast<bool>(clear);
}

/// Opening a bad archive: the error, how long it took and how far the peak resident memory
/// rose above what it was before (-1 when it cannot be measured here).
struct Refusal {
    int number = 0;
    std::string detail;
    double seconds = 0;
    long growthKiB = -1;
};

Refusal openRefused(Phigs& phigs, const std::filesystem::path& path) {
    const bool measured = resetPeakResident();
    const long before = statusKiB("VmRSS");
    const auto start = std::chrono::steady_clock::now();
    Refusal r;
    try {
        phigs.openArchiveFile(9, path);
        phigs.closeArchiveFile(9);
    } catch (const Error& e) {
        r.number = e.number();
        r.detail = e.detail();
    }
    r.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    if (measured && before > 0) r.growthKiB = statusKiB("VmHWM") - before;
    return r;
}

std::map<int, std::vector<Element>> snapshot(const StructureStore& store) {
    std::map<int, std::vector<Element>> out;
    for (int id : store.structureIds()) {
        out[id];
        for (int n = 1; n <= store.elementCount(id); ++n) out[id].push_back(store.elementAt(id, n));
    }
    return out;
}

/// Everything a refused call must leave alone: contents, versions, serials, the operation count.
struct StoreState {
    std::map<int, std::vector<Element>> contents;
    std::map<int, std::uint64_t> versions;
    std::vector<std::uint64_t> serials;
    std::uint64_t operations = 0;
    bool operator==(const StoreState&) const = default;
};

StoreState stateOf(const StructureStore& store) {
    StoreState s{snapshot(store), {}, {}, store.operationCount()};
    for (int id : store.structureIds()) {
        s.versions[id] = store.structure(id).version;
        const ElementArena& elements = store.structure(id).elements;
        for (std::size_t i = 0; i < elements.size(); ++i) s.serials.push_back(elements.serial(i));
    }
    return s;
}

const std::string kHeader = "PHIGS-ARCHIVE 1\nSTRUCTURE 1 1\n";

}  // namespace

TEST_CASE("a huge count followed by little data is refused at once, without memory growth",
          "[archive][errors][limits]") {
    // Before the counts were checked against the bytes left, each of these made room for every
    // item first: 24 bytes per point, 80 per trimming curve, 152 per element, about 0.4, 0.6 and
    // 2.5 GB here, before error 403.
    const std::size_t blanks = std::size_t{16} << 20;
    const std::string n = std::to_string(blanks);
    const std::string half = std::to_string(blanks / 2);
    struct Case {
        std::string what, text;
        int line = 3;
    };
    const std::vector<Case> cases{
        {"points", kHeader + "POLYLINE_3 " + n + "\n" + std::string(blanks, ' ')},
        {"trimming curves", kHeader + "NON-UNIFORM_B-SPLINE_SURFACE 1 1 0 0 0 0 0 0 1 " + half + "\n" +
                                std::string(blanks / 2, ' ')},
        {"elements", "PHIGS-ARCHIVE 1\nSTRUCTURE 1 " + n + "\n" + std::string(blanks, '\n'), 2},
        {"string bytes", kHeader + "APPLICATION_DATA " + n + ":" + std::string(1000, 'x')},
    };
    auto path = outputFile("huge_count.phar");
    Phigs phigs;
    phigs.open();
    phigs.store().openStructure(1);
    phigs.store().insert(label(1));
    phigs.store().closeStructure();
    const StoreState before = stateOf(phigs.store());
    for (const auto& c : cases) {
        INFO(c.what);
        writeFile(path, c.text);
        const Refusal r = openRefused(phigs, path);
        CHECK(r.number == errors::NotAnArchive);
        CHECK(r.detail.find(path.string() + ": line " + std::to_string(c.line) + ": ") == 0);
        CHECK(r.seconds < 1.0);
        if (r.growthKiB >= 0) CHECK(r.growthKiB < 64 * 1024);  // the file itself is 16 MiB
        WARN(c.what << ": " << r.detail.substr(path.string().size()) << " (" << r.seconds
                    << " s, peak resident +" << r.growthKiB << " KiB)");
    }
    CHECK_FALSE(phigs.anyArchiveOpen());
    CHECK(stateOf(phigs.store()) == before);
    std::filesystem::remove(path);
}

TEST_CASE("a count is read when the bytes left can hold its items, refused one byte short",
          "[archive][errors][limits]") {
    // Each pair: the text with exactly the least bytes the count needs (it is read; the error
    // that follows is another one) and the same text one byte short (the count is refused).
    struct Case {
        std::string what, prefix, items;
    };
    const std::vector<Case> cases{
        {"points, 6 bytes each", kHeader + "POLYLINE_3 5", " 0 0 0 0 0 0 0 0 0 0 0 0 0 0 0"},
        {"elements, 8 bytes each", "PHIGS-ARCHIVE 1\nSTRUCTURE 1 3", "\nLABEL 0\nLABEL 0\nLABEL 0"},
        {"trimming curves, 8 bytes each", kHeader + "NON-UNIFORM_B-SPLINE_SURFACE 1 1 0 0 0 0 0 0 1 2",
         " 1 0 0 0 1 0 0 0"},
        {"colours, 4 bytes each", kHeader + "TRIANGLE_STRIP_3_WITH_DATA 0 3", " I 0 I 0 I 0"},
        {"list items of lists, 2 bytes each", kHeader + "FILL_AREA_SET_3 4", " 0 0 0 0"},
        {"half spaces, 12 bytes each", kHeader + "SET_MODEL_CLIPPING_VOLUME_3 1 1", " 0 0 0 0 0 0"},
    };
    for (const auto& c : cases) {
        INFO(c.what);
        try {
            ArchiveFile::decode(c.prefix + c.items, "at-limit", nullptr);
            FAIL("decoded");
        } catch (const Error& e) {
            CHECK(e.detail().find("bytes are left") == std::string::npos);
        }
        try {
            ArchiveFile::decode(c.prefix + c.items.substr(0, c.items.size() - 1), "short", nullptr);
            FAIL("decoded");
        } catch (const Error& e) {
            CHECK(e.number() == errors::NotAnArchive);
            CHECK(e.detail().find("short: line ") == 0);
            CHECK(e.detail().find("bytes are left in the file") != std::string::npos);
        }
    }
}

TEST_CASE("lists in their shortest form read back: no count is checked too tightly", "[archive][limits]") {
    geom::Surface surface(1, 1, {0, 0, 1, 1}, {0, 0, 1, 1}, 2, 2,
                          {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {1, 1, 0}});
    std::map<int, std::vector<Element>> contents;
    contents[0] = {label(0),
                   PolylineElement{},
                   PolylineElement{{{0, 0, 0}}, true},
                   FillAreaSetElement{{{}, {}, {}}, false},
                   CellArrayElement{{}, {}, {}, 0, 0, {}, true},
                   QuadrilateralMeshElement{},
                   TriangleStripElement{{{0, 0, 0}}, {Colour::indexed(0)}, {}},
                   NurbsSurfaceElement{surface, {{}, {}}},
                   LightSourceStateAttribute{},
                   NameSetElement{true, {0, 0}},
                   ModelClipElement{1, {{{0, 0, 0}, {0, 0, 0}}}, false},
                   ApplicationDataElement{},
                   RestoreModelClipElement{}};
    contents[1] = {};
    const std::string text = ArchiveFile::encode(contents);
    CHECK(ArchiveFile::decode(text, "shortest", nullptr) == contents);
}

TEST_CASE("the file size limit: a file of the limit opens, one byte more is refused before it is read",
          "[archive][errors][limits]") {
    auto path = outputFile("size_limit.phar");
    std::map<int, std::vector<Element>> contents{{1, {label(1), polyline3({{0, 1, 2}})}}, {2, {}}};
    writeFile(path, ArchiveFile::encode(contents));
    const std::size_t size = std::filesystem::file_size(path);
    CHECK(ArchiveFile(path, nullptr, size).contents() == contents);
    ErrorLog log;
    try {
        ArchiveFile(path, &log, size - 1);
        FAIL("opened");
    } catch (const Error& e) {
        CHECK(e.number() == errors::NotAnArchive);
        CHECK(e.detail() == path.string() + ": " + std::to_string(size) + " bytes, more than the limit of " +
                                std::to_string(size - 1) + " bytes for an archive");
    }

    SECTION("writing: up to the limit, beyond it error 903 with the file and the object unchanged") {
        ArchiveFile file(path, &log, size);
        file.commit({{3, {}}}, {2});  // "STRUCTURE 3 0" is as long as "STRUCTURE 2 0"
        CHECK(file.structureIds() == std::vector<int>{1, 3});
        const std::string written = readFile(path);
        CHECK(written.size() == size);
        CHECK(errorOf([&] { file.commit({{4, {}}}, {}); }) == errors::WriteError);
        CHECK(log.entries().back().detail.find("more than the limit of " + std::to_string(size)) !=
              std::string::npos);
        CHECK(file.structureIds() == std::vector<int>{1, 3});
        CHECK(readFile(path) == written);
    }
    SECTION("writing far beyond the limit stops making the text there") {
        // Ten polylines of 100,000 points, about 50 MB of text: the refusal comes at the first
        // (the whole text was made before it, 23 times the archive limit at most).
        ArchiveFile file(path, &log, size);
        std::vector<Element> large;
        for (int k = 0; k < 10; ++k) {
            std::vector<glm::dvec3> points;
            for (int i = 0; i < 100000; ++i) points.push_back({0.1 * i, 1.0 / (i + 3), k + 0.3});
            large.push_back(polyline3(points));
        }
        CHECK(errorOf([&] { file.commit({{5, large}}, {}); }) == errors::WriteError);
        CHECK(log.entries().back().detail ==
              path.string() + ": the archive would be more than the limit of " + std::to_string(size) +
                  " bytes (passed at structure 5, element 1 of 10)");
        CHECK(file.structureIds() == std::vector<int>{1, 2});
        CHECK(readFile(path).size() == size);
    }
    SECTION("the default limit") {
        std::filesystem::resize_file(path, ArchiveFile::kMaxFileBytes + 1);  // sparse: costs nothing
        const auto start = std::chrono::steady_clock::now();
        CHECK(errorOf([&] { ArchiveFile(path, &log); }) == errors::NotAnArchive);
        CHECK(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count() < 0.5);
        CHECK(log.entries().back().detail.find("more than the limit of 67108864 bytes") != std::string::npos);
        // at the limit the file is read, and refused for what it holds (NUL bytes), not its size
        writeFile(path, "");
        std::filesystem::resize_file(path, ArchiveFile::kMaxFileBytes);
        CHECK(errorOf([&] { ArchiveFile(path, &log); }) == errors::NotAnArchive);
        CHECK(log.entries().back().detail.find("no PHIGS-ARCHIVE header") != std::string::npos);
    }
    std::filesystem::remove(path);
}

TEST_CASE("an archive holding what INSERT refuses is refused naming the line", "[archive][errors]") {
    // Files written elsewhere: indices out of their ISO range (INSERT gives 100, 113, 114, 119,
    // 121) and a NURBS surface whose count wraps the kernel's size arithmetic (it crashed).
    const std::vector<std::string> lines{
        "SET_POLYLINE_INDEX 0",
        "SET_INTERIOR_INDEX -2147483648",
        "SET_VIEW_INDEX -1",
        "SET_DEPTH_CUE_INDEX -7",
        "SET_COLOUR_MAPPING_INDEX -2",
        "NON-UNIFORM_B-SPLINE_SURFACE 1 1 0 4 0 0 1 1 18446744073709551614 2 0 0 0 0",
        "NON-UNIFORM_B-SPLINE_SURFACE 2 1 0 4 0 0 1 1 18446744073709551613 2 0 0 0 0",
    };
    auto path = outputFile("refused_content.phar");
    Phigs phigs;
    phigs.open();
    const StoreState before = stateOf(phigs.store());
    for (const std::string& line : lines) {
        INFO(line);
        writeFile(path, kHeader + line + "\n");
        const Refusal r = openRefused(phigs, path);
        CHECK(r.number == errors::NotAnArchive);
        CHECK(r.detail.find(path.string() + ": line 3: ") == 0);
    }
    CHECK(stateOf(phigs.store()) == before);
    std::filesystem::remove(path);
}

TEST_CASE("one file is open under one archive id at a time", "[archive][errors]") {
    // Each archive writes its whole contents back: a second id on the file would overwrite what
    // the first one wrote.
    auto path = outputFile("twice.phar");
    Phigs phigs;
    phigs.open();
    for (int id : {10, 20}) {
        phigs.store().openStructure(id);
        phigs.store().insert(label(id));
        phigs.store().closeStructure();
    }
    phigs.openArchiveFile(1, path);
    const std::filesystem::path sameFile = path.parent_path() / "." / path.filename();
    for (const auto& spelling : {path, sameFile}) {
        try {
            phigs.openArchiveFile(2, spelling);
            FAIL("the second open was accepted");
        } catch (const Error& e) {
            CHECK(e.number() == errors::ArchiveCannotOpen);
            CHECK(e.detail().find("already open as archive 1") != std::string::npos);
        }
    }
    CHECK(phigs.openArchiveIds() == std::vector<int>{1});
    phigs.archiveStructures(1, {10});
    phigs.archiveStructures(1, {20});
    phigs.closeArchiveFile(1);
    // Closed, the file opens again, under any id, and holds both.
    phigs.openArchiveFile(2, sameFile);
    CHECK(phigs.archiveContents(2) == std::vector<int>{10, 20});
    phigs.closeArchiveFile(2);
    std::filesystem::remove(path);
}

TEST_CASE("a refused retrieval changes nothing: contents, versions, serials, postings", "[archive][errors]") {
    auto path = outputFile("refused_retrieval.phar");
    // A hand-made archive (this toolkit never writes one) whose structure 7 executes 8 and 8
    // executes 7, beside a good structure 1 that executes 5.
    writeFile(path, ArchiveFile::encode({{1, {label(10), executeStructure(5)}},
                                         {7, {executeStructure(8)}},
                                         {8, {executeStructure(7)}}}));
    Phigs phigs;
    phigs.open();
    StructureStore& store = phigs.store();
    store.openStructure(5);
    store.insert(executeStructure(1));  // with the archive's 1, retrieving 1 closes a cycle
    store.closeStructure();
    store.openStructure(1);
    store.insert(label(1));
    Workstation& ws = phigs.openWorkstation(1, WorkstationType::OffscreenImage);
    ws.postStructure(1, 0.5);
    phigs.openArchiveFile(1, path);
    const StoreState before = stateOf(store);
    for (auto mode :
         {ConflictResolution::Maintain, ConflictResolution::Abandon, ConflictResolution::Update}) {
        phigs.setConflictResolution(ConflictResolution::Update, mode);
        CHECK(errorOf([&] { phigs.retrieveAllStructures(1); }) ==
              (mode == ConflictResolution::Abandon ? errors::ArchiveNameConflict : errors::StructureCycle));
        CHECK(errorOf([&] { phigs.retrieveStructureNetworks(1, {7}); }) == errors::StructureCycle);
        if (mode == ConflictResolution::Update)
            CHECK(errorOf([&] { phigs.retrieveStructures(1, {1}); }) == errors::StructureCycle);
        CHECK(stateOf(store) == before);
        CHECK(store.openStructureId() == 1);
        CHECK(store.elementPointer() == 1);
        CHECK(ws.postedStructures() == std::vector<PostedStructure>{{1, 0.5}});
    }
    // Maintain skips the conflicting 1, so only the cycle of 7 and 8 stops the retrieval; without
    // them the rest comes in.
    phigs.setConflictResolution(ConflictResolution::Update, ConflictResolution::Maintain);
    phigs.retrieveStructures(1, {1, 8});
    CHECK(store.structureIds() == std::vector<int>{1, 5, 7, 8});
    phigs.closeArchiveFile(1);
    std::filesystem::remove(path);
}

TEST_CASE("archive writes leave no temporary file and a complete archive", "[archive][durability]") {
    auto path = outputFile("durable.phar");
    const std::filesystem::path temporary = path.string() + ".tmp";
    Phigs phigs;
    phigs.open();
    StructureStore& store = phigs.store();
    for (int id = 1; id <= 5; ++id) {
        store.openStructure(id);
        store.insert(label(id));
        store.closeStructure();
    }
    phigs.openArchiveFile(1, path);
    for (int round = 0; round < 5; ++round) {
        phigs.archiveStructures(1, {round + 1});
        CHECK_FALSE(std::filesystem::exists(temporary));
        const std::string text = readFile(path);
        CHECK(text == ArchiveFile::encode(ArchiveFile(path, nullptr).contents()));
        CHECK(text.ends_with("\n"));
        CHECK(ArchiveFile(path, nullptr).structureIds().size() == static_cast<std::size_t>(round + 1));
    }
    phigs.deleteStructuresFromArchive(1, {2});
    CHECK_FALSE(std::filesystem::exists(temporary));
    CHECK(ArchiveFile(path, nullptr).structureIds() == std::vector<int>{1, 3, 4, 5});

    SECTION("a write that cannot make its temporary file is refused, the archive as it was") {
        const std::string old = readFile(path);
        std::filesystem::create_directory(temporary);  // in the way of the temporary file
        CHECK(errorOf([&] { phigs.archiveStructures(1, {2}); }) == errors::WriteError);
        CHECK(phigs.errorLog().entries().back().detail.find(temporary.string() + ": cannot be written (") ==
              0);
        CHECK(readFile(path) == old);
        CHECK(phigs.archiveContents(1) == std::vector<int>{1, 3, 4, 5});
        CHECK(std::filesystem::is_directory(temporary));  // not ours to remove
        std::filesystem::remove(temporary);
        phigs.archiveStructures(1, {2});
        CHECK(ArchiveFile(path, nullptr).structureIds() == std::vector<int>{1, 2, 3, 4, 5});
    }
    phigs.closeArchiveFile(1);
    std::filesystem::remove(path);
}

TEST_CASE("an archive opened through a link is written through it, the link kept", "[archive][durability]") {
    const auto target = outputFile("linked_target.phar"), link = outputFile("linked.phar");
    std::filesystem::create_symlink(target.filename(), link);  // dangling: the archive is created
    Phigs phigs;
    phigs.open();
    phigs.store().openStructure(7);
    phigs.store().insert(label(7));
    phigs.store().closeStructure();
    phigs.openArchiveFile(1, link);
    phigs.archiveStructures(1, {7});
    phigs.closeArchiveFile(1);
    CHECK(std::filesystem::is_symlink(link));
    CHECK(ArchiveFile(target, nullptr).structureIds() == std::vector<int>{7});
    std::filesystem::remove(link), std::filesystem::remove(target);
}

TEST_CASE("a temporary file left by a killed write is removed when the archive is opened",
          "[archive][durability]") {
    auto path = outputFile("stale.phar");
    const std::filesystem::path temporary = path.string() + ".tmp";
    const std::map<int, std::vector<Element>> contents{{4, {label(4)}}};
    writeFile(path, ArchiveFile::encode(contents));
    const std::string partial = ArchiveFile::encode({{4, {label(4)}}, {5, {label(5)}}}).substr(0, 30);

    SECTION("beside an archive") {
        writeFile(temporary, partial);
        ArchiveFile file(path, nullptr);
        CHECK_FALSE(std::filesystem::exists(temporary));
        CHECK(file.contents() == contents);  // the last complete archive
    }
    SECTION("of an archive never completed") {
        std::filesystem::remove(path);
        writeFile(temporary, partial);
        ArchiveFile file(path, nullptr);
        CHECK_FALSE(std::filesystem::exists(temporary));
        CHECK(file.contents().empty());
        CHECK(std::filesystem::exists(path));
    }
    SECTION("a link: the link goes, not what it names") {
        auto target = outputFile("stale_target.txt");
        writeFile(target, "keep me");
        std::filesystem::create_symlink(target, temporary);
        ArchiveFile file(path, nullptr);
        CHECK_FALSE(std::filesystem::exists(std::filesystem::symlink_status(temporary)));
        CHECK(readFile(target) == "keep me");
        std::filesystem::remove(target);
    }
    std::filesystem::remove(path);
}

}  // namespace test_archive_limits
