#include "phigs/Phigs.h"

#include "phigs/store/StructurePaths.h"

namespace phigs {

namespace {

/// Whether two paths name one file: the same file on disk, or (not made yet) one normal path.
bool sameFile(const std::filesystem::path& a, const std::filesystem::path& b) {
    std::error_code error;
    if (std::filesystem::equivalent(a, b, error)) return true;
    std::error_code errorA, errorB;
    const auto normalA = std::filesystem::weakly_canonical(a, errorA);
    const auto normalB = std::filesystem::weakly_canonical(b, errorB);
    return !errorA && !errorB && normalA == normalB;
}

}  // namespace

void Phigs::requireOpen(const char* function) const {
    if (!open_) raise(const_cast<ErrorLog*>(&log_), errors::NotPhigsOpen, function);
}

void Phigs::warn(int number, const char* function, std::string detail) {
    log_.record(Error(number, function, std::move(detail)));
}

void Phigs::open() {
    if (open_) raise(&log_, errors::NotPhigsClosed, "OPEN PHIGS");
    open_ = true;
}

void Phigs::close() {
    requireOpen("CLOSE PHIGS");
    if (!workstations_.empty() || store_.isStructureOpen() || !archives_.empty())
        raise(&log_, errors::NotAllClosed, "CLOSE PHIGS");
    store_.deleteAllStructures();
    open_ = false;
}

StructureStore& Phigs::store() {
    requireOpen("structure store function");
    return store_;
}

Workstation& Phigs::openWorkstation(int id, WorkstationType type, const OutputConnection& connection) {
    const char* function = "OPEN WORKSTATION";
    requireOpen(function);
    if (!isWorkstationType(type))
        raise(&log_, errors::BadWorkstationType, function,
              "workstation type " + std::to_string(static_cast<int>(type)));
    if (workstations_.contains(id))
        raise(&log_, errors::WorkstationIdInUse, function, "workstation " + std::to_string(id));
    auto ws = std::make_unique<Workstation>(id, type, store_, &log_);
    ws->setConnectionIdentifier(connection.identifier);
    if (const OutputFactory* factory = outputs_.find(type)) {
        const std::string which =
            "workstation " + std::to_string(id) + " (" + std::string(ws->description().name) + "): ";
        try {
            ws->ownOutput((*factory)(*ws, connection));
        } catch (const ConnectionRefused& e) {
            raise(&log_, errors::ConnectionNotRecognized, function, which + e.what());
        } catch (const Error&) {
            throw;
        } catch (const std::exception& e) {
            raise(&log_, errors::WorkstationCannotOpen, function, which + e.what());
        }
    }
    auto& slot = workstations_[id];
    slot = std::move(ws);
    return *slot;
}

void Phigs::closeWorkstation(int id) {
    Workstation& ws = workstation(id);
    std::string failure;
    try {
        ws.closeOutput();
    } catch (const Error&) {
        workstations_.erase(id);
        throw;
    } catch (const std::exception& e) {
        failure = e.what();
    }
    workstations_.erase(id);
    if (!failure.empty())
        raise(&log_, errors::WriteError, "CLOSE WORKSTATION",
              "workstation " + std::to_string(id) + ": " + failure);
}

Workstation& Phigs::workstation(int id) {
    const char* function = "workstation function";
    requireOpen(function);
    if (workstations_.empty()) raise(&log_, errors::NoWorkstationOpen, function);
    auto it = workstations_.find(id);
    if (it == workstations_.end())
        raise(&log_, errors::WorkstationNotOpen, function, "workstation " + std::to_string(id));
    return *it->second;
}

std::vector<int> Phigs::openWorkstationIds() const {
    std::vector<int> ids;
    for (const auto& [id, ws] : workstations_) ids.push_back(id);
    return ids;
}

std::vector<int> Phigs::workstationsPostedTo(int structureId) {
    const char* function = "INQUIRE SET OF WORKSTATIONS TO WHICH POSTED";
    if (!open_) raise(nullptr, errors::NotPhigsOpen, function);
    if (!store_.exists(structureId))
        raise(nullptr, errors::StructureDoesNotExist, function, "structure " + std::to_string(structureId));
    std::vector<int> ids;
    for (const auto& [id, ws] : workstations_)
        if (ws->isPosted(structureId)) ids.push_back(id);
    return ids;
}

std::vector<int> Phigs::openArchiveIds() const {
    std::vector<int> ids;
    for (const auto& [id, file] : archives_) ids.push_back(id);
    return ids;
}

void Phigs::openArchiveFile(int archiveId, const std::filesystem::path& path) {
    const char* function = "OPEN ARCHIVE FILE";
    requireOpen(function);
    if (archives_.contains(archiveId))
        raise(&log_, errors::ArchiveIdInUse, function, "archive " + std::to_string(archiveId));
    // Each open archive keeps the file's contents and writes them back whole: a second one on the
    // same file would overwrite what the first wrote.
    for (const auto& [id, file] : archives_)
        if (file && sameFile(file->path(), path))
            raise(&log_, errors::ArchiveCannotOpen, function,
                  path.string() + " is already open as archive " + std::to_string(id));
    archives_[archiveId] = nullptr;
    try {
        archives_[archiveId] = std::make_unique<ArchiveFile>(path, &log_);
    } catch (...) {
        archives_.erase(archiveId);
        throw;
    }
}

void Phigs::closeArchiveFile(int archiveId) {
    archive(archiveId, "CLOSE ARCHIVE FILE");
    archives_.erase(archiveId);
}

ArchiveFile& Phigs::archive(int archiveId, const char* function, bool inquiry) {
    ErrorLog* log = inquiry ? nullptr : &log_;  // inquiries never log
    if (!open_) raise(log, errors::NotPhigsOpen, function);
    if (archives_.empty()) raise(log, errors::NoArchiveOpen, function);
    auto it = archives_.find(archiveId);
    if (it == archives_.end())
        raise(log, errors::ArchiveNotOpen, function, "archive " + std::to_string(archiveId));
    return *it->second;
}

void Phigs::setConflictResolution(ConflictResolution archival, ConflictResolution retrieval) {
    requireOpen("SET CONFLICT RESOLUTION");
    archival_ = archival;
    retrieval_ = retrieval;
}

std::map<int, std::vector<Element>> Phigs::cssContents(const std::set<int>& ids) const {
    std::map<int, std::vector<Element>> out;
    for (int id : ids)
        if (const Structure* s = store_.find(id)) {
            auto& elements = out[id];
            elements.reserve(s->elements.size());
            for (std::size_t i = 0; i < s->elements.size(); ++i) elements.push_back(s->elements.element(i));
        }
    return out;
}

void Phigs::archiveSet(int archiveId, std::set<int> ids, const char* function) {
    ArchiveFile& file = archive(archiveId, function);
    std::string missing;
    for (auto it = ids.begin(); it != ids.end();) {
        if (store_.exists(*it)) {
            ++it;
            continue;
        }
        missing += (missing.empty() ? "" : ", ") + std::to_string(*it);
        it = ids.erase(it);
    }
    std::set<int> conflicts;
    for (int id : ids)
        if (file.contains(id)) conflicts.insert(id);
    if (!conflicts.empty() && archival_ == ConflictResolution::Abandon)
        raise(&log_, errors::ArchiveNameConflict, function,
              "structure " + std::to_string(*conflicts.begin()));
    if (archival_ == ConflictResolution::Maintain)
        for (int id : conflicts) ids.erase(id);
    file.commit(cssContents(ids), {});
    if (!missing.empty()) warn(errors::IgnoringMissingStructures, function, "structures " + missing);
}

void Phigs::archiveStructures(int archiveId, const std::vector<int>& ids) {
    archiveSet(archiveId, {ids.begin(), ids.end()}, "ARCHIVE STRUCTURES");
}

void Phigs::archiveStructureNetworks(int archiveId, const std::vector<int>& ids) {
    std::set<int> all;
    for (int id : ids)
        if (store_.exists(id))
            all.merge(store_.network(id));
        else
            all.insert(id);
    archiveSet(archiveId, std::move(all), "ARCHIVE STRUCTURE NETWORKS");
}

void Phigs::archiveAllStructures(int archiveId) {
    auto ids = store_.structureIds();
    archiveSet(archiveId, {ids.begin(), ids.end()}, "ARCHIVE ALL STRUCTURES");
}

void Phigs::retrieveSet(int archiveId, std::set<int> ids, const char* function) {
    ArchiveFile& file = archive(archiveId, function);
    std::string missing;
    std::map<int, std::vector<Element>> contents;
    // ISO 9592: a structure the archive lacks is retrieved as an empty one (warning 408), and
    // meets the conflict resolution like any other: ABANDON refuses, UPDATE empties the CSS one.
    for (int id : ids) {
        auto it = file.contents().find(id);
        if (it == file.contents().end()) {
            missing += (missing.empty() ? "" : ", ") + std::to_string(id);
            contents.emplace(id, std::vector<Element>{});
        } else {
            contents.emplace(id, it->second);
        }
    }
    std::set<int> conflicts;
    for (const auto& [id, e] : contents)
        if (store_.exists(id)) conflicts.insert(id);
    if (!conflicts.empty() && retrieval_ == ConflictResolution::Abandon)
        raise(&log_, errors::ArchiveNameConflict, function,
              "structure " + std::to_string(*conflicts.begin()));
    if (retrieval_ == ConflictResolution::Maintain)
        for (int id : conflicts) contents.erase(id);
    store_.replaceStructures(contents, function);
    if (!missing.empty()) warn(errors::MissingInArchiveCreatedEmpty, function, "structures " + missing);
}

std::set<int> Phigs::archiveNetwork(const ArchiveFile& file, int id) {
    std::set<int> seen;
    std::vector<int> todo{id};
    while (!todo.empty()) {
        int next = todo.back();
        todo.pop_back();
        if (!seen.insert(next).second) continue;
        auto it = file.contents().find(next);
        if (it == file.contents().end()) continue;
        for (const Element& e : it->second)
            if (auto x = std::get_if<ExecuteStructureElement>(&e)) todo.push_back(x->structureId);
    }
    return seen;
}

std::vector<StructurePath> Phigs::retrievePathsToAncestors(int archiveId, int id, StructurePathOrder order,
                                                           int depth) {
    const char* function = "RETRIEVE PATHS TO ANCESTORS";
    const ArchiveFile& file = archive(archiveId, function);
    if (depth < 0) raise(&log_, errors::NegativePathDepth, function, "depth " + std::to_string(depth));
    // An executed structure the archive does not hold still ends paths, as in the store.
    const ExecuteReferences references = executeReferences(file.contents());
    bool referenced = false;
    for (const auto& [parent, refs] : references)
        for (const auto& ref : refs) referenced = referenced || ref.second == id;
    if (!file.contains(id) && !referenced) {
        warn(errors::MissingInArchive, function, "structure " + std::to_string(id));
        return {};
    }
    return ancestorPaths(references, id, order, depth, &log_, function);
}

std::vector<StructurePath> Phigs::retrievePathsToDescendants(int archiveId, int id, StructurePathOrder order,
                                                             int depth) {
    const char* function = "RETRIEVE PATHS TO DESCENDANTS";
    const ArchiveFile& file = archive(archiveId, function);
    if (depth < 0) raise(&log_, errors::NegativePathDepth, function, "depth " + std::to_string(depth));
    if (!file.contains(id)) {
        warn(errors::MissingInArchive, function, "structure " + std::to_string(id));
        return {};
    }
    return descendantPaths(executeReferences(file.contents()), id, order, depth, &log_, function);
}

void Phigs::retrieveStructures(int archiveId, const std::vector<int>& ids) {
    retrieveSet(archiveId, {ids.begin(), ids.end()}, "RETRIEVE STRUCTURES");
}

void Phigs::retrieveStructureNetworks(int archiveId, const std::vector<int>& ids) {
    const char* function = "RETRIEVE STRUCTURE NETWORKS";
    ArchiveFile& file = archive(archiveId, function);
    // Each root (one the archive lacks is warned and made empty, as RETRIEVE STRUCTURES does)
    // and the structures of its network the archive holds: one it only references is not
    // retrieved, so it neither conflicts nor is emptied.
    std::set<int> all;
    for (int id : ids) {
        all.insert(id);
        for (int member : archiveNetwork(file, id))
            if (file.contains(member)) all.insert(member);
    }
    retrieveSet(archiveId, std::move(all), function);
}

void Phigs::retrieveAllStructures(int archiveId) {
    const char* function = "RETRIEVE ALL STRUCTURES";
    auto ids = archive(archiveId, function).structureIds();
    retrieveSet(archiveId, {ids.begin(), ids.end()}, function);
}

std::vector<int> Phigs::archiveContents(int archiveId) {
    return archive(archiveId, "RETRIEVE STRUCTURE IDENTIFIERS").structureIds();
}

void Phigs::deleteStructuresFromArchive(int archiveId, const std::vector<int>& ids) {
    const char* function = "DELETE STRUCTURES FROM ARCHIVE";
    ArchiveFile& file = archive(archiveId, function);
    std::string missing;
    for (int id : ids)
        if (!file.contains(id)) missing += (missing.empty() ? "" : ", ") + std::to_string(id);
    file.commit({}, ids);
    if (!missing.empty()) warn(errors::MissingInArchive, function, "structures " + missing);
}

void Phigs::deleteStructureNetworksFromArchive(int archiveId, const std::vector<int>& ids) {
    const char* function = "DELETE STRUCTURE NETWORKS FROM ARCHIVE";
    ArchiveFile& file = archive(archiveId, function);
    std::set<int> all;
    std::string missing;
    for (int id : ids) {
        if (!file.contains(id)) missing += (missing.empty() ? "" : ", ") + std::to_string(id);
        all.merge(archiveNetwork(file, id));
    }
    std::vector<int> present;
    for (int id : all)
        if (file.contains(id)) present.push_back(id);
    file.commit({}, present);
    if (!missing.empty()) warn(errors::MissingInArchive, function, "structures " + missing);
}

void Phigs::deleteAllStructuresFromArchive(int archiveId) {
    ArchiveFile& file = archive(archiveId, "DELETE ALL STRUCTURES FROM ARCHIVE");
    file.commit({}, file.structureIds());
}

std::vector<int> Phigs::conflictingStructures(int archiveId) {
    ArchiveFile& file = archive(archiveId, "INQUIRE ALL CONFLICTING STRUCTURES", true);
    std::vector<int> out;
    for (int id : file.structureIds())
        if (store_.exists(id)) out.push_back(id);
    return out;
}

std::vector<int> Phigs::conflictingStructuresInNetwork(int archiveId, int id, NetworkSource source) {
    const char* function = "INQUIRE CONFLICTING STRUCTURES IN NETWORK";
    ArchiveFile& file = archive(archiveId, function, true);
    if (source == NetworkSource::Css && !store_.exists(id))
        raise(nullptr, errors::StructureDoesNotExist, function, "structure " + std::to_string(id));
    if (source == NetworkSource::Archive && !file.contains(id))
        raise(nullptr, errors::StructureDoesNotExist, function,
              "structure " + std::to_string(id) + " is not in archive " + std::to_string(archiveId));
    std::set<int> network = source == NetworkSource::Css ? store_.network(id) : archiveNetwork(file, id);
    std::vector<int> out;
    for (int member : network)
        if (store_.exists(member) && file.contains(member)) out.push_back(member);
    return out;
}

}  // namespace phigs
