#pragma once

// The workstation and workstation type a function of the workstation-state, representation and
// description-table groups works on, and the conversions they share.

#include "Binding.h"
#include "Conversions.h"
#include "StoreBuffer.h"
#include "phigs.h"
#include "phigs/ws/PatternTable.h"

#include <glm/vec3.hpp>

namespace phigs::c {

/// The core type of a generic PWST_* number or of an open workstation's specific type: error 52
/// for another number.
WorkstationType workstationTypeOf(Pint type, const char* function);

/// The description table of `type`: a generic type's as built, a specific type's as its open
/// workstation has it now (a resized window's display size); error 52 for another number.
WorkstationDescription describedType(Pint type, const char* function);

/// The open workstation an inquiry asks about: errors 3 (none open), 54 (this one not open).
Workstation& inquiredWorkstation(Phigs& p, Pint id);

/// Runs function `function` on the open workstation `id` (errors 3, 54 first).
template <class Body>
void onOpenWorkstation(int function, Pint id, Body&& body) {
    Binding::instance().call(function, [&](Phigs& p) { body(p.workstation(id)); });
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
/// A pattern answered in `store` (its colour indices in store.ints).
Ppat_rep* answerPattern(const PatternRepresentation& p, Phigs_store& store);
Pcolr_rep cColour(const glm::dvec3& rgb);

}  // namespace phigs::c
