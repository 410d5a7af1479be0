#include "PlusBundleAccess.h"

#include "Conversions.h"
#include "phigs/view/WorkstationTables.h"
#include "phigs/ws/WorkstationErrors.h"

#include <algorithm>
#include <string>

namespace phigs::c {
namespace {

Pfloat real(double v) {
    return static_cast<Pfloat>(v);
}

/// An interior style argument: PSTYLE_HOLLOW .. PSTYLE_EMPTY (2202 otherwise).
InteriorStyle interiorStyle(const Pint_style& style, const char* function) {
    const int s = raw(style);
    if (s < PSTYLE_HOLLOW || s > PSTYLE_EMPTY)
        throw Error(PE_ENUM_TYPE_INVAL, function, "interior style " + std::to_string(s));
    return static_cast<InteriorStyle>(s);
}

AreaPropertiesAttribute coreProperties(ElementType type, const Prefl_props& p, const char* function) {
    AreaPropertiesAttribute a{type};
    a.ambient = p.ambient_coef, a.diffuse = p.diffuse_coef, a.specular = p.specular_coef;
    a.specularColour = coreColour(p.specular_colr, function);
    a.specularExponent = p.specular_exp, a.transparency = p.transpar_coef;
    return a;
}

Prefl_props plusProperties(const AreaPropertiesAttribute& a) {
    return {real(a.ambient),          real(a.diffuse),     real(a.specular), generalColour(a.specularColour),
            real(a.specularExponent), real(a.transparency)};
}

}  // namespace

Colour coreColour(const Pgcolr& colour, const char* function) {
    if (colour.type == PINDIRECT) return Colour::indexed(colour.val.ind);
    if (!isColourModel(colour.type))
        throw Error(errors::ColourModelNotAvailable, function, "colour type " + std::to_string(colour.type));
    return Colour::inModel(static_cast<ColourModel>(colour.type),
                           {colour.val.general.x, colour.val.general.y, colour.val.general.z});
}

Pgcolr generalColour(const Colour& colour) {
    Pgcolr g{};
    if (colour.direct) {
        g.type = static_cast<Pint>(colour.model);
        g.val.general.x = real(colour.rgb.x), g.val.general.y = real(colour.rgb.y),
        g.val.general.z = real(colour.rgb.z);
    } else {
        g.type = PINDIRECT;
        g.val.ind = colour.index;
    }
    return g;
}

PolylineBundle coreBundle(const Pline_bundle_plus& b, const char* function) {
    PolylineBundle r{static_cast<LineType>(b.type), b.width, coreColour(b.colr, function)};
    r.shading = static_cast<ShadingMethod>(b.shad_meth);
    r.approximation = {ElementType::CurveApproximationCriteria, b.approx_type, b.approx_val, b.approx_val};
    return r;
}

PolymarkerBundle coreBundle(const Pmarker_bundle_plus& b, const char* function) {
    return {static_cast<MarkerType>(b.type), b.size, coreColour(b.colr, function)};
}

TextBundle coreBundle(const Ptext_bundle_plus& b, const char* function) {
    const int precision = raw(b.prec);
    if (precision < PPREC_STRING || precision > PPREC_STROKE)
        throw Error(PE_ENUM_TYPE_INVAL, function, "text precision " + std::to_string(precision));
    return {b.font, precision, b.char_expan, b.char_space, coreColour(b.colr, function)};
}

InteriorBundle coreBundle(const Pint_bundle_plus& b, const char* function) {
    InteriorBundle r;
    r.style = interiorStyle(b.style, function);
    r.backStyle = interiorStyle(b.back_style, function);
    r.styleIndex = b.style_ind, r.backStyleIndex = b.back_style_ind;
    r.colour = coreColour(b.colr, function);
    r.backColour = coreColour(b.back_colr, function);
    r.shading = static_cast<ShadingMethod>(b.shad_meth);
    r.backShading = static_cast<ShadingMethod>(b.back_shad_meth);
    r.reflectance = static_cast<ReflectanceModel>(b.refl_eqn);
    r.backReflectance = static_cast<ReflectanceModel>(b.back_refl_eqn);
    r.properties = coreProperties(ElementType::AreaProperties, b.refl_props, function);
    r.backProperties = coreProperties(ElementType::BackAreaProperties, b.back_refl_props, function);
    r.approximation = {ElementType::SurfaceApproximationCriteria, b.approx_type, b.approx_val[0],
                       b.approx_val[1]};
    return r;
}

EdgeBundle coreBundle(const Pedge_bundle_plus& b, const char* function) {
    const int flag = raw(b.flag);
    if (flag != PEDGE_OFF && flag != PEDGE_ON) throw Error(PE_ENUM_TYPE_INVAL, function, "edge flag");
    return {flag == PEDGE_ON, static_cast<LineType>(b.type), b.width, coreColour(b.colr, function)};
}

PatternRepresentation corePattern(const Ppat_rep_plus& p, const char* function) {
    if (p.type != PINDIRECT && !isColourModel(p.type))
        throw Error(errors::ColourModelNotAvailable, function, "colour type " + std::to_string(p.type));
    PatternRepresentation r{p.dims.size_x, p.dims.size_y, {}};
    if (p.dims.size_x < 1 || p.dims.size_y < 1) return r;  // error 116 in the table, after 112
    const std::size_t n = cellCount(p.dims.size_x, p.dims.size_y, function);
    require(p.colr_array, function);
    r.colours.reserve(n);
    for (std::size_t i = 0; i < n; ++i) {
        const Pcoval& c = p.colr_array[i];
        r.colours.push_back(p.type == PINDIRECT
                                ? Colour::indexed(c.ind)
                                : Colour::inModel(static_cast<ColourModel>(p.type),
                                                  {c.direct.rgb.red, c.direct.rgb.green, c.direct.rgb.blue}));
    }
    return r;
}

Pline_bundle_plus plusBundle(const PolylineBundle& b) {
    return {static_cast<Pint>(b.type), real(b.width),
            generalColour(b.colour),   static_cast<Pint>(b.shading),
            b.approximation.criteria,  real(b.approximation.valueU)};
}

Pmarker_bundle_plus plusBundle(const PolymarkerBundle& b) {
    return {static_cast<Pint>(b.type), real(b.scale), generalColour(b.colour)};
}

Ptext_bundle_plus plusBundle(const TextBundle& b) {
    return {b.font, static_cast<Ptext_prec>(b.precision), real(b.expansion), real(b.spacing),
            generalColour(b.colour)};
}

Pint_bundle_plus plusBundle(const InteriorBundle& b) {
    Pint_bundle_plus r{};
    r.style = static_cast<Pint_style>(b.style), r.style_ind = b.styleIndex;
    r.colr = generalColour(b.colour);
    r.refl_eqn = static_cast<Pint>(b.reflectance), r.shad_meth = static_cast<Pint>(b.shading);
    r.refl_props = plusProperties(b.properties);
    r.back_style = static_cast<Pint_style>(b.backStyle), r.back_style_ind = b.backStyleIndex;
    r.back_colr = generalColour(b.backColour);
    r.back_refl_eqn = static_cast<Pint>(b.backReflectance),
    r.back_shad_meth = static_cast<Pint>(b.backShading);
    r.back_refl_props = plusProperties(b.backProperties);
    r.approx_type = b.approximation.criteria;
    r.approx_val[0] = real(b.approximation.valueU), r.approx_val[1] = real(b.approximation.valueV);
    return r;
}

Pedge_bundle_plus plusBundle(const EdgeBundle& b) {
    return {b.visible ? PEDGE_ON : PEDGE_OFF, static_cast<Pint>(b.type), real(b.width),
            generalColour(b.colour)};
}

Ppat_rep_plus* answerPatternPlus(const PatternRepresentation& p, const ColourTable& colours, Phigs_store& s) {
    s.clear();
    const bool direct =
        std::any_of(p.colours.begin(), p.colours.end(), [](const Colour& c) { return c.direct; });
    // Cells all direct in one model answer as given; a mixed pattern as the RGB drawn.
    const ColourModel model = direct ? p.colours.front().model : ColourModel::Rgb;
    const bool asGiven = direct && std::all_of(p.colours.begin(), p.colours.end(),
                                               [&](const Colour& c) { return c.direct && c.model == model; });
    for (const Colour& c : p.colours) {
        Pcoval v{};
        if (direct) {
            const glm::dvec3 rgb = asGiven ? c.rgb : colours.resolve(c);
            v.direct.rgb.red = real(rgb.x), v.direct.rgb.green = real(rgb.y), v.direct.rgb.blue = real(rgb.z);
        } else {
            v.ind = c.index;
        }
        s.covals.push_back(v);
    }
    s.patternPlus = {{p.columns, p.rows},
                     !direct   ? PINDIRECT
                     : asGiven ? static_cast<Pint>(model)
                               : PMODEL_RGB,
                     s.covals.data()};
    return &s.patternPlus;
}

}  // namespace phigs::c
