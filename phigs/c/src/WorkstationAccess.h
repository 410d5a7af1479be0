#pragma once

// The workstation and workstation type a function of the workstation-state, representation and
// description-table groups works on, and the conversions they share.

#include "Binding.h"
#include "Conversions.h"
#include "StoreBuffer.h"
#include "phigs.h"
#include "phigs/ws/PatternTable.h"
#include "phigs/ws/PredefinedRepresentations.h"
#include "phigs/ws/Realization.h"
#include "phigs/ws/WorkstationErrors.h"

#include <glm/vec3.hpp>

#include <algorithm>
#include <numeric>
#include <vector>

namespace phigs::c {

/// The core type of a generic PWST_* number or of an open workstation's specific type: error 52
/// for another number.
WorkstationType workstationTypeOf(Pint type, const char* function);

/// The description table of `type`: a generic type's as built, a specific type's as its open
/// workstation has it now (a resized window's display size); error 52 for another number.
WorkstationDescription describedType(Pint type, const char* function);

/// 1, 2, .., n (empty when n < 1): the indices of a table of n entries.
inline std::vector<int> oneTo(int n) {
    std::vector<int> v(static_cast<std::size_t>(std::max(n, 0)));
    std::iota(v.begin(), v.end(), 1);
    return v;
}

/// A count as the binding's Pint.
inline Pint countOf(std::size_t n) {
    return static_cast<Pint>(n);
}

/// The open workstation an inquiry asks about: errors 3 (none open), 54 (this one not open).
Workstation& inquiredWorkstation(Phigs& p, Pint id);

/// Runs function `function` on the open workstation `id` (errors 3, 54 first).
template <class Body>
void onOpenWorkstation(int function, Pint id, Body&& body) {
    Binding::instance().call(function, [&](Phigs& p) { body(p.workstation(id)); });
}

/// PINQ_SET or PINQ_REALIZED (2202 otherwise): whether the realized value is asked.
bool realizedWanted(const Pinq_type& type);

/// The bundle INQUIRE ... REPRESENTATION (PLUS) answers from table `table` of the open
/// workstation `ws_id`: 100 for an index below 1; the entry as set (101 when not defined) or as
/// realized (entry 1's for an undefined index).
template <class Bundle>
Bundle inquiredBundle(Phigs& p, Pint ws_id, Pint index, const Pinq_type& type,
                      BundleTable<Bundle> WorkstationTables::*table) {
    const Workstation& ws = inquiredWorkstation(p, ws_id);
    if (index < 1) throw Error(errors::BundleIndexBelowOne, "inquiry", "index " + std::to_string(index));
    const bool realize = realizedWanted(type);
    const BundleTable<Bundle>& t = ws.tables().*table;
    if (!t.defined(index) && !realize)
        throw Error(errors::RepresentationNotDefined, "inquiry", "index " + std::to_string(index));
    return realize ? realized(t.get(index), ws.description(), ws.tables().colours) : t.get(index);
}

/// The pattern INQUIRE PATTERN REPRESENTATION (PLUS) answers, likewise (112 below 1).
PatternRepresentation inquiredPattern(Phigs& p, Pint ws_id, Pint index, const Pinq_type& type);

/// The predefined representations of the PWST_* type `type` (52 for another number).
const PredefinedRepresentations& predefinedOf(Pint type);

/// Entry `index` of a predefined list numbered from `first`: error `below` under it, 102 past
/// the last.
template <class T>
const T& predefinedEntry(const std::vector<T>& entries, Pint index, int first, int below) {
    if (index < first) throw Error(below, "inquiry", "index " + std::to_string(index));
    if (index - first >= static_cast<Pint>(entries.size()))
        throw Error(errors::RepresentationNotPredefined, "inquiry", "index " + std::to_string(index));
    return entries[static_cast<std::size_t>(index - first)];
}

/// Limits between phigs.h and the core.
Plimit3 limit3(const glm::dvec3& min, const glm::dvec3& max);
Plimit limit2(const glm::dvec3& min, const glm::dvec3& max);

/// A view representation as phigs.h's.
Pview_rep3 viewRep3(const ViewRepresentation& v);

/// A colour of a bundle as the colour index phigs.h's bundles hold (134 when it is direct).
Pint colourIndexOf(const Colour& colour);

/// Bundles between phigs.h and the core; an enumeration outside its type is error 2202.
PolylineBundle coreBundle(const Pline_bundle& b);
PolymarkerBundle coreBundle(const Pmarker_bundle& b);
TextBundle coreBundle(const Ptext_bundle& b, const char* function);
InteriorBundle coreBundle(const Pint_bundle& b, const char* function);
EdgeBundle coreBundle(const Pedge_bundle& b, const char* function);
PatternRepresentation corePattern(const Ppat_rep& p, const char* function);
Pline_bundle cBundle(const PolylineBundle& b);
Pmarker_bundle cBundle(const PolymarkerBundle& b);
Ptext_bundle cBundle(const TextBundle& b);
Pint_bundle cBundle(const InteriorBundle& b);
Pedge_bundle cBundle(const EdgeBundle& b);
/// A pattern answered in `store` (its colour indices in store.ints; 134 when a colour is direct).
Ppat_rep* answerPattern(const PatternRepresentation& p, Phigs_store& store);
Pcolr_rep cColour(const glm::dvec3& rgb);
/// A colour representation of components `v` in colour model `model` (PMODEL_RGB .. PMODEL_HLS).
Pcolr_rep cColour(const glm::dvec3& v, int model);
/// The components of `r` in colour model `model` (the union member that model names).
glm::dvec3 colourComponents(const Pcolr_rep& r, int model);

}  // namespace phigs::c
