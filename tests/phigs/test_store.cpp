#include "ErrorNumber.h"
#include "StoreModel.h"
#include "phigs/Phigs.h"
#include "phigs/store/StructureStore.h"

#include <catch2/catch.hpp>

#include <random>

namespace test_store {

using namespace phigs;
using phigs::test::errorOf;

namespace {

int labelAt(const StructureStore& store, int id, int n) {
    return std::get<LabelElement>(store.elementAt(id, n)).label;
}

std::vector<int> labels(const StructureStore& store, int id) {
    std::vector<int> out;
    for (int n = 1; n <= store.elementCount(id); ++n) {
        const Element& e = store.elementAt(id, n);
        out.push_back(std::holds_alternative<LabelElement>(e) ? std::get<LabelElement>(e).label : -1);
    }
    return out;
}

/// A store with structure `id` open holding LABEL 1 .. LABEL n.
void fillLabels(StructureStore& store, int id, int n) {
    store.openStructure(id);
    for (int i = 1; i <= n; ++i) store.insert(label(i));
}

}  // namespace

TEST_CASE("element pointer at 0 and at the end, insert and replace", "[store]") {
    StructureStore store;
    fillLabels(store, 1, 3);
    CHECK(store.elementPointer() == 3);
    store.setElementPointer(0);
    store.insert(label(10));  // insert at 0: becomes element 1
    CHECK(labels(store, 1) == std::vector<int>{10, 1, 2, 3});
    CHECK(store.elementPointer() == 1);
    store.setElementPointer(99);  // clamped to the end
    CHECK(store.elementPointer() == 4);
    store.setElementPointer(-5);
    CHECK(store.elementPointer() == 0);
    store.setEditMode(EditMode::Replace);
    store.insert(label(20));  // replace at 0 inserts
    CHECK(labels(store, 1) == std::vector<int>{20, 10, 1, 2, 3});
    CHECK(store.elementPointer() == 1);
    store.setElementPointer(3);
    store.insert(label(30));  // replaces element 3
    CHECK(labels(store, 1) == std::vector<int>{20, 10, 30, 2, 3});
    CHECK(store.elementPointer() == 3);
    store.offsetElementPointer(100);
    CHECK(store.elementPointer() == 5);
    store.offsetElementPointer(-2);
    CHECK(store.elementPointer() == 3);
}

TEST_CASE("labels: pointer at label, not found, delete between labels", "[store]") {
    StructureStore store;
    fillLabels(store, 1, 6);
    store.setElementPointer(0);
    store.setElementPointerAtLabel(4);
    CHECK(store.elementPointer() == 4);
    // the search starts after the pointer: label 2 lies behind it
    CHECK(errorOf([&] { store.setElementPointerAtLabel(2); }) == errors::LabelNotFound);
    CHECK(store.elementPointer() == 4);
    CHECK(errorOf([&] { store.setElementPointerAtLabel(77); }) == 205);
    store.setElementPointer(0);
    store.deleteElementsBetweenLabels(2, 5);
    CHECK(labels(store, 1) == std::vector<int>{1, 2, 5, 6});
    CHECK(store.elementPointer() == 2);
    CHECK(errorOf([&] { store.deleteElementsBetweenLabels(6, 1); }) == errors::LabelsNotFound);
    CHECK(labels(store, 1) == std::vector<int>{1, 2, 5, 6});
}

TEST_CASE("delete element and element range", "[store]") {
    StructureStore store;
    fillLabels(store, 1, 6);
    store.setElementPointer(0);
    store.deleteElement();  // nothing at 0
    CHECK(store.elementCount(1) == 6);
    store.setElementPointer(2);
    store.deleteElement();
    CHECK(labels(store, 1) == std::vector<int>{1, 3, 4, 5, 6});
    CHECK(store.elementPointer() == 1);
    store.deleteElementRange(4, 2);  // order does not matter
    CHECK(labels(store, 1) == std::vector<int>{1, 6});
    CHECK(store.elementPointer() == 1);
    store.deleteElementRange(0, 100);
    CHECK(store.elementCount(1) == 0);
    CHECK(store.elementPointer() == 0);
}

TEST_CASE("structure state errors 5 and 6", "[store][errors]") {
    ErrorLog log;
    StructureStore store(&log);
    CHECK(errorOf([&] { store.insert(label(1)); }) == errors::NotStructureOpen);
    CHECK(errorOf([&] { store.closeStructure(); }) == 5);
    CHECK(errorOf([&] { store.elementPointer(); }) == 5);  // an inquiry: not logged
    store.openStructure(1);
    CHECK(errorOf([&] { store.openStructure(2); }) == errors::NotStructureClosed);
    REQUIRE(log.size() == 3);
    CHECK(log.entries()[0].function == "INSERT ELEMENT");
    CHECK(log.entries()[2].function == "OPEN STRUCTURE");
    CHECK(log.text().find("ERROR 6 in OPEN STRUCTURE") != std::string::npos);
}

TEST_CASE("an element whose type tag lies outside the enumeration is refused, the store unchanged",
          "[store][errors]") {
    // A tag cast from any int: only the payload's own types go in (what an archive can write back).
    StructureStore store;
    store.openStructure(1);
    store.insert(label(1));
    std::mt19937 random(9999);
    for (int trial = 0; trial < 50; ++trial) {
        const int tag = trial % 2
                            ? static_cast<int>(ElementType::Count_) + static_cast<int>(random() % 100000)
                            : -1 - static_cast<int>(random() % 100000);
        INFO("tag " << tag);
        CHECK(errorOf([&] { store.insert(IndexAttribute{static_cast<ElementType>(tag), 5}); }) != 0);
        CHECK(store.elementCount(1) == 1);
    }
}

TEST_CASE("inquiries: element type, size and content, current element, status", "[store]") {
    StructureStore store;
    CHECK(store.structureStatus(5) == StructureStatus::NonExistent);
    store.openStructure(5);
    CHECK(store.structureStatus(5) == StructureStatus::Empty);
    store.insert(polyline3({{0, 0, 0}, {1, 1, 1}}));
    store.insert(PolylineElement{{{0, 0, 0}, {1, 0, 0}}, true});
    CHECK(store.structureStatus(5) == StructureStatus::NotEmpty);
    CHECK(store.elementTypeAt(5, 1) == ElementType::Polyline3);
    CHECK(store.elementTypeAt(5, 2) == ElementType::Polyline);
    CHECK(elementTypeName(ElementType::Polyline3) == "POLYLINE 3");
    CHECK(store.elementSizeAt(5, 1) > 2 * sizeof(glm::dvec3));
    CHECK(std::get<PolylineElement>(store.currentElement()).twoD);
    CHECK(errorOf([&] { store.elementAt(5, 3); }) == errors::ElementDoesNotExist);
    CHECK(errorOf([&] { store.elementAt(6, 1); }) == errors::StructureDoesNotExist);
    store.setElementPointer(0);
    CHECK(errorOf([&] { store.currentElement(); }) == 202);
}

TEST_CASE("invalid elements are refused and leave the structure unchanged", "[store][errors]") {
    StructureStore store;
    store.openStructure(1);
    CellArrayElement cells;
    cells.columns = 2, cells.rows = 2, cells.colourIndices = {1, 2, 3};
    CHECK(errorOf([&] { store.insert(cells); }) == errors::InvalidElementData);
    CHECK(errorOf([&] {
              store.insert(IndexAttribute{ElementType::PolylineColour, 2});
          }) == errors::InvalidElementData);
    NurbsCurveElement curve;
    curve.curve.degree = 2;
    curve.curve.knots = {0, 0, 1, 1};
    curve.curve.points = {{0, 0, 0}, {1, 0, 0}};
    CHECK(errorOf([&] { store.insert(curve); }) == errors::InvalidElementData);
    CHECK(store.elementCount(1) == 0);
    CHECK(store.elementPointer() == 0);
}

TEST_CASE("execute structure creates the child and refuses cycles", "[store][errors]") {
    StructureStore store;
    store.openStructure(1);
    store.insert(executeStructure(2));
    CHECK(store.exists(2));
    store.closeStructure();
    store.openStructure(2);
    store.insert(executeStructure(3));
    store.closeStructure();
    store.openStructure(3);
    std::uint64_t version = store.structure(3).version;
    CHECK(errorOf([&] { store.insert(executeStructure(1)); }) == errors::StructureCycle);
    CHECK(errorOf([&] { store.insert(executeStructure(3)); }) == errors::StructureCycle);
    CHECK(store.elementCount(3) == 0);
    CHECK(store.structure(3).version == version);
    store.closeStructure();
    // copying the elements of 1 into 2 would make 2 execute 2
    store.openStructure(2);
    CHECK(errorOf([&] { store.copyAllElementsFromStructure(1); }) == errors::StructureCycle);
    CHECK(store.elementCount(2) == 1);
}

TEST_CASE("copy all elements from structure", "[store]") {
    StructureStore store;
    fillLabels(store, 1, 3);
    store.closeStructure();
    fillLabels(store, 2, 2);
    store.setElementPointer(1);
    store.copyAllElementsFromStructure(1);
    CHECK(labels(store, 2) == std::vector<int>{1, 1, 2, 3, 2});
    CHECK(store.elementPointer() == 4);
    store.copyAllElementsFromStructure(9);  // nothing to copy, no error (ISO 9592)
    CHECK(labels(store, 2) == std::vector<int>{1, 1, 2, 3, 2});
    CHECK(store.elementPointer() == 4);
}

TEST_CASE("delete structure removes references and unposts, empties the open structure", "[store]") {
    Phigs phigs;
    phigs.open();
    StructureStore& store = phigs.store();
    Workstation& ws = phigs.openWorkstation(1, WorkstationType::OffscreenImage);
    store.openStructure(1);
    store.insert(label(1));
    store.insert(executeStructure(2));
    store.insert(label(2));
    store.insert(executeStructure(2));
    store.closeStructure();
    ws.postStructure(2, 0.5);
    store.deleteStructure(2);
    CHECK_FALSE(store.exists(2));
    CHECK(labels(store, 1) == std::vector<int>{1, 2});
    CHECK(ws.postedStructures().empty());
    // deleting the open structure empties it and keeps it open
    store.openStructure(1);
    store.deleteStructure(1);
    CHECK(store.exists(1));
    CHECK(store.isStructureOpen());
    CHECK(store.elementCount(1) == 0);
    CHECK(store.elementPointer() == 0);
    store.closeStructure();
}

TEST_CASE("deleting a referenced structure while its parent is open keeps the pointer right", "[store]") {
    StructureStore store;
    store.openStructure(1);
    store.insert(label(1));
    store.insert(executeStructure(2));
    store.insert(label(2));
    CHECK(store.elementPointer() == 3);
    store.deleteStructure(2);
    CHECK(store.elementPointer() == 2);
    CHECK(labelAt(store, 1, store.elementPointer()) == 2);
}

TEST_CASE("delete structure network with and without keeping shared structures", "[store]") {
    auto build = [](StructureStore& store) {
        // 1 -> 2 -> 3, 4 -> 3 (3 is shared with a network outside)
        store.openStructure(1);
        store.insert(executeStructure(2));
        store.closeStructure();
        store.openStructure(2);
        store.insert(executeStructure(3));
        store.closeStructure();
        store.openStructure(4);
        store.insert(executeStructure(3));
        store.closeStructure();
    };
    StructureStore keep;
    build(keep);
    keep.deleteStructureNetwork(1, ReferenceHandling::Keep);
    CHECK(keep.structureIds() == std::vector<int>{3, 4});
    StructureStore all;
    build(all);
    all.deleteStructureNetwork(1, ReferenceHandling::Delete);
    CHECK(all.structureIds() == std::vector<int>{4});
    CHECK(all.elementCount(4) == 0);                           // its reference to 3 went with 3
    all.deleteStructureNetwork(1, ReferenceHandling::Delete);  // no network, no error (ISO 9592)
    CHECK(all.structureIds() == std::vector<int>{4});
}

TEST_CASE("delete all structures keeps the open structure, empty", "[store]") {
    StructureStore store;
    fillLabels(store, 1, 2);
    store.closeStructure();
    fillLabels(store, 2, 2);
    store.deleteAllStructures();
    CHECK(store.structureIds() == std::vector<int>{2});
    CHECK(store.elementPointer() == 0);
}

TEST_CASE("change structure identifier, references, and both", "[store]") {
    auto build = [](StructureStore& store) {
        store.openStructure(1);
        store.insert(executeStructure(2));
        store.closeStructure();
        store.openStructure(2);
        store.insert(label(22));
        store.closeStructure();
    };
    SECTION("identifier: contents move, references stay, a referenced original stays empty") {
        StructureStore store;
        build(store);
        store.changeStructureIdentifier(2, 5);
        CHECK(labels(store, 5) == std::vector<int>{22});
        CHECK(store.exists(2));
        CHECK(store.elementCount(2) == 0);
        CHECK(std::get<ExecuteStructureElement>(store.elementAt(1, 1)).structureId == 2);
        // an unreferenced original disappears
        store.changeStructureIdentifier(5, 6);
        CHECK_FALSE(store.exists(5));
        CHECK(labels(store, 6) == std::vector<int>{22});
    }
    SECTION("references: executes and postings move, the original stays") {
        Phigs phigs;
        phigs.open();
        StructureStore& store = phigs.store();
        build(store);
        Workstation& ws = phigs.openWorkstation(1, WorkstationType::Window);
        ws.postStructure(2, 0.25);
        store.changeStructureReferences(2, 7);
        CHECK(std::get<ExecuteStructureElement>(store.elementAt(1, 1)).structureId == 7);
        CHECK(store.exists(7));
        CHECK(labels(store, 2) == std::vector<int>{22});
        REQUIRE(ws.postedStructures().size() == 1);
        CHECK(ws.postedStructures()[0] == PostedStructure{7, 0.25});
    }
    SECTION("both: the original is gone, everything points at the result") {
        StructureStore store;
        build(store);
        store.changeStructureIdentifierAndReferences(2, 8);
        CHECK_FALSE(store.exists(2));
        CHECK(labels(store, 8) == std::vector<int>{22});
        CHECK(std::get<ExecuteStructureElement>(store.elementAt(1, 1)).structureId == 8);
    }
    SECTION("a change that would make a cycle is refused and changes nothing") {
        StructureStore store;
        build(store);
        std::uint64_t v1 = store.structure(1).version;
        CHECK(errorOf([&] { store.changeStructureReferences(2, 1); }) == errors::StructureCycle);
        CHECK(errorOf([&] { store.changeStructureIdentifier(1, 2); }) == errors::StructureCycle);
        CHECK(store.structure(1).version == v1);
        CHECK(labels(store, 2) == std::vector<int>{22});
    }
}

TEST_CASE("element search with inclusion and exclusion sets both ways", "[store]") {
    StructureStore store;
    store.openStructure(1);
    store.insert(label(1));                           // 1
    store.insert(polyline3({{0, 0, 0}, {1, 0, 0}}));  // 2
    store.insert(pickId(3));                          // 3
    store.insert(polymarker3({{0, 0, 0}}));           // 4
    store.insert(label(2));                           // 5
    std::set<ElementType> prims{ElementType::Polyline3, ElementType::Polymarker3};
    CHECK(store.elementSearch(1, 1, SearchDirection::Forward, prims, {}).elementNumber == 2);
    CHECK(store.elementSearch(1, 3, SearchDirection::Forward, prims, {}).elementNumber == 4);
    CHECK(store.elementSearch(1, 5, SearchDirection::Backward, prims, {}).elementNumber == 4);
    CHECK(store.elementSearch(1, 4, SearchDirection::Backward, prims, {ElementType::Polymarker3})
              .elementNumber == 2);
    CHECK(store.elementSearch(1, 99, SearchDirection::Backward, {ElementType::All}, {}).elementNumber == 5);
    CHECK(store.elementSearch(1, 2, SearchDirection::Forward, {ElementType::All}, {ElementType::All}).found ==
          false);
    CHECK_FALSE(store.elementSearch(1, 5, SearchDirection::Forward, prims, {}).found);
}

TEST_CASE("paths to ancestors and descendants with order and depth", "[store]") {
    StructureStore store;
    // 1 executes 2 at element 1 and 3 at element 2; 2 executes 3 at element 1
    store.openStructure(1);
    store.insert(executeStructure(2));
    store.insert(executeStructure(3));
    store.closeStructure();
    store.openStructure(2);
    store.insert(executeStructure(3));
    store.closeStructure();
    auto up = store.pathsToAncestors(3, StructurePathOrder::TopFirst, 0);
    REQUIRE(up.size() == 2);
    CHECK(up[0] == StructurePath{{1, 1}, {2, 1}, {3, 0}});
    CHECK(up[1] == StructurePath{{1, 2}, {3, 0}});
    auto top1 = store.pathsToAncestors(3, StructurePathOrder::TopFirst, 1);
    CHECK(top1 == std::vector<StructurePath>{{{1, 1}}, {{1, 2}}});
    auto bottom1 = store.pathsToAncestors(3, StructurePathOrder::BottomFirst, 1);
    CHECK(bottom1 == std::vector<StructurePath>{{{3, 0}}});  // duplicates removed
    auto down = store.pathsToDescendants(1, StructurePathOrder::TopFirst, 0);
    REQUIRE(down.size() == 2);
    CHECK(down[0] == StructurePath{{1, 1}, {2, 1}, {3, 0}});
    CHECK(down[1] == StructurePath{{1, 2}, {3, 0}});
    CHECK(store.pathsToDescendants(3, StructurePathOrder::TopFirst, 0).empty());  // a leaf: no path
    CHECK(store.pathsToAncestors(1, StructurePathOrder::TopFirst, 0).empty());    // a root: no path
    CHECK(errorOf([&] { store.pathsToAncestors(3, StructurePathOrder::TopFirst, -1); }) ==
          errors::NegativePathDepth);
    CHECK(errorOf([&] { store.pathsToDescendants(9, StructurePathOrder::TopFirst, 0); }) == 201);
}

namespace {

// n chained diamonds: structure 3k+1 executes 3k+2 and 3k+3, which both execute 3k+4.
void chainDiamonds(StructureStore& store, int n) {
    for (int k = 0; k < n; ++k) {
        const int top = 3 * k + 1;
        store.openStructure(top);
        store.insert(executeStructure(top + 1));
        store.insert(executeStructure(top + 2));
        store.closeStructure();
        for (int side : {top + 1, top + 2}) {
            store.openStructure(side);
            store.insert(executeStructure(top + 3));
            store.closeStructure();
        }
    }
}

}  // namespace

TEST_CASE("a cut path inquiry equals the whole answer cut, on random networks", "[store]") {
    std::mt19937 random(20261202);
    for (int network = 0; network < 40; ++network) {
        StructureStore store;
        const int count = 4 + static_cast<int>(random() % 8);
        // Executes only go to higher ids, so the network is acyclic.
        for (int id = 1; id <= count; ++id) {
            store.openStructure(id);
            for (int child = id + 1; child <= count; ++child)
                if (random() % 3 == 0) store.insert(executeStructure(child));
            store.closeStructure();
        }
        for (int id = 1; id <= count; ++id)
            for (auto order : {StructurePathOrder::TopFirst, StructurePathOrder::BottomFirst})
                for (int depth = 1; depth <= 4; ++depth) {
                    CHECK(store.pathsToDescendants(id, order, depth) ==
                          test::cutPaths(store.pathsToDescendants(id, order, 0), depth,
                                         order == StructurePathOrder::TopFirst));
                    CHECK(store.pathsToAncestors(id, order, depth) ==
                          test::cutPaths(store.pathsToAncestors(id, order, 0), depth,
                                         order == StructurePathOrder::TopFirst));
                }
    }
}

TEST_CASE("a path inquiry with 2^n answers is refused, a cut one answers", "[store]") {
    StructureStore store;
    chainDiamonds(store, 64);  // 2^64 paths from structure 1 to structure 193
    CHECK(errorOf([&] { store.pathsToDescendants(1, StructurePathOrder::TopFirst, 0); }) ==
          errors::StorageOverflow);
    CHECK(errorOf([&] { store.pathsToAncestors(193, StructurePathOrder::TopFirst, 0); }) ==
          errors::StorageOverflow);
    // A cut that keeps the references near the start of the walk stops the walk there.
    CHECK(store.pathsToDescendants(1, StructurePathOrder::TopFirst, 4).size() == 4);
    CHECK(store.pathsToAncestors(193, StructurePathOrder::BottomFirst, 3).size() == 2);
    // The refusal changed nothing: a small inquiry still answers in full.
    CHECK(store.pathsToDescendants(190, StructurePathOrder::TopFirst, 0).size() == 2);
}

TEST_CASE("versions change on every edit and only on edits", "[store]") {
    StructureStore store;
    store.openStructure(1);
    std::uint64_t v0 = store.structure(1).version;
    store.insert(label(1));
    std::uint64_t v1 = store.structure(1).version;
    CHECK(v1 != v0);
    store.setElementPointer(0);
    store.setElementPointerAtLabel(1);
    CHECK(store.structure(1).version == v1);
    store.setEditMode(EditMode::Replace);
    store.insert(label(2));
    CHECK(store.structure(1).version != v1);
}

TEST_CASE("PHIGS operating states: errors 1, 2, 3, 4, 7, 53, 54", "[errors]") {
    Phigs phigs;
    CHECK(errorOf([&] { phigs.store(); }) == errors::NotPhigsOpen);
    CHECK(errorOf([&] { phigs.openWorkstation(1, WorkstationType::Window); }) == 2);
    phigs.open();
    CHECK(errorOf([&] { phigs.open(); }) == errors::NotPhigsClosed);
    CHECK(errorOf([&] { phigs.workstation(1); }) == errors::NoWorkstationOpen);
    CHECK(errorOf([&] { phigs.archiveContents(1); }) == errors::NoArchiveOpen);
    phigs.openWorkstation(1, WorkstationType::Window);
    CHECK(errorOf([&] { phigs.openWorkstation(1, WorkstationType::Hardcopy); }) ==
          errors::WorkstationIdInUse);
    CHECK(errorOf([&] { phigs.workstation(2); }) == errors::WorkstationNotOpen);
    CHECK(errorOf([&] { phigs.close(); }) == errors::NotAllClosed);
    phigs.closeWorkstation(1);
    phigs.store().openStructure(1);
    CHECK(errorOf([&] { phigs.close(); }) == 4);
    phigs.store().closeStructure();
    phigs.close();
    CHECK_FALSE(phigs.isOpen());
    const auto& log = phigs.errorLog().entries();
    REQUIRE(log.size() == 9);
    CHECK(log[0].number == 2);
    CHECK(log[5].function == "OPEN WORKSTATION");
    CHECK(errorMessage(201) == "Ignoring function, the specified structure does not exist");
}

}  // namespace test_store
