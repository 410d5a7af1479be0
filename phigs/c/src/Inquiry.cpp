#include "Inquiry.h"

#include <algorithm>

namespace phigs::c {

void answerList(const std::vector<int>& all, Pint appl, Pint start, Pint_list* out, Pint* total) {
    const char* function = "inquiry";
    if (appl < 0) throw Error(PE_LIST_LENGTH_LT_ZERO, function);
    const Pint size = static_cast<Pint>(all.size());
    if (start < 0 || (start >= size && size > 0)) throw Error(PE_START_IND_INVAL, function);
    require(total, function);
    *total = size;
    if (!out) return;
    const Pint n = std::min(appl, size - start);
    if (n > 0) require(out->ints, function);
    for (Pint i = 0; i < n; ++i) out->ints[i] = all[static_cast<std::size_t>(start + i)];
    out->num_ints = std::max(n, 0);
}

Phigs_store& storeOf(Pstore store) {
    if (!store) throw Error(PE_ALLOC_STORE, "inquiry", "no store");
    return *store;
}

Pelem_ref_list_list* answerPaths(const std::vector<StructurePath>& paths, Phigs_store& s) {
    s.clear();
    for (const auto& path : paths)
        for (const auto& ref : path) s.refs.push_back({ref.structureId, ref.elementNumber});
    std::size_t at = 0;
    for (const auto& path : paths) {
        s.refLists.push_back({static_cast<Pint>(path.size()), s.refs.data() + at});
        at += path.size();
    }
    s.paths = {static_cast<Pint>(s.refLists.size()), s.refLists.data()};
    return &s.paths;
}

}  // namespace phigs::c
