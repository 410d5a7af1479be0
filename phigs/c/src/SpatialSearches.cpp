// INCREMENTAL SPATIAL SEARCH (3): an inquiry-style function (*err_ind only) over the core's
// incrementalSpatialSearch; the found path is a simple list of element references.

#include "Conversions.h"
#include "Inquiry.h"
#include "phigs.h"
#include "phigs/pick/SpatialSearch.h"

#include <algorithm>

using namespace phigs;

namespace {

constexpr const char* kName = "INCREMENTAL SPATIAL SEARCH";

std::vector<NameSetFilter> filters(const Pfilter_list* list) {
    c::require(list, kName);
    std::vector<NameSetFilter> out(c::count(list->num_filters, kName));
    if (!out.empty()) c::require(list->filters, kName);
    for (std::size_t i = 0; i < out.size(); ++i) {
        const std::vector<int> in = c::ints(&list->filters[i].incl_set, kName);
        const std::vector<int> ex = c::ints(&list->filters[i].excl_set, kName);
        out[i] = {{in.begin(), in.end()}, {ex.begin(), ex.end()}};
    }
    return out;
}

StructurePath startPath(const Pelem_ref_list* list) {
    c::require(list, kName);
    StructurePath out(c::count(list->num_elem_refs, kName));
    if (!out.empty()) c::require(list->elem_refs, kName);
    for (std::size_t i = 0; i < out.size(); ++i)
        out[i] = {list->elem_refs[i].struct_id, list->elem_refs[i].elem_pos};
    return out;
}

// The found path as the binding's simple list: `appl` references from `start` into the
// application's array, the whole length in *total.
void answerPath(const StructurePath& path, Pint appl, Pint start, Pelem_ref_list* out, Pint* total) {
    if (appl < 0) throw Error(PE_LIST_LENGTH_LT_ZERO, kName);
    const Pint size = static_cast<Pint>(path.size());
    if (start < 0 || (start >= size && size > 0)) throw Error(PE_START_IND_INVAL, kName);
    c::require(total, kName);
    *total = size;
    if (!out) return;
    const Pint n = std::max(std::min(appl, size - start), 0);
    if (n > 0) c::require(out->elem_refs, kName);
    for (Pint i = 0; i < n; ++i) {
        const ElementRef& r = path[static_cast<std::size_t>(start + i)];
        out->elem_refs[i] = {r.structureId, r.elementNumber};
    }
    out->num_elem_refs = n;
}

void search(const glm::dvec3& point, Pfloat dist, const Pelem_ref_list* sp, const Pclip_ind& mclip,
            Pint ceiling, const Pfilter_list* norm, const Pfilter_list* inv, Pint appl, Pint start, Pint* err,
            Pelem_ref_list* found, Pint* total) {
    const int clip = c::raw(mclip);
    c::inquire(err, [&](Phigs& p) {
        if (clip != PIND_NO_CLIP && clip != PIND_CLIP)
            throw Error(PE_ENUM_TYPE_INVAL, kName, "model clip flag");
        SpatialSearchQuery q;
        q.point = point;
        q.distance = dist;
        q.start = startPath(sp);
        q.ceiling = ceiling;
        q.modelClip = clip == PIND_CLIP;
        q.normal = filters(norm);
        q.inverted = filters(inv);
        answerPath(incrementalSpatialSearch(p.store(), q, kName), appl, start, found, total);
    });
}

}  // namespace

extern "C" {

void pincr_spa_search3(const Ppoint3* ref, Pfloat dist, const Pelem_ref_list* start_path,
                       Pclip_ind mclip_flag, Pint ceiling, const Pfilter_list* norm_filter,
                       const Pfilter_list* inv_filter, Pint num_elems_appl_list, Pint start_ind,
                       Pint* err_ind, Pelem_ref_list* found_path, Pint* num_elems_impl_list) {
    if (!ref) {
        c::inquire(err_ind, [](Phigs&) { c::require(nullptr, kName); });
        return;
    }
    search({ref->x, ref->y, ref->z}, dist, start_path, mclip_flag, ceiling, norm_filter, inv_filter,
           num_elems_appl_list, start_ind, err_ind, found_path, num_elems_impl_list);
}

void pincr_spa_search(const Ppoint* ref, Pfloat dist, const Pelem_ref_list* start_path, Pclip_ind mclip_flag,
                      Pint ceiling, const Pfilter_list* norm_filter, const Pfilter_list* inv_filter,
                      Pint num_elems_appl_list, Pint start_ind, Pint* err_ind, Pelem_ref_list* found_path,
                      Pint* num_elems_impl_list) {
    if (!ref) {
        c::inquire(err_ind, [](Phigs&) { c::require(nullptr, kName); });
        return;
    }
    search({ref->x, ref->y, 0.0}, dist, start_path, mclip_flag, ceiling, norm_filter, inv_filter,
           num_elems_appl_list, start_ind, err_ind, found_path, num_elems_impl_list);
}

}  // extern "C"
