#include "phigs/input/InputQueue.h"

#include "phigs/input/WorkstationInput.h"

#include <algorithm>
#include <stdexcept>

namespace phigs {

InputQueue::InputQueue(std::size_t capacity) : capacity_(capacity) {
    if (capacity_ < 1)
        throw std::invalid_argument("InputQueue: the input queue must hold at least one event");
}

void InputQueue::enqueue(std::vector<EventReport> reports) {
    if (reports.empty()) return;
    // After an overflow the queue takes nothing until AWAIT EVENT finds it empty (ISO 9592's
    // overflow condition): the lost reports are those of later triggers too.
    if (closedByOverflow_) return;
    if (events_.size() + reports.size() > capacity_) {
        const EventReport& first = reports.front();
        closedByOverflow_ = true;
        if (!overflow_) {
            overflow_ = QueueOverflow{first.workstation, first.inputClass, first.device};
            overflowWorkstationClosed_ = false;
        }
        if (warningSink_)
            warningSink_(Error(errors::InputQueueOverflowed, "AWAIT EVENT",
                               std::string("input queue overflowed; the ") + nameOf(first.inputClass) + " " +
                                   std::to_string(first.device) + " event of workstation " +
                                   std::to_string(first.workstation) + " was lost"));
        return;
    }
    const std::uint64_t trigger = nextTrigger_++;
    for (auto& r : reports) {
        r.moreSimultaneous = false;
        events_.push_back({std::move(r), trigger});
    }
}

std::optional<EventReport> InputQueue::awaitEvent(std::chrono::milliseconds timeout) {
    const auto takeFront = [this]() {
        Queued q = std::move(events_.front());
        events_.pop_front();
        currentTrigger_ = q.trigger;
        q.report.moreSimultaneous = !events_.empty() && events_.front().trigger == q.trigger;
        current_ = q.report;
        return q.report;
    };
    current_.reset();
    currentTrigger_ = 0;
    // What the operator did while the program was elsewhere is queued first, in order.
    for (WorkstationInput* input : std::vector<WorkstationInput*>(inputs_)) input->catchUp();
    if (!events_.empty()) return takeFront();
    closedByOverflow_ = false;  // emptied: the queue takes events again
    if (inputs_.empty()) return std::nullopt;

    // One source may wait the whole timeout; several share it in short slices.
    const auto deadline = std::chrono::steady_clock::now() + timeout;
    const auto slice = inputs_.size() == 1 ? timeout : std::min(timeout, std::chrono::milliseconds(10));
    for (;;) {
        bool waited = false;
        for (WorkstationInput* input : std::vector<WorkstationInput*>(inputs_)) {
            const auto remaining = std::chrono::duration_cast<std::chrono::milliseconds>(
                deadline - std::chrono::steady_clock::now());
            const auto give = std::max(std::chrono::milliseconds(0), std::min(slice, remaining));
            if (input->pump(give) == WorkstationInput::Pumped::Waited) waited = true;
            if (!events_.empty()) return takeFront();
        }
        if (waited || std::chrono::steady_clock::now() >= deadline) return std::nullopt;
    }
}

bool InputQueue::moreSimultaneousEvents() const {
    return current_ && !events_.empty() && events_.front().trigger == currentTrigger_;
}

const Measure& InputQueue::currentMeasure(InputClass inputClass, const char* function) const {
    if (!current_)
        throw Error(errors::InputClassMismatch, function,
                    "there is no current event report (AWAIT EVENT returned NONE)");
    if (current_->inputClass != inputClass)
        throw Error(errors::InputClassMismatch, function,
                    std::string("the current event report is of class ") + nameOf(current_->inputClass) +
                        ", not " + nameOf(inputClass));
    return current_->measure;
}

void InputQueue::flush(int workstation, InputClass inputClass, int device) {
    // The device's events the operator made before the flush are flushed too.
    for (WorkstationInput* input : std::vector<WorkstationInput*>(inputs_))
        if (input->workstation() == workstation) input->catchUp();
    std::erase_if(events_, [&](const Queued& q) {
        return q.report.workstation == workstation && q.report.inputClass == inputClass &&
               q.report.device == device;
    });
}

void InputQueue::flushWorkstation(int workstation) {
    std::erase_if(events_, [&](const Queued& q) { return q.report.workstation == workstation; });
}

QueueOverflow InputQueue::inquireOverflow() {
    if (!overflow_)
        throw Error(errors::InputQueueNotOverflowed, "INQUIRE INPUT QUEUE OVERFLOW",
                    "the input queue has not overflowed since the last inquiry");
    const QueueOverflow o = *overflow_;
    overflow_.reset();
    if (overflowWorkstationClosed_)
        throw Error(errors::OverflowWorkstationClosed, "INQUIRE INPUT QUEUE OVERFLOW",
                    "the input queue overflowed with an event of workstation " +
                        std::to_string(o.workstation) + ", which has been closed since");
    return o;
}

InputQueue::~InputQueue() {
    for (WorkstationInput* input : std::vector<WorkstationInput*>(inputs_)) input->disconnect();
}

void InputQueue::attach(WorkstationInput& input) {
    if (std::find(inputs_.begin(), inputs_.end(), &input) == inputs_.end()) inputs_.push_back(&input);
}

void InputQueue::detach(WorkstationInput& input) {
    std::erase(inputs_, &input);
    flushWorkstation(input.workstation());
    if (overflow_ && overflow_->workstation == input.workstation()) overflowWorkstationClosed_ = true;
}

}  // namespace phigs
