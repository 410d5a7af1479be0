// The PHIGS PLUS entries of the workstation description tables: polyline and interior
// facilities with shading methods and reflectance equations, the table lengths with the depth
// cue, light source and colour mapping tables, and their dynamics.

#include "Inquiry.h"
#include "WorkstationAccess.h"
#include "phigs.h"

#include <algorithm>
#include <numeric>

using namespace phigs;
using phigs::c::inquire;

extern "C" {

void pinq_line_facs_plus(Pint ws_type, Pint lt_length, Pint lt_start, Pint sm_length, Pint sm_start,
                         Pint* err, Pint* tot_lt_length, Pint* tot_sm_length, Pline_facs_plus* facs) {
    if (!c::somewhereToAnswer(err, tot_lt_length, tot_sm_length, facs)) return;
    inquire(err, [&](Phigs&) {
        const WorkstationDescription d = c::describedType(ws_type, "inquiry");
        c::answerList(c::oneTo(d.primitives.lineTypes), lt_length, lt_start, facs ? &facs->types : nullptr,
                      tot_lt_length);
        c::answerList(d.polylineShadingMethods, sm_length, sm_start, facs ? &facs->shads : nullptr,
                      tot_sm_length);
        if (!facs) return;
        facs->num_widths = 0;
        facs->nom_width = static_cast<Pfloat>(d.primitives.nominalLineWidth);
        facs->min_width = static_cast<Pfloat>(d.primitives.minLineWidth);
        facs->max_width = static_cast<Pfloat>(d.primitives.maxLineWidth);
        facs->num_pred_inds = c::countOf(predefinedRepresentations(d.type).polylines.size());
    });
}

void pinq_int_facs_plus(Pint ws_type, Pint is_length, Pint is_start, Pint hs_length, Pint hs_start,
                        Pint re_length, Pint re_start, Pint sh_length, Pint sh_start, Pint* err,
                        Pint_facs_plus* facs, Pint* tot_is_length, Pint* tot_hs_length, Pint* tot_re_length,
                        Pint* tot_sh_length) {
    if (!c::somewhereToAnswer(err, facs, tot_is_length, tot_hs_length, tot_re_length, tot_sh_length)) return;
    inquire(err, [&](Phigs&) {
        const WorkstationDescription d = c::describedType(ws_type, "inquiry");
        std::vector<int> styles(static_cast<std::size_t>(std::max(d.interiorStyles, 0)));
        std::iota(styles.begin(), styles.end(), static_cast<int>(PSTYLE_HOLLOW));
        // The styles are Pint_style: answered through a list of ints, then copied.
        std::vector<Pint> room(
            static_cast<std::size_t>(std::clamp<Pint>(is_length, 0, c::countOf(styles.size()))));
        Pint_list positions{0, room.data()};
        c::answerList(styles, is_length, is_start, facs ? &positions : nullptr, tot_is_length);
        c::answerList(c::oneTo(d.primitives.hatchStyles), hs_length, hs_start,
                      facs ? &facs->hatch_styles : nullptr, tot_hs_length);
        c::answerList(d.reflectanceEquations, re_length, re_start, facs ? &facs->refl_eqns : nullptr,
                      tot_re_length);
        c::answerList(d.interiorShadingMethods, sh_length, sh_start, facs ? &facs->shad_meths : nullptr,
                      tot_sh_length);
        if (!facs) return;
        if (positions.num_ints > 0) c::require(facs->int_styles, "INQUIRE INTERIOR FACILITIES PLUS");
        for (Pint i = 0; i < positions.num_ints; ++i)
            facs->int_styles[i] = static_cast<Pint_style>(room[static_cast<std::size_t>(i)]);
        facs->num_int_styles = positions.num_ints;
        facs->num_pred_inds = c::countOf(predefinedRepresentations(d.type).interiors.size());
    });
}

void pinq_ws_st_table_plus(Pint ws_type, Pint* err, Pws_tables_plus* lengths) {
    if (!c::somewhereToAnswer(err, lengths)) return;
    inquire(err, [&](Phigs&) {
        const WorkstationDescription d = c::describedType(ws_type, "inquiry");
        if (!lengths) return;
        const Pint b = d.bundleTableSize;
        *lengths = {b,
                    b,
                    b,
                    b,
                    b,
                    d.patternTableSize,
                    d.colourTableSize,
                    d.viewTableSize,
                    d.depthCueTableSize,
                    d.lightTableSize,
                    d.colourMappingTableSize};
    });
}

void pinq_dyns_ws_attrs_plus(Pint ws_type, Pint* err, Pdyns_ws_attrs_plus* attrs) {
    if (!c::somewhereToAnswer(err, attrs)) return;
    inquire(err, [&](Phigs&) {
        const Pdyn_mod m = static_cast<Pdyn_mod>(c::describedType(ws_type, "inquiry").attributeDynamics);
        if (attrs) *attrs = {m, m, m};
    });
}

}  // extern "C"
