// PHIGS PLUS representations: light sources and depth cueing on a workstation, and their
// inquiries (SET: the values given, colours in the model or as the index given; REALIZED: what
// the workstation draws, colours as clamped RGB, as phigs/view/RealizedLighting.h rules); the predefined
// representations and the PHIGS PLUS facilities of the workstation types.

#include "Binding.h"
#include "Conversions.h"
#include "Inquiry.h"
#include "PlusBundleAccess.h"
#include "WorkstationAccess.h"
#include "phigs.h"

#include <climits>

using phigs::c::Binding;

namespace {

using namespace phigs;

/// A light or depth cue colour as given: an index, or direct in a colour model (2202 for any
/// other type; the workstation checks the index).
Colour given(const Pgcolr& c, const char* name) {
    if (c.type == PINDIRECT) return Colour::indexed(c.val.ind);
    if (!isColourModel(c.type)) throw Error(PE_ENUM_TYPE_INVAL, name, "colour type");
    return Colour::inModel(static_cast<ColourModel>(c.type),
                           {c.val.general.x, c.val.general.y, c.val.general.z});
}

Pgcolr gcolr(const glm::vec3& c) {
    Pgcolr g{};
    g.type = PMODEL_RGB;
    g.val.general = {c.x, c.y, c.z};
    return g;
}

/// The colour of a light source bundle (any type; `B` a bundle, const or not).
template <class B>
auto& colourOf(B& b) {
    switch (b.type) {
        case PLIGHT_AMBIENT:
            return b.rec.ambient.colr;
        case PLIGHT_DIRECTIONAL:
            return b.rec.directional.colr;
        case PLIGHT_POSITIONAL:
            return b.rec.positional.colr;
        default:
            return b.rec.spot.colr;
    }
}

/// The light of a bundle; its colour comes apart (given()).
Light light(const Plight_src_bundle& b, const char* name) {
    Light l;
    if (b.type < PLIGHT_AMBIENT || b.type > PLIGHT_SPOT)
        throw Error(PE_ENUM_TYPE_INVAL, name, "light source type");
    l.type = static_cast<LightType>(b.type);
    auto vec = [](const Pvec3& v) { return glm::dvec3(v.delta_x, v.delta_y, v.delta_z); };
    auto point = [](const Ppoint3& p) { return glm::dvec3(p.x, p.y, p.z); };
    switch (b.type) {
        case PLIGHT_AMBIENT:
            break;
        case PLIGHT_DIRECTIONAL:
            l.direction = vec(b.rec.directional.dir);
            break;
        case PLIGHT_POSITIONAL:
            l.position = point(b.rec.positional.pos);
            l.attenuation = {b.rec.positional.coef[0], b.rec.positional.coef[1]};
            break;
        default:
            l.position = point(b.rec.spot.pos);
            l.direction = vec(b.rec.spot.dir);
            l.concentration = b.rec.spot.exp;
            l.attenuation = {b.rec.spot.coef[0], b.rec.spot.coef[1]};
            l.spreadAngle = b.rec.spot.angle;
            break;
    }
    return l;
}

Plight_src_bundle bundle(const Light& l) {
    Plight_src_bundle b{};
    b.type = static_cast<Pint>(l.type);
    auto vec = [](const glm::dvec3& v) {
        return Pvec3{static_cast<Pfloat>(v.x), static_cast<Pfloat>(v.y), static_cast<Pfloat>(v.z)};
    };
    auto point = [](const glm::dvec3& p) {
        return Ppoint3{static_cast<Pfloat>(p.x), static_cast<Pfloat>(p.y), static_cast<Pfloat>(p.z)};
    };
    switch (l.type) {
        case LightType::Ambient:
            b.rec.ambient.colr = gcolr(l.colour);
            break;
        case LightType::Directional:
            b.rec.directional = {gcolr(l.colour), vec(l.direction)};
            break;
        case LightType::Positional:
            b.rec.positional = {gcolr(l.colour), point(l.position), {l.attenuation.x, l.attenuation.y}};
            break;
        case LightType::Spot:
            b.rec.spot = {gcolr(l.colour),
                          point(l.position),
                          vec(l.direction),
                          l.concentration,
                          {l.attenuation.x, l.attenuation.y},
                          l.spreadAngle};
            break;
    }
    return b;
}

Pdcue_bundle bundle(const DepthCue& d) {
    Pdcue_bundle b{};
    b.mode = d.enabled ? PALLOWED : PSUPPRESSED;
    b.ref_planes[0] = static_cast<Pfloat>(d.frontPlane), b.ref_planes[1] = static_cast<Pfloat>(d.backPlane);
    b.scaling[0] = d.frontScale, b.scaling[1] = d.backScale;
    b.colr = gcolr(d.colour);
    return b;
}

Workstation& inquired(Phigs& p, Pint id) {
    if (!p.anyWorkstationOpen()) throw Error(errors::NoWorkstationOpen, "inquiry");
    Workstation* ws = p.findWorkstation(id);
    if (!ws) throw Error(errors::WorkstationNotOpen, "inquiry", "workstation " + std::to_string(id));
    return *ws;
}

void checkInquiryType(int type) {
    if (type != PINQ_SET && type != PINQ_REALIZED) throw Error(PE_ENUM_TYPE_INVAL, "inquiry", "inquiry type");
}

/// The description of a generic or specific type (52 for any other).
WorkstationDescription description(Pint type) {
    return c::describedType(type, "inquiry");
}

template <class Map>
std::vector<int> keys(const Map& map) {
    std::vector<int> out;
    for (const auto& [index, value] : map) out.push_back(index);
    return out;
}

}  // namespace

