#pragma once

#include "phigs/core/Error.h"
#include "phigs/input/InputTypes.h"

#include <chrono>
#include <cstddef>
#include <cstdint>
#include <deque>
#include <functional>
#include <optional>
#include <vector>

namespace phigs {

class WorkstationInput;

/// Which device's event could not be queued when the input queue overflowed.
struct QueueOverflow {
    int workstation = 0;
    InputClass inputClass = InputClass::Locator;
    int device = 0;
};

/// The PHIGS input queue shared by every workstation: event reports in arrival order with a
/// bound, AWAIT EVENT, the current event report read by `GET <device>`, FLUSH DEVICE EVENTS, the
/// overflow condition and simultaneous events.
class InputQueue {
public:
    explicit InputQueue(std::size_t capacity = 64);
    /// The workstations' inputs attached to it lose their connection (they keep their devices).
    ~InputQueue();
    InputQueue(const InputQueue&) = delete;
    InputQueue& operator=(const InputQueue&) = delete;

    /// Reports warning 256 (queue overflow) to `sink` when it happens (e.g. into the error log).
    void setWarningSink(std::function<void(const Error&)> sink) { warningSink_ = std::move(sink); }

    /// AWAIT EVENT: moves the oldest report to the current event report and returns it; with an
    /// empty queue, pumps the workstations' input sources until an event arrives or `timeout`
    /// passes (a script's `wait` line counts as the timeout). nullopt: no event (class NONE).
    std::optional<EventReport> awaitEvent(std::chrono::milliseconds timeout);

    /// `GET <device>`: the measure of the current event report; error 259 when the current report
    /// is of another class (or there is none).
    const Measure& currentMeasure(InputClass inputClass, const char* function) const;
    /// INQUIRE MORE SIMULTANEOUS EVENTS.
    bool moreSimultaneousEvents() const;

    /// FLUSH DEVICE EVENTS: removes the queued reports of one device.
    void flush(int workstation, InputClass inputClass, int device);
    /// Removes every report of a workstation (when it closes).
    void flushWorkstation(int workstation);

    /// INQUIRE INPUT QUEUE OVERFLOW: the device that overflowed, and the condition is cleared;
    /// error 257 when the queue has not overflowed, 258 (also clearing it) when that device's
    /// workstation has been closed since.
    QueueOverflow inquireOverflow();

    std::size_t size() const { return events_.size(); }
    std::size_t capacity() const { return capacity_; }

    /// Appends the reports one trigger produced, marked as simultaneous; all or none are queued
    /// (none when they do not fit: the overflow condition is set and warning 256 reported). After
    /// an overflow it takes none until AWAIT EVENT is called with the queue empty.
    void enqueue(std::vector<EventReport> reports);

    void attach(WorkstationInput& input);
    void detach(WorkstationInput& input);

private:
    std::size_t capacity_;
    struct Queued {
        EventReport report;
        std::uint64_t trigger = 0;  ///< reports of one trigger share it
    };
    std::deque<Queued> events_;
    std::uint64_t nextTrigger_ = 1;
    std::uint64_t currentTrigger_ = 0;
    std::optional<EventReport> current_;
    std::optional<QueueOverflow> overflow_;
    bool overflowWorkstationClosed_ = false;  ///< overflow_'s workstation has closed since
    bool closedByOverflow_ = false;           ///< overflowed and not yet emptied by AWAIT EVENT
    std::function<void(const Error&)> warningSink_;
    std::vector<WorkstationInput*> inputs_;
};

}  // namespace phigs
