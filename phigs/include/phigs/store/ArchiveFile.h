#pragma once

#include "phigs/core/ErrorLog.h"
#include "phigs/store/Element.h"

#include <filesystem>
#include <map>
#include <vector>

namespace phigs {

/// One PHIGS archive file: structures (id -> elements) kept in memory and written back whole
/// after every change, to a temporary file in the same directory renamed over the old one, so
/// the file on disk is always a complete archive.
///
/// Format (version 1, text, UTF-8, tokens separated by white space):
///   PHIGS-ARCHIVE 1
///   STRUCTURE <id> <element count>        one per structure, ascending id
///   <ELEMENT_TYPE_NAME> <fields...>       one line per element (names as in ISO 9592,
///                                         spaces written as '_', e.g. POLYLINE_3)
///   END <structure count> <checksum>      FNV-1a 64 of every byte before "END", in hex
/// Fields: integers and reals in decimal (reals shortest round-trip), booleans 0/1, strings as
/// <byte count>:<bytes>, lists as <count> then the items, points as x y z, matrices as 16
/// reals column by column, colours as D r g b or I index, B-spline curves as degree, knots,
/// points, weights. A file that does not parse, misses its END line or fails its checksum is
/// refused with error 403 naming the file and the line.
class ArchiveFile {
public:
    /// Opens (creating when missing) the archive at `path`; error 400 / 403 on failure.
    ArchiveFile(std::filesystem::path path, ErrorLog* log);

    const std::filesystem::path& path() const { return path_; }
    const std::map<int, std::vector<Element>>& contents() const { return contents_; }
    bool contains(int id) const { return contents_.contains(id); }
    std::vector<int> structureIds() const;

    /// Replaces or adds structures and deletes others, then writes the file (error 903 on failure,
    /// leaving the old file and this object as they were).
    void commit(const std::map<int, std::vector<Element>>& put, const std::vector<int>& remove);

    /// Serializes / parses the format above (exposed for tests and tools).
    static std::string encode(const std::map<int, std::vector<Element>>& contents);
    /// Throws Error 403 naming `sourceName` and the line of the first problem.
    static std::map<int, std::vector<Element>> decode(const std::string& text, const std::string& sourceName,
                                                      ErrorLog* log);

private:
    std::filesystem::path path_;
    ErrorLog* log_;
    std::map<int, std::vector<Element>> contents_;
};

}  // namespace phigs
