#include "WorkstationAccess.h"

#include <string>

namespace phigs::c {

namespace {

Workstation* specificWorkstation(Pint type) {
    return type >= PWST_SPECIFIC_BASE ? Binding::instance().workstationOfSpecificType(type) : nullptr;
}

}  // namespace

WorkstationType workstationTypeOf(Pint type, const char* function) {
    if (Workstation* ws = specificWorkstation(type)) return ws->description().type;
    const WorkstationType core = static_cast<WorkstationType>(type - PWST_OFFSCREEN);
    if (type < PWST_OFFSCREEN || type >= PWST_SPECIFIC_BASE || !isWorkstationType(core))
        throw Error(errors::BadWorkstationType, function, "workstation type " + std::to_string(type));
    return core;
}

WorkstationDescription describedType(Pint type, const char* function) {
    if (Workstation* ws = specificWorkstation(type)) {
        ws->followDrawable();
        return ws->description();
    }
    return describeWorkstationType(workstationTypeOf(type, function));
}

Workstation& inquiredWorkstation(Phigs& p, Pint id) {
    if (!p.anyWorkstationOpen()) throw Error(errors::NoWorkstationOpen, "inquiry");
    Workstation* ws = p.findWorkstation(id);
    if (!ws) throw Error(errors::WorkstationNotOpen, "inquiry", "workstation " + std::to_string(id));
    return *ws;
}

bool realizedWanted(const Pinq_type& type) {
    const int t = raw(type);
    if (t != PINQ_SET && t != PINQ_REALIZED)
        throw Error(PE_ENUM_TYPE_INVAL, "inquiry", "type of returned value");
    return t == PINQ_REALIZED;
}

PatternRepresentation inquiredPattern(Phigs& p, Pint ws_id, Pint index, const Pinq_type& type) {
    const Workstation& ws = inquiredWorkstation(p, ws_id);
    if (index < 1) throw Error(errors::PatternIndexBelowOne, "inquiry", "index " + std::to_string(index));
    const bool realize = realizedWanted(type);
    const PatternRepresentation* pattern = ws.patterns().find(index);
    if (!pattern && realize) pattern = ws.patterns().find(1);
    if (!pattern)
        throw Error(errors::RepresentationNotDefined, "inquiry", "pattern " + std::to_string(index));
    return realize ? realized(*pattern, ws.tables().colours) : *pattern;
}

const PredefinedRepresentations& predefinedOf(Pint type) {
    return predefinedRepresentations(workstationTypeOf(type, "inquiry"));
}

Plimit3 limit3(const glm::dvec3& min, const glm::dvec3& max) {
    return {static_cast<Pfloat>(min.x), static_cast<Pfloat>(max.x), static_cast<Pfloat>(min.y),
            static_cast<Pfloat>(max.y), static_cast<Pfloat>(min.z), static_cast<Pfloat>(max.z)};
}

Plimit limit2(const glm::dvec3& min, const glm::dvec3& max) {
    return {static_cast<Pfloat>(min.x), static_cast<Pfloat>(max.x), static_cast<Pfloat>(min.y),
            static_cast<Pfloat>(max.y)};
}

Pview_rep3 viewRep3(const ViewRepresentation& v) {
    Pview_rep3 r{};
    fromGlm(v.orientation, r.ori_matrix);
    fromGlm(v.mapping, r.map_matrix);
    r.clip_limit = limit3(v.clipMin, v.clipMax);
    r.xy_clip = v.clipXY ? PIND_CLIP : PIND_NO_CLIP;
    r.back_clip = v.clipBack ? PIND_CLIP : PIND_NO_CLIP;
    r.front_clip = v.clipFront ? PIND_CLIP : PIND_NO_CLIP;
    return r;
}

Pint colourIndexOf(const Colour& colour) {
    // A direct colour has no index: error 134 (the core's bundles hold PHIGS PLUS colours).
    if (colour.direct)
        throw Error(errors::NotIndirectColour, "inquiry", "the representation's colour is direct");
    return colour.index;
}

PolylineBundle coreBundle(const Pline_bundle& b) {
    return {static_cast<LineType>(b.type), b.width, Colour::indexed(b.colr_ind)};
}

PolymarkerBundle coreBundle(const Pmarker_bundle& b) {
    return {static_cast<MarkerType>(b.type), b.size, Colour::indexed(b.colr_ind)};
}

TextBundle coreBundle(const Ptext_bundle& b, const char* function) {
    const int precision = raw(b.prec);
    if (precision < PPREC_STRING || precision > PPREC_STROKE) throw Error(PE_ENUM_TYPE_INVAL, function);
    return {b.font, precision, b.char_expan, b.char_space, Colour::indexed(b.colr_ind)};
}

InteriorBundle coreBundle(const Pint_bundle& b, const char* function) {
    const int style = raw(b.style);
    if (style < PSTYLE_HOLLOW || style > PSTYLE_EMPTY) throw Error(PE_ENUM_TYPE_INVAL, function);
    InteriorBundle r;
    r.style = r.backStyle = static_cast<InteriorStyle>(style);
    r.styleIndex = r.backStyleIndex = b.style_ind;
    r.colour = r.backColour = Colour::indexed(b.colr_ind);
    return r;
}

EdgeBundle coreBundle(const Pedge_bundle& b, const char* function) {
    const int flag = raw(b.flag);
    if (flag != PEDGE_OFF && flag != PEDGE_ON) throw Error(PE_ENUM_TYPE_INVAL, function);
    return {flag == PEDGE_ON, static_cast<LineType>(b.type), b.width, Colour::indexed(b.colr_ind)};
}

PatternRepresentation corePattern(const Ppat_rep& p, const char* function) {
    PatternRepresentation r{p.dims.size_x, p.dims.size_y, {}};
    if (p.dims.size_x < 1 || p.dims.size_y < 1) return r;  // error 116 in the table, after 112
    const std::size_t n = cellCount(p.dims.size_x, p.dims.size_y, function);
    require(p.colr_array, function);
    r.colours.clear();
    for (std::size_t i = 0; i < n; ++i) r.colours.push_back(Colour::indexed(p.colr_array[i]));
    return r;
}

Pline_bundle cBundle(const PolylineBundle& b) {
    return {static_cast<Pint>(b.type), static_cast<Pfloat>(b.width), colourIndexOf(b.colour)};
}

Pmarker_bundle cBundle(const PolymarkerBundle& b) {
    return {static_cast<Pint>(b.type), static_cast<Pfloat>(b.scale), colourIndexOf(b.colour)};
}

Ptext_bundle cBundle(const TextBundle& b) {
    return {b.font, static_cast<Ptext_prec>(b.precision), static_cast<Pfloat>(b.expansion),
            static_cast<Pfloat>(b.spacing), colourIndexOf(b.colour)};
}

Pint_bundle cBundle(const InteriorBundle& b) {
    return {static_cast<Pint_style>(b.style), b.styleIndex, colourIndexOf(b.colour)};
}

Pedge_bundle cBundle(const EdgeBundle& b) {
    return {b.visible ? PEDGE_ON : PEDGE_OFF, static_cast<Pint>(b.type), static_cast<Pfloat>(b.width),
            colourIndexOf(b.colour)};
}

Ppat_rep* answerPattern(const PatternRepresentation& p, Phigs_store& s) {
    s.clear();
    for (const Colour& c : p.colours) s.ints.push_back(colourIndexOf(c));
    s.pattern = {{p.columns, p.rows}, s.ints.data()};
    return &s.pattern;
}

Pcolr_rep cColour(const glm::dvec3& rgb) {
    return cColour(rgb, PMODEL_RGB);
}

Pcolr_rep cColour(const glm::dvec3& v, int model) {
    Pcolr_rep r{};
    const Pfloat x = static_cast<Pfloat>(v.x), y = static_cast<Pfloat>(v.y), z = static_cast<Pfloat>(v.z);
    switch (model) {
        case PMODEL_CIELUV:
            r.cieluv = {x, y, z};
            break;
        case PMODEL_HSV:
            r.hsv = {x, y, z};
            break;
        case PMODEL_HLS:
            r.hls = {x, y, z};
            break;
        default:
            r.rgb = {x, y, z};
            break;
    }
    return r;
}

glm::dvec3 colourComponents(const Pcolr_rep& r, int model) {
    switch (model) {
        case PMODEL_CIELUV:
            return {r.cieluv.cieluv_x, r.cieluv.cieluv_y, r.cieluv.cieluv_y_lum};
        case PMODEL_HSV:
            return {r.hsv.hue, r.hsv.satur, r.hsv.value};
        case PMODEL_HLS:
            return {r.hls.hue, r.hls.lightness, r.hls.satur};
        default:
            return {r.rgb.red, r.rgb.green, r.rgb.blue};
    }
}

}  // namespace phigs::c
