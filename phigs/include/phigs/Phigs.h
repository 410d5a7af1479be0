#pragma once

#include "phigs/core/ErrorLog.h"
#include "phigs/store/ArchiveFile.h"
#include "phigs/store/StructureStore.h"
#include "phigs/ws/OutputRegistry.h"
#include "phigs/ws/Workstation.h"

#include <filesystem>
#include <map>
#include <memory>
#include <vector>

namespace phigs {

/// Archive conflict resolution (SET CONFLICT RESOLUTION).
enum class ConflictResolution { Maintain, Abandon, Update };
/// Where INQUIRE CONFLICTING STRUCTURES IN NETWORK takes the network from.
enum class NetworkSource { Css, Archive };

/// The PHIGS system: the operating states (PHIGS, workstation, structure and archive state),
/// the central structure store, open workstations, open archive files and the error log.
/// Functions check the state they need first (errors 1-7) and raise phigs::Error, which the
/// error log records. One thread at a time uses a Phigs and everything it holds (the store's
/// const inquiries fill caches too).
class Phigs {
public:
    Phigs() : store_(&log_) {}

    // ---- PHIGS state
    /// OPEN PHIGS (error 1 when already open).
    void open();
    /// CLOSE PHIGS: needs every workstation, structure and archive closed (error 4).
    void close();
    bool isOpen() const { return open_; }
    ErrorLog& errorLog() { return log_; }

    /// The central structure store (error 2 while PHIGS is closed).
    StructureStore& store();

    // ---- workstations
    /// The output factories OPEN WORKSTATION uses (each drawing library's registerOutputs adds
    /// its own: vk::registerOutputs, hardcopy::registerOutputs, window::registerOutputs).
    OutputRegistry& outputs() { return outputs_; }
    /// OPEN WORKSTATION: the workstation with the output its type's factory makes on
    /// `connection`. Errors 2, 52 (not a workstation type), 53 (identifier in use), 50 (the
    /// factory refused the connection: a file type without a file name), 55 (the target could
    /// not be made; the reason in the error). A type no library registered opens without an
    /// output (the GPU-free tests of store, traversal and pick; attachOutput adds one).
    Workstation& openWorkstation(int id, WorkstationType type, const OutputConnection& connection = {});
    /// CLOSE WORKSTATION: errors 3, 54; the output writes its last picture first (903 when
    /// that fails; the workstation is closed all the same).
    void closeWorkstation(int id);
    /// The open workstation `id`: errors 3 (none open), 54 (this one not open).
    Workstation& workstation(int id);
    /// The open workstation `id`, or null (inquiries, which raise nothing).
    Workstation* findWorkstation(int id) {
        auto it = workstations_.find(id);
        return it == workstations_.end() ? nullptr : it->second.get();
    }
    std::vector<int> openWorkstationIds() const;
    /// INQUIRE SET OF WORKSTATIONS TO WHICH POSTED (error 201 when the structure does not exist).
    std::vector<int> workstationsPostedTo(int structureId);
    bool anyWorkstationOpen() const { return !workstations_.empty(); }

    // ---- archives
    /// OPEN ARCHIVE FILE: errors 2, 402 (identifier in use), 400, 403 (not an archive, with file and line).
    void openArchiveFile(int archiveId, const std::filesystem::path& path);
    void closeArchiveFile(int archiveId);
    bool anyArchiveOpen() const { return !archives_.empty(); }
    /// INQUIRE ARCHIVE FILES: the open archive identifiers.
    std::vector<int> openArchiveIds() const;
    /// The open archive `archiveId`, or nullptr (INQUIRE ARCHIVE FILES names their files).
    const ArchiveFile* findArchive(int archiveId) const {
        auto it = archives_.find(archiveId);
        return it == archives_.end() ? nullptr : it->second.get();
    }
    void setConflictResolution(ConflictResolution archival, ConflictResolution retrieval);
    ConflictResolution archivalResolution() const { return archival_; }
    ConflictResolution retrievalResolution() const { return retrieval_; }

    void archiveStructures(int archiveId, const std::vector<int>& ids);
    void archiveStructureNetworks(int archiveId, const std::vector<int>& ids);
    void archiveAllStructures(int archiveId);
    /// RETRIEVE STRUCTURES (and NETWORKS, ALL): a structure the archive lacks is retrieved empty
    /// (warning 408) under the conflict resolution like any other (ABANDON: 405 when the store
    /// has it; UPDATE empties it; MAINTAIN keeps it).
    void retrieveStructures(int archiveId, const std::vector<int>& ids);
    void retrieveStructureNetworks(int archiveId, const std::vector<int>& ids);
    void retrieveAllStructures(int archiveId);
    /// RETRIEVE STRUCTURE IDENTIFIERS: what the archive holds.
    std::vector<int> archiveContents(int archiveId);
    /// RETRIEVE PATHS TO ANCESTORS / DESCENDANTS: the paths of the network as the archive holds
    /// it (the store is not touched), as INQUIRE PATHS TO ... gives them for the store. A
    /// structure the archive does not hold gives no paths and warning 407; error 207 for a
    /// negative depth, -201 for a cyclic archive (one this toolkit did not write).
    std::vector<StructurePath> retrievePathsToAncestors(int archiveId, int id, StructurePathOrder order,
                                                        int depth);
    std::vector<StructurePath> retrievePathsToDescendants(int archiveId, int id, StructurePathOrder order,
                                                          int depth);
    void deleteStructuresFromArchive(int archiveId, const std::vector<int>& ids);
    void deleteStructureNetworksFromArchive(int archiveId, const std::vector<int>& ids);
    void deleteAllStructuresFromArchive(int archiveId);
    /// INQUIRE ALL CONFLICTING STRUCTURES: ids both in the store and in the archive. This and the
    /// other inquiries throw phigs::Error without logging it (the C binding's error indicator).
    std::vector<int> conflictingStructures(int archiveId);
    /// INQUIRE CONFLICTING STRUCTURES IN NETWORK: of the network of `id` (in the store or the archive).
    std::vector<int> conflictingStructuresInNetwork(int archiveId, int id, NetworkSource source);

private:
    void requireOpen(const char* function) const;
    ArchiveFile& archive(int archiveId, const char* function, bool inquiry = false);
    void warn(int number, const char* function, std::string detail);
    std::map<int, std::vector<Element>> cssContents(const std::set<int>& ids) const;
    void archiveSet(int archiveId, std::set<int> ids, const char* function);
    void retrieveSet(int archiveId, std::set<int> ids, const char* function);
    static std::set<int> archiveNetwork(const ArchiveFile& file, int id);

    ErrorLog log_;
    bool open_ = false;
    StructureStore store_;
    OutputRegistry outputs_;
    std::map<int, std::unique_ptr<Workstation>> workstations_;
    std::map<int, std::unique_ptr<ArchiveFile>> archives_;
    ConflictResolution archival_ = ConflictResolution::Update;
    ConflictResolution retrieval_ = ConflictResolution::Abandon;
};

}  // namespace phigs
