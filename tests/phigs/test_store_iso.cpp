// Cases where ISO 9592, as the NIST PHIGS validation tests (PVT) read it, decides what the store
// does and a plain reading might not: CHANGE STRUCTURE IDENTIFIER (AND REFERENCES) of a missing
// structure, CHANGE STRUCTURE REFERENCES with nothing to move, and paths of a single structure.
// The PVT test numbers name the source of each expectation.

#include "ErrorNumber.h"
#include "phigs/Phigs.h"

#include <catch2/catch.hpp>

#include <filesystem>
#include <limits>

namespace test_store_iso {

using namespace phigs;
using phigs::test::errorOf;

namespace {

void build(StructureStore& store, int id, const std::vector<Element>& elements) {
    store.openStructure(id);
    for (const auto& e : elements) store.insert(e);
    store.closeStructure();
}

}  // namespace

TEST_CASE("change structure identifier of a missing structure empties the result, no error", "[store][iso]") {
    Phigs phigs;
    phigs.open();
    StructureStore& store = phigs.store();
    build(store, 1, {executeStructure(2)});
    build(store, 2, {label(20)});
    Workstation& ws = phigs.openWorkstation(1, WorkstationType::OffscreenImage);
    ws.postStructure(2, 0.5);

    store.changeStructureIdentifier(300, 350);  // PVT 02.01.03.01/01 case 1: result created, empty
    CHECK(store.structureStatus(350) == StructureStatus::Empty);
    CHECK_FALSE(store.exists(300));
    store.changeStructureIdentifier(300, 2);  // cases 4-5: referenced, posted result emptied
    CHECK(store.structureStatus(2) == StructureStatus::Empty);
    CHECK(std::get<ExecuteStructureElement>(store.elementAt(1, 1)).structureId == 2);
    CHECK(ws.postedStructures() == std::vector<PostedStructure>{{2, 0.5}});
    CHECK_FALSE(store.exists(300));
    store.changeStructureIdentifier(301, 301);  // PVT 02.01.03.01/02: the same identifier creates it
    CHECK(store.structureStatus(301) == StructureStatus::Empty);
    store.changeStructureIdentifierAndReferences(302, 302);  // PVT 02.01.03.03/02
    CHECK(store.structureStatus(302) == StructureStatus::Empty);

    build(store, 4, {label(1), label(2), label(3)});
    store.openStructure(4);
    store.setElementPointer(2);
    store.changeStructureIdentifier(303, 4);  // PVT 02.01.03.01/03: the open result, pointer 0
    CHECK(store.elementPointer() == 0);
    CHECK(store.elementCount(4) == 0);
    store.changeStructureIdentifierAndReferences(304, 4);  // PVT 02.01.03.03/03 likewise
    CHECK(store.elementPointer() == 0);
    store.closeStructure();
    CHECK_FALSE(store.exists(304));
}

TEST_CASE("change structure references with nothing to move changes nothing", "[store][iso]") {
    Phigs phigs;
    phigs.open();
    StructureStore& store = phigs.store();
    build(store, 1, {executeStructure(2)});
    const auto before = store.structureIds();
    const std::uint64_t operations = store.operationCount();
    store.changeStructureReferences(300, 320);  // PVT 02.01.03.02/01: both missing
    store.changeStructureReferences(300, 1);    // the original missing, the result there
    store.changeStructureReferences(1, 2);      // the original not referenced
    store.changeStructureReferences(2, 2);      // the same identifier
    CHECK(store.structureIds() == before);
    CHECK(store.operationCount() == operations);

    // A posted original moves its posting to a result that did not exist, which is created
    // (PVT 02.01.03.02/03); a referenced one its executes (02.01.03.02/02).
    Workstation& ws = phigs.openWorkstation(1, WorkstationType::OffscreenImage);
    ws.postStructure(1, 0.42);
    store.changeStructureReferences(1, 40);
    CHECK(store.exists(40));
    CHECK(ws.postedStructures() == std::vector<PostedStructure>{{40, 0.42}});
    store.changeStructureReferences(2, 41);
    CHECK(std::get<ExecuteStructureElement>(store.elementAt(1, 1)).structureId == 41);
    CHECK(store.exists(41));
    CHECK(store.exists(2));
}

TEST_CASE("paths are at least two references: a root has no ancestors, a leaf no descendants",
          "[store][iso][paths]") {
    // The network of PVT 02.01 programs 2 and 3 (SR5, ISO 9592 defect 066):
    // 101 -> 102 (1), 103 (2), 107 (3); 102 -> 109 (1), 104 (2); 103 -> 104 (1), 105 (2), 105 (3);
    // 104 -> 109 (1); 105 -> 109 (1); 106 -> 107 (1); 108 alone.
    StructureStore store;
    build(store, 101, {executeStructure(102), executeStructure(103), executeStructure(107)});
    build(store, 102, {executeStructure(109), executeStructure(104)});
    build(store, 103, {executeStructure(104), executeStructure(105), executeStructure(105)});
    build(store, 104, {executeStructure(109)});
    build(store, 105, {executeStructure(109)});
    build(store, 106, {executeStructure(107)});
    build(store, 108, {});
    using P = std::vector<StructurePath>;
    const auto top = StructurePathOrder::TopFirst;
    const auto bottom = StructurePathOrder::BottomFirst;
    CHECK(store.pathsToAncestors(109, top, 0) == P{{{101, 1}, {102, 1}, {109, 0}},
                                                   {{101, 1}, {102, 2}, {104, 1}, {109, 0}},
                                                   {{101, 2}, {103, 1}, {104, 1}, {109, 0}},
                                                   {{101, 2}, {103, 2}, {105, 1}, {109, 0}},
                                                   {{101, 2}, {103, 3}, {105, 1}, {109, 0}}});
    CHECK(store.pathsToAncestors(107, bottom, 0) == P{{{101, 3}, {107, 0}}, {{106, 1}, {107, 0}}});
    CHECK(store.pathsToAncestors(106, bottom, 0).empty());
    CHECK(store.pathsToAncestors(108, top, 0).empty());
    CHECK(store.pathsToAncestors(109, bottom, 2) ==
          P{{{102, 1}, {109, 0}}, {{104, 1}, {109, 0}}, {{105, 1}, {109, 0}}});
    CHECK(store.pathsToAncestors(105, top, 1) == P{{{101, 2}}});
    CHECK(store.pathsToAncestors(101, top, 5).empty());
    CHECK(store.pathsToAncestors(107, bottom, 1) == P{{{107, 0}}});
    CHECK(store.pathsToAncestors(106, bottom, 1).empty());

    CHECK(store.pathsToDescendants(103, bottom, 0) ==
          P{{{103, 1}, {104, 1}, {109, 0}}, {{103, 2}, {105, 1}, {109, 0}}, {{103, 3}, {105, 1}, {109, 0}}});
    CHECK(store.pathsToDescendants(109, bottom, 0).empty());
    CHECK(store.pathsToDescendants(108, top, 0).empty());
    CHECK(store.pathsToDescendants(101, top, 1) == P{{{101, 1}}, {{101, 2}}, {{101, 3}}});
    CHECK(store.pathsToDescendants(101, top, 2) == P{{{101, 1}, {102, 1}},
                                                     {{101, 1}, {102, 2}},
                                                     {{101, 2}, {103, 1}},
                                                     {{101, 2}, {103, 2}},
                                                     {{101, 2}, {103, 3}},
                                                     {{101, 3}, {107, 0}}});
    CHECK(errorOf([&] { store.pathsToDescendants(110, top, 0); }) == errors::StructureDoesNotExist);
}

TEST_CASE("a NURBS curve's parameter range is an interval inside its domain or the whole of it",
          "[store][errors]") {
    // A range past the domain was taken, and every traversal after it threw (the workstation drew
    // nothing again); a reversed one drew the whole curve.
    Phigs phigs;
    phigs.open();
    StructureStore& store = phigs.store();
    const geom::Curve curve(2, {0, 0, 0, 0.5, 1, 1, 1}, {{0, 0, 0}, {1, 1, 0}, {2, 0, 0}, {3, 1, 0}});
    store.openStructure(1);
    for (const auto& range : std::vector<std::pair<double, double>>{{-0.5, 0.5}, {0.5, 1.5}, {0.8, 0.2}}) {
        const NurbsCurveElement e{curve, range.first, range.second};
        INFO("range " << range.first << " .. " << range.second);
        CHECK(errorOf([&] { store.insert(e); }) == errors::InvalidElementData);
    }
    CHECK(store.elementCount(1) == 0);
    store.insert(NurbsCurveElement{curve, 0.0, 0.0});          // the whole domain
    store.insert(NurbsCurveElement{curve, 0.25, 0.75});        // a part of it
    store.insert(NurbsCurveElement{curve, 0.5, 1.0 + 1e-15});  // a rounding past its end
    store.closeStructure();
    Workstation& ws = phigs.openWorkstation(1, WorkstationType::OffscreenImage);
    ws.postStructure(1, 0.5);
    const DrawList& list = ws.display();
    REQUIRE(list.items.size() == 3);
    // The last draws from C(0.5) to C(1), the curve's end point.
    const auto& points = primitiveAs<DrawCurve>(list.items[2].primitive).points;
    REQUIRE(points.size() >= 2);
    CHECK(glm::length(points[points.size() - 1] - glm::dvec3(3, 1, 0)) < 1e-12);
}

TEST_CASE("an element with a value that is not finite is refused, whatever its type", "[store][errors]") {
    StructureStore store;
    store.openStructure(1);
    const double nan = std::numeric_limits<double>::quiet_NaN();
    const double inf = std::numeric_limits<double>::infinity();
    glm::dmat4 m(1.0);
    m[3][0] = inf;
    const std::vector<Element> bad{
        TextElement{{0, nan, 0}, {1, 0, 0}, {0, 1, 0}, "x", false},
        AnnotationTextElement{{0, 0, 0}, {inf, 0, 0}, "x", false},
        RealAttribute{ElementType::CharacterHeight, nan},
        UpVectorAttribute{ElementType::CharacterUpVector, {nan, 1}},
        ColourAttribute{ElementType::TextColour, Colour::fromRgb({0, nan, 0})},
        localTransformation3(m, Composition::Preconcatenate),
        ModelClipElement{1, {{{0, 0, 0}, {0, 0, inf}}}, false},
        ApproximationAttribute{ElementType::CurveApproximationCriteria, 2, nan, 1},
        NurbsCurveElement{geom::Curve(1, {0, 0, 1, 1}, {{0, 0, 0}, {1, 0, 0}}), nan, 1}};
    for (const auto& e : bad) {
        INFO(elementTypeName(elementType(e)));
        CHECK(errorOf([&] { store.insert(e); }) == errors::InvalidElementData);
    }
    CHECK(store.elementCount(1) == 0);
    // an indexed colour's unused rgb is not looked at
    Colour indexed = Colour::indexed(3);
    indexed.rgb = {nan, nan, nan};
    store.insert(ColourAttribute{ElementType::TextColour, indexed});
    CHECK(store.elementCount(1) == 1);
}

TEST_CASE("an element's largest magnitude counts every real a binding answers", "[store][c]") {
    // What the C binding checks against a Pfloat's range before it answers content (error 908):
    // points, reals, knots and weights, and a rational pole's homogeneous form w P.
    CHECK(largestMagnitude(polyline3({{1, -7, 2}, {3, 0, 0}})) == 7.0);
    CHECK(largestMagnitude(RealAttribute{ElementType::CharacterHeight, -1e300}) == 1e300);
    CHECK(largestMagnitude(label(5)) == 0.0);
    geom::Curve rational(1, {0, 0, 1e3, 1e3}, {{0, 0, 0}, {1e30, 0, 0}});
    CHECK(largestMagnitude(NurbsCurveElement{rational, 0, 0}) == 1e30);
    rational.weights = {1, 1e10};
    CHECK(largestMagnitude(NurbsCurveElement{rational, 0, 0}) == 1e40);
    const geom::Surface patch(1, 1, {0, 0, 1, 1}, {0, 0, 1, 1}, 2, 2,
                              {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {1, 1, 4e30}}, {1, 1, 1, 1e9});
    CHECK(largestMagnitude(NurbsSurfaceElement{patch}) == Approx(4e39));
    CHECK(std::isnan(largestMagnitude(RealAttribute{ElementType::CharacterHeight, std::nan("")})));
}

TEST_CASE("pattern elements carry only their own fields and come back from an archive", "[store][iso]") {
    using T = ElementType;
    PatternAttribute size{T::PatternSize};
    size.size = {0.25, 3};
    PatternAttribute point{T::PatternReferencePoint};
    point.referencePoint = {1, 2, 0};
    PatternAttribute vectors{T::PatternReferencePointAndVectors};
    vectors.referencePoint = {1, 2, 3}, vectors.vectorX = {0, 0, 1}, vectors.vectorY = {0, 2, 0};
    PatternAttribute sizeWithPoint = size;
    sizeWithPoint.referencePoint = {1, 0, 0};
    PatternAttribute pointWithZ = point;
    pointWithZ.referencePoint.z = 1;  // SET PATTERN REFERENCE POINT is 2D: z is 0
    PatternAttribute pointWithVectors = point;
    pointWithVectors.vectorX = {0, 1, 0};  // and it resets the vectors to the axes
    PatternAttribute vectorsWithSize = vectors;
    vectorsWithSize.size = {2, 2};

    Phigs phigs;
    phigs.open();
    StructureStore& store = phigs.store();
    store.openStructure(1);
    for (const PatternAttribute& bad : {sizeWithPoint, pointWithZ, pointWithVectors, vectorsWithSize}) {
        INFO(elementTypeName(bad.type));
        CHECK(errorOf([&] { store.insert(bad); }) == errors::InvalidElementData);
    }
    CHECK(store.elementCount(1) == 0);
    for (const PatternAttribute& good : {size, point, vectors}) store.insert(good);
    store.closeStructure();
    CHECK(elementTypeName(T::PatternReferencePointAndVectors) == "SET PATTERN REFERENCE POINT AND VECTORS");

    const std::filesystem::path file = std::filesystem::path(PHIGS_TEST_OUTPUT_DIR) / "iso_patterns.phar";
    std::filesystem::remove(file);
    phigs.openArchiveFile(3, file);
    phigs.archiveStructures(3, {1});
    phigs.closeArchiveFile(3);
    store.deleteAllStructures();
    phigs.openArchiveFile(3, file);
    phigs.retrieveStructures(3, {1});
    phigs.closeArchiveFile(3);
    REQUIRE(store.elementCount(1) == 3);
    CHECK(store.elementAt(1, 1) == Element{size});
    CHECK(store.elementAt(1, 2) == Element{point});
    CHECK(store.elementAt(1, 3) == Element{vectors});
}

TEST_CASE("empty structure creates, copy and delete network of a missing structure do nothing",
          "[store][iso]") {
    Phigs phigs;
    phigs.open();
    StructureStore& store = phigs.store();
    store.emptyStructure(5);  // ISO 9592 EMPTY STRUCTURE: a structure that does not exist is created
    CHECK(store.structureStatus(5) == StructureStatus::Empty);
    build(store, 1, {label(1), label(2)});
    store.openStructure(1);
    store.setElementPointer(1);
    const std::size_t logged = phigs.errorLog().size();
    store.copyAllElementsFromStructure(77);  // nothing to copy, no error 201
    CHECK(store.elementCount(1) == 2);
    CHECK(store.elementPointer() == 1);
    store.closeStructure();
    store.deleteStructureNetwork(77, ReferenceHandling::Delete);  // no error 201
    store.deleteStructureNetwork(77, ReferenceHandling::Keep);
    CHECK_FALSE(store.exists(77));
    CHECK(store.structureIds() == std::vector<int>{1, 5});
    CHECK(phigs.errorLog().size() == logged);
}

TEST_CASE("delete element range that deletes nothing leaves the pointer", "[store][iso]") {
    StructureStore store;
    build(store, 1, {label(1), label(2), label(3)});
    store.openStructure(1);
    store.setElementPointer(2);
    store.deleteElementRange(0, 0);
    CHECK(store.elementPointer() == 2);
    CHECK(store.elementCount(1) == 3);
    store.deleteElementRange(3, 5);  // clamped to 3..3: the pointer goes before the deleted one
    CHECK(store.elementCount(1) == 2);
    CHECK(store.elementPointer() == 2);
    store.deleteElementRange(0, 1);
    CHECK(store.elementPointer() == 0);
    store.setElementPointer(1);
    store.deleteElementRange(-4, -1);  // clamped to 0..0: nothing
    CHECK(store.elementPointer() == 1);
    store.closeStructure();
}

TEST_CASE("position 0 is the NIL element: type and size, element search", "[store][iso]") {
    StructureStore store;
    build(store, 1, {label(1), pickId(3)});
    build(store, 2, {});
    CHECK(store.elementTypeAt(1, 0) == ElementType::Nil);
    CHECK(store.elementSizeAt(1, 0) == 0);
    CHECK(store.elementTypeAt(2, 0) == ElementType::Nil);
    CHECK(errorOf([&] { store.elementTypeAt(1, 3); }) == errors::ElementDoesNotExist);
    CHECK(errorOf([&] { store.elementTypeAt(1, -1); }) == errors::ElementDoesNotExist);
    CHECK(errorOf([&] { store.elementTypeAt(3, 0); }) == errors::StructureDoesNotExist);
    const auto fwd = SearchDirection::Forward;
    const auto back = SearchDirection::Backward;
    const std::set<ElementType> all{ElementType::All}, nil{ElementType::Nil}, none{};
    const std::set<ElementType> labels{ElementType::Label};
    auto at = [](SearchResult r) { return r.found ? r.elementNumber : -1; };
    CHECK(at(store.elementSearch(1, 0, fwd, all, none)) == 0);
    CHECK(at(store.elementSearch(1, 0, fwd, nil, none)) == 0);
    CHECK(at(store.elementSearch(1, 2, back, nil, none)) == 0);
    CHECK(at(store.elementSearch(1, 0, fwd, labels, none)) == 1);
    CHECK(at(store.elementSearch(1, 0, fwd, all, nil)) == 1);
    CHECK(at(store.elementSearch(1, 1, fwd, nil, none)) == -1);
    CHECK(at(store.elementSearch(2, 5, back, all, none)) == 0);  // clamped to 0
}

TEST_CASE("inquiry errors are not logged", "[store][iso][errors]") {
    Phigs phigs;
    phigs.open();
    StructureStore& store = phigs.store();
    build(store, 1, {label(1)});
    CHECK(errorOf([&] { store.elementAt(1, 2); }) == errors::ElementDoesNotExist);
    CHECK(errorOf([&] { store.elementAt(9, 1); }) == errors::StructureDoesNotExist);
    CHECK(errorOf([&] { store.currentElement(); }) == errors::NotStructureOpen);
    CHECK(errorOf([&] { store.elementPointer(); }) == errors::NotStructureOpen);
    CHECK(errorOf([&] { store.openStructureId(); }) == errors::NotStructureOpen);
    CHECK(errorOf([&] { store.elementSearch(9, 0, SearchDirection::Forward, {}, {}); }) ==
          errors::StructureDoesNotExist);
    CHECK(errorOf([&] { store.pathsToAncestors(9, StructurePathOrder::TopFirst, 0); }) ==
          errors::StructureDoesNotExist);
    CHECK(errorOf([&] { store.pathsToDescendants(1, StructurePathOrder::TopFirst, -1); }) ==
          errors::NegativePathDepth);
    CHECK(errorOf([&] { phigs.workstationsPostedTo(9); }) == errors::StructureDoesNotExist);
    CHECK(errorOf([&] { phigs.conflictingStructures(1); }) == errors::NoArchiveOpen);
    CHECK(phigs.errorLog().size() == 0);
}

TEST_CASE("retrieve of a structure the archive lacks creates it empty, warning 408", "[archive][iso]") {
    const std::filesystem::path file = std::filesystem::path(PHIGS_TEST_OUTPUT_DIR) / "iso_retrieve.phar";
    std::filesystem::remove(file);
    Phigs phigs;
    phigs.open();
    StructureStore& store = phigs.store();
    build(store, 1, {label(10)});
    phigs.openArchiveFile(1, file);
    phigs.archiveStructures(1, {1});
    build(store, 2, {label(20)});  // 2 exists only in the store
    const auto lastNumber = [&] { return phigs.errorLog().entries().back().number; };

    phigs.setConflictResolution(ConflictResolution::Update, ConflictResolution::Abandon);
    CHECK(errorOf([&] { phigs.retrieveStructures(1, {2}); }) == errors::ArchiveNameConflict);
    CHECK(store.elementCount(2) == 1);
    phigs.retrieveStructures(1, {3});  // neither in the store nor in the archive
    CHECK(store.structureStatus(3) == StructureStatus::Empty);
    CHECK(lastNumber() == errors::MissingInArchiveCreatedEmpty);
    phigs.setConflictResolution(ConflictResolution::Update, ConflictResolution::Maintain);
    phigs.retrieveStructures(1, {2});
    CHECK(store.elementCount(2) == 1);
    CHECK(lastNumber() == errors::MissingInArchiveCreatedEmpty);
    phigs.setConflictResolution(ConflictResolution::Update, ConflictResolution::Update);
    phigs.retrieveStructures(1, {2});
    CHECK(store.structureStatus(2) == StructureStatus::Empty);

    const std::size_t logged = phigs.errorLog().size();
    phigs.deleteStructureNetworksFromArchive(1, {1, 9});
    CHECK(phigs.errorLog().size() == logged + 1);
    CHECK(lastNumber() == errors::MissingInArchive);
    CHECK(phigs.archiveContents(1).empty());
    phigs.closeArchiveFile(1);
    std::filesystem::remove(file);
}

TEST_CASE("ISO paths: a depth cut answers from the cut, not from every whole path", "[store][iso]") {
    // Layers of two structures each executing both of the next layer's: 2^40 whole paths from
    // structure 1 (or 2) down to the leaf, a handful once cut.
    StructureStore store;
    const int layers = 40;
    for (int i = 0; i < layers; ++i)
        for (int s = 2 * i + 1; s <= 2 * i + 2; ++s) {
            store.openStructure(s);
            store.insert(executeStructure(2 * i + 3));
            store.insert(executeStructure(2 * i + 4));
            store.closeStructure();
        }
    const int leaf = 2 * layers + 1;
    using P = std::vector<StructurePath>;
    const auto top = StructurePathOrder::TopFirst, bottom = StructurePathOrder::BottomFirst;
    CHECK(store.pathsToAncestors(leaf, top, 1) == P{{{1, 1}}, {{1, 2}}, {{2, 1}}, {{2, 2}}});
    CHECK(store.pathsToAncestors(leaf, top, 2) == P{{{1, 1}, {3, 1}},
                                                    {{1, 1}, {3, 2}},
                                                    {{1, 2}, {4, 1}},
                                                    {{1, 2}, {4, 2}},
                                                    {{2, 1}, {3, 1}},
                                                    {{2, 1}, {3, 2}},
                                                    {{2, 2}, {4, 1}},
                                                    {{2, 2}, {4, 2}}});
    CHECK(store.pathsToDescendants(1, bottom, 1) == P{{{leaf, 0}}, {{leaf + 1, 0}}});
    CHECK(store.pathsToDescendants(1, bottom, 2) == P{{{leaf - 2, 1}, {leaf, 0}},
                                                      {{leaf - 2, 2}, {leaf + 1, 0}},
                                                      {{leaf - 1, 1}, {leaf, 0}},
                                                      {{leaf - 1, 2}, {leaf + 1, 0}}});
    // Whole paths still refuse with 900 past the limit.
    try {
        store.pathsToAncestors(leaf, top, 0);
        FAIL("2^40 whole paths answered");
    } catch (const Error& e) {
        CHECK(e.number() == errors::StorageOverflow);
    }
}

}  // namespace test_store_iso
