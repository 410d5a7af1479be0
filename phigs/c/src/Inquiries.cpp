// Structure, CSS and archive inquiries: *err_ind answers, the error handler is never called.

#include "Conversions.h"
#include "ElementContent.h"
#include "ElementTypes.h"
#include "Inquiry.h"
#include "phigs.h"

#include <limits>

using namespace phigs;
using phigs::c::inquire;

namespace {

StructurePathOrder order(int o) {
    if (o != PORDER_TOP_FIRST && o != PORDER_BOTTOM_FIRST)
        throw Error(PE_ENUM_TYPE_INVAL, "inquiry", "path order");
    return o == PORDER_TOP_FIRST ? StructurePathOrder::TopFirst : StructurePathOrder::BottomFirst;
}

std::vector<Pelem_type> typeList(const Pelem_type_list* list) {
    c::require(list, "ELEMENT SEARCH");
    std::vector<Pelem_type> out(c::count(list->num_elem_types, "ELEMENT SEARCH"));
    if (!out.empty()) c::require(list->elem_types, "ELEMENT SEARCH");
    for (std::size_t i = 0; i < out.size(); ++i) {
        const int t = c::raw(list->elem_types[i]);
        if (!c::validElementType(t)) throw Error(PE_ENUM_TYPE_INVAL, "ELEMENT SEARCH");
        out[i] = static_cast<Pelem_type>(t);
    }
    return out;
}

bool contains(const std::vector<Pelem_type>& set, const Pelem_type& t) {
    for (Pelem_type s : set)
        if (s == PELEM_ALL || s == t) return true;
    return false;
}

void answerContent(const Element& e, Pstore store, Pint* err, Pelem_data** data) {
    Phigs_store& s = c::storeOf(store);
    c::require(data, "INQUIRE ELEMENT CONTENT");
    // The store keeps doubles (an archive may hold 1e300); a Pfloat would answer infinity.
    if (!(largestMagnitude(e) <= std::numeric_limits<float>::max()))
        throw Error(c::kArithmeticError, "INQUIRE ELEMENT CONTENT",
                    "the element holds a real beyond the range of a Pfloat (3.4e38)");
    if (int failed = c::fillContent(e, s)) throw Error(failed, "INQUIRE ELEMENT CONTENT");
    *data = &s.data;
    *err = 0;
}

}  // namespace

