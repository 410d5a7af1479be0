// Control, error handling and stores.

#include "Binding.h"
#include "Conversions.h"
#include "Input.h"
#include "Inquiry.h"
#include "StoreBuffer.h"
#include "phigs.h"

#include <limits>
#include <new>
#include <string>

using phigs::c::Binding;

extern "C" {

void popen_phigs(const char* err_file, size_t /*mem_units: the store grows as needed*/) {
    Binding::instance().open(err_file);
}

void pclose_phigs(void) {
    Binding::instance().close();
}

void pemergency_close_phigs(void) {
    Binding::instance().emergencyClose();
}

void pinq_sys_st(Psys_st* sys_st) {
    if (sys_st) *sys_st = Binding::instance().system() ? PSYS_ST_PHOP : PSYS_ST_PHCL;
}

void pmessage(Pint ws_id, const char* message) {
    Binding& b = Binding::instance();
    b.call(Pfn_message, [&](phigs::Phigs& p) {
        p.workstation(ws_id);  // errors 3, 54
        phigs::c::require(message, "MESSAGE");
        b.message(ws_id, message);
    });
}

void pescape(Pint func_id, const Pescape_in_data* in_data, Pstore /*store*/, Pescape_out_data** out_data) {
    if (out_data) *out_data = nullptr;
    Binding::instance().call(Pfn_escape, [&](phigs::Phigs& p) {
        if (func_id == PUESC_INPUT_SCRIPT) return phigs::c::attachInputScript(p, in_data);
        throw phigs::Error(phigs::errors::EscapeNotAvailable, "ESCAPE",
                           "escape " + std::to_string(func_id) + " is not registered");
    });
}

void pinq_phigs_facs(Pint appl, Pint start, Pint* err, Pint* max_open_ws, Pint* max_open_ar, Pint* num_names,
                     Pint_list* char_sets, Pint* total, Pint* max_norm_filter, Pint* max_inv_filter) {
    if (!phigs::c::somewhereToAnswer(err, max_open_ws, max_open_ar, num_names, char_sets, total,
                                     max_norm_filter, max_inv_filter))
        return;
    phigs::c::inquire(err, [&](phigs::Phigs&) {
        for (Pint* unlimited : {max_open_ws, max_open_ar, num_names, max_norm_filter, max_inv_filter})
            if (unlimited) *unlimited = std::numeric_limits<Pint>::max();
        phigs::c::answerList({}, appl, start, char_sets, total);
    });
}

void perr_hand(Pint err_num, Pint func_num, const char* err_file) {
    perr_log(err_num, func_num, err_file);
}

void perr_log(Pint err_num, Pint func_num, const char* err_file) {
    Binding::instance().log(err_num, func_num, err_file);
}

void pset_err_hand(void (*new_err_hand)(Pint, Pint, const char*),
                   void (**old_err_hand)(Pint, Pint, const char*)) {
    Binding::instance().setHandler(new_err_hand, old_err_hand);
}

void pset_err_hand_mode(Perr_mode value) {
    const int mode = phigs::c::raw(value);
    Binding& b = Binding::instance();
    if (!b.system()) {
        b.report(phigs::errors::NotPhigsOpen, Pfn_set_err_hand_mode);
        return;
    }
    if (mode != PERR_OFF && mode != PERR_ON) {
        b.report(PE_ENUM_TYPE_INVAL, Pfn_set_err_hand_mode);
        return;
    }
    b.setMode(mode == PERR_ON ? PERR_ON : PERR_OFF);
}

void pinq_err_hand_mode(Pint* err_ind, Perr_mode* mode) {
    if (!phigs::c::somewhereToAnswer(err_ind, mode)) return;
    if (!err_ind) return;
    Binding& b = Binding::instance();
    *err_ind = b.system() ? 0 : phigs::errors::NotPhigsOpen;
    if (*err_ind == 0 && mode) *mode = b.mode();
}

void pcreate_store(Pint* err_ind, Pstore* store) {
    if (!err_ind) return;
    *err_ind = 0;
    if (!store) {
        *err_ind = PE_ALLOC_STORE;
        return;
    }
    *store = new (std::nothrow) Phigs_store;
    if (!*store) *err_ind = PE_ALLOC_STORE_MEM;
}

void pdel_store(Pstore store) {
    delete store;
}

}  // extern "C"
