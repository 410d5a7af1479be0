// Output primitives and attribute elements: each checks the state (error 5), then its
// arguments, and inserts one element at the element pointer through the core.

#include "Binding.h"
#include "Conversions.h"
#include "phigs.h"
#include "phigs/store/Gdp.h"

#include <cstring>

using namespace phigs;
using phigs::c::Binding;

namespace {

template <class Make>
void insertElement(int fn, Make&& make) {
    Binding::instance().call(fn, [&](Phigs& p) {
        const std::string name = c::functionName(fn);
        StructureStore& store = p.store();
        if (!store.isStructureOpen()) raise(&p.errorLog(), errors::NotStructureOpen, name.c_str());
        store.insert(make(name.c_str()));
    });
}

void insertIndex(int fn, ElementType type, Pint value) {
    insertElement(fn, [&](const char*) -> Element { return IndexAttribute{type, value}; });
}

void insertReal(int fn, ElementType type, Pfloat value) {
    insertElement(fn, [&](const char*) -> Element { return RealAttribute{type, value}; });
}

void insertColourIndex(int fn, ElementType type, Pint index) {
    insertElement(fn, [&](const char*) -> Element { return ColourAttribute{type, Colour::indexed(index)}; });
}

void insertColour(int fn, ElementType type, const Pgcolr* colr) {
    insertElement(fn, [&](const char* name) -> Element {
        c::require(colr, name);
        if (colr->type == PINDIRECT) return ColourAttribute{type, Colour::indexed(colr->val.ind)};
        if (!isColourModel(colr->type)) throw Error(PE_ENUM_TYPE_INVAL, name, "colour type");
        const auto& d = colr->val.general;
        return ColourAttribute{type, Colour::inModel(static_cast<ColourModel>(colr->type), {d.x, d.y, d.z})};
    });
}

/// An enumerated value checked against its range (error 2202 outside).
void insertEnum(int fn, ElementType type, int v, int last) {
    insertElement(fn, [&](const char* name) -> Element {
        if (v < 0 || v > last) throw Error(PE_ENUM_TYPE_INVAL, name, "value " + std::to_string(v));
        return IndexAttribute{type, v};
    });
}

std::string text(const char* s, const char* name) {
    c::require(s, name);
    return s;
}

Element cellArray(const glm::dvec3& p, const glm::dvec3& q, const glm::dvec3& r, const Ppat_rep* rep,
                  bool twoD, const char* name) {
    c::require(rep, name);
    const std::size_t cells = c::cellCount(rep->dims.size_x, rep->dims.size_y, name);
    if (cells > 0) c::require(rep->colr_array, name);
    CellArrayElement e{p, q, r, rep->dims.size_x, rep->dims.size_y, {}, twoD};
    e.colourIndices.assign(rep->colr_array, rep->colr_array + cells);
    return e;
}

Element alignment(ElementType type, const Ptext_align* a, const char* name) {
    c::require(a, name);
    const int hor = c::raw(a->hor), vert = c::raw(a->vert);
    if (hor < PHOR_NORM || hor > PHOR_RIGHT || vert < PVERT_NORM || vert > PVERT_BOTTOM)
        throw Error(PE_ENUM_TYPE_INVAL, name, "text alignment");
    return AlignmentAttribute{type, hor, vert};
}

Element upVector(ElementType type, const Pvec* v, const char* name) {
    c::require(v, name);
    return UpVectorAttribute{type, {v->delta_x, v->delta_y}};
}

// The bytes a Pdata gives (NULL data with size 0 is an empty record).
std::string bytesOf(const Pdata& data, const char* name) {
    const std::size_t size = c::count(data.size, name);
    if (size > 0) c::require(data.data, name);
    const char* bytes = static_cast<const char*>(data.data);
    return std::string(bytes, bytes + size);
}

// An unregistered GDP's or a GSE's record: its `unsupp` bytes; a NULL record is an empty one.
template <class Record>
std::string record(const Record* data, const char* name) {
    return data ? bytesOf(data->unsupp, name) : std::string();
}

Composition composition(int type, const char* name) {
    if (type < PTYPE_PRECONCAT || type > PTYPE_REPLACE)
        throw Error(PE_ENUM_TYPE_INVAL, name, "composition type");
    return static_cast<Composition>(type);
}

}  // namespace

