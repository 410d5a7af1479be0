#pragma once

#include "phigs/ws/WorkstationOutput.h"
#include "phigs/ws/WorkstationType.h"

#include <any>
#include <cstdint>
#include <functional>
#include <map>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

namespace phigs {

class Workstation;

/// What OPEN WORKSTATION opens a workstation's output on: its connection identifier and the
/// target's own settings.
struct OutputConnection {
    /// The connection identifier: a file name (hardcopies; the offscreen type's optional PNG), a
    /// display name (a window the output opens itself); empty: none.
    std::string identifier;
    /// The drawable in pixels; 0: the type's display size.
    std::uint32_t width = 0, height = 0;
    /// What the registering library documents: a vk::WindowSurface* (a window the program made),
    /// hardcopy::VectorSettings (page and surface drawing of a vector file).
    std::any settings;
};

/// An output factory's refusal of a connection it cannot use (OPEN WORKSTATION answers error 50).
class ConnectionRefused : public std::invalid_argument {
public:
    using std::invalid_argument::invalid_argument;
};

/// Makes the output of a workstation that is being opened; throws ConnectionRefused for a
/// connection it cannot use, another std::exception when the target cannot be made.
using OutputFactory =
    std::function<std::unique_ptr<WorkstationOutput>(Workstation&, const OutputConnection&)>;

/// The output factories by workstation type. The libraries that draw (phigs_vk, phigs_window,
/// phigs_hardcopy) add theirs with their registerOutputs(...), called by the program that links
/// them; OPEN WORKSTATION makes a type's output with its factory.
class OutputRegistry {
public:
    /// Adds (or replaces) the factory of `type`.
    void add(WorkstationType type, OutputFactory factory) { factories_[type] = std::move(factory); }
    /// The factory of `type`, or null.
    const OutputFactory* find(WorkstationType type) const {
        auto it = factories_.find(type);
        return it == factories_.end() ? nullptr : &it->second;
    }
    /// The types with a factory, in WorkstationType order.
    std::vector<WorkstationType> types() const {
        std::vector<WorkstationType> out;
        for (const auto& [type, factory] : factories_) out.push_back(type);
        return out;
    }
    bool empty() const { return factories_.empty(); }

private:
    std::map<WorkstationType, OutputFactory> factories_;
};

}  // namespace phigs
