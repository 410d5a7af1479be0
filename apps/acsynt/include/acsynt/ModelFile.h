#pragma once

#include "acsynt/AircraftDescription.h"

#include <filesystem>
#include <iosfwd>
#include <stdexcept>
#include <string>
#include <string_view>

namespace acsynt {

/// A bad aircraft description file: what() is "FILE:LINE: REASON"; the parts are kept apart
/// for the message line.
class ModelFileError : public std::runtime_error {
public:
    ModelFileError(std::string file, int line, std::string reason);
    const std::string& file() const { return file_; }
    int line() const { return line_; }
    const std::string& reason() const { return reason_; }

private:
    std::string file_;
    int line_;
    std::string reason_;
};

/// The format version this code reads and writes (`acsynt-model 1`).
inline constexpr int aircraftDescriptionVersion = 1;

/// A model or component name: 1 to 20 characters of letters, digits, '_', '-' and '.'.
bool isValidName(std::string_view name);

/// Parses a description (format in apps/acsynt/README.md). Any fault throws ModelFileError
/// naming fileName, the line and the reason; nothing is returned half-read.
AircraftDescription parseAircraftDescription(std::istream& in, const std::string& fileName);

/// parseAircraftDescription on a file; a file that cannot be opened is a ModelFileError at line 0.
AircraftDescription readAircraftDescription(const std::filesystem::path& path);

/// Writes a description that parseAircraftDescription reads back to the same values.
void writeAircraftDescription(std::ostream& out, const AircraftDescription& description);

}  // namespace acsynt
