#pragma once

// The archive part of the reference model of test_store_random.cpp: one open archive file and
// the conflict resolution, reading and writing a StoreModel as Phigs's archive functions do.

#include "StoreModel.h"

namespace phigs::test {

/// One open archive file and the conflict resolution, with the store model it reads and writes.
struct ArchiveModel {
    Contents contents;
    ConflictResolution archival = ConflictResolution::Update;
    ConflictResolution retrieval = ConflictResolution::Abandon;

    int archive(StoreModel& store, std::set<int> ids) {
        std::set<int> missing;
        for (int id : ids)
            if (!store.structures.contains(id)) missing.insert(id);
        for (int id : missing) ids.erase(id);
        std::set<int> conflicts;
        for (int id : ids)
            if (contents.contains(id)) conflicts.insert(id);
        if (!conflicts.empty() && archival == ConflictResolution::Abandon) return errors::ArchiveNameConflict;
        for (int id : ids)
            if (archival != ConflictResolution::Maintain || !conflicts.contains(id))
                contents[id] = store.structures.at(id);
        if (!missing.empty()) store.warning = errors::IgnoringMissingStructures;
        return 0;
    }
    std::set<int> storeNetworks(const StoreModel& store, const std::vector<int>& ids) const {
        std::set<int> all;
        for (int id : ids)
            if (store.structures.contains(id))
                all.merge(networkOf(store.structures, id));
            else
                all.insert(id);
        return all;
    }
    /// Each root and the members of its network the archive holds (one it only references is
    /// not retrieved).
    std::set<int> archiveNetworks(const std::vector<int>& ids) const {
        std::set<int> all;
        for (int id : ids) {
            all.insert(id);
            for (int member : networkOf(contents, id))
                if (contents.contains(member)) all.insert(member);
        }
        return all;
    }
    int retrieve(StoreModel& store, const std::set<int>& ids) {
        Contents taken;
        bool missing = false;
        for (int id : ids) {  // one the archive lacks comes back empty (ISO 9592, warning 408)
            missing = missing || !contents.contains(id);
            taken[id] = contents.contains(id) ? contents.at(id) : std::vector<Element>{};
        }
        bool conflict = false;
        for (const auto& [id, e] : taken) conflict = conflict || store.structures.contains(id);
        if (conflict && retrieval == ConflictResolution::Abandon) return errors::ArchiveNameConflict;
        if (retrieval == ConflictResolution::Maintain)
            std::erase_if(taken, [&](const auto& entry) { return store.structures.contains(entry.first); });
        Graph after = graphOf(store.structures);
        for (const auto& [id, elements] : taken) {
            const int from = id;  // clang 14 cannot capture a structured binding
            std::erase_if(after.edges, [from](auto& edge) { return edge.first == from; });
            for (const auto& e : elements)
                if (auto x = executeOf(e)) after.add(id, x->structureId);
        }
        if (after.cyclic()) return errors::StructureCycle;
        for (const auto& [id, elements] : taken) {
            store.structures[id] = elements;
            for (const auto& e : elements)
                if (auto x = executeOf(e)) store.structures[x->structureId];
            if (store.open == id) store.pointer = static_cast<int>(elements.size());
        }
        if (missing) store.warning = errors::MissingInArchiveCreatedEmpty;
        return 0;
    }
    int remove(StoreModel& store, const std::vector<int>& ids) {
        for (int id : ids)
            if (!contents.contains(id)) store.warning = errors::MissingInArchive;
        for (int id : ids) contents.erase(id);
        return 0;
    }
    std::vector<int> conflicting(const StoreModel& store) const {
        std::vector<int> out;
        for (const auto& [id, e] : contents)
            if (store.structures.contains(id)) out.push_back(id);
        return out;
    }
    bool referencedInArchive(int id) const {
        for (const auto& [sid, elements] : contents)
            for (const auto& e : elements)
                if (auto x = executeOf(e); x && x->structureId == id) return true;
        return false;
    }
};

}  // namespace phigs::test
