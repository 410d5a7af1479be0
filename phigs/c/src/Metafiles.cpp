// Metafile functions and INQUIRE TEXT EXTENT. This implementation has no metafile workstation
// type (no MO or MI category), so the metafile functions answer the standard's errors: 56 for
// WRITE ITEM TO METAFILE, 58 for GET ITEM TYPE / READ ITEM FROM METAFILE on any open
// workstation, and INTERPRET ITEM knows no item type (304).

#include "Binding.h"
#include "Conversions.h"
#include "Inquiry.h"
#include "WorkstationAccess.h"
#include "phigs.h"
#include "phigs/render/StrokeFont.h"

#include <cmath>

using phigs::c::Binding;

namespace {

using namespace phigs;

constexpr int kNotMetafileOutput = 56;  // the specified workstation is not of category MO
constexpr int kNotMetafileInput = 58;   // the specified workstation is not of category MI
constexpr int kBadItemLength = 301;     // item length is invalid
constexpr int kUnknownItemType = 304;   // item type is unknown
constexpr int kFontNotAvailable = 106;  // text font not available on the workstation

[[noreturn]] void notMetafile(Phigs& p, Pint ws_id, int error, const char* function) {
    p.workstation(ws_id);  // 3 and 54 first
    throw Error(
        error, function,
        "workstation " + std::to_string(ws_id) + ": this implementation has no metafile workstation type");
}

}  // namespace

extern "C" {

void pwrite_item(Pint ws_id, Pint item_type, Pint item_data_length, const Pitem_data* item_data) {
    (void)item_type, (void)item_data_length, (void)item_data;
    Binding::instance().call(Pfn_write_item, [&](Phigs& p) {
        notMetafile(p, ws_id, kNotMetafileOutput, "WRITE ITEM TO METAFILE");
    });
}

void pget_item_type(Pint ws_id, Pint* item_type, Pint* item_data_length) {
    (void)item_type, (void)item_data_length;
    Binding::instance().call(Pfn_get_item_type, [&](Phigs& p) {
        notMetafile(p, ws_id, kNotMetafileInput, "GET ITEM TYPE FROM METAFILE");
    });
}

void pread_item(Pint ws_id, Pint max_item_data_length, Pitem_data* item_data) {
    (void)max_item_data_length, (void)item_data;
    Binding::instance().call(Pfn_read_item, [&](Phigs& p) {
        notMetafile(p, ws_id, kNotMetafileInput, "READ ITEM FROM METAFILE");
    });
}

void pinterpret_item(Pint type, Pint item_data_length, const Pitem_data* item_data) {
    (void)item_data;
    Binding::instance().call(Pfn_interpret_item, [&](Phigs&) {
        if (item_data_length < 0) throw Error(kBadItemLength, "INTERPRET ITEM");
        throw Error(kUnknownItemType, "INTERPRET ITEM", "item type " + std::to_string(type));
    });
}

void pinq_text_extent(Pint ws_type, Pint font, Pfloat char_expan, Pfloat char_space, Pfloat char_ht,
                      Ptext_path text_path, Phor_text_align hor_align, Pvert_text_align vert_align,
                      const char* str, Pint* err_ind, Prect* rect, Ppoint* offset) {
    if (!c::somewhereToAnswer(err_ind, rect, offset)) return;
    const int path = c::raw(text_path), hor = c::raw(hor_align), vert = c::raw(vert_align);
    c::inquire(err_ind, [&](Phigs&) {
        constexpr const char* kName = "INQUIRE TEXT EXTENT";
        c::workstationTypeOf(ws_type, kName);
        if (path < PPATH_RIGHT || path > PPATH_DOWN || hor < PHOR_NORM || hor > PHOR_RIGHT ||
            vert < PVERT_NORM || vert > PVERT_BOTTOM)
            throw Error(PE_ENUM_TYPE_INVAL, kName, "text path or alignment");
        if (font < 1 || font > 4) throw Error(kFontNotAvailable, kName, "font " + std::to_string(font));
        if (!std::isfinite(char_expan) || !std::isfinite(char_space) || !std::isfinite(char_ht))
            throw Error(errors::NonFiniteValue, kName, "the expansion, spacing or height is not finite");
        c::require(str, kName);
        c::require(rect, kName);
        c::require(offset, kName);
        TextStyle style;
        style.font = font;
        style.expansion = std::abs(char_expan);  // as drawn (ISO 9592: absolute values)
        style.spacing = char_space;
        style.height = std::abs(char_ht);
        style.path = static_cast<TextPath>(path);
        style.horizontal = static_cast<HorizontalAlignment>(hor);
        style.vertical = static_cast<VerticalAlignment>(vert);
        const render::TextExtent e = render::textExtent(render::StrokeFont::forIndex(font), str, style);
        *rect = {{static_cast<Pfloat>(e.min.x), static_cast<Pfloat>(e.min.y)},
                 {static_cast<Pfloat>(e.max.x), static_cast<Pfloat>(e.max.y)}};
        *offset = {static_cast<Pfloat>(e.concatenation.x), static_cast<Pfloat>(e.concatenation.y)};
    });
}

}  // extern "C"