extern "C" {

void pset_light_src_rep(Pint ws_id, Pint index, const Plight_src_bundle* rep) {
    Binding::instance().call(Pfn_set_light_src_rep, [&](Phigs& p) {
        Workstation& ws = p.workstation(ws_id);
        const char* name = "SET LIGHT SOURCE REPRESENTATION";
        c::require(rep, name);
        const Light l = light(*rep, name);
        ws.setLightSourceRepresentation(index, l, given(colourOf(*rep), name));
    });
}

void pinq_light_src_rep(Pint ws_id, Pint index, Pinq_type type, Pint* err, Plight_src_bundle* rep) {
    if (!c::somewhereToAnswer(err, rep)) return;
    const int t = c::raw(type);
    c::inquire(err, [&](Phigs& p) {
        const Workstation& ws = inquired(p, ws_id);
        checkInquiryType(t);
        if (index < 1) throw Error(errors::BundleIndexBelowOne, "inquiry");
        const auto found = ws.tables().lights.find(index);
        if (found == ws.tables().lights.end()) throw Error(errors::RepresentationNotDefined, "inquiry");
        c::require(rep, "inquiry");
        if (t == PINQ_REALIZED) {
            *rep = bundle(*ws.tables().drawnLight(index));
        } else {
            *rep = bundle(found->second);
            colourOf(*rep) = c::generalColour(ws.tables().givenLightColour(index));
        }
    });
}

void pinq_list_light_src_inds(Pint ws_id, Pint appl, Pint start, Pint* err, Pint_list* inds, Pint* total) {
    if (!c::somewhereToAnswer(err, inds, total)) return;
    c::inquire(err, [&](Phigs& p) {
        c::answerList(keys(inquired(p, ws_id).tables().lights), appl, start, inds, total);
    });
}

void pset_dcue_rep(Pint ws_id, Pint index, const Pdcue_bundle* rep) {
    Binding::instance().call(Pfn_set_dcue_rep, [&](Phigs& p) {
        Workstation& ws = p.workstation(ws_id);
        const char* name = "SET DEPTH CUE REPRESENTATION";
        c::require(rep, name);
        const int mode = c::raw(rep->mode);
        if (mode != PSUPPRESSED && mode != PALLOWED) throw Error(PE_ENUM_TYPE_INVAL, name, "depth cue mode");
        DepthCue cue;
        cue.enabled = mode == PALLOWED;
        cue.frontPlane = rep->ref_planes[0], cue.backPlane = rep->ref_planes[1];
        cue.frontScale = rep->scaling[0], cue.backScale = rep->scaling[1];
        ws.setDepthCueRepresentation(index, cue, given(rep->colr, name));
    });
}

void pinq_dcue_rep(Pint ws_id, Pint index, Pinq_type type, Pint* err, Pdcue_bundle* rep) {
    if (!c::somewhereToAnswer(err, rep)) return;
    const int t = c::raw(type);
    c::inquire(err, [&](Phigs& p) {
        const Workstation& ws = inquired(p, ws_id);
        checkInquiryType(t);
        if (index < 0) throw Error(errors::BundleIndexBelowOne, "inquiry");
        const auto found = ws.tables().depthCues.find(index);
        if (found == ws.tables().depthCues.end()) throw Error(errors::RepresentationNotDefined, "inquiry");
        c::require(rep, "inquiry");
        if (t == PINQ_REALIZED) {
            *rep = bundle(*ws.tables().drawnDepthCue(index));
        } else {
            *rep = bundle(found->second);
            rep->colr = c::generalColour(ws.tables().givenDepthCueColour(index));
        }
    });
}

void pinq_list_dcue_inds(Pint ws_id, Pint appl, Pint start, Pint* err, Pint_list* inds, Pint* total) {
    if (!c::somewhereToAnswer(err, inds, total)) return;
    c::inquire(err, [&](Phigs& p) {
        c::answerList(keys(inquired(p, ws_id).tables().depthCues), appl, start, inds, total);
    });
}

// Every type starts with the same predefined tables: light 1 (white ambient), depth cue 0
// (suppressed).
void pinq_pred_light_src_rep(Pint ws_type, Pint index, Pint* err, Plight_src_bundle* rep) {
    if (!c::somewhereToAnswer(err, rep)) return;
    c::inquire(err, [&](Phigs&) {
        description(ws_type);
        if (index < 1) throw Error(errors::BundleIndexBelowOne, "inquiry");
        const WorkstationTables initial;
        const auto found = initial.lights.find(index);
        if (found == initial.lights.end()) throw Error(errors::RepresentationNotPredefined, "inquiry");
        c::require(rep, "inquiry");
        *rep = bundle(found->second);
    });
}

void pinq_pred_dcue_rep(Pint ws_type, Pint index, Pint* err, Pdcue_bundle* rep) {
    if (!c::somewhereToAnswer(err, rep)) return;
    c::inquire(err, [&](Phigs&) {
        description(ws_type);
        if (index < 0) throw Error(errors::BundleIndexBelowOne, "inquiry");
        const WorkstationTables initial;
        const auto found = initial.depthCues.find(index);
        if (found == initial.depthCues.end()) throw Error(errors::RepresentationNotPredefined, "inquiry");
        c::require(rep, "inquiry");
        *rep = bundle(found->second);
    });
}

void pinq_light_src_facs(Pint ws_type, Pint appl, Pint start, Pint* err, Plight_src_facs* facs, Pint* total) {
    if (!c::somewhereToAnswer(err, facs, total)) return;
    c::inquire(err, [&](Phigs&) {
        const WorkstationDescription d = description(ws_type);
        c::require(facs, "inquiry");
        c::answerList({PLIGHT_AMBIENT, PLIGHT_DIRECTIONAL, PLIGHT_POSITIONAL, PLIGHT_SPOT}, appl, start,
                      &facs->types, total);
        facs->max = d.lightTableSize;
        facs->num_pred_inds = static_cast<Pint>(WorkstationTables{}.lights.size());
    });
}

void pinq_dcue_facs(Pint ws_type, Pint* err, Pint* num_pred_inds) {
    if (!c::somewhereToAnswer(err, num_pred_inds)) return;
    c::inquire(err, [&](Phigs&) {
        description(ws_type);
        c::require(num_pred_inds, "inquiry");
        *num_pred_inds = static_cast<Pint>(WorkstationTables{}.depthCues.size());
    });
}

void pinq_rendering_colr_model_facs(Pint ws_type, Pint appl, Pint start, Pint* err, Pint_list* models,
                                    Pint* total) {
    if (!c::somewhereToAnswer(err, models, total)) return;
    c::inquire(err, [&](Phigs&) {
        description(ws_type);
        // Every type draws in each (0, workstation dependent, is drawn as RGB).
        c::answerList({PRCM_RGB, PRCM_CIE, PRCM_HSV, PRCM_HLS}, appl, start, models, total);
    });
}

// The PHIGS PLUS binding puts the total before the list here.
void pinq_direct_colr_model_facs(Pint ws_type, Pint appl, Pint start, Pint* err, Pint* total,
                                 Pint_list* models) {
    if (!c::somewhereToAnswer(err, total, models)) return;
    c::inquire(err,
               [&](Phigs&) { c::answerList(description(ws_type).colourModels, appl, start, models, total); });
}

void pinq_curv_surf_facs(Pint ws_type, Pint cat_len, Pint cat_st, Pint sat_len, Pint sat_st, Pint tcat_len,
                         Pint tcat_st, Pint psc_len, Pint psc_st, Pint* err, Pcurvsurf_facs* facs,
                         Pint* tot_cat_len, Pint* tot_sat_len, Pint* tot_tcat_len, Pint* tot_psc_len) {
    if (!c::somewhereToAnswer(err, facs, tot_cat_len, tot_sat_len, tot_tcat_len, tot_psc_len)) return;
    c::inquire(err, [&](Phigs&) {
        description(ws_type);
        c::require(facs, "inquiry");
        c::answerList({PCURV_WS_DEP, PCURV_CONST_PARAM_SUBDIV_BETWEEN_KNOTS, PCURV_CHORDAL_DEVIATION_WC},
                      cat_len, cat_st, &facs->cat_types, tot_cat_len);
        c::answerList({PSURF_WS_DEP, PSURF_CONST_PARAM_SUBDIV_BETWEEN_KNOTS, PSURF_CHORDAL_DEVIATION_WC},
                      sat_len, sat_st, &facs->sat_types, tot_sat_len);
        c::answerList({PCURV_WS_DEP}, tcat_len, tcat_st, &facs->tcat_types, tot_tcat_len);
        c::answerList(
            {PSC_NONE, PSC_WS_DEP, PSC_ISOPARAMETRIC_CURVES, PSC_LEVEL_CURVES_MC, PSC_LEVEL_CURVES_WC},
            psc_len, psc_st, &facs->psc_types, tot_psc_len);
        facs->max_bsp_order = INT_MAX;  // the geometry kernel sets no limit
        facs->max_tc_order = INT_MAX;
    });
}

}  // extern "C"
