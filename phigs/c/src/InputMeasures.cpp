// REQUEST, SAMPLE and GET of each class, AWAIT EVENT and FLUSH DEVICE EVENTS.

#include "Input.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <functional>
#include <optional>

using phigs::c::Binding;

namespace {

using namespace phigs;

/// Hands a measure of the device's class to the application's outputs.
using Answer = std::function<void(const Measure&, const char* function)>;

/// REQUEST <class>: the status, and the measure unless the operator broke the request.
void request(int function, Pint wsId, InputClass inputClass, Pint number, Pin_status* status,
             const Answer& answer) {
    Binding::instance().call(function, [&](Phigs& p) {
        const char* name = c::inputFunctionName(function);
        Workstation& ws = c::inputWorkstation(p, wsId, inputClass);
        c::require(status, name);
        const auto [s, measure] = c::requestMeasure(ws, inputClass, number, name);
        *status = s;
        if (s != PIN_STATUS_NONE) answer(measure, name);
    });
}

void sampleInput(int function, Pint wsId, InputClass inputClass, Pint number, const Answer& answer) {
    Binding::instance().call(function, [&](Phigs& p) {
        const char* name = c::inputFunctionName(function);
        Workstation& ws = c::inputWorkstation(p, wsId, inputClass);
        answer(c::sampleMeasure(ws, inputClass, number, name), name);
    });
}

/// GET <class>: the current event report's measure (3 with no workstation open, 259).
void get(int function, InputClass inputClass, const Answer& answer) {
    Binding::instance().call(function, [&](Phigs& p) {
        const char* name = c::inputFunctionName(function);
        if (!p.anyWorkstationOpen()) throw Error(errors::NoWorkstationOpen, name);
        answer(c::InputSession::of().queue().currentMeasure(inputClass, name), name);
    });
}

Answer locator3(Pint* view, Ppoint3* at) {
    return [=](const Measure& m, const char* name) {
        c::require(at, name);
        const auto& l = std::get<LocatorMeasure>(m);
        if (view) *view = l.viewIndex;
        *at = {static_cast<Pfloat>(l.position.x), static_cast<Pfloat>(l.position.y),
               static_cast<Pfloat>(l.position.z)};
    };
}

Answer locator(Pint* view, Ppoint* at) {
    return [=](const Measure& m, const char* name) {
        c::require(at, name);
        const auto& l = std::get<LocatorMeasure>(m);
        if (view) *view = l.viewIndex;
        *at = {static_cast<Pfloat>(l.position.x), static_cast<Pfloat>(l.position.y)};
    };
}

template <class List>
Answer stroke(Pint* view, List* out) {
    return [=](const Measure& m, const char* name) {
        c::answerStroke(std::get<StrokeMeasure>(m), view, out, name);
    };
}

Answer valuator(Pfloat* value) {
    return [=](const Measure& m, const char* name) {
        c::require(value, name);
        *value = static_cast<Pfloat>(std::get<ValuatorMeasure>(m).value);
    };
}

/// A choice: its status (when `status` is given) and number (0 for no choice).
Answer choice(Pin_status* status, Pint* number) {
    return [=](const Measure& m, const char* name) {
        c::require(number, name);
        const auto& ch = std::get<ChoiceMeasure>(m);
        if (status) *status = c::statusOf(m);
        *number = ch.status == InputStatus::Ok ? ch.choice : 0;
    };
}

Answer pick(Pint depth, Pin_status* status, Ppick_path* path) {
    return [=](const Measure& m, const char* name) {
        const auto& pk = std::get<PickMeasure>(m);
        if (status) *status = c::statusOf(m);
        if (pk.status == InputStatus::Ok)
            c::answerPickPath(pk, depth, path, name);
        else if (path)
            path->depth = 0;
    };
}

Answer string(char* out) {
    return
        [=](const Measure& m, const char* name) { c::answerString(std::get<StringMeasure>(m), out, name); };
}

/// Sample and GET of choice and pick answer their status themselves: it must be given.
template <class T>
T* given(T* pointer, int function) {
    if (!pointer)
        Binding::instance().call(function,
                                 [&](Phigs&) { c::require(pointer, c::inputFunctionName(function)); });
    return pointer;
}

}  // namespace

