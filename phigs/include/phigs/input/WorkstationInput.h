#pragma once

#include "phigs/input/InputDevice.h"
#include "phigs/input/InputMeasurer.h"
#include "phigs/input/InputQueue.h"
#include "phigs/input/InputSource.h"

#include <chrono>
#include <cstdint>
#include <functional>
#include <map>
#include <optional>
#include <set>
#include <string>
#include <utility>
#include <vector>

namespace phigs {

/// The logical input devices of one workstation, fed by one input source: INITIALIZE, SET MODE,
/// REQUEST, SAMPLE, pick filters, device-state inquiries; event-mode reports go to the queue.
/// The devices exist from the start; the operator's actions reach them once a source and a
/// queue are connected.
class WorkstationInput {
public:
    /// The devices, not yet connected to a source (a Workstation owns one such).
    WorkstationInput(int workstation, const InputMeasurer& measurer, DeviceCounts counts = {});
    /// The devices, connected to `source` and `queue` at once.
    WorkstationInput(int workstation, InputSource& source, const InputMeasurer& measurer, InputQueue& queue,
                     DeviceCounts counts = {});
    ~WorkstationInput();
    WorkstationInput(const WorkstationInput&) = delete;
    WorkstationInput& operator=(const WorkstationInput&) = delete;

    int workstation() const { return workstation_; }
    const DeviceCounts& counts() const { return counts_; }

    /// Actions now come from `source` (it gets the echo layout) and event reports go to `queue`;
    /// both outlive the connection (a queue that goes first disconnects it). A new source on the
    /// same queue keeps this workstation's queued events and overflow; another queue drops them.
    void connect(InputSource& source, InputQueue& queue);
    /// Drops the connection; the devices keep their modes and measures.
    void disconnect();
    /// The connected source, or null.
    InputSource* source() const { return source_; }
    /// Called whenever what the echoes show may have changed: after each action taken from the
    /// source whose string echo moved (typing in a window) or that reached a device in SAMPLE or
    /// EVENT mode, when a REQUEST starts and ends, at SET MODE. The workstation shows its echo
    /// areas again, even inside a REQUEST.
    void setEchoListener(std::function<void()> listener) { echoListener_ = std::move(listener); }
    /// The source's string echo (nothing typed when none is connected).
    StringEcho stringEcho() const { return source_ ? source_->stringEcho() : StringEcho{}; }

    /// `INITIALIZE <class>`: the device must be in REQUEST mode (251) and the setup valid.
    void initialise(InputClass inputClass, int device, DeviceInitialisation setup);
    /// `SET <class> MODE`.
    void setMode(InputClass inputClass, int device, OperatingMode mode, EchoSwitch echo = EchoSwitch::Echo);
    /// SET PICK FILTER.
    void setPickFilter(int device, std::set<int> inclusion, std::set<int> exclusion);
    /// The panels and sliders of choice devices with prompt/echo type 3 and valuators with
    /// type 2 that are initialised with an echo area.
    EchoLayout echoLayout() const;
    /// Those of echoLayout() whose devices take input now (SAMPLE or EVENT mode, or a request
    /// waiting for them): only they turn clicks into choices and values (throughEcho), and the
    /// source is handed them whenever they change. A panel of an idle device is not drawn, and a
    /// click there is the pick or locator the operator meant.
    EchoLayout activeEchoLayout() const;

    /// SET PICK PATH DEPTH (0: the whole path).
    void setPickPathDepth(int device, int depth);
    /// `INQUIRE <class> DEVICE STATE`.
    const InputDevice& device(InputClass inputClass, int device) const;

    /// `REQUEST <class>`: waits for the operator to trigger this device; status NONE on a break.
    /// Error 250 (device not available) with no source connected.
    std::pair<InputStatus, Measure> request(InputClass inputClass, int device);
    /// The device a REQUEST waits on now (null when none does).
    const InputDevice* requested() const { return requested_; }
    /// Whether `d` takes input now: SAMPLE or EVENT mode, or a request waiting for it (its
    /// echo shows, its panel or slider takes clicks).
    bool takesInput(const InputDevice& d) const {
        return d.mode != OperatingMode::Request || requested_ == &d;
    }
    /// `SAMPLE <class>`: the device's current measure (device in SAMPLE mode, else 252).
    const Measure& sample(InputClass inputClass, int device) const;

