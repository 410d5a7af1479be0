#pragma once

#include "acsynt/AircraftDescription.h"

#include <cstddef>
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

/// Limits of a description file (each a ModelFileError at the line that breaks it). The patch
/// budget bounds what a model costs the session: every patch is a structure, a pick target and
/// a tessellation.
inline constexpr std::size_t kModelFileMaxBytes = 1u << 20;
inline constexpr std::size_t kModelFileMaxLineLength = 4096;
inline constexpr std::size_t kModelMaxComponents = 64;  ///< components lofted, mirror images included
inline constexpr std::size_t kModelMaxPatches = 8192;   ///< all components, mirror images included
inline constexpr double kModelMaxLength = 1e6;          ///< places (from the origin) and sizes, model units

/// The patches the loft of `component` has (its mirror image has as many again).
std::size_t loftedPatchCount(const ComponentDescription& component);

/// Parses a description (format in apps/acsynt/README.md). Any fault throws ModelFileError
/// naming fileName, the line and the reason; nothing is returned half-read.
AircraftDescription parseAircraftDescription(std::istream& in, const std::string& fileName);

/// parseAircraftDescription on a file; a file that cannot be opened is a ModelFileError at line 0.
AircraftDescription readAircraftDescription(const std::filesystem::path& path);

/// Throws ModelFileError at line 0 where `path` is a directory, a device or a pipe (which could
/// block the open or never end) rather than a file: "is a directory" or "is not a regular file",
/// then `suffix`. A path that does not exist passes (its open fails with its own message).
void requireRegularFile(const std::filesystem::path& path, const std::string& suffix = {});

/// std::getline for text from any system: a line ends at "\n", "\r\n" or a lone "\r" (the old
/// Macintosh's files, which getline read as one line), and a UTF-8 byte-order mark before it is
/// dropped.
bool readTextLine(std::istream& in, std::string& line);

/// Writes a description that parseAircraftDescription reads back to the same values.
void writeAircraftDescription(std::ostream& out, const AircraftDescription& description);

}  // namespace acsynt
