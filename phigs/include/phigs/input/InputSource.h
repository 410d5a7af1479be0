#pragma once

#include "phigs/input/EchoLayout.h"
#include "phigs/input/InputAction.h"

#include <chrono>
#include <cstdint>
#include <optional>
#include <stdexcept>
#include <string>

namespace phigs {

/// What a string device's echo area shows while the operator types (a window; a script types
/// nothing): the text so far, or that the entry was cancelled (Escape). `edits` counts the
/// changes, so a reader redraws only when it moves.
struct StringEcho {
    std::string text;
    bool cancelled = false;
    std::uint64_t edits = 0;
};

/// Raised when a script runs out while the application still waits for input.
class InputExhausted : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

/// Where operator actions come from: a window (mouse, keys, on-screen panels) or a session
/// script. The application cannot tell the two apart.
class InputSource {
public:
    virtual ~InputSource() = default;
    /// The next action, waiting at most `timeout`; nullopt when none came in time. A source with
    /// nothing left to give throws InputExhausted.
    virtual std::optional<InputAction> next(std::chrono::milliseconds timeout) = 0;
    /// True once every action has been delivered (a script at its end; never for a window).
    virtual bool exhausted() const = 0;
    /// Where the source is, for messages ("session.txt line 12", "window").
    virtual std::string position() const = 0;
    /// The choice panels and valuator sliders now on the screen; a window maps clicks in them
    /// to choices and values, a script has no use for them.
    virtual void setEchoLayout(const EchoLayout&) {}
    /// The string echo now (typed text not yet accepted).
    virtual StringEcho stringEcho() const { return {}; }
    /// The text being typed starts over as `text`: a string device's initial string, which the
    /// operator edits, as a request for it starts or it enters SAMPLE or EVENT mode (a script's
    /// line is the whole string: no use for it).
    virtual void startString(const std::string& /*text*/) {}
    /// True once the operator closed the source (a window closed by its user): a REQUEST pending
    /// or made after it ends with status NONE, as a break does.
    virtual bool closed() const { return false; }
    /// True for an operator acting in real time (a window): what the operator did while no input
    /// function ran already happened, and AWAIT EVENT and FLUSH DEVICE EVENTS read it in first
    /// (WorkstationInput::catchUp). A script's lines happen when they are read.
    virtual bool live() const { return false; }
};

}  // namespace phigs
