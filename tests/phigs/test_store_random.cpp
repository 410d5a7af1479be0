// A randomized comparison of the structure store as an application drives it through Phigs
// (the store, two workstations' posting lists, one archive file) against the reference model of
// StoreModel.h and ArchiveModel.h. Every inquiry must agree after every operation: structures,
// elements, element pointer, postings, the archive's file contents, conflicts, element search
// and the path inquiries; and so must the versions (a structure whose contents change gets a new
// version, a refused operation changes no version, serial or operation count), the element
// serials (new ones only for new elements) and the error log (one entry per error or warning).
//
// Operations: the editing functions with valid elements and ones the store must refuse (NaN and
// infinite values, wrong counts, bad curves, a type outside its payload), pointer moves with
// extreme values, deletion of structures and networks, CHANGE STRUCTURE IDENTIFIER / REFERENCES,
// POST / UNPOST with good and bad priorities, ARCHIVE / RETRIEVE / DELETE FROM ARCHIVE under
// every conflict resolution, closing and reopening the archive.
//
// By default 4 seeds x 100,000 operations (about 2 s in a RelWithDebInfo build); built with
// AddressSanitizer, which makes every allocation dear, 4 seeds x 40,000 (about 6 s). The long
// mode, PHIGS_STORE_RANDOM_OPS=10000000 build/tests/test_phigs "[random]", runs that many
// operations per seed (about 3 minutes); PHIGS_STORE_RANDOM_SEED=<n> runs that one seed only.

#include "ArchiveModel.h"
#include "ErrorNumber.h"
#include "RandomElements.h"
#include "Sanitized.h"

#include <catch2/catch.hpp>

#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <limits>
#include <optional>
#include <random>
#include <unordered_map>

namespace test_store_random {

using namespace phigs;
using phigs::test::errorOf;
using test::ArchiveModel;
using test::Contents;
using test::StoreModel;

namespace {

constexpr long kOperations = kSanitizedBuild ? 40000 : 100000;

constexpr int kArchive = 1;
const int kWorkstations[] = {1, 2};

/// An element to insert and whether the store must accept it.
struct Candidate {
    Element element;
    bool valid = true;
};

geom::Curve badCurve(int kind) {
    geom::Curve c;  // the aggregate, not the checking constructor
    c.degree = kind == 0 ? 0 : 1;
    c.points = {{0, 0, 0}, {1, 0, 0}};
    c.knots = kind == 1 ? std::vector<double>{0, 1, 0.5, 1} : std::vector<double>{0, 0, 1, 1};
    if (kind == 2) c.weights = {1.0, -1.0};
    return c;
}

Candidate invalidCandidate(std::mt19937& rng) {
    const double nan = std::numeric_limits<double>::quiet_NaN();
    const double inf = std::numeric_limits<double>::infinity();
    switch (testing::randomInt(rng, 0, 9)) {
        case 0:
            return {polyline3({{0, 0, 0}, {nan, 1, 1}}), false};
        case 1:
            return {TextElement{{inf, 0, 0}, {1, 0, 0}, {0, 1, 0}, "x", false}, false};
        case 2: {
            glm::dmat4 m(1.0);
            m[1][2] = nan;
            return {localTransformation3(m, Composition::Replace), false};
        }
        case 3:
            return {CellArrayElement{{}, {1, 0, 0}, {0, 1, 0}, 2, 2, {1, 2, 3}, false}, false};
        case 4:
            return {QuadrilateralMeshElement{2, 2, {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}, {}, {}}, false};
        case 5:
            return {NurbsCurveElement{badCurve(testing::randomInt(rng, 0, 2)), 0.0, 0.0}, false};
        case 6:
            return {IndexAttribute{ElementType::PolylineColour, 1}, false};  // a colour type, index payload
        case 7:
            return {RealAttribute{ElementType::CharacterHeight, nan}, false};
        case 8:
            return {AsfAttribute{AspectId::Count_, true}, false};
        default:
            return {TriangleStripElement{{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}, {}, {{0, 0, 1}}}, false};
    }
}

Candidate randomCandidate(std::mt19937& rng, int child) {
    switch (testing::randomInt(rng, 0, 15)) {
        case 0:
        case 1:
        case 2:
            return {label(testing::randomInt(rng, 0, 4))};
        case 3:
        case 4:
            return {polyline3({{double(testing::randomInt(rng, 0, 9)), 0, 0}, {1, 1, 1}})};
        case 5:
        case 6:
        case 7:
            return {executeStructure(child)};
        case 8:
        case 9:
            return {pickId(testing::randomInt(rng, 0, 3))};
        case 10:
        case 11:
            return {testing::randomElement(rng, 100, 100)};  // any family, no executes
        default:
            return invalidCandidate(rng);
    }
}

/// Follows the store's versions and element serials from one operation to the next: a structure
/// that keeps its version keeps its elements (serials), an element that keeps its serial keeps
/// its value, new versions and serials come from the operation just done, and a refused
/// operation changes none of them. Each check returns the first broken rule, "" when none.
class StampTracker {
public:
    std::string check(const StructureStore& store, const StoreModel& model, bool refused);

private:
    struct Known {
        std::uint64_t version = 0;
        std::vector<std::uint64_t> serials;
        std::uint64_t round = 0;
    };
    struct Value {
        Element value;
        std::uint64_t round = 0;
    };
    std::string checkStructure(const Structure& s, const std::vector<Element>& elements, bool refused,
                               std::uint64_t now);

