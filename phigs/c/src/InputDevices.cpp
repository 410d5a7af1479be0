// INITIALIZE <class> (3 and 2D forms), SET <class> MODE and SET PICK FILTER.

#include "Conversions.h"
#include "Input.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <set>

using phigs::c::Binding;

namespace {

using namespace phigs;

/// The part of INITIALIZE that depends on the class: the initial measure and the data record
/// into the core's setup and the binding's record (errors 260 and 261 of the class).
using Fill = std::function<void(int pet, bool defaults, DeviceInitialisation&, c::DeviceRecord&)>;

/// INITIALIZE <class>: the workstation (3, 54, 61/60), the device (250), REQUEST mode (251),
/// the echo volume (254, 255), the view index (114, when `view` is given), the prompt/echo type
/// (warning 253: type 1 with the default data record), then `fill` and the core's checks.
/// Nothing changes on error.
void initialise(int function, Pint wsId, InputClass inputClass, Pint number, const Plimit3* volume, Pint pet,
                const Pint* view, const Fill& fill) {
    Binding::instance().call(function, [&](Phigs& p) {
        const char* name = c::inputFunctionName(function);
        Workstation& ws = c::inputWorkstation(p, wsId, inputClass);
        const InputDevice& d = c::inputDevice(ws, inputClass, number, name);
        if (d.mode != OperatingMode::Request)
            throw Error(errors::NotRequestMode, name, "the device is not in REQUEST mode");
        c::require(volume, name);
        DeviceInitialisation setup;
        setup.echoVolume = c::coreEchoVolume(ws, *volume, name);
        if (view && (*view < 0 || *view >= ws.description().viewTableSize))
            throw Error(c::kBadViewIndex, name, "initial view index " + std::to_string(*view));
        const std::vector<int>& types = c::promptEchoTypes(inputClass);
        const bool offered = std::find(types.begin(), types.end(), pet) != types.end();
        if (!offered)
            p.errorLog().record(
                Error(c::kEchoTypeUnavailable, name, "prompt/echo type " + std::to_string(pet)));
        setup.promptEchoType = offered ? pet : 1;
        c::DeviceRecord record;
        fill(setup.promptEchoType, !offered, setup, record);
        ws.input().initialise(inputClass, number, std::move(setup));
        c::InputSession::of().setRecord(ws.id(), inputClass, number, std::move(record));
    });
}

[[noreturn]] void badRecord(int function, const std::string& why) {
    throw Error(errors::BadInputDataRecord, c::inputFunctionName(function), why);
}

bool interval(Pfloat v) {
    return std::isfinite(v) && v >= 0;
}

/// A stroke or string buffer and editing position of a data record (260).
void checkBuffer(int function, Pint bufferSize, Pint initPos, std::size_t length) {
    if (bufferSize < 1 || bufferSize > c::kMaxBuffer)
        badRecord(function, "buffer size " + std::to_string(bufferSize) + " is outside [1, 4096]");
    if (initPos < 1 || static_cast<std::size_t>(initPos) > length + 1)
        badRecord(function,
                  "initial editing position " + std::to_string(initPos) + " is outside the initial value");
}

void initLocator(int function, Pint ws, Pint n, Pint view, const Ppoint3* at, Pint pet,
                 const Plimit3* volume) {
    initialise(function, ws, InputClass::Locator, n, volume, pet, &view,
               [&](int, bool, DeviceInitialisation& s, c::DeviceRecord&) {
                   c::require(at, c::inputFunctionName(function));
                   s.initial = LocatorMeasure{view, {at->x, at->y, at->z}};
               });
}

/// `stroke3` or `stroke` is the initial stroke (both null: the bad-argument error).
void initStroke(int function, Pint ws, Pint n, Pint view, const Ppoint_list3* stroke3,
                const Ppoint_list* stroke, Pint pet, const Plimit3* volume, const Pstroke_data3* data) {
    initialise(function, ws, InputClass::Stroke, n, volume, pet, &view,
               [&](int, bool defaults, DeviceInitialisation& s, c::DeviceRecord& r) {
                   const char* name = c::inputFunctionName(function);
                   std::vector<glm::dvec3> points =
                       stroke3 ? c::points(stroke3, name) : c::points(stroke, name);
                   Pstroke_data3 record{256, 1, 0, 0, 0, 0, {}};
                   if (!defaults) {
                       c::require(data, c::inputFunctionName(function));
                       record = *data;
                   }
                   checkBuffer(function, record.buffer_size, record.init_pos, points.size());
                   if (!interval(record.x_interval) || !interval(record.y_interval) ||
                       !interval(record.z_interval) || !interval(record.time_interval))
                       badRecord(function, "a stroke interval is negative");
                   s.bufferSize = static_cast<std::size_t>(record.buffer_size);
                   s.initial = StrokeMeasure{view, std::move(points)};
                   r.initPos = record.init_pos;
                   r.xInterval = record.x_interval, r.yInterval = record.y_interval;
                   r.zInterval = record.z_interval, r.timeInterval = record.time_interval;
               });
}

void initValuator(int function, Pint ws, Pint n, Pfloat value, Pint pet, const Plimit3* volume,
                  const Pval_data3* data) {
    initialise(function, ws, InputClass::Valuator, n, volume, pet, nullptr,
               [&](int, bool defaults, DeviceInitialisation& s, c::DeviceRecord&) {
                   Pval_data3 record{0, 1, {}};
                   if (!defaults) {
                       c::require(data, c::inputFunctionName(function));
                       record = *data;
                   }
                   s.valuatorLow = record.low, s.valuatorHigh = record.high;  // the core checks them (260)
                   s.initial = ValuatorMeasure{value};
               });
}

InputStatus initialStatus(const Pin_status& status, int function) {
    const int v = c::raw(status);
    if (v < PIN_STATUS_NONE || v > PIN_STATUS_NO_IN)
        throw Error(PE_ENUM_TYPE_INVAL, c::inputFunctionName(function), "input status");
    return v == PIN_STATUS_OK ? InputStatus::Ok : InputStatus::None;
}

/// The alternatives of a choice data record of type 2 (prompts) or 3 (strings), 260 when bad.
void choiceAlternatives(int function, int pet, const Pchoice_data3& data, DeviceInitialisation& s,
                        c::DeviceRecord& r) {
    const Pint n = pet == 2 ? data.pets.pet_r2.num_prompts : data.pets.pet_r3.num_strings;
    if (n < 1 || n > c::kMaxChoices)
        badRecord(function, std::to_string(n) + " alternatives (1 to 64 are possible)");
    for (Pint i = 0; i < n; ++i) {
        if (pet == 2) {
            c::require(data.pets.pet_r2.prompts, c::inputFunctionName(function));
            const int prompt = c::raw(data.pets.pet_r2.prompts[i]);
            if (prompt != PPR_OFF && prompt != PPR_ON)
                badRecord(function, "a prompt switch is neither ON nor OFF");
            r.prompts.push_back(static_cast<Ppr_switch>(prompt));
            s.choiceStrings.push_back(std::to_string(i + 1));
        } else {
            c::require(data.pets.pet_r3.strings, c::inputFunctionName(function));
            if (!data.pets.pet_r3.strings[i]) badRecord(function, "a choice string is NULL");
            s.choiceStrings.emplace_back(data.pets.pet_r3.strings[i]);
        }
    }
}

void initChoice(int function, Pint ws, Pint n, const Pin_status& status, Pint choice, Pint pet,
                const Plimit3* volume, const Pchoice_data3* data) {
    initialise(function, ws, InputClass::Choice, n, volume, pet, nullptr,
               [&](int type, bool defaults, DeviceInitialisation& s, c::DeviceRecord& r) {
                   if (type > 1 && !defaults) {
                       c::require(data, c::inputFunctionName(function));
                       choiceAlternatives(function, type, *data, s, r);
                   }
                   s.initial = ChoiceMeasure{initialStatus(status, function), choice};
               });
}

void initPick(int function, Pint ws, Pint n, const Pin_status& status, const Ppick_path* path, Pint pet,
              const Plimit3* volume, const Ppath_order& order) {
    initialise(function, ws, InputClass::Pick, n, volume, pet, nullptr,
               [&](int, bool, DeviceInitialisation& s, c::DeviceRecord&) {
                   const char* name = c::inputFunctionName(function);
                   const int o = c::raw(order);
                   if (o != PORDER_TOP_FIRST && o != PORDER_BOTTOM_FIRST)
                       throw Error(PE_ENUM_TYPE_INVAL, name, "path order");
                   PickMeasure initial{initialStatus(status, function), {}, {}};
                   if (initial.status == InputStatus::Ok) {
                       c::require(path, name);
                       const std::size_t depth = c::count(path->depth, name);
                       if (depth > 0) c::require(path->path_list, name);
                       for (std::size_t i = 0; i < depth; ++i)
                           initial.path.push_back({path->path_list[i].struct_id, path->path_list[i].elem_pos,
                                                   path->path_list[i].pick_id});
                   }
                   s.pathOrder = o == PORDER_TOP_FIRST ? PathOrder::TopFirst : PathOrder::BottomFirst;
                   s.initial = std::move(initial);
               });
}

void initString(int function, Pint ws, Pint n, const char* text, Pint pet, const Plimit3* volume,
                const Pstring_data3* data) {
    initialise(function, ws, InputClass::String, n, volume, pet, nullptr,
               [&](int, bool defaults, DeviceInitialisation& s, c::DeviceRecord& r) {
                   c::require(text, c::inputFunctionName(function));
                   Pstring_data3 record{256, 1, {}};
                   if (!defaults) {
                       c::require(data, c::inputFunctionName(function));
                       record = *data;
                   }
                   const std::string initial = text;
                   checkBuffer(function, record.buffer_size, record.init_pos, initial.size());
                   s.bufferSize = static_cast<std::size_t>(record.buffer_size);
                   s.initial = StringMeasure{initial};
                   r.initPos = record.init_pos;
               });
}

void setMode(int function, Pint wsId, InputClass inputClass, Pint number, const Pop_mode& mode,
             const Pecho_switch& echo) {
    Binding::instance().call(function, [&](Phigs& p) {
        const char* name = c::inputFunctionName(function);
        Workstation& ws = c::inputWorkstation(p, wsId, inputClass);
        c::inputDevice(ws, inputClass, number, name);
        const OperatingMode m = c::coreMode(mode, name);
        const EchoSwitch e = c::coreEcho(echo, name);
        ws.input().setMode(inputClass, number, m, e);
    });
}

/// The 2D forms' arguments as the 3D ones (null stays null, for the checks).
struct Lifted {
    Plimit3 volume{};
    const Plimit3* pointer = nullptr;
    explicit Lifted(const Plimit* area) {
        if (area) volume = c::lift(*area), pointer = &volume;
    }
};

}  // namespace

