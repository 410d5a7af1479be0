#pragma once

#include <stdexcept>
#include <string>

namespace phigs {

/// An input function refused its arguments: the PHIGS error number (ISO 9592, 250-263 for
/// input), the function that raised it and the reason. Nothing was changed when it is thrown.
class InputError : public std::runtime_error {
public:
    InputError(int number, std::string function, const std::string& reason)
        : std::runtime_error("PHIGS error " + std::to_string(number) + " in " + function + ": " + reason),
          number_(number),
          function_(std::move(function)) {}
    int number() const { return number_; }
    const std::string& function() const { return function_; }

private:
    int number_;
    std::string function_;
};

}  // namespace phigs
