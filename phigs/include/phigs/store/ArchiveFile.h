#pragma once

#include "phigs/core/ErrorLog.h"
#include "phigs/store/Element.h"

#include <cstddef>
#include <filesystem>
#include <map>
#include <vector>

namespace phigs {

/// One PHIGS archive file: structures (id -> elements) kept in memory and written back whole
/// after every change, to `<name>.tmp` in the same directory, flushed to the disk (fsync) and
/// renamed over the old one, the directory flushed after; so the file on disk is always a
/// complete archive, and a change that returned survives a crash. A `<name>.tmp` left by a killed
/// write is removed when the archive is opened.
///
/// Format (version 3, text, UTF-8, tokens separated by white space):
/// @verbatim
///   PHIGS-ARCHIVE 3
///   STRUCTURE <id> <element count>        one per structure, ascending id
///   <ELEMENT_TYPE_NAME> <fields...>       one line per element (names as in ISO 9592,
///                                         spaces written as '_', e.g. POLYLINE_3)
///   END <structure count> <checksum>      FNV-1a 64 of every byte before "END", in hex
/// @endverbatim
/// The checksum's offset basis is 1469598103934665603, one digit short of the standard FNV-1a's
/// 14695981039346656037 (the prime is the standard 1099511628211): every archive written so far
/// uses it, so it stays; a tool making an archive by hand must use it too.
/// Fields: integers and reals in decimal (reals shortest round-trip), booleans 0/1, strings as
/// `<byte count>:<bytes>`, lists as `<count>` then the items, points as x y z, matrices as 16
/// reals column by column, colours as D r g b (RGB), D<model> c1 c2 c3 (another colour
/// model, 2 .. 4) or I index, B-spline curves as degree, knots,
/// points, weights. A file that does not parse, misses its END line or fails its checksum is
/// refused with error 403 naming the file and the line.
///
/// Versions: files are written at version 3, versions 1 to 3 are read. Version 2 added, after
/// the fields of version 1, the facet colours and normals of triangle strips and quadrilateral
/// meshes, the edge flags of fill area set 3 with data, and the level-curve origin, direction and
/// levels of parametric surface characteristics. Version 3 added each trimming curve's
/// visibility and approximation (after a NURBS surface's loops). Fields a file's version lacks
/// read as empty or default.
///
/// Limits: a file of more than maxFileBytes (default kMaxFileBytes) is refused before it is
/// read (403) and never written (903). Every count is checked against the bytes left in the
/// file, each item needing at least the text of its smallest form (6 bytes for a point, 8 for
/// an element), before room is made for it, so a false count cannot make memory grow beyond
/// what the file itself holds (read, an archive takes at most about 23 bytes per file byte).
class ArchiveFile {
public:
    /// The largest archive file read or written by default (64 MiB).
    static constexpr std::size_t kMaxFileBytes = std::size_t{64} << 20;
    /// The format version written; every version from 1 up to it is read.
    static constexpr int kFormatVersion = 3;

    /// Opens (creating when missing) the archive at `path`; error 400 / 403 on failure.
    ArchiveFile(std::filesystem::path path, ErrorLog* log, std::size_t maxFileBytes = kMaxFileBytes);
    /// One object per open file: a copy would write the same file from contents of its own, and
    /// the last to write would silently undo the other's changes.
    ArchiveFile(const ArchiveFile&) = delete;
    ArchiveFile& operator=(const ArchiveFile&) = delete;
    ArchiveFile(ArchiveFile&&) = default;
    ArchiveFile& operator=(ArchiveFile&&) = default;

    const std::filesystem::path& path() const { return path_; }
    const std::map<int, std::vector<Element>>& contents() const { return contents_; }
    bool contains(int id) const { return contents_.contains(id); }
    std::vector<int> structureIds() const;

    /// Replaces or adds structures and deletes others, then writes the file (error 903 on failure,
    /// leaving the old file and this object as they were). Writes nothing when nothing changes.
    void commit(const std::map<int, std::vector<Element>>& put, const std::vector<int>& remove);

    /// Serializes / parses the format above (exposed for tests and tools).
    static std::string encode(const std::map<int, std::vector<Element>>& contents);
    /// Throws Error 403 naming `sourceName`, the line of the first problem and, for a count, the
    /// bytes it would need and the bytes left.
    static std::map<int, std::vector<Element>> decode(const std::string& text, const std::string& sourceName,
                                                      ErrorLog* log);

private:
    std::string readText(const char* function) const;
    void write(std::map<int, std::vector<Element>> next, const char* function);

    std::filesystem::path path_;
    ErrorLog* log_;
    std::size_t maxFileBytes_;
    std::map<int, std::vector<Element>> contents_;
};

}  // namespace phigs
