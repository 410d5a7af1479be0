// The input inquiries: device states, default device data, the number of devices, queue
// overflow and simultaneous events. They answer through *err_ind only.

#include "Conversions.h"
#include "Input.h"
#include "Inquiry.h"

using phigs::c::InputAnswer;

namespace {

using namespace phigs;

/// What a device-state inquiry answers from: the workstation, the device, its record (null
/// before INITIALIZE) and the store's input answer (cleared).
struct DeviceState {
    const Workstation& ws;
    const InputDevice& device;
    const c::DeviceRecord* record;
    InputAnswer& answer;
};

/// INQUIRE <class> DEVICE STATE: errors 3, 54, 61 (60 for pick), 250, 2202, 2203; then `body`.
template <class Body>
void deviceState(Pint* err, Pint wsId, InputClass inputClass, Pint number, const Pinq_type* type,
                 Pstore store, Pop_mode* mode, Pecho_switch* echo, Pint* pet, Body&& body) {
    c::inquire(err, [&](Phigs& p) {
        const Workstation& ws = c::inputWorkstation(p, wsId, inputClass, true);
        const InputDevice& d = c::inputDevice(ws, inputClass, number, "inquiry");
        if (type && c::raw(*type) != PINQ_SET && c::raw(*type) != PINQ_REALIZED)
            throw Error(PE_ENUM_TYPE_INVAL, "inquiry", "type of returned values");
        Phigs_store& s = c::storeOf(store);
        s.clear();
        if (mode) *mode = c::cMode(d.mode);
        if (echo) *echo = d.echo == EchoSwitch::Echo ? PSWITCH_ECHO : PSWITCH_NO_ECHO;
        if (pet) *pet = d.setup.promptEchoType;
        body(DeviceState{ws, d, c::InputSession::of().record(ws.id(), inputClass, number), s.input});
    });
}

/// The device's echo volume in device coordinates (the whole display before INITIALIZE).
Plimit3 echoVolume(const DeviceState& s) {
    return s.record ? c::cEchoVolume(s.ws.displaySize(), s.device.setup.echoVolume)
                    : c::wholeDisplay(s.ws.displaySize());
}

template <class Out>
void put(Out* out, const Out& value) {
    if (out) *out = value;
}

Pstroke_data3 strokeRecord(const DeviceState& s) {
    const c::DeviceRecord r = s.record ? *s.record : c::DeviceRecord{};
    return {static_cast<Pint>(s.device.setup.bufferSize),
            r.initPos,
            r.xInterval,
            r.yInterval,
            r.zInterval,
            r.timeInterval,
            {}};
}

/// The initial stroke into the answer's memory.
void initialStroke(const DeviceState& s) {
    const auto& points = std::get<StrokeMeasure>(s.device.setup.initial).points;
    for (const auto& q : points) {
        s.answer.points3Memory.push_back(
            {static_cast<Pfloat>(q.x), static_cast<Pfloat>(q.y), static_cast<Pfloat>(q.z)});
        s.answer.pointsMemory.push_back({static_cast<Pfloat>(q.x), static_cast<Pfloat>(q.y)});
    }
    const auto n = static_cast<Pint>(points.size());
    s.answer.points3 = {n, n ? s.answer.points3Memory.data() : nullptr};
    s.answer.points = {n, n ? s.answer.pointsMemory.data() : nullptr};
}

/// The choice data record of the device's prompt/echo type.
Pchoice_data3* choiceRecord(const DeviceState& s) {
    Pchoice_data3& out = s.answer.choice;
    out = {};
    if (s.device.setup.promptEchoType == 2 && s.record) {
        s.answer.prompts = s.record->prompts;
        out.pets.pet_r2 = {static_cast<Pint>(s.answer.prompts.size()), s.answer.prompts.data()};
    } else if (s.device.setup.promptEchoType == 3) {
        s.answer.strings = s.device.setup.choiceStrings;
        for (std::string& text : s.answer.strings) s.answer.stringPointers.push_back(text.data());
        out.pets.pet_r3 = {static_cast<Pint>(s.answer.stringPointers.size()), s.answer.stringPointers.data()};
    }
    return &out;
}

/// The pick filter and initial path into the answer's memory.
void pickAnswer(const DeviceState& s, Pfilter** filter, Pin_status* status, Ppick_path** path) {
    InputAnswer& a = s.answer;
    a.inclusion.assign(s.device.pickInclusion.begin(), s.device.pickInclusion.end());
    a.exclusion.assign(s.device.pickExclusion.begin(), s.device.pickExclusion.end());
    a.filter = {{static_cast<Pint>(a.inclusion.size()), a.inclusion.data()},
                {static_cast<Pint>(a.exclusion.size()), a.exclusion.data()}};
    const auto& initial = std::get<PickMeasure>(s.device.setup.initial);
    for (const PickPathItem& item : initial.path)
        a.pathItems.push_back({item.structureId, item.pickId, item.elementNumber});
    a.path = {static_cast<Pint>(a.pathItems.size()), a.pathItems.empty() ? nullptr : a.pathItems.data()};
    put(filter, &a.filter);
    put(status, c::statusOf(initial));
    put(path, &a.path);
}

/// INQUIRE DEFAULT <class> DEVICE DATA: 52, 61, 250, 2203; the prompt/echo types into the
/// store, then `body` with the type's description.
template <class Body>
void defaultData(Pint* err, Pint type, InputClass inputClass, Pint number, Pstore store, Pint_list** pets,
                 Body&& body) {
    c::inquire(err, [&](Phigs&) {
        const WorkstationDescription d = c::inputType(type, inputClass, number);
        Phigs_store& s = c::storeOf(store);
        s.clear();
        s.input.petMemory = c::promptEchoTypes(inputClass);
        s.input.pets = {static_cast<Pint>(s.input.petMemory.size()), s.input.petMemory.data()};
        put(pets, &s.input.pets);
        body(d, s.input);
    });
}

/// INQUIRE PICK DEVICE STATE 3 with the inquiry type by address: pinq_pick_st forwards it
/// without an enum-typed load of a value the application may have passed out of range.
void pickState(Pint ws_id, Pint pick_num, const Pinq_type* type, Pstore store, Pint* err_ind,
               Pop_mode* op_mode, Pecho_switch* echo_switch, Pfilter** pick_filter, Pin_status* init_status,
               Ppick_path** init_pick, Pint* prompt_echo, Plimit3* echo_vol, Ppick_data3** pick_data,
               Ppath_order* order) {
    deviceState(err_ind, ws_id, InputClass::Pick, pick_num, type, store, op_mode, echo_switch, prompt_echo,
                [&](const DeviceState& s) {
                    pickAnswer(s, pick_filter, init_status, init_pick);
                    put(echo_vol, echoVolume(s));
                    put(pick_data, &s.answer.pick);
                    put(order, s.device.setup.pathOrder == PathOrder::TopFirst ? PORDER_TOP_FIRST
                                                                               : PORDER_BOTTOM_FIRST);
                });
}

}  // namespace

