// Archive functions.

#include "Binding.h"
#include "Conversions.h"
#include "Inquiry.h"
#include "phigs.h"

using namespace phigs;
using phigs::c::Binding;

namespace {

ConflictResolution resolution(int r) {
    if (r < PRES_MAINTAIN || r > PRES_UPDATE) throw Error(PE_ENUM_TYPE_INVAL, "SET CONFLICT RESOLUTION");
    return static_cast<ConflictResolution>(r);
}

/// The archive functions need an archive open (error 7) and this one open (404) before
/// their other arguments are looked at.
void requireArchive(Phigs& p, Pint ar_id, int fn) {
    const std::string name = c::functionName(fn);
    if (!p.anyArchiveOpen()) raise(&p.errorLog(), errors::NoArchiveOpen, name.c_str());
    if (!p.findArchive(ar_id))
        raise(&p.errorLog(), errors::ArchiveNotOpen, name.c_str(), "archive " + std::to_string(ar_id));
}

template <class Body>
void withIds(int fn, Pint ar_id, const Pint_list* ids, Body&& body) {
    Binding::instance().call(fn, [&](Phigs& p) {
        requireArchive(p, ar_id, fn);
        body(p, c::ints(ids, c::functionName(fn).c_str()));
    });
}

void retrievePaths(int fn, Pint ar_id, Pint id, int order, Pint depth, Pstore store,
                   Pelem_ref_list_list** paths) {
    Binding::instance().call(fn, [&](Phigs& p) {
        requireArchive(p, ar_id, fn);
        if (order != PORDER_TOP_FIRST && order != PORDER_BOTTOM_FIRST)
            throw Error(PE_ENUM_TYPE_INVAL, c::functionName(fn));
        Phigs_store& s = c::storeOf(store);
        c::require(paths, "RETRIEVE PATHS");
        const auto o =
            order == PORDER_TOP_FIRST ? StructurePathOrder::TopFirst : StructurePathOrder::BottomFirst;
        *paths = c::answerPaths(fn == Pfn_ret_paths_ances ? p.retrievePathsToAncestors(ar_id, id, o, depth)
                                                          : p.retrievePathsToDescendants(ar_id, id, o, depth),
                                s);
    });
}

}  // namespace

extern "C" {

void popen_ar_file(Pint ar_id, const char* ar_file) {
    Binding::instance().call(Pfn_open_ar_file, [&](Phigs& p) {
        c::require(ar_file, "OPEN ARCHIVE FILE");
        p.openArchiveFile(ar_id, ar_file);
    });
}

void pclose_ar_file(Pint ar_id) {
    Binding::instance().call(Pfn_close_ar_file, [&](Phigs& p) { p.closeArchiveFile(ar_id); });
}

void par_structs(Pint ar_id, const Pint_list* ids) {
    withIds(Pfn_ar_structs, ar_id, ids,
            [&](Phigs& p, const std::vector<int>& v) { p.archiveStructures(ar_id, v); });
}
void par_struct_nets(Pint ar_id, const Pint_list* ids) {
    withIds(Pfn_ar_struct_nets, ar_id, ids,
            [&](Phigs& p, const std::vector<int>& v) { p.archiveStructureNetworks(ar_id, v); });
}
void par_all_structs(Pint ar_id) {
    Binding::instance().call(Pfn_ar_all_structs, [&](Phigs& p) { p.archiveAllStructures(ar_id); });
}

void pset_conf_res(Pconf_res archive_res, Pconf_res retrieve_res) {
    Binding::instance().call(Pfn_set_conf_res, [&](Phigs& p) {
        p.setConflictResolution(resolution(c::raw(archive_res)), resolution(c::raw(retrieve_res)));
    });
}

void pret_struct_ids(Pint ar_id, Pint appl, Pint start, Pint_list* ids, Pint* total) {
    Binding::instance().call(Pfn_ret_struct_ids, [&](Phigs& p) {
        requireArchive(p, ar_id, Pfn_ret_struct_ids);
        c::answerList(p.archiveContents(ar_id), appl, start, ids, total);
    });
}

void pret_structs(Pint ar_id, const Pint_list* ids) {
    withIds(Pfn_ret_structs, ar_id, ids,
            [&](Phigs& p, const std::vector<int>& v) { p.retrieveStructures(ar_id, v); });
}
void pret_struct_nets(Pint ar_id, const Pint_list* ids) {
    withIds(Pfn_ret_struct_nets, ar_id, ids,
            [&](Phigs& p, const std::vector<int>& v) { p.retrieveStructureNetworks(ar_id, v); });
}
void pret_all_structs(Pint ar_id) {
    Binding::instance().call(Pfn_ret_all_structs, [&](Phigs& p) { p.retrieveAllStructures(ar_id); });
}

void pret_paths_ances(Pint ar_id, Pint id, Ppath_order order, Pint depth, Pstore store,
                      Pelem_ref_list_list** paths) {
    retrievePaths(Pfn_ret_paths_ances, ar_id, id, c::raw(order), depth, store, paths);
}
void pret_paths_descs(Pint ar_id, Pint id, Ppath_order order, Pint depth, Pstore store,
                      Pelem_ref_list_list** paths) {
    retrievePaths(Pfn_ret_paths_descs, ar_id, id, c::raw(order), depth, store, paths);
}

void pdel_structs_ar(Pint ar_id, const Pint_list* ids) {
    withIds(Pfn_del_structs_ar, ar_id, ids,
            [&](Phigs& p, const std::vector<int>& v) { p.deleteStructuresFromArchive(ar_id, v); });
}
void pdel_struct_nets_ar(Pint ar_id, const Pint_list* ids) {
    withIds(Pfn_del_struct_nets_ar, ar_id, ids,
            [&](Phigs& p, const std::vector<int>& v) { p.deleteStructureNetworksFromArchive(ar_id, v); });
}
void pdel_all_structs_ar(Pint ar_id) {
    Binding::instance().call(Pfn_del_all_structs_ar,
                             [&](Phigs& p) { p.deleteAllStructuresFromArchive(ar_id); });
}

}  // extern "C"