extern "C" {

void pinit_loc3(Pint ws_id, Pint loc_num, Pint init_view_ind, const Ppoint3* init_loc_pos, Pint pet,
                const Plimit3* echo_vol, const Ploc_data3* /*loc_data: no fields for types 1-3*/) {
    initLocator(Pfn_init_loc3, ws_id, loc_num, init_view_ind, init_loc_pos, pet, echo_vol);
}

void pinit_loc(Pint ws_id, Pint loc_num, Pint init_view_ind, const Ppoint* init_loc_pos, Pint pet,
               const Plimit* echo_area, const Ploc_data* /*loc_data*/) {
    const Lifted area(echo_area);
    const Ppoint3 at = init_loc_pos ? Ppoint3{init_loc_pos->x, init_loc_pos->y, 0} : Ppoint3{};
    initLocator(Pfn_init_loc, ws_id, loc_num, init_view_ind, init_loc_pos ? &at : nullptr, pet, area.pointer);
}

void pinit_stroke3(Pint ws_id, Pint stroke_num, Pint init_view_ind, const Ppoint_list3* init_stroke, Pint pet,
                   const Plimit3* echo_vol, const Pstroke_data3* stroke_data) {
    initStroke(Pfn_init_stroke3, ws_id, stroke_num, init_view_ind, init_stroke, nullptr, pet, echo_vol,
               stroke_data);
}

void pinit_stroke(Pint ws_id, Pint stroke_num, Pint init_view_ind, const Ppoint_list* init_stroke, Pint pet,
                  const Plimit* echo_area, const Pstroke_data* stroke_data) {
    const Lifted area(echo_area);
    Pstroke_data3 data{};
    if (stroke_data)
        data = {stroke_data->buffer_size,
                stroke_data->init_pos,
                stroke_data->x_interval,
                stroke_data->y_interval,
                0,
                stroke_data->time_interval,
                {}};
    initStroke(Pfn_init_stroke, ws_id, stroke_num, init_view_ind, nullptr, init_stroke, pet, area.pointer,
               stroke_data ? &data : nullptr);
}

void pinit_val3(Pint ws_id, Pint val_num, Pfloat init_value, Pint pet, const Plimit3* echo_vol,
                const Pval_data3* val_data) {
    initValuator(Pfn_init_val3, ws_id, val_num, init_value, pet, echo_vol, val_data);
}

void pinit_val(Pint ws_id, Pint val_num, Pfloat init_value, Pint pet, const Plimit* echo_area,
               const Pval_data* val_data) {
    const Lifted area(echo_area);
    initValuator(Pfn_init_val, ws_id, val_num, init_value, pet, area.pointer, val_data);
}

void pinit_choice3(Pint ws_id, Pint choice_num, Pin_status init_status, Pint init_choice, Pint pet,
                   const Plimit3* echo_vol, const Pchoice_data3* choice_data) {
    initChoice(Pfn_init_choice3, ws_id, choice_num, init_status, init_choice, pet, echo_vol, choice_data);
}

void pinit_choice(Pint ws_id, Pint choice_num, Pin_status init_status, Pint init_choice, Pint pet,
                  const Plimit* echo_area, const Pchoice_data* choice_data) {
    const Lifted area(echo_area);
    initChoice(Pfn_init_choice, ws_id, choice_num, init_status, init_choice, pet, area.pointer, choice_data);
}

void pinit_pick3(Pint ws_id, Pint pick_num, Pin_status init_status, const Ppick_path* init_pick, Pint pet,
                 const Plimit3* echo_vol, const Ppick_data3* /*pick_data: no fields*/, Ppath_order order) {
    initPick(Pfn_init_pick3, ws_id, pick_num, init_status, init_pick, pet, echo_vol, order);
}

void pinit_pick(Pint ws_id, Pint pick_num, Pin_status init_status, const Ppick_path* init_pick, Pint pet,
                const Plimit* echo_area, const Ppick_data* /*pick_data*/, Ppath_order order) {
    const Lifted area(echo_area);
    initPick(Pfn_init_pick, ws_id, pick_num, init_status, init_pick, pet, area.pointer, order);
}

void pinit_string3(Pint ws_id, Pint string_num, const char* init_string, Pint pet, const Plimit3* echo_vol,
                   const Pstring_data3* string_data) {
    initString(Pfn_init_string3, ws_id, string_num, init_string, pet, echo_vol, string_data);
}

void pinit_string(Pint ws_id, Pint string_num, const char* init_string, Pint pet, const Plimit* echo_area,
                  const Pstring_data* string_data) {
    const Lifted area(echo_area);
    initString(Pfn_init_string, ws_id, string_num, init_string, pet, area.pointer, string_data);
}

void pset_loc_mode(Pint ws_id, Pint loc_num, Pop_mode op_mode, Pecho_switch echo_switch) {
    setMode(Pfn_set_loc_mode, ws_id, InputClass::Locator, loc_num, op_mode, echo_switch);
}

void pset_stroke_mode(Pint ws_id, Pint stroke_num, Pop_mode op_mode, Pecho_switch echo_switch) {
    setMode(Pfn_set_stroke_mode, ws_id, InputClass::Stroke, stroke_num, op_mode, echo_switch);
}

void pset_val_mode(Pint ws_id, Pint val_num, Pop_mode op_mode, Pecho_switch echo_switch) {
    setMode(Pfn_set_val_mode, ws_id, InputClass::Valuator, val_num, op_mode, echo_switch);
}

void pset_choice_mode(Pint ws_id, Pint choice_num, Pop_mode op_mode, Pecho_switch echo_switch) {
    setMode(Pfn_set_choice_mode, ws_id, InputClass::Choice, choice_num, op_mode, echo_switch);
}

void pset_pick_mode(Pint ws_id, Pint pick_num, Pop_mode op_mode, Pecho_switch echo_switch) {
    setMode(Pfn_set_pick_mode, ws_id, InputClass::Pick, pick_num, op_mode, echo_switch);
}

void pset_string_mode(Pint ws_id, Pint string_num, Pop_mode op_mode, Pecho_switch echo_switch) {
    setMode(Pfn_set_string_mode, ws_id, InputClass::String, string_num, op_mode, echo_switch);
}

void pset_pick_filter(Pint ws_id, Pint pick_num, const Pfilter* filter) {
    Binding::instance().call(Pfn_set_pick_filter, [&](Phigs& p) {
        const char* name = "SET PICK FILTER";
        Workstation& ws = c::inputWorkstation(p, ws_id, InputClass::Pick);
        c::inputDevice(ws, InputClass::Pick, pick_num, name);
        c::require(filter, name);
        const std::vector<int> inclusion = c::ints(&filter->incl_set, name);
        const std::vector<int> exclusion = c::ints(&filter->excl_set, name);
        ws.input().setPickFilter(pick_num, {inclusion.begin(), inclusion.end()},
                                 {exclusion.begin(), exclusion.end()});
    });
}

}  // extern "C"
