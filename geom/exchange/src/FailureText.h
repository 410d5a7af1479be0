#pragma once
// What an OpenCASCADE exception says, for our error messages (private to geom_exchange).

#include <Standard_Failure.hxx>

#include <string>

namespace geom::exchange {

/// The exception's message, or its type's name where it carries none.
inline std::string failureText(const Standard_Failure& e) {
    const char* text = e.GetMessageString();
    return text && *text ? text : e.DynamicType()->Name();
}

}  // namespace geom::exchange
