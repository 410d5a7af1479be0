#pragma once

#include <stdexcept>
#include <string>

namespace geom::exchange {

/// A file that cannot be written or read as IGES/STEP; what() is "FILE: REASON".
class ExchangeError : public std::runtime_error {
public:
    ExchangeError(std::string file, std::string reason)
        : std::runtime_error(file + ": " + reason), file_(std::move(file)), reason_(std::move(reason)) {}

    const std::string& file() const { return file_; }
    const std::string& reason() const { return reason_; }

private:
    std::string file_, reason_;
};

}  // namespace geom::exchange
