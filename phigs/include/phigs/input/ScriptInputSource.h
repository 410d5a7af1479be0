#pragma once

#include "phigs/input/InputSource.h"

#include <filesystem>
#include <set>
#include <string>
#include <vector>

namespace phigs {

/// Raised for a session script that cannot be read; the message names file, line and reason.
class ScriptError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

/// An input source that replays a session script: one action per line,
///
///     pick X Y [device D]        locator X Y [device D]      stroke X1 Y1 X2 Y2 ... [device D]
///     valuator D VALUE           choice N|NAME [device D]    string TEXT (rest of the line)
///     move X Y [device D]        break                       wait
///     <directive> ARGS...        # comment
///
/// `#` starts a comment anywhere but on a string line, whose text (`#` included) runs to the
/// end of the line less the blanks at its ends.
/// X and Y are device coordinates (pixels from the top left). Directives are the words the
/// application registers (e.g. "snapshot"); any other word is an error. The whole script is
/// parsed up front, so a bad line is reported before anything runs. Limits: kMaxScriptBytes per
/// file, kMaxScriptLineLength per line, and no control characters but tab (and a CR before the
/// newline).
class ScriptInputSource : public InputSource {
public:
    static constexpr std::size_t kMaxScriptBytes = 16u << 20;
    static constexpr std::size_t kMaxScriptLineLength = 4096;

    /// Parses `text`; `name` is used in messages (usually the file name).
    ScriptInputSource(const std::string& text, std::string name, std::set<std::string> directives = {});
    /// Reads and parses a script file; throws ScriptError naming the file when it cannot be read.
    static ScriptInputSource fromFile(const std::filesystem::path& path,
                                      std::set<std::string> directives = {});

    std::optional<InputAction> next(std::chrono::milliseconds timeout) override;
    bool exhausted() const override { return cursor_ >= actions_.size(); }
    std::string position() const override;

    const std::vector<InputAction>& actions() const { return actions_; }

    /// One action as a script line: what the parser reads back to the same action where
    /// `readsBack` says so.
    static std::string format(const InputAction& action);
    /// Whether `format(action)` is one line this parser reads back as `action` (not so, for
    /// example, for a string with a blank at an end or a control character, a choice name or
    /// directive word holding a blank or `#`, a number that is not finite, a string on a device
    /// other than 1, a line over kMaxScriptLineLength).
    static bool readsBack(const InputAction& action);

private:
    std::string name_;
    std::vector<InputAction> actions_;
    std::size_t cursor_ = 0;
    int lastLine_ = 0;
};

}  // namespace phigs
