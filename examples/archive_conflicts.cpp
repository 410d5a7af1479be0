// Example 5, archives: structures written to an archive file and retrieved again under the
// three conflict resolutions (what happens when a retrieved structure is already in the store):
// MAINTAIN keeps the store's, UPDATE takes the archive's, ABANDON refuses (error 405).
//
//     archive_conflicts [FILE]      the archive file to write (default: example.phigs)
#include "phigs/Phigs.h"

#include <cstdio>
#include <exception>

namespace {

void show(phigs::Phigs& phigs, const char* when) {
    std::printf("%-28s structure 1: %d elements, structure 2: %d elements\n", when,
                phigs.store().elementCount(1), phigs.store().elementCount(2));
}

}  // namespace

int main(int argc, char** argv) {
    const char* file = argc > 1 ? argv[1] : "example.phigs";
    try {
        phigs::Phigs phigs;
        phigs.open();
        phigs::StructureStore& store = phigs.store();
        // A small network: structure 1 (3 elements) executes structure 2 (2 elements).
        store.openStructure(1);
        store.insert(phigs::label(10));
        store.insert(phigs::polyline3({{0, 0, 0}, {1, 1, 0}}));
        store.insert(phigs::executeStructure(2));
        store.closeStructure();
        store.openStructure(2);
        store.insert(phigs::IndexAttribute{phigs::ElementType::InteriorStyle, 1});
        store.insert(phigs::fillArea3({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}));
        store.closeStructure();

        // ARCHIVE STRUCTURE NETWORKS: structure 1 and everything it executes.
        phigs.openArchiveFile(1, file);
        phigs.archiveStructureNetworks(1, {1});
        std::printf("archive %s holds %zu structures\n", file, phigs.archiveContents(1).size());

        // Change the store: structure 2 loses its fill area.
        store.openStructure(2);
        store.deleteElement();
        store.closeStructure();
        show(phigs, "store changed:");
        std::printf("conflicting structures: %zu\n", phigs.conflictingStructures(1).size());

        // MAINTAIN: structures already in the store stay as they are.
        phigs.setConflictResolution(phigs::ConflictResolution::Update, phigs::ConflictResolution::Maintain);
        phigs.retrieveStructureNetworks(1, {1});
        show(phigs, "retrieved with MAINTAIN:");

        // ABANDON: the retrieval is refused as a whole (error 405), the store untouched.
        phigs.setConflictResolution(phigs::ConflictResolution::Update, phigs::ConflictResolution::Abandon);
        try {
            phigs.retrieveStructureNetworks(1, {1});
        } catch (const phigs::Error& e) {
            std::printf("retrieved with ABANDON:      refused: %s\n", e.what());
        }
        show(phigs, "after ABANDON:");

        // UPDATE: the archive's contents replace the store's.
        phigs.setConflictResolution(phigs::ConflictResolution::Update, phigs::ConflictResolution::Update);
        phigs.retrieveStructureNetworks(1, {1});
        show(phigs, "retrieved with UPDATE:");

        phigs.closeArchiveFile(1);
        phigs.close();
        return 0;
    } catch (const std::exception& e) {
        std::fprintf(stderr, "archive_conflicts: %s\n", e.what());
        return 1;
    }
}
