#pragma once

#include "phigs/input/InputTypes.h"

#include <set>
#include <string>
#include <vector>

namespace phigs {

/// What `INITIALIZE <device>` sets: the initial measure, prompt/echo type, echo volume and the
/// class's data record fields (only those of the device's class are used).
struct DeviceInitialisation {
    Measure initial;
    int promptEchoType = 1;
    EchoVolume echoVolume{0, 1, 0, 1, 0, 1};
    double valuatorLow = 0.0;   ///< valuator data record
    double valuatorHigh = 1.0;  ///< valuator data record
    /// Choice alternatives, 1-based in measures; empty: kMaxChoiceAlternatives numbered ones.
    std::vector<std::string> choiceStrings;
    std::size_t bufferSize = 256;               ///< stroke: points; string: bytes (whole UTF-8 characters)
    PathOrder pathOrder = PathOrder::TopFirst;  ///< pick
    double pickAperture = 0.01;                 ///< pick: half-size of the aperture in NPC
};

/// The most alternatives a choice device has (its workstation description's maximum).
inline constexpr int kMaxChoiceAlternatives = 64;

/// The number of alternatives a choice device initialised with `setup` offers.
inline int choiceAlternatives(const DeviceInitialisation& setup) {
    return setup.choiceStrings.empty() ? kMaxChoiceAlternatives
                                       : static_cast<int>(setup.choiceStrings.size());
}

/// The state of one logical input device: its class and number, mode, echo switch and what it
/// was initialised with, its pick filter, and its current measure (for SAMPLE).
struct InputDevice {
    InputClass inputClass = InputClass::Locator;
    int number = 1;
    OperatingMode mode = OperatingMode::Request;
    EchoSwitch echo = EchoSwitch::Echo;
    DeviceInitialisation setup;
    Measure current;
    /// Pick filter: a primitive is pickable when its name set meets the inclusion set and misses
    /// the exclusion set. Both start empty (ISO 9592), so nothing is pickable until SET PICK FILTER.
    std::set<int> pickInclusion;
    std::set<int> pickExclusion;
    int pickPathDepth = 0;  ///< 0: the whole path
};

/// How many devices of each class a workstation has (numbered from 1).
struct DeviceCounts {
    int locator = 1, stroke = 1, valuator = 12, choice = 4, pick = 1, string = 1;
    int of(InputClass inputClass) const;
};

/// Checks an initialisation against the rules of the device's class and returns the PHIGS error
/// number it breaks (253 echo type, 254 echo volume, 260 data record, 261 initial value,
/// 262 stroke buffer, 263 string buffer), or 0 when it is valid.
int validateInitialisation(InputClass inputClass, const DeviceInitialisation& setup, std::string& reason);

/// Number of prompt/echo types each class supports (1..n).
int promptEchoTypeCount(InputClass inputClass);

}  // namespace phigs
