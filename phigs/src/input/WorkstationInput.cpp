#include "phigs/input/WorkstationInput.h"

#include "phigs/core/Error.h"
#include "phigs/input/ScriptInputSource.h"

#include <algorithm>
#include <type_traits>

namespace phigs {
namespace {

constexpr InputClass allClasses[] = {InputClass::Locator, InputClass::Stroke, InputClass::Valuator,
                                     InputClass::Choice,  InputClass::Pick,   InputClass::String};

Measure defaultMeasure(InputClass inputClass) {
    switch (inputClass) {
        case InputClass::Locator:
            return LocatorMeasure{};
        case InputClass::Stroke:
            return StrokeMeasure{};
        case InputClass::Valuator:
            return ValuatorMeasure{};
        case InputClass::Choice:
            return ChoiceMeasure{InputStatus::Ok, 1};
        case InputClass::Pick:
            return PickMeasure{};
        case InputClass::String:
            return StringMeasure{};
    }
    return LocatorMeasure{};
}

std::string deviceName(InputClass inputClass, int device) {
    return std::string(nameOf(inputClass)) + " " + std::to_string(device);
}

/// The longest start of `text` of at most `bytes` bytes that cuts no UTF-8 character in two.
std::string utf8Prefix(const std::string& text, std::size_t bytes) {
    if (text.size() <= bytes) return text;
    std::size_t n = bytes;
    while (n > 0 && (static_cast<unsigned char>(text[n]) & 0xC0) == 0x80) --n;  // a continuation byte
    return text.substr(0, n);
}

}  // namespace

WorkstationInput::WorkstationInput(int workstation, const InputMeasurer& measurer, DeviceCounts counts)
    : workstation_(workstation), measurer_(measurer), counts_(counts) {
    for (InputClass c : allClasses) {
        for (int n = 1; n <= counts_.of(c); ++n) {
            InputDevice d;
            d.inputClass = c;
            d.number = n;
            d.setup.initial = defaultMeasure(c);
            d.current = d.setup.initial;
            devices_.emplace(std::make_pair(c, n), std::move(d));
        }
    }
}

WorkstationInput::WorkstationInput(int workstation, InputSource& source, const InputMeasurer& measurer,
                                   InputQueue& queue, DeviceCounts counts)
    : WorkstationInput(workstation, measurer, counts) {
    connect(source, queue);
}

WorkstationInput::~WorkstationInput() {
    disconnect();
}

void WorkstationInput::connect(InputSource& source, InputQueue& queue) {
    // A new source on the same queue leaves the queued events and any overflow as they are: only
    // leaving the queue (closing the workstation) removes them.
    if (queue_ != &queue) {
        disconnect();
        queue_ = &queue;
        queue_->attach(*this);
    }
    source_ = &source;
    echoEdits_ = source_->stringEcho().edits;
    layoutChanged();
}

void WorkstationInput::disconnect() {
    if (queue_) queue_->detach(*this);
    queue_ = nullptr;
    source_ = nullptr;
}

InputDevice& WorkstationInput::lookup(InputClass inputClass, int device, const char* function) {
    const auto it = devices_.find({inputClass, device});
    if (it == devices_.end())
        throw Error(errors::DeviceNotAvailable, function,
                    deviceName(inputClass, device) + " is not available on workstation " +
                        std::to_string(workstation_) + " (it has " + std::to_string(counts_.of(inputClass)) +
                        ")");
    return it->second;
}

const InputDevice& WorkstationInput::lookup(InputClass inputClass, int device, const char* function) const {
    return const_cast<WorkstationInput*>(this)->lookup(inputClass, device, function);
}

void WorkstationInput::initialise(InputClass inputClass, int device, DeviceInitialisation setup) {
    const char* function = "INITIALIZE DEVICE";
    InputDevice& d = lookup(inputClass, device, function);
    if (d.mode != OperatingMode::Request)
        throw Error(errors::NotRequestMode, function,
                    deviceName(inputClass, device) + " must be in REQUEST mode");
    std::string reason;
    if (const int number = validateInitialisation(inputClass, setup, reason))
        throw Error(number, function, deviceName(inputClass, device) + ": " + reason);
    d.setup = std::move(setup);
    d.current = d.setup.initial;
    if (drawsPanels(inputClass)) layoutChanged();
}

EchoLayout WorkstationInput::echoLayout() const {
    EchoLayout layout;
    for (const auto& [key, d] : devices_) {
        const EchoVolume& a = d.setup.echoVolume;
        if (!(a.xmax > a.xmin && a.ymax > a.ymin)) continue;
        if (key.first == InputClass::Choice && d.setup.promptEchoType == 3 && !d.setup.choiceStrings.empty())
            layout.panels.push_back({d.number, a, d.setup.choiceStrings});
        if (key.first == InputClass::Valuator && d.setup.promptEchoType == 2)
            layout.sliders.push_back({d.number, a, d.setup.valuatorLow, d.setup.valuatorHigh});
    }
    return layout;
}

EchoLayout WorkstationInput::activeEchoLayout() const {
    const EchoLayout all = echoLayout();
    auto active = [&](InputClass inputClass, int number) {
        return takesInput(devices_.at({inputClass, number}));
    };
    EchoLayout layout;
    for (const ChoicePanel& p : all.panels)
        if (active(InputClass::Choice, p.device)) layout.panels.push_back(p);
    for (const ValuatorSlider& s : all.sliders)
        if (active(InputClass::Valuator, s.device)) layout.sliders.push_back(s);
    return layout;
}

InputAction WorkstationInput::throughEcho(const InputAction& a) const {
    glm::dvec2 at;
    if (const auto* pick = std::get_if<action::Pick>(&a.what))
        at = pick->position;
    else if (const auto* locate = std::get_if<action::Locate>(&a.what))
        at = locate->position;
    else
        return a;
    const EchoLayout layout = activeEchoLayout();
    InputAction routed = a;
    for (const ChoicePanel& p : layout.panels)
        if (const auto n = p.choiceAt(at)) {
            routed.what = action::Choice{*n, p.device, {}};
            return routed;
        }
    for (const ValuatorSlider& s : layout.sliders)
        if (s.contains(at)) {
            routed.what = action::Valuator{s.device, s.valueAt(at)};
            return routed;
        }
    return a;
}

void WorkstationInput::setMode(InputClass inputClass, int device, OperatingMode mode, EchoSwitch echo) {
    InputDevice& d = lookup(inputClass, device, "SET DEVICE MODE");
    d.mode = mode;
    d.echo = echo;
    // A device entering SAMPLE or EVENT mode starts from its initial measure; a string device's
    // typing from its initial string.
    d.current = d.setup.initial;
    if (inputClass == InputClass::String && mode != OperatingMode::Request) startTyping(d);
    if (drawsPanels(inputClass)) layoutChanged();
    echoChanged();  // a device entering SAMPLE or EVENT mode with echo on shows it at once
}

void WorkstationInput::startTyping(const InputDevice& d) {
    // A window's keyboard types for string device 1 (action::String's device).
    const auto* initial = std::get_if<StringMeasure>(&d.setup.initial);
    if (source_ && d.number == 1) source_->startString(initial ? initial->text : std::string());
}

void WorkstationInput::setPickFilter(int device, std::set<int> inclusion, std::set<int> exclusion) {
    InputDevice& d = lookup(InputClass::Pick, device, "SET PICK FILTER");
    d.pickInclusion = std::move(inclusion);
    d.pickExclusion = std::move(exclusion);
}

void WorkstationInput::setPickPathDepth(int device, int depth) {
    if (depth < 0)
        throw Error(errors::NegativePathDepth, "SET PICK PATH DEPTH", "the path depth is less than zero");
    lookup(InputClass::Pick, device, "SET PICK PATH DEPTH").pickPathDepth = depth;
}

const InputDevice& WorkstationInput::device(InputClass inputClass, int device) const {
    return lookup(inputClass, device, "INQUIRE DEVICE STATE");
}

std::pair<InputStatus, Measure> WorkstationInput::request(InputClass inputClass, int device) {
    const InputDevice& d = lookup(inputClass, device, "REQUEST DEVICE");
    if (d.mode != OperatingMode::Request)
        throw Error(errors::NotRequestMode, "REQUEST DEVICE",
                    deviceName(inputClass, device) + " must be in REQUEST mode");
    if (!source_)
        throw Error(errors::DeviceNotAvailable, "REQUEST DEVICE",
                    "workstation " + std::to_string(workstation_) + " has no input source connected");
    std::pair<InputStatus, Measure> result{InputStatus::None, d.current};
    requested_ = &d;  // its echo shows while the request waits
    if (inputClass == InputClass::String) startTyping(d);
    // A requested menu or slider takes clicks while the request waits.
    const bool panel = drawsPanels(inputClass);
    if (panel) layoutChanged();
    // The request's echo goes when it ends, by a throw too (a bad script line); a failure to show
    // that is no reason to lose the request's own outcome.
    struct Clear {
        WorkstationInput& input;
        bool panel;
        ~Clear() {
            input.requested_ = nullptr;
            try {
                if (panel) input.layoutChanged();
                input.echoChanged();
            } catch (...) {
            }
        }
    } clear{*this, panel};
    echoChanged();
    for (;;) {
        const Pumped p = pump(std::chrono::milliseconds(100), &d, &result);
        if (p == Pumped::Satisfied || p == Pumped::Broke) break;
    }
    return result;
}

const Measure& WorkstationInput::sample(InputClass inputClass, int device) const {
    const InputDevice& d = lookup(inputClass, device, "SAMPLE DEVICE");
    if (d.mode != OperatingMode::Sample)
        throw Error(errors::NotSampleMode, "SAMPLE DEVICE",
                    deviceName(inputClass, device) + " must be in SAMPLE mode");
    return d.current;
}

void WorkstationInput::ignore(std::string message) {
    ignored_.push_back(std::move(message));
    if (ignoredHandler_) ignoredHandler_(ignored_.back());
}

Measure WorkstationInput::measureFor(InputDevice& device, const InputAction& a) {
    const auto fail = [&](const std::string& reason) -> void {
        throw ScriptError(position() + ": '" + a.text + "': " + reason);
    };
    return std::visit(
        [&](const auto& w) -> Measure {
            using T = std::decay_t<decltype(w)>;
            if constexpr (std::is_same_v<T, action::Pick>) {
                if (device.inputClass == InputClass::Locator) return measurer_.locate(w.position);
                return measurer_.pick(w.position, device);
            } else if constexpr (std::is_same_v<T, action::Locate> || std::is_same_v<T, action::Move>) {
                return measurer_.locate(w.position);
            } else if constexpr (std::is_same_v<T, action::Stroke>) {
                std::vector<glm::dvec2> points = w.points;
                if (points.size() > device.setup.bufferSize) points.resize(device.setup.bufferSize);
                return measurer_.stroke(points);
            } else if constexpr (std::is_same_v<T, action::Valuator>) {
                if (!(w.value >= device.setup.valuatorLow && w.value <= device.setup.valuatorHigh))
                    fail("value is outside the range [" + std::to_string(device.setup.valuatorLow) + ", " +
                         std::to_string(device.setup.valuatorHigh) + "] of VALUATOR " +
                         std::to_string(device.number));
                return ValuatorMeasure{w.value};
            } else if constexpr (std::is_same_v<T, action::Choice>) {
                const auto& names = device.setup.choiceStrings;
                int choice = w.choice;
                if (!w.name.empty()) {
                    const auto it = std::find(names.begin(), names.end(), w.name);
                    if (it == names.end())
                        fail("CHOICE " + std::to_string(device.number) + " has no alternative '" + w.name +
                             "'");
                    choice = static_cast<int>(it - names.begin()) + 1;
                }
                if (choice == 0) return ChoiceMeasure{InputStatus::None, 0};
                if (choice < 0 || choice > choiceAlternatives(device.setup))
                    fail("CHOICE " + std::to_string(device.number) + " has alternatives 1.." +
                         std::to_string(choiceAlternatives(device.setup)));
                return ChoiceMeasure{InputStatus::Ok, choice};
            } else if constexpr (std::is_same_v<T, action::String>) {
                return StringMeasure{utf8Prefix(w.text, device.setup.bufferSize)};
            } else {
                return device.current;
            }
        },
        a.what);
}

std::vector<std::pair<InputDevice*, Measure>> WorkstationInput::measuresFor(const InputAction& a) {
    std::vector<InputDevice*> triggered;
    const auto add = [&](InputClass c, int n) {
        const auto it = devices_.find({c, n});
        if (it != devices_.end()) triggered.push_back(&it->second);
    };
    std::visit(
        [&](const auto& w) {
            using T = std::decay_t<decltype(w)>;
            // A button press at a point triggers the pick and the locator of the same number:
            // the two events are simultaneous.
            if constexpr (std::is_same_v<T, action::Pick>) {
                add(InputClass::Pick, w.device);
                add(InputClass::Locator, w.device);
            } else if constexpr (std::is_same_v<T, action::Locate>) {
                add(InputClass::Locator, w.device);
            } else if constexpr (std::is_same_v<T, action::Move>) {
                // Motion is no trigger: it reaches only a locator that is sampled.
                const auto it = devices_.find({InputClass::Locator, w.device});
                if (it != devices_.end() && it->second.mode == OperatingMode::Sample)
                    triggered.push_back(&it->second);
            } else if constexpr (std::is_same_v<T, action::Stroke>) {
                add(InputClass::Stroke, w.device);
            } else if constexpr (std::is_same_v<T, action::Valuator>) {
                add(InputClass::Valuator, w.device);
            } else if constexpr (std::is_same_v<T, action::Choice>) {
                add(InputClass::Choice, w.device);
            } else if constexpr (std::is_same_v<T, action::String>) {
                add(InputClass::String, w.device);
            }
        },
        a.what);
    std::vector<std::pair<InputDevice*, Measure>> out;
    // Measure everything first, so an action that fails leaves every device unchanged.
    for (InputDevice* d : triggered) {
        try {
            out.emplace_back(d, measureFor(*d, a));
        } catch (const ScriptError& e) {
            if (!a.fromOperator) throw;
            ignore(e.what());  // an operator's: the device is not triggered, the others still are
        }
    }
    return out;
}

void WorkstationInput::catchUp() {
    if (!source_ || !source_->live()) return;
    // Bounded: an operator acting faster than the loop reads stops it after this many actions.
    constexpr int kMostActions = 4096;
    for (int i = 0; i < kMostActions; ++i)
        if (pump(std::chrono::milliseconds(0)) == Pumped::Idle) break;
}

WorkstationInput::Pumped WorkstationInput::pump(std::chrono::milliseconds timeout, const InputDevice* pending,
                                                std::pair<InputStatus, Measure>* result) {
    if (!source_) return Pumped::Idle;
    // A window its user closed gives no more input: a pending request ends as a break ends it.
    if (pending && result && source_->closed()) {
        *result = {InputStatus::None, pending->current};
        return Pumped::Broke;
    }
    std::optional<InputAction> a = source_->next(timeout);
    if (echoListener_) {
        // Typing moves the echo without completing an action: the echo areas show it now.
        const std::uint64_t edits = source_->stringEcho().edits;
        if (edits != echoEdits_) {
            echoEdits_ = edits;
            echoListener_();
        }
    }
    if (!a) return Pumped::Idle;
    if (const auto* wait = std::get_if<action::Wait>(&a->what)) {
        if (!wait->surfaceChanged) history_.push_back(*a);
        return Pumped::Waited;
    }
    history_.push_back(*a);
    if (const auto* d = std::get_if<action::Directive>(&a->what)) {
        if (directiveHandler_) directiveHandler_(*d, *a);
        return Pumped::Delivered;
    }
    if (std::holds_alternative<action::Break>(a->what)) {
        if (pending && result) {
            *result = {InputStatus::None, pending->current};
            return Pumped::Broke;
        }
        // Not handed to the ignored handler: Escape in a window is a break, and cancels quietly.
        ignored_.push_back(position() + ": 'break' with no request pending");
        return Pumped::Nothing;
    }

    measuredSurface_ = a->surface;
    struct Forget {
        std::optional<glm::uvec2>& surface;
        ~Forget() { surface.reset(); }
    } forget{measuredSurface_};
    auto measures = measuresFor(throughEcho(*a));
    std::vector<EventReport> reports;
    bool satisfied = false;
    bool reached = false;
    for (auto& [device, measure] : measures) {
        if (device == pending) {
            if (result) {
                const auto* pick = std::get_if<PickMeasure>(&measure);
                const auto* choice = std::get_if<ChoiceMeasure>(&measure);
                InputStatus status = InputStatus::Ok;
                if (pick) status = pick->status;
                if (choice) status = choice->status;
                *result = {status, measure};
            }
            satisfied = true;
            reached = true;
        } else if (device->mode == OperatingMode::Sample) {
            device->current = measure;
            reached = true;
        } else if (device->mode == OperatingMode::Event) {
            device->current = measure;
            reports.push_back({workstation_, device->inputClass, device->number, measure, false});
            reached = true;
        }
    }
    if (queue_) queue_->enqueue(std::move(reports));
    if (reached && !satisfied) echoChanged();  // a request's end shows its own
    if (!reached && std::holds_alternative<action::Move>(a->what)) {
        history_.pop_back();  // motion nobody samples is not worth recording
        return Pumped::Nothing;
    }
    if (!reached)
        ignore(position() + ": '" + a->text +
               "' reached no device (none of its class waits in a request, sample or event mode)");
    if (satisfied) return Pumped::Satisfied;
    return reached ? Pumped::Delivered : Pumped::Nothing;
}

}  // namespace phigs
