#pragma once

#include "phigs/core/ErrorLog.h"
#include "phigs/store/IdTable.h"
#include "phigs/store/Structure.h"

#include <cstdint>
#include <functional>
#include <map>
#include <optional>
#include <set>
#include <unordered_map>
#include <utility>
#include <vector>

namespace phigs {

enum class EditMode { Insert, Replace };
enum class StructureStatus { NonExistent, Empty, NotEmpty };
enum class SearchDirection { Backward, Forward };
/// DELETE STRUCTURE NETWORK: delete descendants referenced from outside the network too, or keep them.
enum class ReferenceHandling { Delete, Keep };
/// Order of the element references in an ancestor / descendant path.
enum class StructurePathOrder { TopFirst, BottomFirst };

/// One element reference (structure id, element number) of a structure path.
struct ElementRef {
    int structureId = 0;
    int elementNumber = 0;
    bool operator==(const ElementRef&) const = default;
    auto operator<=>(const ElementRef&) const = default;
};
using StructurePath = std::vector<ElementRef>;

/// What an element search found.
struct SearchResult {
    bool found = false;
    int elementNumber = 0;
};

/// Told about changes a workstation must follow (unposting a deleted structure, moving a posting).
class StoreListener {
public:
    virtual ~StoreListener() = default;
    virtual void structureDeleted(int structureId) = 0;
    /// CHANGE STRUCTURE REFERENCES: postings of `from` become postings of `to`.
    virtual void referencesChanged(int from, int to) = 0;
    /// Whether any listener has `structureId` posted (CHANGE STRUCTURE IDENTIFIER keeps it then).
    virtual bool isPosted(int structureId) const = 0;
};

/// The central structure store (ISO 9592 clause 7.3-7.5): structures, the open structure with
/// its element pointer and edit mode, editing, inquiries and structure networks. Every
/// function checks its state and arguments first and throws phigs::Error before changing
/// anything, so a refused call leaves the store as it was. Not thread-safe, const inquiries
/// included (they fill caches of the network): one thread at a time uses a store.
class StructureStore {
public:
    explicit StructureStore(ErrorLog* log = nullptr) : log_(log) {}
    // Listeners and workstations refer to the store, and it to its open structure: it stays put.
    StructureStore(const StructureStore&) = delete;
    StructureStore& operator=(const StructureStore&) = delete;

    void setErrorLog(ErrorLog* log) { log_ = log; }
    void addListener(StoreListener* listener);
    void removeListener(StoreListener* listener);

    // ---- structure state
    /// OPEN STRUCTURE: creates the structure when it does not exist; pointer at its end.
    void openStructure(int id);
    void closeStructure();
    bool isStructureOpen() const { return open_.has_value(); }
    /// The open structure's id (error 5 when none is open).
    int openStructureId() const;

    // ---- editing the open structure
    void setEditMode(EditMode mode) { editMode_ = mode; }
    EditMode editMode() const { return editMode_; }
    /// Inserts after the element pointer (then points at it), or replaces the element at the
    /// pointer (inserts when the pointer is 0). Refuses invalid elements and cyclic executes.
    void insert(Element element);
    void setElementPointer(int position);
    void offsetElementPointer(int offset);
    /// Moves the pointer to the next LABEL `label` after it (error 205 when there is none).
    void setElementPointerAtLabel(int label);
    int elementPointer() const;
    /// DELETE ELEMENT: the element at the pointer; the pointer moves to the one before.
    void deleteElement();
    /// DELETE ELEMENT RANGE: elements between the two positions inclusive (clamped); the pointer
    /// goes to the element before them, and stays where it was when nothing is deleted.
    void deleteElementRange(int first, int second);
    /// DELETE ELEMENTS BETWEEN LABELS: strictly between the next `first` and the next `second` after it.
    void deleteElementsBetweenLabels(int first, int second);
    /// COPY ALL ELEMENTS FROM STRUCTURE: inserted after the pointer, which then points at the last
    /// copy; a structure that does not exist has nothing to copy (no error).
    void copyAllElementsFromStructure(int id);

    // ---- structures
    /// EMPTY STRUCTURE: removes every element; creates a structure that does not exist, empty.
    void emptyStructure(int id);
    /// DELETE STRUCTURE: removes references to it and its postings; the open structure is emptied instead.
    void deleteStructure(int id);
    /// DELETE STRUCTURE NETWORK: nothing happens for a structure that does not exist.
    void deleteStructureNetwork(int id, ReferenceHandling handling);
    void deleteAllStructures();
    /// CHANGE STRUCTURE IDENTIFIER: a missing original counts as empty (the result is emptied).
    void changeStructureIdentifier(int original, int result);
    /// CHANGE STRUCTURE REFERENCES: creates the result only when an execute or posting moves to it.
    void changeStructureReferences(int original, int result);
    void changeStructureIdentifierAndReferences(int original, int result);

    /// Creates an empty structure when `id` does not exist (POST STRUCTURE, EXECUTE STRUCTURE do).
    void createStructure(int id) { createIfMissing(id); }

