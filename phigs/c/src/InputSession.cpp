// The C binding's input session (queue, scripts, records), the input workstation and device
// lookups with the standard's errors, conversions, and the REQUEST and SAMPLE loops.

#include "Conversions.h"
#include "Input.h"
#include "WorkstationAccess.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <map>

namespace phigs::c {

namespace {

const std::map<int, const char*>& inputNames() {
    static const std::map<int, const char*> table = {
        {Pfn_set_pick_filter, "SET PICK FILTER"},
        {Pfn_init_loc3, "INITIALIZE LOCATOR 3"},
        {Pfn_init_loc, "INITIALIZE LOCATOR"},
        {Pfn_init_stroke3, "INITIALIZE STROKE 3"},
        {Pfn_init_stroke, "INITIALIZE STROKE"},
        {Pfn_init_val3, "INITIALIZE VALUATOR 3"},
        {Pfn_init_val, "INITIALIZE VALUATOR"},
        {Pfn_init_choice3, "INITIALIZE CHOICE 3"},
        {Pfn_init_choice, "INITIALIZE CHOICE"},
        {Pfn_init_pick3, "INITIALIZE PICK 3"},
        {Pfn_init_pick, "INITIALIZE PICK"},
        {Pfn_init_string3, "INITIALIZE STRING 3"},
        {Pfn_init_string, "INITIALIZE STRING"},
        {Pfn_set_loc_mode, "SET LOCATOR MODE"},
        {Pfn_set_stroke_mode, "SET STROKE MODE"},
        {Pfn_set_val_mode, "SET VALUATOR MODE"},
        {Pfn_set_choice_mode, "SET CHOICE MODE"},
        {Pfn_set_pick_mode, "SET PICK MODE"},
        {Pfn_set_string_mode, "SET STRING MODE"},
        {Pfn_req_loc3, "REQUEST LOCATOR 3"},
        {Pfn_req_loc, "REQUEST LOCATOR"},
        {Pfn_req_stroke3, "REQUEST STROKE 3"},
        {Pfn_req_stroke, "REQUEST STROKE"},
        {Pfn_req_val, "REQUEST VALUATOR"},
        {Pfn_req_choice, "REQUEST CHOICE"},
        {Pfn_req_pick, "REQUEST PICK"},
        {Pfn_req_string, "REQUEST STRING"},
        {Pfn_sample_loc3, "SAMPLE LOCATOR 3"},
        {Pfn_sample_loc, "SAMPLE LOCATOR"},
        {Pfn_sample_stroke3, "SAMPLE STROKE 3"},
        {Pfn_sample_stroke, "SAMPLE STROKE"},
        {Pfn_sample_val, "SAMPLE VALUATOR"},
        {Pfn_sample_choice, "SAMPLE CHOICE"},
        {Pfn_sample_pick, "SAMPLE PICK"},
        {Pfn_sample_string, "SAMPLE STRING"},
        {Pfn_await_event, "AWAIT EVENT"},
        {Pfn_flush_events, "FLUSH DEVICE EVENTS"},
        {Pfn_get_loc3, "GET LOCATOR 3"},
        {Pfn_get_loc, "GET LOCATOR"},
        {Pfn_get_stroke3, "GET STROKE 3"},
        {Pfn_get_stroke, "GET STROKE"},
        {Pfn_get_val, "GET VALUATOR"},
        {Pfn_get_choice, "GET CHOICE"},
        {Pfn_get_pick, "GET PICK"},
        {Pfn_get_string, "GET STRING"},
    };
    return table;
}

/// A core error raised by a script source or the devices, as the binding's error.
template <class Body>
auto scripted(const char* function, Body&& body) -> decltype(body()) {
    try {
        return body();
    } catch (const InputExhausted& e) {
        throw Error(kScriptEnded, function, e.what());
    } catch (const ScriptError& e) {
        throw Error(kEscapeRecord, function, e.what());
    }
}

}  // namespace

const char* inputFunctionName(int function) {
    const auto it = inputNames().find(function);
    return it == inputNames().end() ? nullptr : it->second;
}

InputSession::InputSession() : queue_(std::make_unique<InputQueue>()) {
}

InputSession& InputSession::of() {
    static std::unique_ptr<InputSession> session;
    static std::uint64_t opening = 0;
    Binding& b = Binding::instance();
    if (!session || opening != b.openings()) {
        session.reset(new InputSession());
        opening = b.openings();
    }
    if (Phigs* p = b.system())
        session->queue_->setWarningSink([p](const Error& e) { p->errorLog().record(e); });
    return *session;
}

void InputSession::attachScript(Workstation& ws, std::unique_ptr<ScriptInputSource> script) {
    ws.connectInput(*script, *queue_);  // the queued events stay; then the old script goes
    scripts_[ws.id()] = std::move(script);
}

void InputSession::connectWindow(Workstation& ws) {
    if (ws.input().source()) return;
    if (InputSource* window = windowInputSource(ws)) ws.connectInput(*window, *queue_);
}

void InputSession::forget(int ws) {
    scripts_.erase(ws);
    std::erase_if(records_, [ws](const auto& entry) { return std::get<0>(entry.first) == ws; });
}

const DeviceRecord* InputSession::record(int ws, InputClass inputClass, int device) const {
    const auto it = records_.find({ws, inputClass, device});
    return it == records_.end() ? nullptr : &it->second;
}

void InputSession::setRecord(int ws, InputClass inputClass, int device, DeviceRecord record) {
    records_[{ws, inputClass, device}] = std::move(record);
}

void forgetInput(int ws) {
    InputSession::of().forget(ws);
}

void attachInputScript(Phigs& p, const Pescape_in_data* in) {
    const char* function = "ESCAPE";
    require(in, function);
    Workstation& ws = inputWorkstation(p, in->escape_in_u11.ws_id, InputClass::Locator);
    std::unique_ptr<ScriptInputSource> script;
    try {
        if (in->escape_in_u11.script)
            script = std::make_unique<ScriptInputSource>(
                in->escape_in_u11.script, "input script of workstation " + std::to_string(ws.id()));
        else if (in->escape_in_u11.file)
            script = std::make_unique<ScriptInputSource>(ScriptInputSource::fromFile(in->escape_in_u11.file));
        else
            throw Error(kEscapeRecord, function, "neither a script nor a file name");
    } catch (const ScriptError& e) {
        raise(&p.errorLog(), kEscapeRecord, function, e.what());
    }
    InputSession::of().attachScript(ws, std::move(script));
}

Workstation& inputWorkstation(Phigs& p, Pint id, InputClass inputClass, bool inquiry) {
    Workstation* ws = nullptr;
    if (inquiry) {
        if (!p.anyWorkstationOpen()) throw Error(errors::NoWorkstationOpen, "inquiry");
        ws = p.findWorkstation(id);
        if (!ws) throw Error(errors::WorkstationNotOpen, "inquiry", "workstation " + std::to_string(id));
    } else {
        ws = &p.workstation(id);
    }
    if (ws->description().category != WorkstationCategory::OutIn)
        throw Error(inputClass == InputClass::Pick ? kNotOutIn : kNotInput, "input",
                    "workstation " + std::to_string(id) + " is of category OUTPUT");
    if (!inquiry) InputSession::of().connectWindow(*ws);
    return *ws;
}

const InputDevice& inputDevice(const Workstation& ws, InputClass inputClass, Pint number,
                               const char* function) {
    if (number < 1 || number > ws.input().counts().of(inputClass))
        throw Error(errors::DeviceNotAvailable, function,
                    std::string(nameOf(inputClass)) + " " + std::to_string(number) +
                        " is not on workstation " + std::to_string(ws.id()));
    return ws.input().device(inputClass, number);
}

WorkstationDescription inputType(Pint type, InputClass inputClass, Pint number) {
    const char* function = "inquiry";
    WorkstationDescription d = describedType(type, function);
    if (d.category != WorkstationCategory::OutIn) throw Error(kNotInput, function);
    if (number < 1 || number > d.inputDevices.of(inputClass))
        throw Error(errors::DeviceNotAvailable, function);
    return d;
}

InputClass coreClass(const Pin_class& inputClass, const char* function) {
    const int v = raw(inputClass);
    if (v < PIN_LOC || v > PIN_STRING) throw Error(PE_ENUM_TYPE_INVAL, function, "input class");
    return static_cast<InputClass>(v - PIN_LOC);
}

Pin_class cClass(InputClass inputClass) {
    return static_cast<Pin_class>(static_cast<int>(inputClass) + PIN_LOC);
}

OperatingMode coreMode(const Pop_mode& mode, const char* function) {
    const int v = raw(mode);
    if (v < POP_REQ || v > POP_EVENT) throw Error(PE_ENUM_TYPE_INVAL, function, "operating mode");
    return static_cast<OperatingMode>(v - POP_REQ);
}

Pop_mode cMode(OperatingMode mode) {
    return static_cast<Pop_mode>(static_cast<int>(mode) + POP_REQ);
}

EchoSwitch coreEcho(const Pecho_switch& echo, const char* function) {
    const int v = raw(echo);
    if (v != PSWITCH_NO_ECHO && v != PSWITCH_ECHO) throw Error(PE_ENUM_TYPE_INVAL, function, "echo switch");
    return v == PSWITCH_ECHO ? EchoSwitch::Echo : EchoSwitch::NoEcho;
}

EchoVolume coreEchoVolume(const Workstation& ws, const Plimit3& v, const char* function) {
    if (!(v.x_min < v.x_max && v.y_min < v.y_max && v.z_min <= v.z_max))
        throw Error(kEchoAreaEmpty, function, "echo area/volume with min >= max");
    const glm::dvec2 size = ws.displaySize();
    if (v.x_min < 0 || v.x_max > size.x || v.y_min < 0 || v.y_max > size.y || v.z_min < 0 || v.z_max > 1)
        throw Error(kEchoAreaOutside, function, "echo area/volume outside the display space");
    return {v.x_min, v.x_max, size.y - v.y_max, size.y - v.y_min, v.z_min, v.z_max};
}

Plimit3 cEchoVolume(glm::dvec2 size, const EchoVolume& v) {
    return {static_cast<Pfloat>(v.xmin),          static_cast<Pfloat>(v.xmax),
            static_cast<Pfloat>(size.y - v.ymax), static_cast<Pfloat>(size.y - v.ymin),
            static_cast<Pfloat>(v.zmin),          static_cast<Pfloat>(v.zmax)};
}

Plimit3 wholeDisplay(glm::dvec2 size) {
    return {0, static_cast<Pfloat>(size.x), 0, static_cast<Pfloat>(size.y), 0, 1};
}

Plimit3 lift(const Plimit& a) {
    return {a.x_min, a.x_max, a.y_min, a.y_max, 0, 1};
}

Plimit lower(const Plimit3& v) {
    return {v.x_min, v.x_max, v.y_min, v.y_max};
}

const std::vector<int>& promptEchoTypes(InputClass inputClass) {
    static const std::vector<int> locator{1, 2, 3}, two{1, 2}, choice{1, 2, 3}, one{1};
    switch (inputClass) {
        case InputClass::Locator:
            return locator;
        case InputClass::Choice:
            return choice;
        case InputClass::String:
            return one;
        default:
            return two;
    }
}

Pin_status statusOf(const Measure& m) {
    if (const auto* pick = std::get_if<PickMeasure>(&m))
        return pick->status == InputStatus::Ok ? PIN_STATUS_OK : PIN_STATUS_NO_IN;
    if (const auto* choice = std::get_if<ChoiceMeasure>(&m))
        return choice->status == InputStatus::Ok ? PIN_STATUS_OK : PIN_STATUS_NO_IN;
    return PIN_STATUS_OK;
}

std::pair<Pin_status, Measure> requestMeasure(Workstation& ws, InputClass inputClass, Pint number,
                                              const char* function) {
    const InputDevice& d = inputDevice(ws, inputClass, number, function);
    if (d.mode != OperatingMode::Request)
        throw Error(errors::NotRequestMode, function, "the device is not in REQUEST mode");
    WorkstationInput& input = ws.input();
    if (!input.source())
        throw Error(errors::DeviceNotAvailable, function,
                    "no input script is attached to workstation " + std::to_string(ws.id()));
    std::pair<InputStatus, Measure> result{InputStatus::None, d.current};
    for (;;) {  // a script answers at once; a window waits for the operator in slices
        const auto pumped =
            scripted(function, [&] { return input.pump(std::chrono::milliseconds(100), &d, &result); });
        if (pumped == WorkstationInput::Pumped::Broke) return {PIN_STATUS_NONE, d.current};
        if (pumped == WorkstationInput::Pumped::Satisfied) return {statusOf(result.second), result.second};
    }
}

Measure sampleMeasure(Workstation& ws, InputClass inputClass, Pint number, const char* function) {
    const InputDevice& d = inputDevice(ws, inputClass, number, function);
    if (d.mode != OperatingMode::Sample)
        throw Error(errors::NotSampleMode, function, "the device is not in SAMPLE mode");
    WorkstationInput& input = ws.input();
    if (input.source() && !input.source()->exhausted())
        scripted(function, [&] { return input.pump(std::chrono::milliseconds(0)); });
    return input.sample(inputClass, number);
}

void answerPickPath(const PickMeasure& m, Pint depth, Ppick_path* out, const char* function) {
    if (depth < 0) throw Error(kBadArgument, function, "negative pick path depth");
    require(out, function);
    // As the sample implementation: the path's real depth, and its first `depth` items (so an
    // application can tell a path was cut).
    const Pint real = static_cast<Pint>(m.path.size()), n = std::min(depth, real);
    if (n > 0) require(out->path_list, function);
    for (Pint i = 0; i < n; ++i) {
        const PickPathItem& item = m.path[static_cast<std::size_t>(i)];
        out->path_list[i] = {item.structureId, item.pickId, item.elementNumber};
    }
    out->depth = real;
}

void answerStroke(const StrokeMeasure& m, Pint* view, Ppoint_list3* out, const char* function) {
    require(out, function);
    if (!m.points.empty()) require(out->points, function);
    for (std::size_t i = 0; i < m.points.size(); ++i)
        out->points[i] = {static_cast<Pfloat>(m.points[i].x), static_cast<Pfloat>(m.points[i].y),
                          static_cast<Pfloat>(m.points[i].z)};
    out->num_points = static_cast<Pint>(m.points.size());
    if (view) *view = m.viewIndex;
}

void answerStroke(const StrokeMeasure& m, Pint* view, Ppoint_list* out, const char* function) {
    require(out, function);
    if (!m.points.empty()) require(out->points, function);
    for (std::size_t i = 0; i < m.points.size(); ++i)
        out->points[i] = {static_cast<Pfloat>(m.points[i].x), static_cast<Pfloat>(m.points[i].y)};
    out->num_points = static_cast<Pint>(m.points.size());
    if (view) *view = m.viewIndex;
}

void answerString(const StringMeasure& m, char* out, const char* function) {
    require(out, function);
    std::copy(m.text.begin(), m.text.end(), out);
    out[m.text.size()] = '\0';
}

}  // namespace phigs::c
