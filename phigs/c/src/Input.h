#pragma once

// The C binding's input: the session beside the open system (the input queue, each
// workstation's script source, the data records INITIALIZE was given), the device lookups
// with the standard's errors, and the conversions between phigs.h's input types and the core's.

#include "Binding.h"
#include "phigs.h"
#include "phigs/input/InputDevice.h"
#include "phigs/input/ScriptInputSource.h"

#include <map>
#include <memory>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

namespace phigs::c {

/// Implementation errors of the input functions (negative: implementation-defined).
inline constexpr int kScriptEnded = PE_INPUT_SCRIPT_ENDED;  ///< a REQUEST's script ran out
inline constexpr int kEscapeRecord = 351;                   ///< a field of the escape data record is in error
inline constexpr int kNotOutIn = 60;                        ///< workstation not of category OUTIN
inline constexpr int kNotInput = 61;                        ///< workstation neither INPUT nor OUTIN
inline constexpr int kEchoTypeUnavailable = 253;            ///< warning: prompt/echo type 1 used instead
inline constexpr int kEchoAreaEmpty = 254;                  ///< echo area/volume with min >= max
inline constexpr int kEchoAreaOutside = 255;                ///< echo area/volume outside the display
inline constexpr int kBadViewIndex = 114;                   ///< view index less than zero
/// The largest stroke and string buffers and the most choice alternatives a device takes.
inline constexpr int kMaxBuffer = 4096;
inline constexpr int kMaxChoices = kMaxChoiceAlternatives;

/// One device's C data record as INITIALIZE gave it (what the core does not keep itself).
struct DeviceRecord {
    Pint initPos = 1;  ///< stroke, string: initial editing position
    Pfloat xInterval = 0, yInterval = 0, zInterval = 0, timeInterval = 0;  ///< stroke
    std::vector<Ppr_switch> prompts;                                       ///< choice type 2
};

/// The input state of the C binding beside the open system: one input queue, each
/// workstation's script source, the data records of initialised devices.
class InputSession {
public:
    /// The session of the system now open (made anew at each OPEN PHIGS).
    static InputSession& of();
    InputQueue& queue() { return *queue_; }
    /// Connects `ws`'s devices to `script` (dropping the script it had) and to the queue.
    void attachScript(Workstation& ws, std::unique_ptr<ScriptInputSource> script);
    /// Connects the devices of a window workstation with no source yet to its window.
    void connectWindow(Workstation& ws);
    /// CLOSE WORKSTATION: its script and records go.
    void forget(int ws);
    /// The record INITIALIZE left for a device, or null (never initialised).
    const DeviceRecord* record(int ws, InputClass inputClass, int device) const;
    void setRecord(int ws, InputClass inputClass, int device, DeviceRecord record);

private:
    InputSession();
    std::unique_ptr<InputQueue> queue_;
    std::map<int, std::unique_ptr<ScriptInputSource>> scripts_;
    std::map<std::tuple<int, InputClass, int>, DeviceRecord> records_;
};

/// The mouse and keys of a PWST_WINDOW workstation's own window (Outputs.cpp), or null.
InputSource* windowInputSource(Workstation& ws);
/// CLOSE WORKSTATION's part: the workstation's script and records go.
void forgetInput(int ws);
/// ESCAPE PUESC_INPUT_SCRIPT (errors 54, 61, 351).
void attachInputScript(Phigs& p, const Pescape_in_data* in);

/// The workstation of an input function: 3, 54, then 61 (60 for pick) unless it is OUTIN.
/// `inquiry`: raised without logging (the inquiries' error indicator); otherwise a window
/// workstation's devices are connected to its window when they have no source yet.
Workstation& inputWorkstation(Phigs& p, Pint id, InputClass inputClass, bool inquiry = false);
/// The device `number` of `ws`: 250 when it has none.
const InputDevice& inputDevice(const Workstation& ws, InputClass inputClass, Pint number,
                               const char* function);
/// The description of an input workstation type (52; 61 for an OUTPUT type; 250 for the device).
WorkstationDescription inputType(Pint type, InputClass inputClass, Pint number);

/// Pin_class and InputClass (PIN_NONE has none: 2202).
InputClass coreClass(const Pin_class& inputClass, const char* function);
Pin_class cClass(InputClass inputClass);
OperatingMode coreMode(const Pop_mode& mode, const char* function);
Pop_mode cMode(OperatingMode mode);
EchoSwitch coreEcho(const Pecho_switch& echo, const char* function);

/// An echo volume in device coordinates (y up) as the core's (pixels from the top left),
/// checked: 254 when min >= max, 255 outside the display space.
EchoVolume coreEchoVolume(const Workstation& ws, const Plimit3& volume, const char* function);
Plimit3 cEchoVolume(glm::dvec2 displaySize, const EchoVolume& volume);
/// The whole display space of a type, the default echo volume.
Plimit3 wholeDisplay(glm::dvec2 displaySize);
Plimit3 lift(const Plimit& area);
Plimit lower(const Plimit3& volume);

/// The prompt/echo types this binding offers for a class.
const std::vector<int>& promptEchoTypes(InputClass inputClass);

/// Pumps the workstation's script until the device's request is satisfied (status OK, or
/// NO_IN for a pick that hit nothing and choice 0) or broken (NONE). Errors 250, 251,
/// kScriptEnded, and kEscapeRecord for an action that does not fit its device.
std::pair<Pin_status, Measure> requestMeasure(Workstation& ws, InputClass inputClass, Pint number,
                                              const char* function);
/// SAMPLE: 250, 252; the script's next line (if any) is delivered first.
Measure sampleMeasure(Workstation& ws, InputClass inputClass, Pint number, const char* function);

/// Copies a pick path, cut to `depth` items, into the application's path.
void answerPickPath(const PickMeasure& measure, Pint depth, Ppick_path* out, const char* function);
/// Copies a stroke's points into the application's list (it holds the device's buffer).
void answerStroke(const StrokeMeasure& measure, Pint* view, Ppoint_list3* out, const char* function);
void answerStroke(const StrokeMeasure& measure, Pint* view, Ppoint_list* out, const char* function);
void answerString(const StringMeasure& measure, char* out, const char* function);
Pin_status statusOf(const Measure& measure);

}  // namespace phigs::c