    /// Handles lines addressed to the application (script directives such as "snapshot").
    void setDirectiveHandler(std::function<void(const action::Directive&, const InputAction&)> handler) {
        directiveHandler_ = std::move(handler);
    }
    /// Actions that reached no device (no device of their class was waiting), as messages.
    const std::vector<std::string>& ignoredActions() const { return ignored_; }
    /// Called with each such message as the action is taken (before the next one is read); a
    /// break with no request pending is noted but not handed to it.
    void setIgnoredHandler(std::function<void(const std::string&)> handler) {
        ignoredHandler_ = std::move(handler);
    }
    /// Every action taken from the source, in order (for recording a session).
    const std::vector<InputAction>& history() const { return history_; }
    /// Where the source is (a script's "NAME line N"), for messages.
    std::string position() const { return source_ ? source_->position() : "no source"; }
    /// While an action is measured, the drawable size it was made on (InputAction::surface), which
    /// the measurer maps its positions through; empty otherwise.
    const std::optional<glm::uvec2>& measuredActionSurface() const { return measuredSurface_; }

    /// Takes one action from the source (waiting at most `timeout`) and delivers it: sample
    /// devices take the new measure, event devices queue a report, a pending request of the
    /// matching device is satisfied. Returns what happened for the caller (the queue or REQUEST);
    /// Idle when the source had no action.
    enum class Pumped { Nothing, Delivered, Waited, Broke, Satisfied, Idle };
    Pumped pump(std::chrono::milliseconds timeout, const InputDevice* pending = nullptr,
                std::pair<InputStatus, Measure>* result = nullptr);
    /// With a live source, delivers what the operator did since the last input function, with no
    /// request pending (AWAIT EVENT and FLUSH DEVICE EVENTS call it first): events are queued in
    /// order (and may overflow the queue), sampled devices move; a trigger for a REQUEST-mode
    /// device reaches none. A resize or exposure meanwhile ends no wait (the application that
    /// draws the window sees its damage when the call returns). Nothing for a script.
    void catchUp();

private:
    InputDevice& lookup(InputClass inputClass, int device, const char* function);
    const InputDevice& lookup(InputClass inputClass, int device, const char* function) const;
    /// A pick or locator click inside a choice panel or valuator slider of the echo layout
    /// becomes that choice or value (what a window source does on its own for real clicks).
    InputAction throughEcho(const InputAction& action) const;
    std::vector<std::pair<InputDevice*, Measure>> measuresFor(const InputAction& action);
    Measure measureFor(InputDevice& device, const InputAction& action);
    void ignore(std::string message);
    /// Choice and valuator devices: the classes with menu panels and sliders (EchoLayout).
    static bool drawsPanels(InputClass inputClass) {
        return inputClass == InputClass::Choice || inputClass == InputClass::Valuator;
    }
    /// Hands the source activeEchoLayout() (after a change to a choice or valuator device).
    void layoutChanged() {
        if (source_) source_->setEchoLayout(activeEchoLayout());
    }
    /// The source's typing starts over from string device d's initial string.
    void startTyping(const InputDevice& d);
    void echoChanged() {
        if (echoListener_) echoListener_();
    }

    int workstation_;
    InputSource* source_ = nullptr;
    const InputMeasurer& measurer_;
    InputQueue* queue_ = nullptr;
    DeviceCounts counts_;
    std::function<void()> echoListener_;
    std::uint64_t echoEdits_ = 0;  ///< the source's string echo edits last seen
    const InputDevice* requested_ = nullptr;
    std::map<std::pair<InputClass, int>, InputDevice> devices_;
    std::function<void(const action::Directive&, const InputAction&)> directiveHandler_;
    std::vector<std::string> ignored_;
    std::function<void(const std::string&)> ignoredHandler_;
    std::vector<InputAction> history_;
    std::optional<glm::uvec2> measuredSurface_;
};

}  // namespace phigs
