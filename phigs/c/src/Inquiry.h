#pragma once

// How the binding's inquiries answer: never through the error handler, only *err_ind.

#include "Binding.h"
#include "StoreBuffer.h"

#include <vector>

namespace phigs::c {

/// Runs `body` on the open system with *err set to 0, or to the error number it throws (2 while
/// PHIGS is closed). Without err_ind there is nowhere to answer, so nothing happens.
template <class Body>
void inquire(Pint* err, Body&& body) {
    if (!err) return;
    Phigs* p = Binding::instance().system();
    if (!p) {
        *err = errors::NotPhigsOpen;
        return;
    }
    *err = 0;
    try {
        body(*p);
    } catch (const Error& e) {
        *err = e.number();
    } catch (const std::bad_alloc&) {
        *err = PE_ALLOC_STORE_MEM;
    }
}

/// Whether an inquiry has somewhere to answer. With every result pointer NULL it answers -204
/// (after the state check, before any other) and the caller returns; any one of several may be
/// NULL to skip that answer unless the inquiry needs it (it then answers -204 too).
template <class... Results>
bool somewhereToAnswer(Pint* err, const Results*... results) {
    if ((... || (results != nullptr))) return true;
    inquire(err, [](Phigs&) { throw Error(kBadArgument, "inquiry", "every result pointer is NULL"); });
    return false;
}

/// The C binding's simple list answer: `appl` items from `start` copied to out->ints, the whole
/// length in *total; 2201 for a negative `appl`, 2200 for a start outside the list.
void answerList(const std::vector<int>& all, Pint appl, Pint start, Pint_list* out, Pint* total);

/// A store the application passed: 2203 when it is NULL.
Phigs_store& storeOf(Pstore store);

/// Paths into `store` as the Pelem_ref_list_list the inquiry returns.
Pelem_ref_list_list* answerPaths(const std::vector<StructurePath>& paths, Phigs_store& store);

}  // namespace phigs::c
