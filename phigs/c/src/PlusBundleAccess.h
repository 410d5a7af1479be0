#pragma once

// The PHIGS PLUS bundles and patterns between phigs.h (Pline_bundle_plus ... Ppat_rep_plus) and
// the core's tables, which hold general colours: one entry serves the plain and the PLUS views.

#include "Binding.h"
#include "StoreBuffer.h"
#include "phigs.h"
#include "phigs/ws/PatternTable.h"

namespace phigs::c {

/// A general colour as the core holds it: PINDIRECT or PMODEL_RGB (110 for any other type).
Colour coreColour(const Pgcolr& colour, const char* function);
/// The core's colour as a general colour (PINDIRECT with its index, or PMODEL_RGB).
Pgcolr generalColour(const Colour& colour);

/// PHIGS PLUS bundles to the core's; an enumeration outside its type is error 2202.
PolylineBundle coreBundle(const Pline_bundle_plus& b, const char* function);
PolymarkerBundle coreBundle(const Pmarker_bundle_plus& b, const char* function);
TextBundle coreBundle(const Ptext_bundle_plus& b, const char* function);
InteriorBundle coreBundle(const Pint_bundle_plus& b, const char* function);
EdgeBundle coreBundle(const Pedge_bundle_plus& b, const char* function);
/// A pattern of general colours (110 for a colour type other than PINDIRECT and PMODEL_RGB; a
/// dimension below 1 gives an empty pattern, which the table refuses with 116).
PatternRepresentation corePattern(const Ppat_rep_plus& p, const char* function);

/// The core's bundles as phigs.h's PHIGS PLUS ones.
Pline_bundle_plus plusBundle(const PolylineBundle& b);
Pmarker_bundle_plus plusBundle(const PolymarkerBundle& b);
Ptext_bundle_plus plusBundle(const TextBundle& b);
Pint_bundle_plus plusBundle(const InteriorBundle& b);
Pedge_bundle_plus plusBundle(const EdgeBundle& b);
/// A pattern answered in `store`, its colours in store.covals: PINDIRECT when every colour is an
/// index, the model and components as given when every colour is direct in one model, otherwise
/// PMODEL_RGB with every colour as drawn (indexed ones resolved through `colours`).
Ppat_rep_plus* answerPatternPlus(const PatternRepresentation& p, const ColourTable& colours,
                                 Phigs_store& store);

}  // namespace phigs::c