    std::map<int, Known> structures_;
    std::unordered_map<std::uint64_t, Value> values_;
    std::uint64_t operations_ = 0;  // the store's operation count at the last check
    std::uint64_t round_ = 0;
};

std::string StampTracker::check(const StructureStore& store, const StoreModel& model, bool refused) {
    ++round_;
    const std::uint64_t now = store.operationCount();
    if (now < operations_ || (refused && now != operations_)) return "the operation count moved wrongly";
    for (int id : store.structureIds())
        if (std::string broken = checkStructure(store.structure(id), model.structures.at(id), refused, now);
            !broken.empty())
            return "structure " + std::to_string(id) + ": " + broken;
    for (auto it = structures_.begin(); it != structures_.end();)
        if (it->second.round == round_)
            ++it;
        else if (refused)
            return "a refused operation deleted structure " + std::to_string(it->first);
        else
            it = structures_.erase(it);
    for (auto it = values_.begin(); it != values_.end();)
        if (it->second.round == round_)
            ++it;
        else if (refused)
            return "a refused operation deleted an element";
        else
            it = values_.erase(it);
    operations_ = now;
    return {};
}

std::string StampTracker::checkStructure(const Structure& s, const std::vector<Element>& elements,
                                         bool refused, std::uint64_t now) {
    auto [known, added] = structures_.try_emplace(s.id);
    Known& k = known->second;
    k.round = round_;
    bool sameSerials = k.serials.size() == s.elements.size();
    for (std::size_t i = 0; sameSerials && i < k.serials.size(); ++i)
        sameSerials = k.serials[i] == s.elements.serial(i);
    if (!added && k.version == s.version) {
        if (!sameSerials) return "its elements changed, its version did not";
    } else {
        if (refused) return "a refused operation changed its version";
        if (s.version <= operations_ || s.version > now) return "a version from the past";
        k.version = s.version;
        k.serials.clear();
        for (std::size_t i = 0; i < s.elements.size(); ++i) k.serials.push_back(s.elements.serial(i));
    }
    for (std::size_t i = 0; i < elements.size(); ++i) {
        const std::uint64_t serial = s.elements.serial(i);
        auto value = values_.find(serial);
        if (value == values_.end()) {
            if (refused || serial <= operations_) return "an element with a serial not from this operation";
            values_.emplace(serial, Value{elements[i], round_});
            continue;
        }
        if (value->second.round == round_) return "two elements share a serial";
        if (!(value->second.value == elements[i])) return "an element changed, its serial did not";
        value->second.round = round_;
    }
    return {};
}

/// The store's contents, open structure, pointer and postings against the model's.
std::string storeDifference(Phigs& phigs, const StoreModel& model, bool postings) {
    const StructureStore& store = phigs.store();
    const std::vector<int> ids = store.structureIds();
    if (ids.size() != model.structures.size() || !std::equal(ids.begin(), ids.end(), model.structures.begin(),
                                                             [](int id, auto& m) { return id == m.first; }))
        return "structure identifiers differ";
    if (store.isStructureOpen() != model.open.has_value()) return "open structure state differs";
    if (model.open && store.openStructureId() != *model.open) return "open structure differs";
    if (model.open && store.elementPointer() != model.pointer)
        return "element pointer " + std::to_string(store.elementPointer()) + ", model " +
               std::to_string(model.pointer);
    for (const auto& [id, elements] : model.structures) {
        const Structure& s = store.structure(id);
        if (s.elements.size() != elements.size())
            return "element count of " + std::to_string(id) + " differs";
        for (std::size_t i = 0; i < elements.size(); ++i)
            if (!(s.elements.element(i) == elements[i]))
                return "element " + std::to_string(i + 1) + " of " + std::to_string(id) + " differs";
        const auto status = elements.empty() ? StructureStatus::Empty : StructureStatus::NotEmpty;
        if (store.structureStatus(id) != status) return "status of " + std::to_string(id) + " differs";
    }
    for (int ws : kWorkstations)
        if (postings && phigs.workstation(ws).postedStructures() != model.postedOrder(ws))
            return "postings of workstation " + std::to_string(ws) + " differ";
    return {};
}

/// Drives one seed: the store, two workstations and one archive file against the models.
class Runner {
public:
    Runner(std::uint32_t seed, std::filesystem::path archivePath)
        : rng_(seed), path_(std::move(archivePath)) {
        std::filesystem::remove(path_);
        phigs_.open();
        for (int ws : kWorkstations) phigs_.openWorkstation(ws, WorkstationType::OffscreenImage);
        phigs_.openArchiveFile(kArchive, path_);
    }
    ~Runner() { std::filesystem::remove(path_); }

