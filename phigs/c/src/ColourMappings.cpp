// PHIGS PLUS colour mapping: SET COLOUR MAPPING REPRESENTATION on a workstation, its inquiries
// (set and realized entries, the defined indices, the mapping state), the predefined entries
// and the colour mapping facilities of the workstation types.

#include "Conversions.h"
#include "Inquiry.h"
#include "WorkstationAccess.h"
#include "phigs.h"

using phigs::c::Binding;

namespace {

using namespace phigs;

constexpr Pint kTrueColours = 1 << 24;

int checkedMethod(Pint method, const char* name) {
    if (method < PCOLR_MAP_TRUE || method > PCOLR_MAP_PSEUDO_N)
        throw Error(errors::ColourMappingMethodNotAvailable, name, "method " + std::to_string(method));
    return method;
}

/// The colour model of PSEUDO or PSEUDO_N data (110 for a number that names none).
ColourModel model(Pint model, const char* name) {
    if (!isColourModel(model))
        throw Error(errors::ColourModelNotAvailable, name, "colour model " + std::to_string(model));
    return static_cast<ColourModel>(model);
}

/// The PSEUDO data of a C record (weights and colours in its model; the core checks their values).
ColourMapping pseudo(const Pcolr_map_data& d, const char* name) {
    ColourMapping m;
    m.method = ColourMappingMethod::Pseudo;
    m.model = model(d.meth_r2.colr_model, name);
    const std::size_t weights = c::count(d.meth_r2.weights.num_floats, name);
    if (weights != 3)
        throw Error(errors::BadColourMappingData, name,
                    std::to_string(weights) + " weights, a colour model needs 3");
    c::require(d.meth_r2.weights.floats, name);
    m.weights = {d.meth_r2.weights.floats[0], d.meth_r2.weights.floats[1], d.meth_r2.weights.floats[2]};
    const std::size_t n = c::count(d.meth_r2.colrs.num_colr_reps, name);
    if (n) c::require(d.meth_r2.colrs.colr_reps, name);
    for (std::size_t i = 0; i < n; ++i)
        m.colours.push_back(c::colourComponents(d.meth_r2.colrs.colr_reps[i], d.meth_r2.colr_model));
    return m;
}

ColourMapping pseudoN(const Pcolr_map_data& d, const char* name) {
    ColourMapping m;
    m.method = ColourMappingMethod::PseudoN;
    m.model = model(d.meth_r3.colr_model, name);
    const std::size_t lists = c::count(d.meth_r3.colr_lists.num_lists, name);
    if (lists) c::require(d.meth_r3.colr_lists.lists, name);
    for (std::size_t i = 0; i < lists; ++i) {
        const Pfloat_list& l = d.meth_r3.colr_lists.lists[i];
        const std::size_t n = c::count(l.num_floats, name);
        if (n) c::require(l.floats, name);
        m.lists.emplace_back(l.floats, l.floats + n);
    }
    return m;
}

/// An entry answered in `store`: the data of PSEUDO and PSEUDO_N point into it.
void answer(const ColourMapping& m, Phigs_store& s, Pint* method, Pcolr_map_data** data) {
    c::require(method, "inquiry");
    c::require(data, "inquiry");
    s.clear();
    *method = static_cast<Pint>(m.method);
    if (m.method == ColourMappingMethod::Pseudo) {
        s.floats = {static_cast<Pfloat>(m.weights.x), static_cast<Pfloat>(m.weights.y),
                    static_cast<Pfloat>(m.weights.z)};
        const Pint model = static_cast<Pint>(m.model);
        for (const auto& c : m.colours) s.colourReps.push_back(c::cColour(c, model));
        s.colourMap.meth_r2 = {
            model, {3, s.floats.data()}, {static_cast<Pint>(s.colourReps.size()), s.colourReps.data()}};
    } else if (m.method == ColourMappingMethod::PseudoN) {
        for (const auto& list : m.lists)
            for (double v : list) s.floats.push_back(static_cast<Pfloat>(v));
        std::size_t at = 0;
        for (const auto& list : m.lists) {
            s.floatLists.push_back({static_cast<Pint>(list.size()), s.floats.data() + at});
            at += list.size();
        }
        s.colourMap.meth_r3 = {static_cast<Pint>(m.model),
                               {static_cast<Pint>(s.floatLists.size()), s.floatLists.data()}};
    }
    *data = &s.colourMap;
}

/// The colours a method has: TRUE the 24-bit colours, PSEUDO and PSEUDO_N the colour table.
Pint available(Pint method, const WorkstationDescription& d, const char* name) {
    return checkedMethod(method, name) == PCOLR_MAP_TRUE ? kTrueColours
                                                         : static_cast<Pint>(d.colourTableSize);
}

}  // namespace