    // ---- inquiries: they never log; an error is thrown as phigs::Error with no ErrorLog entry,
    // which the C binding answers as the error indicator (ISO 9592 inquiries raise no error).
    bool exists(int id) const { return structures_.contains(id); }
    StructureStatus structureStatus(int id) const;
    std::vector<int> structureIds() const;
    const Structure& structure(int id) const;  ///< error 201 when it does not exist
    const Structure* find(int id) const;
    int elementCount(int id) const { return static_cast<int>(structure(id).elements.size()); }
    /// INQUIRE ELEMENT TYPE AND SIZE: NIL and 0 at position 0; error 202 outside 0..count.
    ElementType elementTypeAt(int id, int elementNumber) const;
    std::size_t elementSizeAt(int id, int elementNumber) const;
    Element elementAt(int id, int elementNumber) const;  ///< a copy; error 202 outside 1..count
    /// A copy of the element at the pointer of the open structure (error 202 at position 0).
    Element currentElement() const;
    /// ELEMENT SEARCH: position 0 is the NIL element, which NIL or ALL in `include` finds.
    SearchResult elementSearch(int id, int start, SearchDirection direction,
                               const std::set<ElementType>& include,
                               const std::set<ElementType>& exclude) const;
    /// ELEMENT SEARCH with the caller's test of each element (nullptr: the NIL element at 0),
    /// for type sets finer than ElementType (the C binding's index and general colour forms).
    SearchResult elementSearch(int id, int start, SearchDirection direction,
                               const std::function<bool(const Element*)>& matches) const;
    /// INQUIRE PATHS TO ANCESTORS / DESCENDANTS: every path written top first, sorted; depth > 0
    /// keeps the top (TopFirst) or bottom (BottomFirst) `depth` levels, duplicates removed; a
    /// root has no ancestor paths and a leaf no descendant paths (a path has two references).
    std::vector<StructurePath> pathsToAncestors(int id, StructurePathOrder order, int depth) const;
    std::vector<StructurePath> pathsToDescendants(int id, StructurePathOrder order, int depth) const;
    /// The structure and every structure it executes, directly or not (sorted).
    std::set<int> network(int id) const;
    /// A hash of `id` and its subtree version: it changes whenever any structure of `id`'s
    /// network is edited, without walking the network.
    std::uint64_t networkStamp(int id) const;
    /// A serial that changes whenever any structure in `id`'s network is edited (0 for a
    /// structure that does not exist); kept up to date through the executing structures.
    std::uint64_t subtreeVersion(int id) const;
    /// Whether executing `child` from `parent` would close a cycle.
    bool wouldCycle(int parent, int child) const;

    std::uint64_t operationCount() const { return serial_; }

    /// Replaces the contents of structures wholesale (archive retrieval): creates them when
    /// missing; checks every execute for cycles against the result before changing anything.
    void replaceStructures(const std::map<int, std::vector<Element>>& contents, const char* function);

private:
    Structure& createIfMissing(int id);
    /// structures_.try_emplace(id) with byId_ kept in step; true when it was made.
    std::pair<Structure*, bool> emplaceStructure(int id);
    /// Removes `id` from structures_ and byId_.
    void eraseStructure(int id);
    void touch(Structure& s);
    /// An execute may have been removed or moved: the executing-structure index is rebuilt.
    void executesChanged() { parentsStale_ = true; }
    /// Carries every edit since the last call up to the subtree versions of its ancestors.
    void settleVersions() const;
    /// Rebuilds the index of executing structures when an edit left it stale.
    void refreshParents() const;
    /// Takes `s` out of the index as a parent of what it executes (before its elements go).
    void forgetAsParent(const Structure& s);
    void forgetVersions(int id) { subtreeVersions_.erase(id); }
    std::uint64_t nextSerial() { return ++serial_; }
    /// Throws, before anything changes, when `count` more serials would not fit an element slot.
    void checkSerials(std::size_t count) const { ElementArena::checkSerial(serial_ + count); }
    void requireOpen(const char* function) const;
    void checkElement(const Element& e, int into, const char* function) const;
    /// Every EXECUTE STRUCTURE of any of `ids`, in one pass over the store.
    void removeReferencesTo(const std::set<int>& ids);
    /// Deletes each of `doomed` (existing structures) as DELETE STRUCTURE does.
    void deleteStructures(const std::set<int>& doomed);
    /// The members of id's network (`members`) that DELETE STRUCTURE NETWORK with KEEP deletes:
    /// the root, and each member whose every parent is deleted.
    std::set<int> deletedKeepingReferenced(int id, const std::set<int>& members) const;
    void notifyDeleted(int id);
    bool postedAnywhere(int id) const;
    bool referenced(int id) const;
    std::map<int, std::set<int>> childrenGraph() const;
    /// Each structure's EXECUTE STRUCTURE elements (see StructurePaths.h).
    std::map<int, std::vector<std::pair<int, int>>> executeReferences() const;
    /// The structures `s` executes, in element order; cached per structure version.
    const std::vector<int>& executedBy(const Structure& s) const;

    ErrorLog* log_ = nullptr;
    std::map<int, Structure> structures_;
    /// structures_ by id (map nodes stay put): one array access per find, the hot path of
    /// traversal. Kept in step by every insertion into and removal from structures_.
    IdTable<Structure*> byId_;
    std::optional<int> open_;
    Structure* openStructure_ = nullptr;  ///< open_'s node (map nodes stay put), for each insert
    int pointer_ = 0;
    EditMode editMode_ = EditMode::Insert;
    std::uint64_t serial_ = 0;
    std::vector<StoreListener*> listeners_;
    mutable std::unordered_map<int, std::pair<std::uint64_t, std::vector<int>>> executed_;
    // Subtree versions are settled lazily, so bulk editing pays one push per structure edited.
    mutable std::vector<int> touched_;           ///< structures edited since the last settleVersions()
    mutable bool touchedOverflow_ = false;       ///< too many to carry one by one: every version renews
    mutable IdTable<std::vector<int>> parents_;  ///< who executes each (per element)
    mutable bool parentsStale_ = false;
    mutable IdTable<std::uint64_t> subtreeVersions_;
};

}  // namespace phigs