extern "C" {

void ppolyline3(const Ppoint_list3* l) {
    insertElement(Pfn_polyline3, [&](const char* n) -> Element {
        return PolylineElement{c::points(l, n), false};
    });
}
void ppolyline(const Ppoint_list* l) {
    insertElement(Pfn_polyline, [&](const char* n) -> Element {
        return PolylineElement{c::points(l, n), true};
    });
}
void ppolymarker3(const Ppoint_list3* l) {
    insertElement(Pfn_polymarker3, [&](const char* n) -> Element {
        return PolymarkerElement{c::points(l, n), false};
    });
}
void ppolymarker(const Ppoint_list* l) {
    insertElement(Pfn_polymarker, [&](const char* n) -> Element {
        return PolymarkerElement{c::points(l, n), true};
    });
}
void pfill_area3(const Ppoint_list3* l) {
    insertElement(Pfn_fill_area3, [&](const char* n) -> Element {
        return FillAreaElement{c::points(l, n), false};
    });
}
void pfill_area(const Ppoint_list* l) {
    insertElement(Pfn_fill_area, [&](const char* n) -> Element {
        return FillAreaElement{c::points(l, n), true};
    });
}

void pfill_area_set3(const Ppoint_list_list3* sets) {
    insertElement(Pfn_fill_area_set3, [&](const char* n) -> Element {
        c::require(sets, n);
        FillAreaSetElement e{std::vector<std::vector<glm::dvec3>>(c::count(sets->num_point_lists, n)), false};
        if (!e.contours.empty()) c::require(sets->point_lists, n);
        for (std::size_t i = 0; i < e.contours.size(); ++i)
            e.contours[i] = c::points(&sets->point_lists[i], n);
        return e;
    });
}

void pfill_area_set(const Ppoint_list_list* sets) {
    insertElement(Pfn_fill_area_set, [&](const char* n) -> Element {
        c::require(sets, n);
        FillAreaSetElement e{std::vector<std::vector<glm::dvec3>>(c::count(sets->num_point_lists, n)), true};
        if (!e.contours.empty()) c::require(sets->point_lists, n);
        for (std::size_t i = 0; i < e.contours.size(); ++i)
            e.contours[i] = c::points(&sets->point_lists[i], n);
        return e;
    });
}

void ptext3(const Ppoint3* pos, const Pvec3 dir[2], const char* s) {
    insertElement(Pfn_text3, [&](const char* n) -> Element {
        c::require(pos, n);
        c::require(dir, n);
        return TextElement{{pos->x, pos->y, pos->z},
                           {dir[0].delta_x, dir[0].delta_y, dir[0].delta_z},
                           {dir[1].delta_x, dir[1].delta_y, dir[1].delta_z},
                           text(s, n),
                           false};
    });
}

void ptext(const Ppoint* pos, const char* s) {
    insertElement(Pfn_text, [&](const char* n) -> Element {
        c::require(pos, n);
        return TextElement{{pos->x, pos->y, 0.0}, {1, 0, 0}, {0, 1, 0}, text(s, n), true};
    });
}

void panno_text_rel3(const Ppoint3* ref, const Pvec3* offset, const char* s) {
    insertElement(Pfn_anno_text_rel3, [&](const char* n) -> Element {
        c::require(ref, n);
        c::require(offset, n);
        return AnnotationTextElement{
            {ref->x, ref->y, ref->z}, {offset->delta_x, offset->delta_y, offset->delta_z}, text(s, n), false};
    });
}

void panno_text_rel(const Ppoint* ref, const Pvec* offset, const char* s) {
    insertElement(Pfn_anno_text_rel, [&](const char* n) -> Element {
        c::require(ref, n);
        c::require(offset, n);
        return AnnotationTextElement{
            {ref->x, ref->y, 0.0}, {offset->delta_x, offset->delta_y, 0.0}, text(s, n), true};
    });
}

void pcell_array3(const Pparal* pa, const Ppat_rep* rep) {
    insertElement(Pfn_cell_array3, [&](const char* n) -> Element {
        c::require(pa, n);
        return cellArray({pa->p.x, pa->p.y, pa->p.z}, {pa->q.x, pa->q.y, pa->q.z},
                         {pa->r.x, pa->r.y, pa->r.z}, rep, false, n);
    });
}

// CELL ARRAY's rectangle: P and Q opposite corners in the plane z = 0 (the element's 2D form),
// R = (Px, Qy).
void pcell_array(const Prect* rect, const Ppat_rep* rep) {
    insertElement(Pfn_cell_array, [&](const char* n) -> Element {
        c::require(rect, n);
        return cellArray({rect->p.x, rect->p.y, 0}, {rect->q.x, rect->q.y, 0}, {rect->p.x, rect->q.y, 0}, rep,
                         true, n);
    });
}

void pset_line_ind(Pint v) {
    insertIndex(Pfn_set_line_ind, ElementType::PolylineIndex, v);
}
void pset_marker_ind(Pint v) {
    insertIndex(Pfn_set_marker_ind, ElementType::PolymarkerIndex, v);
}
void pset_text_ind(Pint v) {
    insertIndex(Pfn_set_text_ind, ElementType::TextIndex, v);
}
void pset_int_ind(Pint v) {
    insertIndex(Pfn_set_int_ind, ElementType::InteriorIndex, v);
}
void pset_edge_ind(Pint v) {
    insertIndex(Pfn_set_edge_ind, ElementType::EdgeIndex, v);
}
void pset_linetype(Pint v) {
    insertIndex(Pfn_set_linetype, ElementType::Linetype, v);
}
void pset_linewidth(Pfloat v) {
    insertReal(Pfn_set_linewidth, ElementType::LinewidthScaleFactor, v);
}
void pset_line_colr_ind(Pint v) {
    insertColourIndex(Pfn_set_line_colr_ind, ElementType::PolylineColour, v);
}
void pset_marker_type(Pint v) {
    insertIndex(Pfn_set_marker_type, ElementType::MarkerType, v);
}
void pset_marker_size(Pfloat v) {
    insertReal(Pfn_set_marker_size, ElementType::MarkerSizeScaleFactor, v);
}
void pset_marker_colr_ind(Pint v) {
    insertColourIndex(Pfn_set_marker_colr_ind, ElementType::PolymarkerColour, v);
}
void pset_text_font(Pint v) {
    insertIndex(Pfn_set_text_font, ElementType::TextFont, v);
}
void pset_text_prec(Ptext_prec v) {
    insertEnum(Pfn_set_text_prec, ElementType::TextPrecision, c::raw(v), PPREC_STROKE);
}
void pset_char_expan(Pfloat v) {
    insertReal(Pfn_set_char_expan, ElementType::CharacterExpansionFactor, v);
}
void pset_char_space(Pfloat v) {
    insertReal(Pfn_set_char_space, ElementType::CharacterSpacing, v);
}
void pset_text_colr_ind(Pint v) {
    insertColourIndex(Pfn_set_text_colr_ind, ElementType::TextColour, v);
}
void pset_char_ht(Pfloat v) {
    insertReal(Pfn_set_char_ht, ElementType::CharacterHeight, v);
}
void pset_text_path(Ptext_path v) {
    insertEnum(Pfn_set_text_path, ElementType::TextPath, c::raw(v), PPATH_DOWN);
}
void pset_anno_char_ht(Pfloat v) {
    insertReal(Pfn_set_anno_char_ht, ElementType::AnnotationTextCharacterHeight, v);
}
void pset_anno_path(Ptext_path v) {
    insertEnum(Pfn_set_anno_path, ElementType::AnnotationTextPath, c::raw(v), PPATH_DOWN);
}
void pset_anno_style(Pint v) {
    insertIndex(Pfn_set_anno_style, ElementType::AnnotationStyle, v);
}
void pset_int_style(Pint_style v) {
    insertEnum(Pfn_set_int_style, ElementType::InteriorStyle, c::raw(v), PSTYLE_EMPTY);
}
void pset_int_style_ind(Pint v) {
    insertIndex(Pfn_set_int_style_ind, ElementType::InteriorStyleIndex, v);
}
void pset_int_colr_ind(Pint v) {
    insertColourIndex(Pfn_set_int_colr_ind, ElementType::InteriorColour, v);
}
void pset_edge_flag(Pedge_flag v) {
    insertEnum(Pfn_set_edge_flag, ElementType::EdgeFlag, c::raw(v), PEDGE_ON);
}
void pset_edgetype(Pint v) {
    insertIndex(Pfn_set_edgetype, ElementType::Edgetype, v);
}
void pset_edgewidth(Pfloat v) {
    insertReal(Pfn_set_edgewidth, ElementType::EdgewidthScaleFactor, v);
}
void pset_edge_colr_ind(Pint v) {
    insertColourIndex(Pfn_set_edge_colr_ind, ElementType::EdgeColour, v);
}
void pset_pat_size(const Pfloat_size* size) {
    insertElement(Pfn_set_pat_size, [&](const char* name) -> Element {
        c::require(size, name);
        PatternAttribute e{ElementType::PatternSize};
        e.size = {size->size_x, size->size_y};
        return e;
    });
}
void pset_pat_ref_point(const Ppoint* point) {
    insertElement(Pfn_set_pat_ref_point, [&](const char* name) -> Element {
        c::require(point, name);
        PatternAttribute e{ElementType::PatternReferencePoint};
        e.referencePoint = {point->x, point->y, 0.0};
        return e;
    });
}
void pset_pat_ref_point_vecs(const Ppoint3* point, const Pvec3 vectors[2]) {
    insertElement(Pfn_set_pat_ref_point_vecs, [&](const char* name) -> Element {
        c::require(point, name);
        c::require(vectors, name);
        PatternAttribute e{ElementType::PatternReferencePointAndVectors};
        e.referencePoint = {point->x, point->y, point->z};
        e.vectorX = {vectors[0].delta_x, vectors[0].delta_y, vectors[0].delta_z};
        e.vectorY = {vectors[1].delta_x, vectors[1].delta_y, vectors[1].delta_z};
        return e;
    });
}
void pset_line_colr(const Pgcolr* v) {
    insertColour(Pfn_line_colr, ElementType::PolylineColour, v);
}
void pset_marker_colr(const Pgcolr* v) {
    insertColour(Pfn_marker_colr, ElementType::PolymarkerColour, v);
}
void pset_text_colr(const Pgcolr* v) {
    insertColour(Pfn_text_colr, ElementType::TextColour, v);
}
void pset_int_colr(const Pgcolr* v) {
    insertColour(Pfn_int_colr, ElementType::InteriorColour, v);
}
void pset_edge_colr(const Pgcolr* v) {
    insertColour(Pfn_edge_colr, ElementType::EdgeColour, v);
}
void pset_model_clip_ind(Pclip_ind v) {
    insertEnum(Pfn_set_model_clip_ind, ElementType::ModelClippingIndicator, c::raw(v), PIND_CLIP);
}
void pset_view_ind(Pint v) {
    insertIndex(Pfn_set_view_ind, ElementType::ViewIndex, v);
}
void pset_hlhsr_id(Pint v) {
    insertIndex(Pfn_set_hlhsr_id, ElementType::HlhsrIdentifier, v);
}
void pset_pick_id(Pint v) {
    insertIndex(Pfn_set_pick_id, ElementType::PickId, v);
}

void pset_char_up_vec(const Pvec* v) {
    insertElement(Pfn_set_char_up_vec,
                  [&](const char* n) { return upVector(ElementType::CharacterUpVector, v, n); });
}
void pset_anno_char_up_vec(const Pvec* v) {
    insertElement(Pfn_set_anno_char_up_vec, [&](const char* n) {
        return upVector(ElementType::AnnotationTextCharacterUpVector, v, n);
    });
}
void pset_text_align(const Ptext_align* a) {
    insertElement(Pfn_set_text_align,
                  [&](const char* n) { return alignment(ElementType::TextAlignment, a, n); });
}
void pset_anno_align(const Ptext_align* a) {
    insertElement(Pfn_set_anno_align,
                  [&](const char* n) { return alignment(ElementType::AnnotationTextAlignment, a, n); });
}

void pset_indiv_asf(Paspect aspect, Pasf asf) {
    const int id = c::raw(aspect), source = c::raw(asf);
    insertElement(Pfn_set_indiv_asf, [&](const char* n) -> Element {
        const int core = c::aspectOf(id);
        if (core < 0 || (source != PASF_BUNDLED && source != PASF_INDIV))
            throw Error(PE_ENUM_TYPE_INVAL, n, "aspect or source");
        return AsfAttribute{static_cast<AspectId>(core), source == PASF_INDIV};
    });
}

void padd_names_set(const Pint_list* names) {
    insertElement(Pfn_add_names_set, [&](const char* n) -> Element {
        return NameSetElement{true, c::ints(names, n)};
    });
}
void premove_names_set(const Pint_list* names) {
    insertElement(Pfn_remove_names_set, [&](const char* n) -> Element {
        return NameSetElement{false, c::ints(names, n)};
    });
}

void pset_local_tran3(Pmatrix3 m, Pcompose_type type) {
    insertElement(Pfn_set_local_tran3, [&](const char* n) -> Element {
        c::require(m, n);
        return TransformElement{ElementType::LocalModellingTransformation3, c::toGlm(m),
                                composition(c::raw(type), n)};
    });
}
void pset_local_tran(Pmatrix m, Pcompose_type type) {
    insertElement(Pfn_set_local_tran, [&](const char* n) -> Element {
        c::require(m, n);
        return TransformElement{ElementType::LocalModellingTransformation, c::lift(c::toGlm(m)),
                                composition(c::raw(type), n)};
    });
}
void pset_global_tran3(Pmatrix3 m) {
    insertElement(Pfn_set_global_tran3, [&](const char* n) -> Element {
        c::require(m, n);
        return TransformElement{ElementType::GlobalModellingTransformation3, c::toGlm(m),
                                Composition::Replace};
    });
}
void pset_global_tran(Pmatrix m) {
    insertElement(Pfn_set_global_tran, [&](const char* n) -> Element {
        c::require(m, n);
        return TransformElement{ElementType::GlobalModellingTransformation, c::lift(c::toGlm(m)),
                                Composition::Replace};
    });
}

void pset_model_clip_vol3(Pint op, const Phalf_space_list3* list) {
    insertElement(Pfn_set_model_clip_vol3, [&](const char* n) -> Element {
        c::require(list, n);
        ModelClipElement e{
            op, std::vector<std::pair<glm::dvec3, glm::dvec3>>(c::count(list->num_half_spaces, n)), false};
        if (!e.halfSpaces.empty()) c::require(list->half_spaces, n);
        for (std::size_t i = 0; i < e.halfSpaces.size(); ++i) {
            const Phalf_space3& h = list->half_spaces[i];
            e.halfSpaces[i] = {{h.point.x, h.point.y, h.point.z},
                               {h.norm.delta_x, h.norm.delta_y, h.norm.delta_z}};
        }
        return e;
    });
}

void pset_model_clip_vol(Pint op, const Phalf_space_list* list) {
    insertElement(Pfn_set_model_clip_vol, [&](const char* n) -> Element {
        c::require(list, n);
        ModelClipElement e{
            op, std::vector<std::pair<glm::dvec3, glm::dvec3>>(c::count(list->num_half_spaces, n)), true};
        if (!e.halfSpaces.empty()) c::require(list->half_spaces, n);
        for (std::size_t i = 0; i < e.halfSpaces.size(); ++i) {
            const Phalf_space& h = list->half_spaces[i];
            e.halfSpaces[i] = {{h.point.x, h.point.y, 0.0}, {h.norm.delta_x, h.norm.delta_y, 0.0}};
        }
        return e;
    });
}

void prestore_model_clip_vol(void) {
    insertElement(Pfn_restore_model_clip_vol,
                  [](const char*) -> Element { return RestoreModelClipElement{}; });
}
void pexec_struct(Pint id) {
    insertElement(Pfn_exec_struct, [&](const char*) -> Element { return ExecuteStructureElement{id}; });
}
void plabel(Pint id) {
    insertElement(Pfn_label, [&](const char*) -> Element { return LabelElement{id}; });
}
void pappl_data(const Pdata* data) {
    insertElement(Pfn_appl_data, [&](const char* n) -> Element {
        c::require(data, n);
        return ApplicationDataElement{bytesOf(*data, n)};
    });
}

void pgdp3(const Ppoint_list3* l, Pint id, const Pgdp_data3* data) {
    insertElement(Pfn_gdp3, [&](const char* n) -> Element {
        return GdpElement{id, c::points(l, n), isRegisteredGdp(id) ? std::string() : record(data, n), false};
    });
}
void pgdp(const Ppoint_list* l, Pint id, const Pgdp_data* data) {
    insertElement(Pfn_gdp, [&](const char* n) -> Element {
        return GdpElement{id, c::points(l, n), isRegisteredGdp(id) ? std::string() : record(data, n), true};
    });
}
void pgse(Pint id, const Pgse_data* data) {
    insertElement(Pfn_gse, [&](const char* n) -> Element { return GseElement{id, record(data, n)}; });
}

}  // extern "C"