extern "C" {

void pset_colr_map_rep(Pint ws_id, Pint index, Pint map_method, const Pcolr_map_data* map_data) {
    c::onOpenWorkstation(Pfn_set_colr_map_rep, ws_id, [&](Workstation& ws) {
        const char* name = "SET COLOUR MAPPING REPRESENTATION";
        if (index < 0)
            throw Error(errors::ColourMappingIndexBelowZero, name, "index " + std::to_string(index));
        ColourMapping m;
        if (checkedMethod(map_method, name) != PCOLR_MAP_TRUE) {
            c::require(map_data, name);
            m = map_method == PCOLR_MAP_PSEUDO ? pseudo(*map_data, name) : pseudoN(*map_data, name);
        }
        ws.setColourMappingRepresentation(index, m);
    });
}

void pinq_colr_map_rep(Pint ws_id, Pint index, Pinq_type type, Pstore store, Pint* err, Pint* map_method,
                       Pcolr_map_data** map_data) {
    if (!c::somewhereToAnswer(err, map_method, map_data)) return;
    const int t = c::raw(type);
    c::inquire(err, [&](Phigs& p) {
        const Workstation& ws = c::inquiredWorkstation(p, ws_id);
        if (t != PINQ_SET && t != PINQ_REALIZED) throw Error(PE_ENUM_TYPE_INVAL, "inquiry", "inquiry type");
        if (index < 0) throw Error(errors::ColourMappingIndexBelowZero, "inquiry");
        const ColourMappingTable& table = ws.tables().colourMappings;
        const ColourMapping* m = table.find(index);
        if (!m && t == PINQ_SET)
            throw Error(errors::RepresentationNotDefined, "inquiry",
                        "colour mapping " + std::to_string(index));
        answer(m ? *m : table.get(index), c::storeOf(store), map_method, map_data);
    });
}

void pinq_pred_colr_map_rep(Pint ws_type, Pint index, Pstore store, Pint* err, Pint* map_method,
                            Pcolr_map_data** map_data) {
    if (!c::somewhereToAnswer(err, map_method, map_data)) return;
    c::inquire(err, [&](Phigs&) {
        c::workstationTypeOf(ws_type, "inquiry");
        if (index < 0) throw Error(errors::ColourMappingIndexBelowZero, "inquiry");
        const ColourMappingTable initial;
        const ColourMapping* m = initial.find(index);
        if (!m)
            throw Error(errors::RepresentationNotPredefined, "inquiry",
                        "colour mapping " + std::to_string(index));
        answer(*m, c::storeOf(store), map_method, map_data);
    });
}

void pinq_list_colr_map_inds(Pint ws_id, Pint appl, Pint start, Pint* err, Pint_list* inds, Pint* total) {
    if (!c::somewhereToAnswer(err, inds, total)) return;
    c::inquire(err, [&](Phigs& p) {
        c::answerList(c::inquiredWorkstation(p, ws_id).tables().colourMappings.definedIndices(), appl, start,
                      inds, total);
    });
}

void pinq_colr_map_st(Pint ws_id, Pint map_method, Pint* err, Pcolr_map_st* map_st) {
    if (!c::somewhereToAnswer(err, map_st)) return;
    c::inquire(err, [&](Phigs& p) {
        const Workstation& ws = c::inquiredWorkstation(p, ws_id);
        const Pint n = available(map_method, ws.description(), "inquiry");
        c::require(map_st, "inquiry");
        map_st->int_data = n;
    });
}

void pinq_colr_map_facs(Pint ws_type, Pint appl, Pint start, Pint* err, Pcolr_map_facs* facs, Pint* total) {
    if (!c::somewhereToAnswer(err, facs, total)) return;
    c::inquire(err, [&](Phigs&) {
        c::workstationTypeOf(ws_type, "inquiry");
        c::require(facs, "inquiry");
        c::answerList({PCOLR_MAP_TRUE, PCOLR_MAP_PSEUDO, PCOLR_MAP_PSEUDO_N}, appl, start, &facs->meths,
                      total);
        facs->num_pred_inds = static_cast<Pint>(ColourMappingTable{}.definedIndices().size());
    });
}

void pinq_colr_map_method_facs(Pint ws_type, Pint map_method, Pint* err, Pcolr_map_st* map_st) {
    if (!c::somewhereToAnswer(err, map_st)) return;
    c::inquire(err, [&](Phigs&) {
        const Pint n = available(
            map_method, describeWorkstationType(c::workstationTypeOf(ws_type, "inquiry")), "inquiry");
        c::require(map_st, "inquiry");
        map_st->int_data = n;
    });
}

}  // extern "C"
