#pragma once

#include <cstddef>
#include <deque>
#include <optional>
#include <string>
#include <utility>

namespace acsynt {

/// An undo/redo stack of whole states (snapshots), each labelled with the change that followed
/// it; at most `depth` are kept (the oldest are dropped).
template <class State>
class History {
public:
    explicit History(std::size_t depth = 32) : depth_(depth < 1 ? 1 : depth) {}

    /// `before` is the state a change named `what` is about to leave; the redo stack is cleared.
    void record(State before, std::string what) {
        undo_.push_back({std::move(before), std::move(what)});
        if (undo_.size() > depth_) undo_.pop_front();
        redo_.clear();
    }
    /// The state before the last change and its name; `current` goes onto the redo stack.
    std::optional<std::pair<State, std::string>> undo(State current) {
        return move(undo_, redo_, std::move(current));
    }
    /// The state the last undo left and its change's name; `current` goes back onto the undo stack.
    std::optional<std::pair<State, std::string>> redo(State current) {
        return move(redo_, undo_, std::move(current));
    }
    std::size_t undoCount() const { return undo_.size(); }
    std::size_t redoCount() const { return redo_.size(); }

private:
    using Entry = std::pair<State, std::string>;
    static std::optional<Entry> move(std::deque<Entry>& from, std::deque<Entry>& to, State current) {
        if (from.empty()) return std::nullopt;
        Entry e = std::move(from.back());
        from.pop_back();
        to.push_back({std::move(current), e.second});
        return e;
    }

    std::size_t depth_;
    std::deque<Entry> undo_, redo_;
};

}  // namespace acsynt
