#pragma once

// How the binding's inquiries answer: never through the error handler, only *err_ind.

#include "Binding.h"
#include "StoreBuffer.h"

#include <stdexcept>
#include <vector>

namespace phigs::c {

/// The error an inquiry answers while PHIGS is closed: the state error for the operating state
/// it requires (3 WSOP, 5 STOP, 7 AROP, as ISO 9592 lists them), which its own state check
/// raises on a system with nothing open (an inquiry changes nothing), else 2 (PHOP).
template <class Body>
int closedInquiryError(Body& body) {
    try {
        body(closedStateProbe());
    } catch (const Error& e) {
        const int n = e.number();
        if (n == errors::NoWorkstationOpen || n == errors::NotStructureOpen || n == errors::NoArchiveOpen)
            return n;
    } catch (...) {
    }
    return errors::NotPhigsOpen;
}

/// Runs `body` on the open system with *err set to 0, or to the error number it throws (while
/// PHIGS is closed, closedInquiryError). Without err_ind there is nowhere to answer, so nothing
/// happens.
template <class Body>
void inquire(Pint* err, Body&& body) {
    if (!err) return;
    Phigs* p = Binding::instance().system();
    if (!p) {
        *err = closedInquiryError(body);
        return;
    }
    *err = 0;
    try {
        body(*p);
    } catch (const Error& e) {
        *err = e.number();
    } catch (const std::bad_alloc&) {
        *err = PE_ALLOC_STORE_MEM;
    } catch (const std::length_error&) {  // a count past what any container can hold
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
