#include "phigs/input/InputDevice.h"

#include <cmath>

namespace phigs {

int promptEchoTypeCount(InputClass inputClass) {
    switch (inputClass) {
        case InputClass::Locator:
            return 3;  // 1 implementation cursor, 2 crosshair, 3 tracking cross
        case InputClass::Stroke:
            return 3;  // 1 implementation, 2 digital display, 3 markers
        case InputClass::Valuator:
            return 2;  // 1 implementation, 2 slider (drawn as structures)
        case InputClass::Choice:
            return 3;  // 1 implementation, 2 text highlight, 3 menu panel
        case InputClass::Pick:
            return 2;  // 1 highlight the primitive, 2 highlight the structure
        case InputClass::String:
            return 1;  // 1 implementation echo
    }
    return 1;
}

int validateInitialisation(InputClass inputClass, const DeviceInitialisation& setup, std::string& reason) {
    if (setup.promptEchoType < 1 || setup.promptEchoType > promptEchoTypeCount(inputClass)) {
        reason = "prompt/echo type " + std::to_string(setup.promptEchoType) + " is not supported (1.." +
                 std::to_string(promptEchoTypeCount(inputClass)) + ")";
        return 253;
    }
    const EchoVolume& e = setup.echoVolume;
    if (!(e.xmin < e.xmax && e.ymin < e.ymax && e.zmin <= e.zmax)) {
        reason = "echo volume is empty (need xmin < xmax, ymin < ymax, zmin <= zmax)";
        return 254;
    }
    if (classOf(setup.initial) != inputClass) {
        reason = std::string("initial measure is not a ") + nameOf(inputClass) + " measure";
        return 261;
    }
    switch (inputClass) {
        case InputClass::Valuator: {
            if (!(std::isfinite(setup.valuatorLow) && std::isfinite(setup.valuatorHigh) &&
                  setup.valuatorLow < setup.valuatorHigh)) {
                reason = "valuator range must be finite with low < high";
                return 260;
            }
            const double v = std::get<ValuatorMeasure>(setup.initial).value;
            if (!(v >= setup.valuatorLow && v <= setup.valuatorHigh)) {
                reason = "initial value " + std::to_string(v) + " is outside [" +
                         std::to_string(setup.valuatorLow) + ", " + std::to_string(setup.valuatorHigh) + "]";
                return 261;
            }
            break;
        }
        case InputClass::Choice: {
            const auto& c = std::get<ChoiceMeasure>(setup.initial);
            if (c.status == InputStatus::Ok && (c.choice < 1 || c.choice > choiceAlternatives(setup))) {
                reason = "initial choice " + std::to_string(c.choice) + " is not one of the alternatives";
                return 261;
            }
            break;
        }
        case InputClass::Stroke:
            if (setup.bufferSize < 1) {
                reason = "stroke buffer size must be at least 1";
                return 260;
            }
            if (std::get<StrokeMeasure>(setup.initial).points.size() > setup.bufferSize) {
                reason = "initial stroke has more points than the buffer holds";
                return 262;
            }
            break;
        case InputClass::String:
            if (setup.bufferSize < 1) {
                reason = "string buffer size must be at least 1";
                return 260;
            }
            if (std::get<StringMeasure>(setup.initial).text.size() > setup.bufferSize) {
                reason = "initial string is longer than the buffer";
                return 263;
            }
            break;
        case InputClass::Pick:
            if (!(std::isfinite(setup.pickAperture) && setup.pickAperture > 0.0)) {
                reason = "pick aperture must be a positive NPC distance";
                return 260;
            }
            break;
        case InputClass::Locator:
            break;
    }
    return 0;
}

int DeviceCounts::of(InputClass inputClass) const {
    switch (inputClass) {
        case InputClass::Locator:
            return locator;
        case InputClass::Stroke:
            return stroke;
        case InputClass::Valuator:
            return valuator;
        case InputClass::Choice:
            return choice;
        case InputClass::Pick:
            return pick;
        case InputClass::String:
            return string;
    }
    return 0;
}

}  // namespace phigs