    void run(long operations);

private:
    int pick(int lo, int hi) { return testing::randomInt(rng_, lo, hi); }
    int id() {  // mostly 1-8, now and then an extreme identifier
        const int r = pick(0, 99);
        return r < 97 ? pick(1, 8) : (r == 97 ? 0 : r == 98 ? -7 : INT_MAX);
    }
    int position() {
        const int r = pick(0, 49);
        return r == 0 ? INT_MIN : r == 1 ? INT_MAX : pick(-2, 20);
    }
    std::vector<int> ids() {
        std::vector<int> out(static_cast<std::size_t>(pick(1, 3)));
        for (int& i : out) i = id();
        return out;
    }
    void step(int kind);
    void editStep(int kind);
    void networkStep(int kind);
    void postingStep(int kind);
    void archiveStep(int kind);
    void inquire(int a);
    void compareArchive(bool readFile);
    void report(long operations) const;

    std::mt19937 rng_;
    std::filesystem::path path_;
    Phigs phigs_;
    StoreModel model_;
    ArchiveModel archive_;
    StampTracker stamps_;
    std::map<int, long> outcomes_;
    int expected_ = 0, actual_ = 0;  // the error the last operation gave on the model and the store
    int a_ = 0, b_ = 0;              // its structure identifiers
    bool inquireNow_ = false;
    long elementsSeen_ = 0;
    long mostElements_ = 0;
};

/// Whether operation `kind` can change a posting: POST, UNPOST, the deletions, CHANGE STRUCTURE
/// REFERENCES (and IDENTIFIER AND REFERENCES).
bool postingsMayChange(int kind) {
    return (kind >= 670 && kind < 717) || (kind >= 751 && kind < 920);
}

void Runner::run(long operations) {
    for (long op = 0; op < operations; ++op) {
        const int kind = pick(0, 999);
        const std::size_t logBefore = phigs_.errorLog().size();
        model_.warning = 0;
        expected_ = actual_ = a_ = b_ = 0;
        step(kind);
        const int error = actual_;
        ++outcomes_[error];
        long total = 0;
        for (const auto& [i, e] : model_.structures) total += static_cast<long>(e.size());
        elementsSeen_ += total;
        mostElements_ = std::max(mostElements_, total);
        std::string broken;
        const std::size_t logged = (error != 0 ? 1 : 0) + (model_.warning != 0 ? 1 : 0);
        if (actual_ != expected_)
            broken = "the store gave error " + std::to_string(actual_) + ", the model " +
                     std::to_string(expected_);
        else if (phigs_.errorLog().size() != logBefore + logged ||
                 (logged && phigs_.errorLog().entries().back().number != (error ? error : model_.warning)))
            broken = "the error log differs";
        if (broken.empty()) broken = storeDifference(phigs_, model_, postingsMayChange(kind));
        if (broken.empty()) broken = stamps_.check(phigs_.store(), model_, error != 0);
        if (!broken.empty())
            FAIL("operation " << op << " kind " << kind << " (structures " << a_ << ", " << b_
                              << "): " << broken);
        if (op % 50 == 0 || inquireNow_) inquire(id());
        inquireNow_ = false;
        if (op % 1000 == 0) phigs_.errorLog().clear();
    }
    report(operations);
    // the run exercised the refusals as well as the successes
    for (int error : {0, 5, 6, 205, 206, 208, 405, errors::StructureCycle, errors::InvalidElementData})
        CHECK(outcomes_[error] > 0);
}

void Runner::report(long operations) const {
    if (!std::getenv("PHIGS_STORE_RANDOM_DEBUG")) return;
    for (const auto& [e, n] : outcomes_) std::printf("error %d: %ld operations\n", e, n);
    std::printf("%.1f elements in the store on average, %ld at most\n",
                double(elementsSeen_) / double(operations), mostElements_);
}

/// Runs operation `kind` (0-999) on the store and the models.
void Runner::step(int kind) {
    if (kind < 670) return editStep(kind);
    if (kind < 820) return networkStep(kind - 670);
    if (kind < 920) return postingStep(kind - 820);
    return archiveStep(kind - 920);
}

void Runner::editStep(int kind) {
    StructureStore& store = phigs_.store();
    auto check = [&](auto&& onStore, int modelResult) {
        expected_ = modelResult;
        actual_ = errorOf(onStore);
    };
    const int a = a_ = id();
    if (kind < 70) {
        check([&] { store.openStructure(a); }, model_.openStructure(a));
    } else if (kind < 95) {
        check([&] { store.closeStructure(); }, model_.closeStructure());
    } else if (kind < 425) {
        Candidate c = randomCandidate(rng_, id());
        check([&] { store.insert(c.element); }, model_.insert(c.element, c.valid));
    } else if (kind < 450) {
        model_.replace = pick(0, 1) == 1;
        store.setEditMode(model_.replace ? EditMode::Replace : EditMode::Insert);
    } else if (kind < 490) {
        const int p = position();
        check([&] { store.setElementPointer(p); }, model_.setPointer(p));
    } else if (kind < 515) {
        const int d = position();
        check([&] { store.offsetElementPointer(d); }, model_.offsetPointer(d));
    } else if (kind < 550) {
        const int l = pick(0, 4);
        check([&] { store.setElementPointerAtLabel(l); }, model_.pointerAtLabel(l));
    } else if (kind < 585) {
        check([&] { store.deleteElement(); }, model_.deleteElement());
    } else if (kind < 600) {
        const int x = position(), y = position();
        check([&] { store.deleteElementRange(x, y); }, model_.deleteRange(x, y));
    } else if (kind < 620) {
        const int x = pick(0, 4), y = pick(0, 4);
        check([&] { store.deleteElementsBetweenLabels(x, y); }, model_.deleteBetweenLabels(x, y));
    } else {
        check([&] { store.copyAllElementsFromStructure(a); }, model_.copyAll(a));
    }
}

void Runner::networkStep(int kind) {
    StructureStore& store = phigs_.store();
    auto check = [&](auto&& onStore, int modelResult) {
        expected_ = modelResult;
        actual_ = errorOf(onStore);
    };
    const int a = a_ = id(), b = b_ = id();
    if (kind < 10) {
        check([&] { store.emptyStructure(a); }, model_.emptyStructure(a));
    } else if (kind < 30) {
        check([&] { store.deleteStructure(a); }, model_.deleteStructure(a));
    } else if (kind < 45) {
        const bool keep = pick(0, 1) == 1;
        check(
            [&] {
                store.deleteStructureNetwork(a, keep ? ReferenceHandling::Keep : ReferenceHandling::Delete);
            },
            model_.deleteNetwork(a, keep));
    } else if (kind < 47) {
        check([&] { store.deleteAllStructures(); }, model_.deleteAll());
    } else if (kind < 81) {
        check([&] { store.changeStructureIdentifier(a, b); }, model_.changeIdentifier(a, b));
    } else if (kind < 115) {
        check([&] { store.changeStructureReferences(a, b); }, model_.changeReferences(a, b));
    } else {
        check([&] { store.changeStructureIdentifierAndReferences(a, b); }, model_.changeBoth(a, b));
    }
    INFO("a " << a << " b " << b);
}

void Runner::postingStep(int kind) {
    const int ws = kWorkstations[pick(0, 1)];
    const int a = a_ = id();
    Workstation& station = phigs_.workstation(ws);
    if (kind < 60) {
        static const double priorities[] = {0.0, 0.25, 0.5, 0.5,
                                            1.0, -0.5, 1.5, std::numeric_limits<double>::quiet_NaN()};
        const double priority = priorities[pick(0, 7)];
        expected_ = model_.post(ws, a, priority);
        actual_ = errorOf([&] { station.postStructure(a, priority); });
    } else if (kind < 95) {
        expected_ = model_.unpost(ws, a);
        actual_ = errorOf([&] { station.unpostStructure(a); });
    } else {
        expected_ = model_.unpostAll(ws);
        actual_ = errorOf([&] { station.unpostAllStructures(); });
    }
}

void Runner::archiveStep(int kind) {
    auto check = [&](auto&& onPhigs, int modelResult) {
        expected_ = modelResult;
        actual_ = errorOf(onPhigs);
    };
    const std::vector<int> list = ids();
    a_ = list.front();
    if (kind < 8) {
        static const ConflictResolution modes[] = {ConflictResolution::Maintain, ConflictResolution::Abandon,
                                                   ConflictResolution::Update};
        archive_.archival = modes[pick(0, 2)];
        archive_.retrieval = modes[pick(0, 2)];
        phigs_.setConflictResolution(archive_.archival, archive_.retrieval);
    } else if (kind < 18) {
        check([&] { phigs_.archiveStructures(kArchive, list); },
              archive_.archive(model_, {list.begin(), list.end()}));
    } else if (kind < 24) {
        check([&] { phigs_.archiveStructureNetworks(kArchive, list); },
              archive_.archive(model_, archive_.storeNetworks(model_, list)));
    } else if (kind < 27) {
        std::set<int> all;
        for (const auto& [i, e] : model_.structures) all.insert(i);
        check([&] { phigs_.archiveAllStructures(kArchive); }, archive_.archive(model_, all));
    } else if (kind < 45) {
        check([&] { phigs_.retrieveStructures(kArchive, list); },
              archive_.retrieve(model_, {list.begin(), list.end()}));
    } else if (kind < 57) {
        check([&] { phigs_.retrieveStructureNetworks(kArchive, list); },
              archive_.retrieve(model_, archive_.archiveNetworks(list)));
    } else if (kind < 63) {
        std::set<int> all;
        for (const auto& [i, e] : archive_.contents) all.insert(i);
        check([&] { phigs_.retrieveAllStructures(kArchive); }, archive_.retrieve(model_, all));
    } else if (kind < 69) {
        check([&] { phigs_.deleteStructuresFromArchive(kArchive, list); }, archive_.remove(model_, list));
    } else if (kind < 73) {
        std::set<int> members = archive_.archiveNetworks(list);
        for (int id : list)
            if (!archive_.contents.contains(id)) model_.warning = errors::MissingInArchive;
        std::vector<int> present;
        for (int m : members)
            if (archive_.contents.contains(m)) present.push_back(m);
        for (int m : present) archive_.contents.erase(m);
        check([&] { phigs_.deleteStructureNetworksFromArchive(kArchive, list); }, 0);
    } else if (kind < 74) {
        archive_.contents.clear();
        check([&] { phigs_.deleteAllStructuresFromArchive(kArchive); }, 0);
    } else if (kind < 80) {
        phigs_.closeArchiveFile(kArchive);  // a round trip through the file
        phigs_.openArchiveFile(kArchive, path_);
    } else {
        inquireNow_ = true;  // after the checks of this operation
    }
    const bool mayWrite = (kind >= 8 && kind < 27) || (kind >= 63 && kind < 80);
    compareArchive(mayWrite);
}

/// The archive as Phigs reports it and, after an operation that may have written it, as its
/// file holds it.
void Runner::compareArchive(bool readFile) {
    std::vector<int> ids;
    for (const auto& [i, e] : archive_.contents) ids.push_back(i);
    REQUIRE(phigs_.archiveContents(kArchive) == ids);
    REQUIRE(phigs_.conflictingStructures(kArchive) == archive_.conflicting(model_));
    if (readFile) REQUIRE(ArchiveFile(path_, nullptr).contents() == archive_.contents);
}

/// The inquiries that change nothing: element search, the path inquiries on the store and on
/// the archive, INQUIRE SET OF WORKSTATIONS TO WHICH POSTED, conflicts in a network.
void Runner::inquire(int a) {
    const StructureStore& store = phigs_.store();
    const int depth = pick(0, 3);
    const bool top = pick(0, 1) == 1;
    const auto order = top ? StructurePathOrder::TopFirst : StructurePathOrder::BottomFirst;
    const bool exists = model_.structures.contains(a);
    INFO("inquiries on structure " << a << " depth " << depth << " top first " << top);
    if (!exists) {
        CHECK(errorOf([&] { store.pathsToDescendants(a, order, depth); }) == errors::StructureDoesNotExist);
        CHECK(errorOf([&] { phigs_.workstationsPostedTo(a); }) == errors::StructureDoesNotExist);
    } else {
        REQUIRE(store.pathsToDescendants(a, order, depth) ==
                test::descendantsOf(model_.structures, a, depth, top));
        REQUIRE(store.pathsToAncestors(a, order, depth) ==
                test::ancestorsOf(model_.structures, a, depth, top));
        std::vector<int> posted;
        for (int ws : kWorkstations)
            for (const auto& p : model_.posted[ws])
                if (p.structureId == a) posted.push_back(ws);
        REQUIRE(phigs_.workstationsPostedTo(a) == posted);
        const int start = position();
        const auto direction = pick(0, 1) ? SearchDirection::Forward : SearchDirection::Backward;
        const std::set<ElementType> include =
            pick(0, 1) ? std::set<ElementType>{ElementType::All} : std::set<ElementType>{ElementType::Label};
        const std::set<ElementType> exclude =
            pick(0, 1) ? std::set<ElementType>{ElementType::PickId} : std::set<ElementType>{};
        const auto& elements = model_.structures.at(a);
        const int count = static_cast<int>(elements.size());
        const bool forward = direction == SearchDirection::Forward;
        int expectedAt = -1;  // position 0 is the NIL element, which ALL finds
        for (int n = std::clamp(start, 0, count); n >= 0 && n <= count; n += forward ? 1 : -1) {
            const ElementType t =
                n == 0 ? ElementType::Nil : elementType(elements[static_cast<std::size_t>(n - 1)]);
            if ((include.contains(ElementType::All) || include.contains(t)) && !exclude.contains(t)) {
                expectedAt = n;
                break;
            }
        }
        const SearchResult found = store.elementSearch(a, start, direction, include, exclude);
        REQUIRE(found.found == (expectedAt >= 0));
        if (found.found) REQUIRE(found.elementNumber == expectedAt);
    }
    // RETRIEVE PATHS: the archive's network as it holds it; a cycle there is error -201
    auto retrieved = [&](auto&& inquiry, const std::optional<std::vector<StructurePath>>& paths) {
        if (!paths) {
            REQUIRE(errorOf(inquiry) == errors::StructureCycle);
        } else {
            std::vector<StructurePath> got;
            REQUIRE(errorOf([&] { got = inquiry(); }) == 0);
            REQUIRE(got == *paths);
        }
    };
    if (archive_.contents.contains(a))
        retrieved([&] { return phigs_.retrievePathsToDescendants(kArchive, a, order, depth); },
                  test::descendantsOf(archive_.contents, a, depth, top));
    if (archive_.contents.contains(a) || archive_.referencedInArchive(a))
        retrieved([&] { return phigs_.retrievePathsToAncestors(kArchive, a, order, depth); },
                  test::ancestorsOf(archive_.contents, a, depth, top));
    const auto source = pick(0, 1) ? NetworkSource::Css : NetworkSource::Archive;
    if ((source == NetworkSource::Css && !exists) ||
        (source == NetworkSource::Archive && !archive_.contents.contains(a))) {
        CHECK(errorOf([&] { phigs_.conflictingStructuresInNetwork(kArchive, a, source); }) ==
              errors::StructureDoesNotExist);
    } else {
        std::vector<int> conflicts;
        const Contents& from = source == NetworkSource::Css ? model_.structures : archive_.contents;
        for (int m : test::networkOf(from, a))
            if (model_.structures.contains(m) && archive_.contents.contains(m)) conflicts.push_back(m);
        REQUIRE(phigs_.conflictingStructuresInNetwork(kArchive, a, source) == conflicts);
    }
}

long environmentNumber(const char* name, long fallback) {
    const char* text = std::getenv(name);
    if (!text || !*text) return fallback;
    char* end = nullptr;
    const long value = std::strtol(text, &end, 10);
    return end && *end == '\0' && value > 0 ? value : fallback;
}

/// The archive of the random run: on a memory file system when there is one (the run flushes
/// the file to the disk after every change, which costs milliseconds on a real disk).
std::filesystem::path scratchArchive(std::uint32_t seed) {
    std::error_code ec;
    std::filesystem::path dir = "/dev/shm";
    if (!std::filesystem::is_directory(dir, ec) || ::access(dir.c_str(), W_OK) != 0)
        dir = PHIGS_TEST_OUTPUT_DIR;
    return dir / ("phigs_store_random_" + std::to_string(::getpid()) + "_" + std::to_string(seed) + ".phar");
}

}  // namespace

TEST_CASE("random store, posting and archive operations agree with a reference model", "[store][random]") {
    const long operations = environmentNumber("PHIGS_STORE_RANDOM_OPS", kOperations);
    std::vector<std::uint32_t> seeds{20261201, 7, 1234567, 99991};
    if (long only = environmentNumber("PHIGS_STORE_RANDOM_SEED", 0))
        seeds = {static_cast<std::uint32_t>(only)};
    for (std::uint32_t seed : seeds) {
        INFO("seed " << seed << " (PHIGS_STORE_RANDOM_SEED=" << seed << " repeats it)");
        Runner(seed, scratchArchive(seed)).run(operations);
    }
}

}  // namespace test_store_random