extern "C" {

void preq_loc3(Pint ws_id, Pint loc_num, Pin_status* in_status, Pint* view_ind, Ppoint3* loc_pos) {
    request(Pfn_req_loc3, ws_id, InputClass::Locator, loc_num, in_status, locator3(view_ind, loc_pos));
}

void preq_loc(Pint ws_id, Pint loc_num, Pin_status* in_status, Pint* view_ind, Ppoint* loc_pos) {
    request(Pfn_req_loc, ws_id, InputClass::Locator, loc_num, in_status, locator(view_ind, loc_pos));
}

void preq_stroke3(Pint ws_id, Pint stroke_num, Pin_status* in_status, Pint* view_ind, Ppoint_list3* out) {
    request(Pfn_req_stroke3, ws_id, InputClass::Stroke, stroke_num, in_status, stroke(view_ind, out));
}

void preq_stroke(Pint ws_id, Pint stroke_num, Pin_status* in_status, Pint* view_ind, Ppoint_list* out) {
    request(Pfn_req_stroke, ws_id, InputClass::Stroke, stroke_num, in_status, stroke(view_ind, out));
}

void preq_val(Pint ws_id, Pint val_num, Pin_status* in_status, Pfloat* val) {
    request(Pfn_req_val, ws_id, InputClass::Valuator, val_num, in_status, valuator(val));
}

void preq_choice(Pint ws_id, Pint choice_num, Pin_status* in_status, Pint* out) {
    request(Pfn_req_choice, ws_id, InputClass::Choice, choice_num, in_status, choice(nullptr, out));
}

void preq_pick(Pint ws_id, Pint pick_num, Pint depth, Pin_status* in_status, Ppick_path* out) {
    request(Pfn_req_pick, ws_id, InputClass::Pick, pick_num, in_status, pick(depth, nullptr, out));
}

void preq_string(Pint ws_id, Pint string_num, Pin_status* in_status, char* out) {
    request(Pfn_req_string, ws_id, InputClass::String, string_num, in_status, string(out));
}

void psample_loc3(Pint ws_id, Pint loc_num, Pint* view_ind, Ppoint3* loc_pos) {
    sampleInput(Pfn_sample_loc3, ws_id, InputClass::Locator, loc_num, locator3(view_ind, loc_pos));
}

void psample_loc(Pint ws_id, Pint loc_num, Pint* view_ind, Ppoint* loc_pos) {
    sampleInput(Pfn_sample_loc, ws_id, InputClass::Locator, loc_num, locator(view_ind, loc_pos));
}

void psample_stroke3(Pint ws_id, Pint stroke_num, Pint* view_ind, Ppoint_list3* out) {
    sampleInput(Pfn_sample_stroke3, ws_id, InputClass::Stroke, stroke_num, stroke(view_ind, out));
}

void psample_stroke(Pint ws_id, Pint stroke_num, Pint* view_ind, Ppoint_list* out) {
    sampleInput(Pfn_sample_stroke, ws_id, InputClass::Stroke, stroke_num, stroke(view_ind, out));
}

void psample_val(Pint ws_id, Pint val_num, Pfloat* val) {
    sampleInput(Pfn_sample_val, ws_id, InputClass::Valuator, val_num, valuator(val));
}

void psample_choice(Pint ws_id, Pint choice_num, Pin_status* choice_in_status, Pint* out) {
    if (!given(choice_in_status, Pfn_sample_choice)) return;
    sampleInput(Pfn_sample_choice, ws_id, InputClass::Choice, choice_num, choice(choice_in_status, out));
}

void psample_pick(Pint ws_id, Pint pick_num, Pint depth, Pin_status* pick_in_status, Ppick_path* out) {
    if (!given(pick_in_status, Pfn_sample_pick)) return;
    sampleInput(Pfn_sample_pick, ws_id, InputClass::Pick, pick_num, pick(depth, pick_in_status, out));
}

void psample_string(Pint ws_id, Pint string_num, char* out) {
    sampleInput(Pfn_sample_string, ws_id, InputClass::String, string_num, string(out));
}

void pawait_event(Pfloat timeout, Pint* ws_id, Pin_class* dev_class, Pint* in_num) {
    Binding::instance().call(Pfn_await_event, [&](Phigs& p) {
        const char* name = "AWAIT EVENT";
        if (!p.anyWorkstationOpen()) throw Error(errors::NoWorkstationOpen, name);
        c::require(ws_id, name), c::require(dev_class, name), c::require(in_num, name);
        const double seconds =
            std::isfinite(timeout) ? std::min(std::max<double>(timeout, 0.0), 3600.0) : 0.0;
        const auto wait = std::chrono::milliseconds(std::lround(seconds * 1000.0));
        std::optional<EventReport> event;
        try {
            event = c::InputSession::of().queue().awaitEvent(wait);
        } catch (const InputExhausted&) {
            event.reset();  // the end of a script is a timeout
        } catch (const ScriptError& e) {
            throw Error(c::kEscapeRecord, name, e.what());
        }
        *dev_class = event ? c::cClass(event->inputClass) : PIN_NONE;
        if (!event) return;
        *ws_id = event->workstation;
        *in_num = event->device;
    });
}

void pflush_events(Pint ws_id, Pin_class dev_class, Pint dev_num) {
    Binding::instance().call(Pfn_flush_events, [&](Phigs& p) {
        const char* name = "FLUSH DEVICE EVENTS";
        p.workstation(ws_id);
        const InputClass inputClass = c::coreClass(dev_class, name);
        Workstation& ws = c::inputWorkstation(p, ws_id, inputClass);
        c::inputDevice(ws, inputClass, dev_num, name);
        c::InputSession::of().queue().flush(ws_id, inputClass, dev_num);
    });
}

void pget_loc3(Pint* view_ind, Ppoint3* loc_pos) {
    get(Pfn_get_loc3, InputClass::Locator, locator3(view_ind, loc_pos));
}

void pget_loc(Pint* view_ind, Ppoint* loc_pos) {
    get(Pfn_get_loc, InputClass::Locator, locator(view_ind, loc_pos));
}

void pget_stroke3(Pint* view_ind, Ppoint_list3* out) {
    get(Pfn_get_stroke3, InputClass::Stroke, stroke(view_ind, out));
}

void pget_stroke(Pint* view_ind, Ppoint_list* out) {
    get(Pfn_get_stroke, InputClass::Stroke, stroke(view_ind, out));
}

void pget_val(Pfloat* val) {
    get(Pfn_get_val, InputClass::Valuator, valuator(val));
}

void pget_choice(Pin_status* in_status, Pint* out) {
    if (!given(in_status, Pfn_get_choice)) return;
    get(Pfn_get_choice, InputClass::Choice, choice(in_status, out));
}

void pget_pick(Pint depth, Pin_status* in_status, Ppick_path* out) {
    if (!given(in_status, Pfn_get_pick)) return;
    get(Pfn_get_pick, InputClass::Pick, pick(depth, in_status, out));
}

void pget_string(char* out) {
    get(Pfn_get_string, InputClass::String, string(out));
}

}  // extern "C"
