// Structure creation, editing and manipulation.

#include "Binding.h"
#include "Conversions.h"
#include "phigs.h"

using namespace phigs;
using phigs::c::Binding;

namespace {

template <class Body>
void onStore(int fn, Body&& body) {
    Binding::instance().call(fn, [&](Phigs& p) { body(p.store()); });
}

/// Functions that need a structure open check it before their arguments (error 5).
template <class Body>
void onOpenStructure(int fn, Body&& body) {
    Binding::instance().call(fn, [&](Phigs& p) {
        StructureStore& store = p.store();
        if (!store.isStructureOpen())
            raise(&p.errorLog(), errors::NotStructureOpen, c::functionName(fn).c_str());
        body(store);
    });
}

}  // namespace

extern "C" {

void popen_struct(Pint id) {
    onStore(Pfn_open_struct, [&](StructureStore& s) { s.openStructure(id); });
}
void pclose_struct(void) {
    onStore(Pfn_close_struct, [](StructureStore& s) { s.closeStructure(); });
}
void pset_edit_mode(Pedit_mode value) {
    const int mode = c::raw(value);
    onStore(Pfn_set_edit_mode, [&](StructureStore& s) {
        if (mode != PEDIT_INSERT && mode != PEDIT_REPLACE) throw Error(PE_ENUM_TYPE_INVAL, "SET EDIT MODE");
        s.setEditMode(mode == PEDIT_INSERT ? EditMode::Insert : EditMode::Replace);
    });
}
void pset_elem_ptr(Pint value) {
    onOpenStructure(Pfn_set_elem_ptr, [&](StructureStore& s) { s.setElementPointer(value); });
}
void poffset_elem_ptr(Pint offset) {
    onOpenStructure(Pfn_offset_elem_ptr, [&](StructureStore& s) { s.offsetElementPointer(offset); });
}
void pset_elem_ptr_label(Pint label) {
    onOpenStructure(Pfn_set_elem_ptr_label, [&](StructureStore& s) { s.setElementPointerAtLabel(label); });
}
void pdel_elem(void) {
    onOpenStructure(Pfn_del_elem, [](StructureStore& s) { s.deleteElement(); });
}
void pdel_elem_range(Pint first, Pint second) {
    onOpenStructure(Pfn_del_elem_range, [&](StructureStore& s) { s.deleteElementRange(first, second); });
}
void pdel_elems_labels(Pint first, Pint second) {
    onOpenStructure(Pfn_del_elems_labels,
                    [&](StructureStore& s) { s.deleteElementsBetweenLabels(first, second); });
}
void pcopy_all_elems_struct(Pint id) {
    onOpenStructure(Pfn_copy_all_elems_struct,
                    [&](StructureStore& s) { s.copyAllElementsFromStructure(id); });
}
void pempty_struct(Pint id) {
    onStore(Pfn_empty_struct, [&](StructureStore& s) { s.emptyStructure(id); });
}
void pdel_struct(Pint id) {
    onStore(Pfn_del_struct, [&](StructureStore& s) { s.deleteStructure(id); });
}
void pdel_struct_net(Pint id, Pref_flag value) {
    const int flag = c::raw(value);
    onStore(Pfn_del_struct_net, [&](StructureStore& s) {
        if (flag != PFLAG_DEL && flag != PFLAG_KEEP)
            throw Error(PE_ENUM_TYPE_INVAL, "DELETE STRUCTURE NETWORK");
        s.deleteStructureNetwork(id, flag == PFLAG_DEL ? ReferenceHandling::Delete : ReferenceHandling::Keep);
    });
}
void pdel_all_structs(void) {
    onStore(Pfn_del_all_structs, [](StructureStore& s) { s.deleteAllStructures(); });
}
void pchange_struct_id(Pint original, Pint result) {
    onStore(Pfn_change_struct_id, [&](StructureStore& s) { s.changeStructureIdentifier(original, result); });
}
void pchange_struct_refs(Pint original, Pint result) {
    onStore(Pfn_change_struct_refs,
            [&](StructureStore& s) { s.changeStructureReferences(original, result); });
}
void pchange_struct_id_refs(Pint original, Pint result) {
    onStore(Pfn_change_struct_id_refs,
            [&](StructureStore& s) { s.changeStructureIdentifierAndReferences(original, result); });
}

}  // extern "C"