extern "C" {

void pinq_loc_st3(Pint ws_id, Pint loc_num, Pinq_type type, Pstore store, Pint* err_ind, Pop_mode* op_mode,
                  Pecho_switch* echo_switch, Pint* init_view_ind, Ppoint3* init_loc_pos, Pint* prompt_echo,
                  Plimit3* echo_vol, Ploc_data3** loc_data) {
    if (!c::somewhereToAnswer(err_ind, op_mode, echo_switch, init_view_ind, init_loc_pos, prompt_echo,
                              echo_vol, loc_data))
        return;
    deviceState(err_ind, ws_id, InputClass::Locator, loc_num, &type, store, op_mode, echo_switch, prompt_echo,
                [&](const DeviceState& s) {
                    const auto& l = std::get<LocatorMeasure>(s.device.setup.initial);
                    put(init_view_ind, l.viewIndex);
                    put(init_loc_pos, {static_cast<Pfloat>(l.position.x), static_cast<Pfloat>(l.position.y),
                                       static_cast<Pfloat>(l.position.z)});
                    put(echo_vol, echoVolume(s));
                    put(loc_data, &s.answer.loc);
                });
}

void pinq_loc_st(Pint ws_id, Pint loc_num, Pinq_type type, Pstore store, Pint* err_ind, Pop_mode* op_mode,
                 Pecho_switch* echo_switch, Pint* init_view_ind, Ppoint* init_loc_pos, Pint* prompt_echo,
                 Plimit* echo_area, Ploc_data** loc_data) {
    if (!c::somewhereToAnswer(err_ind, op_mode, echo_switch, init_view_ind, init_loc_pos, prompt_echo,
                              echo_area, loc_data))
        return;
    deviceState(err_ind, ws_id, InputClass::Locator, loc_num, &type, store, op_mode, echo_switch, prompt_echo,
                [&](const DeviceState& s) {
                    const auto& l = std::get<LocatorMeasure>(s.device.setup.initial);
                    put(init_view_ind, l.viewIndex);
                    put(init_loc_pos, {static_cast<Pfloat>(l.position.x), static_cast<Pfloat>(l.position.y)});
                    put(echo_area, c::lower(echoVolume(s)));
                    put(loc_data, &s.answer.loc);
                });
}

void pinq_stroke_st3(Pint ws_id, Pint stroke_num, Pinq_type type, Pstore store, Pint* err_ind,
                     Pop_mode* op_mode, Pecho_switch* echo_switch, Pint* init_view_ind,
                     Ppoint_list3** init_stroke, Pint* prompt_echo, Plimit3* echo_vol,
                     Pstroke_data3** stroke_data) {
    if (!c::somewhereToAnswer(err_ind, op_mode, echo_switch, init_view_ind, init_stroke, prompt_echo,
                              echo_vol, stroke_data))
        return;
    deviceState(err_ind, ws_id, InputClass::Stroke, stroke_num, &type, store, op_mode, echo_switch,
                prompt_echo, [&](const DeviceState& s) {
                    put(init_view_ind, std::get<StrokeMeasure>(s.device.setup.initial).viewIndex);
                    initialStroke(s);
                    put(init_stroke, &s.answer.points3);
                    put(echo_vol, echoVolume(s));
                    s.answer.stroke3 = strokeRecord(s);
                    put(stroke_data, &s.answer.stroke3);
                });
}

void pinq_stroke_st(Pint ws_id, Pint stroke_num, Pinq_type type, Pstore store, Pint* err_ind,
                    Pop_mode* op_mode, Pecho_switch* echo_switch, Pint* init_view_ind,
                    Ppoint_list** init_stroke, Pint* prompt_echo, Plimit* echo_area,
                    Pstroke_data** stroke_data) {
    if (!c::somewhereToAnswer(err_ind, op_mode, echo_switch, init_view_ind, init_stroke, prompt_echo,
                              echo_area, stroke_data))
        return;
    deviceState(err_ind, ws_id, InputClass::Stroke, stroke_num, &type, store, op_mode, echo_switch,
                prompt_echo, [&](const DeviceState& s) {
                    put(init_view_ind, std::get<StrokeMeasure>(s.device.setup.initial).viewIndex);
                    initialStroke(s);
                    put(init_stroke, &s.answer.points);
                    put(echo_area, c::lower(echoVolume(s)));
                    const Pstroke_data3 r = strokeRecord(s);
                    s.answer.stroke = {r.buffer_size, r.init_pos,      r.x_interval,
                                       r.y_interval,  r.time_interval, {}};
                    put(stroke_data, &s.answer.stroke);
                });
}

void pinq_val_st3(Pint ws_id, Pint val_num, Pstore store, Pint* err_ind, Pop_mode* op_mode,
                  Pecho_switch* echo_switch, Pfloat* init_value, Pint* prompt_echo, Plimit3* echo_vol,
                  Pval_data3** val_data) {
    if (!c::somewhereToAnswer(err_ind, op_mode, echo_switch, init_value, prompt_echo, echo_vol, val_data))
        return;
    deviceState(err_ind, ws_id, InputClass::Valuator, val_num, nullptr, store, op_mode, echo_switch,
                prompt_echo, [&](const DeviceState& s) {
                    put(init_value,
                        static_cast<Pfloat>(std::get<ValuatorMeasure>(s.device.setup.initial).value));
                    put(echo_vol, echoVolume(s));
                    s.answer.val = {static_cast<Pfloat>(s.device.setup.valuatorLow),
                                    static_cast<Pfloat>(s.device.setup.valuatorHigh),
                                    {}};
                    put(val_data, &s.answer.val);
                });
}

void pinq_val_st(Pint ws_id, Pint val_num, Pstore store, Pint* err_ind, Pop_mode* op_mode,
                 Pecho_switch* echo_switch, Pfloat* init_value, Pint* prompt_echo, Plimit* echo_area,
                 Pval_data** val_data) {
    if (!c::somewhereToAnswer(err_ind, op_mode, echo_switch, init_value, prompt_echo, echo_area, val_data))
        return;
    Plimit3 volume{};
    pinq_val_st3(ws_id, val_num, store, err_ind, op_mode, echo_switch, init_value, prompt_echo, &volume,
                 val_data);
    if (err_ind && *err_ind == 0) put(echo_area, c::lower(volume));
}

void pinq_choice_st3(Pint ws_id, Pint choice_num, Pstore store, Pint* err_ind, Pop_mode* op_mode,
                     Pecho_switch* echo_switch, Pin_status* init_status, Pint* init_choice, Pint* prompt_echo,
                     Plimit3* echo_vol, Pchoice_data3** choice_data) {
    if (!c::somewhereToAnswer(err_ind, op_mode, echo_switch, init_status, init_choice, prompt_echo, echo_vol,
                              choice_data))
        return;
    deviceState(err_ind, ws_id, InputClass::Choice, choice_num, nullptr, store, op_mode, echo_switch,
                prompt_echo, [&](const DeviceState& s) {
                    const auto& ch = std::get<ChoiceMeasure>(s.device.setup.initial);
                    put(init_status, c::statusOf(s.device.setup.initial));
                    put(init_choice, ch.choice);
                    put(echo_vol, echoVolume(s));
                    put(choice_data, choiceRecord(s));
                });
}

void pinq_choice_st(Pint ws_id, Pint choice_num, Pstore store, Pint* err_ind, Pop_mode* op_mode,
                    Pecho_switch* echo_switch, Pin_status* init_status, Pint* init_choice, Pint* prompt_echo,
                    Plimit* echo_area, Pchoice_data** choice_data) {
    if (!c::somewhereToAnswer(err_ind, op_mode, echo_switch, init_status, init_choice, prompt_echo, echo_area,
                              choice_data))
        return;
    Plimit3 volume{};
    pinq_choice_st3(ws_id, choice_num, store, err_ind, op_mode, echo_switch, init_status, init_choice,
                    prompt_echo, &volume, choice_data);
    if (err_ind && *err_ind == 0) put(echo_area, c::lower(volume));
}

void pinq_pick_st3(Pint ws_id, Pint pick_num, Pinq_type type, Pstore store, Pint* err_ind, Pop_mode* op_mode,
                   Pecho_switch* echo_switch, Pfilter** pick_filter, Pin_status* init_status,
                   Ppick_path** init_pick, Pint* prompt_echo, Plimit3* echo_vol, Ppick_data3** pick_data,
                   Ppath_order* order) {
    if (!c::somewhereToAnswer(err_ind, op_mode, echo_switch, pick_filter, init_status, init_pick, prompt_echo,
                              echo_vol, pick_data, order))
        return;
    pickState(ws_id, pick_num, &type, store, err_ind, op_mode, echo_switch, pick_filter, init_status,
              init_pick, prompt_echo, echo_vol, pick_data, order);
}

void pinq_pick_st(Pint ws_id, Pint pick_num, Pinq_type type, Pstore store, Pint* err_ind, Pop_mode* op_mode,
                  Pecho_switch* echo_switch, Pfilter** pick_filter, Pin_status* init_status,
                  Ppick_path** init_pick, Pint* prompt_echo, Plimit* echo_area, Ppick_data** pick_data,
                  Ppath_order* order) {
    if (!c::somewhereToAnswer(err_ind, op_mode, echo_switch, pick_filter, init_status, init_pick, prompt_echo,
                              echo_area, pick_data, order))
        return;
    Plimit3 volume{};
    pickState(ws_id, pick_num, &type, store, err_ind, op_mode, echo_switch, pick_filter, init_status,
              init_pick, prompt_echo, &volume, pick_data, order);
    if (err_ind && *err_ind == 0) put(echo_area, c::lower(volume));
}

void pinq_string_st3(Pint ws_id, Pint string_num, Pstore store, Pint* err_ind, Pop_mode* op_mode,
                     Pecho_switch* echo_switch, char** init_string, Pint* prompt_echo, Plimit3* echo_vol,
                     Pstring_data3** string_data) {
    if (!c::somewhereToAnswer(err_ind, op_mode, echo_switch, init_string, prompt_echo, echo_vol, string_data))
        return;
    deviceState(err_ind, ws_id, InputClass::String, string_num, nullptr, store, op_mode, echo_switch,
                prompt_echo, [&](const DeviceState& s) {
                    s.answer.text = std::get<StringMeasure>(s.device.setup.initial).text;
                    put(init_string, s.answer.text.data());
                    put(echo_vol, echoVolume(s));
                    s.answer.string = {
                        static_cast<Pint>(s.device.setup.bufferSize), s.record ? s.record->initPos : 1, {}};
                    put(string_data, &s.answer.string);
                });
}

void pinq_string_st(Pint ws_id, Pint string_num, Pstore store, Pint* err_ind, Pop_mode* op_mode,
                    Pecho_switch* echo_switch, char** init_string, Pint* prompt_echo, Plimit* echo_area,
                    Pstring_data** string_data) {
    if (!c::somewhereToAnswer(err_ind, op_mode, echo_switch, init_string, prompt_echo, echo_area,
                              string_data))
        return;
    Plimit3 volume{};
    pinq_string_st3(ws_id, string_num, store, err_ind, op_mode, echo_switch, init_string, prompt_echo,
                    &volume, string_data);
    if (err_ind && *err_ind == 0) put(echo_area, c::lower(volume));
}

void pinq_def_loc_data3(Pint ws_type, Pint loc_num, Pstore store, Pint* err_ind, Ppoint3* loc_pos,
                        Pint_list** pet_list, Plimit3* echo_vol, Ploc_data3** loc_data) {
    if (!c::somewhereToAnswer(err_ind, loc_pos, pet_list, echo_vol, loc_data)) return;
    defaultData(err_ind, ws_type, InputClass::Locator, loc_num, store, pet_list,
                [&](const WorkstationDescription& d, InputAnswer& a) {
                    put(loc_pos, Ppoint3{0, 0, 0});
                    put(echo_vol, c::wholeDisplay(d.displaySize));
                    put(loc_data, &a.loc);
                });
}

void pinq_def_loc_data(Pint ws_type, Pint loc_num, Pstore store, Pint* err_ind, Ppoint* loc_pos,
                       Pint_list** pet_list, Plimit* echo_area, Ploc_data** loc_data) {
    if (!c::somewhereToAnswer(err_ind, loc_pos, pet_list, echo_area, loc_data)) return;
    defaultData(err_ind, ws_type, InputClass::Locator, loc_num, store, pet_list,
                [&](const WorkstationDescription& d, InputAnswer& a) {
                    put(loc_pos, Ppoint{0, 0});
                    put(echo_area, c::lower(c::wholeDisplay(d.displaySize)));
                    put(loc_data, &a.loc);
                });
}

void pinq_def_stroke_data3(Pint ws_type, Pint stroke_num, Pstore store, Pint* err_ind, Pint* max_buf_size,
                           Pint_list** pet_list, Plimit3* echo_vol, Pstroke_data3** stroke_data) {
    if (!c::somewhereToAnswer(err_ind, max_buf_size, pet_list, echo_vol, stroke_data)) return;
    defaultData(err_ind, ws_type, InputClass::Stroke, stroke_num, store, pet_list,
                [&](const WorkstationDescription& d, InputAnswer& a) {
                    put(max_buf_size, c::kMaxBuffer);
                    put(echo_vol, c::wholeDisplay(d.displaySize));
                    a.stroke3 = {256, 1, 0, 0, 0, 0, {}};
                    put(stroke_data, &a.stroke3);
                });
}

void pinq_def_stroke_data(Pint ws_type, Pint stroke_num, Pstore store, Pint* err_ind, Pint* max_buf_size,
                          Pint_list** pet_list, Plimit* echo_area, Pstroke_data** stroke_data) {
    if (!c::somewhereToAnswer(err_ind, max_buf_size, pet_list, echo_area, stroke_data)) return;
    defaultData(err_ind, ws_type, InputClass::Stroke, stroke_num, store, pet_list,
                [&](const WorkstationDescription& d, InputAnswer& a) {
                    put(max_buf_size, c::kMaxBuffer);
                    put(echo_area, c::lower(c::wholeDisplay(d.displaySize)));
                    a.stroke = {256, 1, 0, 0, 0, {}};
                    put(stroke_data, &a.stroke);
                });
}

void pinq_def_val_data3(Pint ws_type, Pint val_num, Pstore store, Pint* err_ind, Pfloat* def_value,
                        Pint_list** pet_list, Plimit3* echo_vol, Pval_data3** val_data) {
    if (!c::somewhereToAnswer(err_ind, def_value, pet_list, echo_vol, val_data)) return;
    defaultData(err_ind, ws_type, InputClass::Valuator, val_num, store, pet_list,
                [&](const WorkstationDescription& d, InputAnswer& a) {
                    put(def_value, Pfloat{0});
                    put(echo_vol, c::wholeDisplay(d.displaySize));
                    a.val = {0, 1, {}};
                    put(val_data, &a.val);
                });
}

void pinq_def_val_data(Pint ws_type, Pint val_num, Pstore store, Pint* err_ind, Pfloat* def_value,
                       Pint_list** pet_list, Plimit* echo_area, Pval_data** val_data) {
    if (!c::somewhereToAnswer(err_ind, def_value, pet_list, echo_area, val_data)) return;
    Plimit3 volume{};
    pinq_def_val_data3(ws_type, val_num, store, err_ind, def_value, pet_list, &volume, val_data);
    if (err_ind && *err_ind == 0) put(echo_area, c::lower(volume));
}

void pinq_def_choice_data3(Pint ws_type, Pint choice_num, Pstore store, Pint* err_ind, Pint* max_choices,
                           Pint_list** pet_list, Plimit3* echo_vol, Pchoice_data3** choice_data) {
    if (!c::somewhereToAnswer(err_ind, max_choices, pet_list, echo_vol, choice_data)) return;
    defaultData(err_ind, ws_type, InputClass::Choice, choice_num, store, pet_list,
                [&](const WorkstationDescription& d, InputAnswer& a) {
                    put(max_choices, c::kMaxChoices);
                    put(echo_vol, c::wholeDisplay(d.displaySize));
                    put(choice_data, &a.choice);
                });
}

void pinq_def_choice_data(Pint ws_type, Pint choice_num, Pstore store, Pint* err_ind, Pint* max_choices,
                          Pint_list** pet_list, Plimit* echo_area, Pchoice_data** choice_data) {
    if (!c::somewhereToAnswer(err_ind, max_choices, pet_list, echo_area, choice_data)) return;
    Plimit3 volume{};
    pinq_def_choice_data3(ws_type, choice_num, store, err_ind, max_choices, pet_list, &volume, choice_data);
    if (err_ind && *err_ind == 0) put(echo_area, c::lower(volume));
}

void pinq_def_pick_data3(Pint ws_type, Pint pick_num, Pstore store, Pint* err_ind, Pint_list** pet_list,
                         Plimit3* echo_vol, Ppick_data3** pick_data) {
    if (!c::somewhereToAnswer(err_ind, pet_list, echo_vol, pick_data)) return;
    defaultData(err_ind, ws_type, InputClass::Pick, pick_num, store, pet_list,
                [&](const WorkstationDescription& d, InputAnswer& a) {
                    put(echo_vol, c::wholeDisplay(d.displaySize));
                    put(pick_data, &a.pick);
                });
}

void pinq_def_pick_data(Pint ws_type, Pint pick_num, Pstore store, Pint* err_ind, Pint_list** pet_list,
                        Plimit* echo_area, Ppick_data** pick_data) {
    if (!c::somewhereToAnswer(err_ind, pet_list, echo_area, pick_data)) return;
    Plimit3 volume{};
    pinq_def_pick_data3(ws_type, pick_num, store, err_ind, pet_list, &volume, pick_data);
    if (err_ind && *err_ind == 0) put(echo_area, c::lower(volume));
}

void pinq_def_string_data3(Pint ws_type, Pint string_num, Pstore store, Pint* err_ind, Pint* max_buf_size,
                           Pint_list** pet_list, Plimit3* echo_vol, Pstring_data3** string_data) {
    if (!c::somewhereToAnswer(err_ind, max_buf_size, pet_list, echo_vol, string_data)) return;
    defaultData(err_ind, ws_type, InputClass::String, string_num, store, pet_list,
                [&](const WorkstationDescription& d, InputAnswer& a) {
                    put(max_buf_size, c::kMaxBuffer);
                    put(echo_vol, c::wholeDisplay(d.displaySize));
                    a.string = {256, 1, {}};
                    put(string_data, &a.string);
                });
}

void pinq_def_string_data(Pint ws_type, Pint string_num, Pstore store, Pint* err_ind, Pint* max_buf_size,
                          Pint_list** pet_list, Plimit* echo_area, Pstring_data** string_data) {
    if (!c::somewhereToAnswer(err_ind, max_buf_size, pet_list, echo_area, string_data)) return;
    Plimit3 volume{};
    pinq_def_string_data3(ws_type, string_num, store, err_ind, max_buf_size, pet_list, &volume, string_data);
    if (err_ind && *err_ind == 0) put(echo_area, c::lower(volume));
}

void pinq_num_avail_in(Pint ws_type, Pint* err_ind, Pnum_in* num_in) {
    if (!c::somewhereToAnswer(err_ind, num_in)) return;
    c::inquire(err_ind, [&](Phigs&) {
        const DeviceCounts n = c::inputType(ws_type, InputClass::Locator, 1).inputDevices;
        put(num_in, Pnum_in{n.locator, n.stroke, n.valuator, n.choice, n.pick, n.string});
    });
}

void pinq_in_overf(Pint* err_ind, Pint* ws_id, Pin_class* in_class, Pint* in_num) {
    if (!c::somewhereToAnswer(err_ind, ws_id, in_class, in_num)) return;
    c::inquire(err_ind, [&](Phigs& p) {
        if (!p.anyWorkstationOpen()) throw Error(errors::NoWorkstationOpen, "inquiry");
        const QueueOverflow o = c::InputSession::of().queue().inquireOverflow();
        put(ws_id, o.workstation);
        put(in_class, c::cClass(o.inputClass));
        put(in_num, o.device);
    });
}

void pinq_more_simult_events(Pint* err_ind, Pmore_simult_events* simult_events) {
    if (!c::somewhereToAnswer(err_ind, simult_events)) return;
    c::inquire(err_ind, [&](Phigs&) {
        put(simult_events,
            c::InputSession::of().queue().moreSimultaneousEvents() ? PSIMULT_MORE : PSIMULT_NO_MORE);
    });
}

}  // extern "C"
