#pragma once

#include "phigs/core/Error.h"

#include <cstddef>
#include <string>
#include <vector>

namespace phigs {

/// The PHIGS error file: every error and warning raised, in order, with its function.
class ErrorLog {
public:
    struct Entry {
        int number = 0;
        std::string function;
        std::string detail;
    };

    void record(const Error& error) {
        entries_.push_back({error.number(), error.function(), error.detail()});
    }
    const std::vector<Entry>& entries() const { return entries_; }
    std::size_t size() const { return entries_.size(); }
    void clear() { entries_.clear(); }
    /// The whole log as text, one "ERROR n in function: message (detail)" line per entry.
    std::string text() const;

private:
    std::vector<Entry> entries_;
};

/// Records `error` in `log` (when there is one) and throws it: the one way errors leave the core.
[[noreturn]] void raise(ErrorLog* log, int number, const char* function, std::string detail = {});

}  // namespace phigs
