#include "phigs/input/InputTypes.h"

namespace phigs {

InputClass classOf(const Measure& measure) {
    // The variant's alternatives are declared in InputClass order.
    return static_cast<InputClass>(measure.index());
}

const char* nameOf(InputClass inputClass) {
    switch (inputClass) {
        case InputClass::Locator:
            return "LOCATOR";
        case InputClass::Stroke:
            return "STROKE";
        case InputClass::Valuator:
            return "VALUATOR";
        case InputClass::Choice:
            return "CHOICE";
        case InputClass::Pick:
            return "PICK";
        case InputClass::String:
            return "STRING";
    }
    return "UNKNOWN";
}

}  // namespace phigs