extern "C" {

void pinq_struct_st(Pstruct_st* st) {
    if (!st) return;
    Phigs* p = c::Binding::instance().system();
    *st = p && p->store().isStructureOpen() ? PSTRUCT_ST_STOP : PSTRUCT_ST_STCL;
}

void pinq_ar_st(Par_st* st) {
    if (!st) return;
    Phigs* p = c::Binding::instance().system();
    *st = p && p->anyArchiveOpen() ? PAR_ST_OP : PAR_ST_CL;
}

void pinq_open_struct(Pint* err, Popen_struct_status* status, Pint* id) {
    if (!c::somewhereToAnswer(err, status, id)) return;
    inquire(err, [&](Phigs& p) {
        c::require(status, "INQUIRE OPEN STRUCTURE");
        const StructureStore& s = p.store();
        *status = s.isStructureOpen() ? PSTRUCT_OPEN : PSTRUCT_NONE;
        if (s.isStructureOpen() && id) *id = s.openStructureId();
    });
}

void pinq_elem_ptr(Pint* err, Pint* value) {
    if (!c::somewhereToAnswer(err, value)) return;
    inquire(err, [&](Phigs& p) {
        const int pointer = p.store().elementPointer();
        c::require(value, "INQUIRE ELEMENT POINTER");
        *value = pointer;
    });
}

void pinq_edit_mode(Pint* err, Pedit_mode* mode) {
    if (!c::somewhereToAnswer(err, mode)) return;
    inquire(err, [&](Phigs& p) {
        c::require(mode, "INQUIRE EDIT MODE");
        *mode = p.store().editMode() == EditMode::Insert ? PEDIT_INSERT : PEDIT_REPLACE;
    });
}

// ISO 9592: at element pointer 0 the current element is NIL, of size 0.
void pinq_cur_elem_type_size(Pint* err, Pelem_type* type, size_t* size) {
    if (!c::somewhereToAnswer(err, type, size)) return;
    inquire(err, [&](Phigs& p) {
        const StructureStore& s = p.store();
        const int pointer = s.elementPointer();
        c::require(type, "INQUIRE CURRENT ELEMENT TYPE AND SIZE");
        c::require(size, "INQUIRE CURRENT ELEMENT TYPE AND SIZE");
        *type = pointer == 0 ? PELEM_NIL : c::cElementType(s.currentElement());
        *size = pointer == 0 ? 0 : elementSize(s.currentElement());
    });
}

void pinq_cur_elem_content(Pstore store, Pint* err, Pelem_data** data) {
    if (!c::somewhereToAnswer(err, data)) return;
    inquire(err, [&](Phigs& p) { answerContent(p.store().currentElement(), store, err, data); });
}

void pinq_elem_type_size(Pint id, Pint n, Pint* err, Pelem_type* type, size_t* size) {
    if (!c::somewhereToAnswer(err, type, size)) return;
    inquire(err, [&](Phigs& p) {
        const StructureStore& s = p.store();
        const std::size_t bytes = s.elementSizeAt(id, n);
        c::require(type, "INQUIRE ELEMENT TYPE AND SIZE");
        c::require(size, "INQUIRE ELEMENT TYPE AND SIZE");
        *type = n == 0 ? PELEM_NIL : c::cElementType(s.elementAt(id, n));
        *size = bytes;
    });
}

void pinq_elem_content(Pint id, Pint n, Pstore store, Pint* err, Pelem_data** data) {
    if (!c::somewhereToAnswer(err, data)) return;
    inquire(err, [&](Phigs& p) { answerContent(p.store().elementAt(id, n), store, err, data); });
}

void pinq_struct_status(Pint id, Pint* err, Pstruct_status* status) {
    if (!c::somewhereToAnswer(err, status)) return;
    inquire(err, [&](Phigs& p) {
        c::require(status, "INQUIRE STRUCTURE STATUS");
        switch (p.store().structureStatus(id)) {
            case StructureStatus::NonExistent:
                *status = PSTRUCT_STATUS_NON_EXIST;
                break;
            case StructureStatus::Empty:
                *status = PSTRUCT_STATUS_EMPTY;
                break;
            case StructureStatus::NotEmpty:
                *status = PSTRUCT_STATUS_NOT_EMPTY;
                break;
        }
    });
}

void pinq_struct_ids(Pint appl, Pint start, Pint* err, Pint_list* ids, Pint* total) {
    if (!c::somewhereToAnswer(err, ids, total)) return;
    inquire(err, [&](Phigs& p) { c::answerList(p.store().structureIds(), appl, start, ids, total); });
}

void pinq_paths_ances(Pint id, Ppath_order o, Pint depth, Pstore store, Pint* err,
                      Pelem_ref_list_list** paths) {
    if (!c::somewhereToAnswer(err, paths)) return;
    inquire(err, [&](Phigs& p) {
        Phigs_store& s = c::storeOf(store);
        c::require(paths, "INQUIRE PATHS TO ANCESTORS");
        *paths = c::answerPaths(p.store().pathsToAncestors(id, order(c::raw(o)), depth), s);
    });
}

void pinq_paths_descs(Pint id, Ppath_order o, Pint depth, Pstore store, Pint* err,
                      Pelem_ref_list_list** paths) {
    if (!c::somewhereToAnswer(err, paths)) return;
    inquire(err, [&](Phigs& p) {
        Phigs_store& s = c::storeOf(store);
        c::require(paths, "INQUIRE PATHS TO DESCENDANTS");
        *paths = c::answerPaths(p.store().pathsToDescendants(id, order(c::raw(o)), depth), s);
    });
}

void pelem_search(Pint id, Pint start, Psearch_dir direction, const Pelem_type_list* incl,
                  const Pelem_type_list* excl, Pint* err, Psearch_status* status, Pint* found) {
    const int dir = c::raw(direction);
    inquire(err, [&](Phigs& p) {
        if (dir != PDIR_BACKWARD && dir != PDIR_FORWARD) throw Error(PE_ENUM_TYPE_INVAL, "ELEMENT SEARCH");
        const std::vector<Pelem_type> in = typeList(incl), out = typeList(excl);
        c::require(status, "ELEMENT SEARCH");
        auto matches = [&](const Element* e) {
            const Pelem_type t = e ? c::cElementType(*e) : PELEM_NIL;
            return contains(in, t) && !contains(out, t);
        };
        const SearchResult r = p.store().elementSearch(
            id, start, dir == PDIR_FORWARD ? SearchDirection::Forward : SearchDirection::Backward, matches);
        *status = r.found ? PSEARCH_STATUS_SUCCESS : PSEARCH_STATUS_FAILURE;
        if (r.found && found) *found = r.elementNumber;
    });
}

void pinq_ar_files(Pstore store, Pint* err, Par_file_list** files) {
    if (!c::somewhereToAnswer(err, files)) return;
    inquire(err, [&](Phigs& p) {
        Phigs_store& s = c::storeOf(store);
        c::require(files, "INQUIRE ARCHIVE FILES");
        s.clear();
        for (int id : p.openArchiveIds()) s.names.push_back(p.findArchive(id)->path().string());
        const auto ids = p.openArchiveIds();
        for (std::size_t i = 0; i < ids.size(); ++i) s.files.push_back({ids[i], s.names[i].data()});
        s.fileList = {static_cast<Pint>(s.files.size()), s.files.data()};
        *files = &s.fileList;
    });
}

void pinq_conf_res(Pint* err, Pconf_res* archive_res, Pconf_res* retrieve_res) {
    if (!c::somewhereToAnswer(err, archive_res, retrieve_res)) return;
    inquire(err, [&](Phigs& p) {
        c::require(archive_res, "INQUIRE CONFLICT RESOLUTION");
        c::require(retrieve_res, "INQUIRE CONFLICT RESOLUTION");
        *archive_res = static_cast<Pconf_res>(p.archivalResolution());
        *retrieve_res = static_cast<Pconf_res>(p.retrievalResolution());
    });
}

void pinq_all_conf_structs(Pint ar_id, Pint appl, Pint start, Pint* err, Pint_list* ids, Pint* total) {
    if (!c::somewhereToAnswer(err, ids, total)) return;
    inquire(err, [&](Phigs& p) { c::answerList(p.conflictingStructures(ar_id), appl, start, ids, total); });
}

void pinq_conf_structs_net(Pint ar_id, Pint id, Pstruct_net_source net, Pint appl, Pint start, Pint* err,
                           Pint_list* ids, Pint* total) {
    if (!c::somewhereToAnswer(err, ids, total)) return;
    const int source = c::raw(net);
    inquire(err, [&](Phigs& p) {
        if (source != PNET_CSS && source != PNET_AR) throw Error(PE_ENUM_TYPE_INVAL, "inquiry");
        const auto all = p.conflictingStructuresInNetwork(
            ar_id, id, source == PNET_CSS ? NetworkSource::Css : NetworkSource::Archive);
        c::answerList(all, appl, start, ids, total);
    });
}

}  // extern "C"
