#include "ArchiveV1Elements.h"
#include "RandomElements.h"
#include "phigs/core/Error.h"
#include "phigs/store/ArchiveFile.h"

#include <catch2/catch.hpp>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <type_traits>

namespace test_archive_versions {

// One object per open archive file: a copy would write the file from contents of its own.
static_assert(!std::is_copy_constructible_v<phigs::ArchiveFile> &&
              !std::is_copy_assignable_v<phigs::ArchiveFile>);
static_assert(std::is_nothrow_move_constructible_v<phigs::ArchiveFile>);

using namespace phigs;

namespace {

std::string readFile(const std::filesystem::path& p) {
    std::ifstream in(p, std::ios::binary);
    std::stringstream s;
    s << in.rdbuf();
    return s.str();
}

/// The version-1 archives in tests/data/archive_v1, by the number their contents were drawn from.
std::map<std::uint32_t, std::filesystem::path> v1Files() {
    std::map<std::uint32_t, std::filesystem::path> files;
    for (const auto& entry :
         std::filesystem::directory_iterator(std::filesystem::path(PHIGS_TEST_DATA_DIR) / "archive_v1")) {
        const std::string stem = entry.path().stem().string();
        if (entry.path().extension() == ".phar" && stem.starts_with("v1_"))
            files[static_cast<std::uint32_t>(std::stoul(stem.substr(3)))] = entry.path();
    }
    return files;
}

/// Counts the four payloads version 2 extended, and those holding anything version 2 added.
struct ExtendedCount {
    int records = 0, withVersion2Data = 0;
    void operator()(const FillAreaSetWithDataElement& e) {
        ++records, withVersion2Data += !e.edgeFlags.empty();
    }
    void operator()(const TriangleStripElement& e) {
        ++records, withVersion2Data += !e.facetColours.empty() || !e.facetNormals.empty();
    }
    void operator()(const QuadrilateralMeshElement& e) {
        ++records, withVersion2Data += !e.facetColours.empty() || !e.facetNormals.empty();
    }
    void operator()(const SurfaceCharacteristicsAttribute& e) {
        const SurfaceCharacteristicsAttribute defaults;
        ++records, withVersion2Data +=
                   e.origin != defaults.origin || e.direction != defaults.direction || !e.levels.empty();
    }
    template <class E>
    void operator()(const E&) {}
};

/// `contents` with random version-2 data in every extended payload, of the shapes the checks ask.
std::map<int, std::vector<Element>> withVersion2Data(std::map<int, std::vector<Element>> contents,
                                                     std::mt19937& rng) {
    using namespace testing::v1;
    for (auto& [id, elements] : contents)
        for (Element& element : elements)
            std::visit(
                [&](auto& e) {
                    using E = std::decay_t<decltype(e)>;
                    if constexpr (std::is_same_v<E, FillAreaSetWithDataElement>) {
                        for (const auto& contour : e.contours) {
                            e.edgeFlags.emplace_back();
                            for (std::size_t k = 0; k < contour.size(); ++k)
                                e.edgeFlags.back().push_back(draw(rng, 0, 1));
                        }
                    } else if constexpr (std::is_same_v<E, TriangleStripElement>) {
                        e.facetColours = colours(rng, e.points.size() - 2);
                        e.facetNormals = points(rng, static_cast<int>(e.points.size()) - 2);
                    } else if constexpr (std::is_same_v<E, QuadrilateralMeshElement>) {
                        const int quads = (e.rows - 1) * (e.columns - 1);
                        e.facetColours = colours(rng, static_cast<std::size_t>(quads));
                        e.facetNormals = points(rng, quads);
                    } else if constexpr (std::is_same_v<E, SurfaceCharacteristicsAttribute>) {
                        e.style = draw(rng, 4, 5);
                        e.origin = point(rng), e.direction = point(rng);
                        for (int k = draw(rng, 1, 5); k > 0; --k) e.levels.push_back(real(rng));
                    }
                },
                element);
    return contents;
}

/// The detail of the error 403 decoding `text` raises; fails the test when it raises none.
std::string refusal(const std::string& text) {
    try {
        ArchiveFile::decode(text, "memory", nullptr);
    } catch (const Error& e) {
        CHECK(e.number() == errors::NotAnArchive);
        return e.detail();
    }
    FAIL("decoded without an error");
    return {};
}

}  // namespace

TEST_CASE("version-1 archives written before version 2 read back exactly, version-2 fields empty",
          "[archive]") {
    const auto files = v1Files();
    REQUIRE(files.size() >= 4);
    int records = 0;
    for (const auto& [seed, path] : files) {
        INFO(path.string());
        const std::string text = readFile(path);
        REQUIRE(text.starts_with("PHIGS-ARCHIVE 1\n"));
        const auto expected = testing::v1::archive(seed);
        const auto read = ArchiveFile::decode(text, path.string(), nullptr);
        CHECK(read == expected);
        ExtendedCount count;
        for (const auto& [id, elements] : read)
            for (const Element& element : elements) std::visit(count, element);
        CHECK(count.records >= 4);
        CHECK(count.withVersion2Data == 0);
        records += count.records;

        // Opened as an archive file it reads the same and stays as it was; written again it is
        // the current version and reads back equal.
        const auto copy = std::filesystem::path(PHIGS_TEST_OUTPUT_DIR) / path.filename();
        std::filesystem::copy_file(path, copy, std::filesystem::copy_options::overwrite_existing);
        ErrorLog log;
        ArchiveFile archive(copy, &log);
        CHECK(archive.contents() == expected);
        CHECK(readFile(copy) == text);
        const std::string rewritten = ArchiveFile::encode(read);
        CHECK(rewritten.starts_with("PHIGS-ARCHIVE " + std::to_string(ArchiveFile::kFormatVersion) + "\n"));
        CHECK(ArchiveFile::decode(rewritten, "memory", nullptr) == expected);
    }
    CHECK(records >= 16);
}

TEST_CASE("version-2 data round-trips: cut or missing, it is refused naming the line", "[archive][errors]") {
    const auto files = v1Files();
    REQUIRE(files.size() >= 3);
    for (const auto& [seed, path] : files) {
        std::mt19937 rng(seed);
        const auto v1 = testing::v1::archive(seed);
        const auto contents = withVersion2Data(v1, rng);
        const std::string text = ArchiveFile::encode(contents);
        REQUIRE(ArchiveFile::decode(text, "memory", nullptr) == contents);
        ExtendedCount count;
        for (const auto& [id, elements] : contents)
            for (const Element& element : elements) std::visit(count, element);
        REQUIRE(count.withVersion2Data == count.records);

        // Every cut inside the records is refused, with the line and no crash.
        const std::size_t firstRecord = text.find('\n', text.find("STRUCTURE")) + 1;
        const std::size_t end = text.rfind("END ");
        int refused = 0;
        for (std::size_t cut = firstRecord; cut < end; cut += 1 + cut % 7) {
            const std::string detail = refusal(text.substr(0, cut));
            CHECK(detail.starts_with("memory: line "));
            refused += detail.starts_with("memory: line ");
        }
        CHECK(refused > 100);

        // Version-1 records under a version-2 header lack the fields version 2 added: the reader
        // takes the next record's type name for a count or a real and says so.
        std::string v1Text = readFile(path);
        v1Text.replace(0, v1Text.find('\n'), "PHIGS-ARCHIVE 2");
        const std::string detail = refusal(v1Text);
        INFO(detail);
        CHECK(detail.starts_with("memory: line "));
        CHECK(detail.find(": bad ") != std::string::npos);
    }
}

TEST_CASE("version-2 archives read back with every trimming curve hidden and workstation dependent",
          "[archive]") {
    std::mt19937 rng(7);
    NurbsSurfaceElement surface{testing::randomSurface(rng), {}};
    surface.trimLoops = {{testing::randomCurve(rng, false)}, {testing::randomCurve(rng, true)}};
    const std::map<int, std::vector<Element>> contents{{4, {surface, label(3)}}};
    // Version 3 adds the display list (here empty, " 0") at the end of the surface's record.
    const std::string v3 = ArchiveFile::encode(contents);
    REQUIRE(v3.starts_with("PHIGS-ARCHIVE 3\n"));
    const std::size_t record = v3.find("\nLABEL");
    REQUIRE(record != std::string::npos);
    REQUIRE(v3.compare(record - 2, 2, " 0") == 0);
    std::string v2 = v3;
    v2.erase(record - 2, 2);
    v2.replace(0, v2.find('\n'), "PHIGS-ARCHIVE 2");
    // The checksum covers every byte before END: write it again for the edited text.
    const std::size_t end = v2.rfind("END ");
    std::uint64_t hash = 1469598103934665603ull;  // the format's FNV-1a offset basis
    for (std::size_t i = 0; i < end; ++i)
        hash = (hash ^ static_cast<unsigned char>(v2[i])) * 1099511628211ull;
    char hex[17];
    std::snprintf(hex, sizeof hex, "%016llx", static_cast<unsigned long long>(hash));
    const std::size_t checksum = v2.rfind(' ');
    v2 = v2.substr(0, checksum + 1) + hex + "\n";
    CHECK(ArchiveFile::decode(v2, "memory", nullptr) == contents);

    // With a display list, the version-3 record under a version-2 header is refused by line.
    NurbsSurfaceElement shown = surface;
    shown.trimDisplay = {{true, 2, 5.0}, {false, 6, 0.25}};
    std::string misread = ArchiveFile::encode({{4, {shown, label(3)}}});
    CHECK(ArchiveFile::decode(misread, "memory", nullptr).at(4).front() == Element(shown));
    misread.replace(0, misread.find('\n'), "PHIGS-ARCHIVE 2");
    CHECK(refusal(misread).starts_with("memory: line "));
}

TEST_CASE("archive versions other than 1 to the current one are refused by number", "[archive][errors]") {
    const std::string current = std::to_string(ArchiveFile::kFormatVersion);
    const std::string body =
        ArchiveFile::encode({}).substr(std::string("PHIGS-ARCHIVE ").size() + current.size());
    CHECK(ArchiveFile::decode("PHIGS-ARCHIVE " + current + body, "memory", nullptr).empty());
    const std::string next = std::to_string(ArchiveFile::kFormatVersion + 1);
    for (const std::string& version : {std::string("0"), next, std::string("-1"), std::string("12")})
        CHECK(refusal("PHIGS-ARCHIVE " + version + body) == "memory: line 1: unsupported archive version " +
                                                                version + " (this reader reads 1 to " +
                                                                current + ")");
    CHECK(refusal("PHIGS-ARCHIVE x" + body) == "memory: line 1: bad version 'x'");
}

}  // namespace test_archive_versions
