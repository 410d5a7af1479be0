#include "phigs/store/ArchiveFile.h"

#include "ElementFields.h"
#include "phigs/core/FileTarget.h"
#include "phigs/store/IndexRange.h"

#include <fcntl.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <charconv>
#include <cstdio>
#include <fstream>
#include <limits>
#include <stdexcept>
#include <system_error>
#include <utility>
#include <variant>

namespace phigs {

namespace {

using detail::fields;

std::string typeToken(ElementType t) {
    std::string name(elementTypeName(t));
    for (char& c : name)
        if (c == ' ') c = '_';
    return name;
}

struct Writer {
    std::string& out;
    /// Past this many bytes lists stop writing their items (encodeWithin then stops too).
    std::size_t limit = std::numeric_limits<std::size_t>::max();
    bool full() const { return out.size() > limit; }
    void space() {
        if (!out.empty() && out.back() != '\n') out += ' ';
    }
    void operator()(int x) { space(), out += std::to_string(x); }
    void operator()(std::size_t x) { space(), out += std::to_string(x); }
    void operator()(bool x) { space(), out += x ? '1' : '0'; }
    void operator()(double x) {
        char buffer[64];
        auto r = std::to_chars(buffer, buffer + sizeof buffer, x);
        space(), out.append(buffer, r.ptr);
    }
    void operator()(const std::string& s) { space(), out += std::to_string(s.size()) + ":" + s; }
    void operator()(glm::dvec2 p) { (*this)(p.x), (*this)(p.y); }
    void operator()(glm::dvec3 p) { (*this)(p.x), (*this)(p.y), (*this)(p.z); }
    void operator()(const glm::dmat4& m) {
        for (int c = 0; c < 4; ++c)
            for (int r = 0; r < 4; ++r) (*this)(m[c][r]);
    }
    void operator()(const Colour& c) {
        space();
        if (c.direct && c.model == ColourModel::Rgb)
            out += "D", (*this)(c.rgb);
        else if (c.direct)  // another colour model: D<model>
            out += "D" + std::to_string(static_cast<int>(c.model)), (*this)(c.rgb);
        else
            out += "I", (*this)(c.index);
    }
    void operator()(AspectId a) { (*this)(static_cast<int>(a)); }
    void operator()(Composition c) { (*this)(static_cast<int>(c)); }
    void operator()(const geom::Curve& c) {
        (*this)(c.degree), (*this)(c.knots), (*this)(c.points), (*this)(c.weights);
    }
    void operator()(const geom::Surface& s) {
        (*this)(s.degreeU), (*this)(s.degreeV), (*this)(s.knotsU), (*this)(s.knotsV), (*this)(s.countU),
            (*this)(s.countV), (*this)(s.points), (*this)(s.weights);
    }
    void operator()(const TrimCurveDisplay& d) {
        (*this)(d.visible), (*this)(d.approximation), (*this)(d.approximationValue);
    }
    template <class A, class B>
    void operator()(const std::pair<A, B>& p) {
        (*this)(p.first), (*this)(p.second);
    }
    template <class T>
    void operator()(const std::vector<T>& list) {
        (*this)(list.size());
        for (const T& item : list)
            if (full())
                return;
            else
                (*this)(item);
    }
    void operator()(const PointList& list) {
        (*this)(list.size());
        for (const glm::dvec3& p : list)
            if (full())
                return;
            else
                (*this)(p);
    }
};

// ---- the fewest bytes of text one value of a field type takes, with the white space before it.
// Underestimates are safe (a count is then checked less tightly), overestimates would refuse
// good files: a number is " 0", a string " 0:", a colour " I 0", a list " 0" (empty).
template <class T>
struct MinText {
    static constexpr std::size_t value = 2;
};
template <>
struct MinText<std::string> {
    static constexpr std::size_t value = 3;
};
template <>
struct MinText<glm::dvec2> {
    static constexpr std::size_t value = 4;
};
template <>
struct MinText<glm::dvec3> {
    static constexpr std::size_t value = 6;
};
template <>
struct MinText<glm::dmat4> {
    static constexpr std::size_t value = 32;
};
template <>
struct MinText<Colour> {
    static constexpr std::size_t value = 4;
};
template <class T>
struct MinText<std::vector<T>> {
    static constexpr std::size_t value = 2;
};
template <>
struct MinText<PointList> {
    static constexpr std::size_t value = 2;
};
template <class A, class B>
struct MinText<std::pair<A, B>> {
    static constexpr std::size_t value = MinText<A>::value + MinText<B>::value;
};
template <>
struct MinText<geom::Curve> {
    static constexpr std::size_t value = 4 * 2;  // degree and three empty lists
};
template <>
struct MinText<TrimCurveDisplay> {
    static constexpr std::size_t value = 3 * 2;
};
template <>
struct MinText<geom::Surface> {
    static constexpr std::size_t value = 8 * 2;  // two degrees, two counts, four empty lists
};

/// Adds up MinText over the fields of a payload, as the oldest format version has them (fewer
/// fields, so never more than a newer file's least).
struct MinTextCounter {
    int version = 1;
    std::size_t total = 0;
    template <class T>
    void operator()(T&) {
        total += MinText<T>::value;
    }
};

/// Room is made for at most this many list items before they are read; longer lists grow as
/// their items arrive, so memory follows what the file really holds.
constexpr std::size_t kReserveItems = 4096;

/// A token as an error message quotes it: at most 40 bytes of it, control bytes shown as '?'.
std::string quoted(std::string_view token) {
    constexpr std::size_t kShown = 40;
    std::string shown(token.substr(0, kShown));
    for (char& c : shown)
        if (static_cast<unsigned char>(c) < 0x20 || c == 0x7f) c = '?';
    if (token.size() <= kShown) return "'" + shown + "'";
    return "'" + shown + "...' (" + std::to_string(token.size()) + " bytes)";
}

/// A token reader over the whole text that knows its line, so errors can say where.
struct Reader {
    const std::string& text;
    std::size_t at = 0;
    int line = 1;
    int version = ArchiveFile::kFormatVersion;  ///< the file's: fields added later keep their defaults

    [[noreturn]] void fail(const std::string& reason) {
        throw std::runtime_error("line " + std::to_string(line) + ": " + reason);
    }
    void skipSpace() {
        while (at < text.size() &&
               (text[at] == ' ' || text[at] == '\n' || text[at] == '\t' || text[at] == '\r')) {
            if (text[at] == '\n') ++line;
            ++at;
        }
    }
    bool atEnd() {
        skipSpace();
        return at >= text.size();
    }
    std::string_view token() {
        skipSpace();
        if (at >= text.size()) fail("unexpected end of file (truncated archive)");
        std::size_t start = at;
        while (at < text.size() && text[at] != ' ' && text[at] != '\n' && text[at] != '\t' &&
               text[at] != '\r')
            ++at;
        return std::string_view(text).substr(start, at - start);
    }
    template <class N>
    N number(const char* what) {
        std::string_view t = token();
        N value{};
        auto r = std::from_chars(t.data(), t.data() + t.size(), value);
        if (r.ec != std::errc() || r.ptr != t.data() + t.size())
            fail(std::string("bad ") + what + " " + quoted(t));
        return value;
    }
    /// A list count, refused when its items, `itemBytes` each at the least, cannot fit in the
    /// bytes left: checked before any room is made for them.
    std::size_t count(std::size_t itemBytes) {
        const auto n = number<std::size_t>("count");
        const std::size_t left = text.size() - at;
        if (n > left / itemBytes)
            fail("count " + std::to_string(n) + " needs at least " + std::to_string(itemBytes) +
                 " bytes per item, only " + std::to_string(left) + " bytes are left in the file");
        return n;
    }
    void operator()(int& x) { x = number<int>("integer"); }
    void operator()(std::size_t& x) { x = number<std::size_t>("count"); }
    void operator()(bool& x) {
        int v = number<int>("flag");
        if (v != 0 && v != 1) fail("flag must be 0 or 1");
        x = v == 1;
    }
    void operator()(double& x) { x = number<double>("real"); }
    void operator()(std::string& s) {
        skipSpace();
        std::size_t colon = text.find(':', at);
        if (colon == std::string::npos) fail("bad string");
        std::size_t n = 0;
        auto r = std::from_chars(text.data() + at, text.data() + colon, n);
        if (r.ec != std::errc() || r.ptr != text.data() + colon) fail("bad string length");
        if (n > text.size() - colon - 1)
            fail("string of " + std::to_string(n) +
                 " bytes runs past the end of the file (truncated archive)");
        s.assign(text, colon + 1, n);
        for (char c : s)
            if (c == '\n') ++line;
        at = colon + 1 + n;
    }
    void operator()(glm::dvec2& p) { (*this)(p.x), (*this)(p.y); }
    void operator()(glm::dvec3& p) { (*this)(p.x), (*this)(p.y), (*this)(p.z); }
    void operator()(glm::dmat4& m) {
        for (int c = 0; c < 4; ++c)
            for (int r = 0; r < 4; ++r) (*this)(m[c][r]);
    }
    void operator()(Colour& c) {
        std::string_view kind = token();
        if (kind == "D")
            c.direct = true, c.model = ColourModel::Rgb, (*this)(c.rgb);
        else if (kind.size() == 2 && kind[0] == 'D' && isColourModel(kind[1] - '0'))
            c.direct = true, c.model = static_cast<ColourModel>(kind[1] - '0'), (*this)(c.rgb);
        else if (kind == "I")
            c.direct = false, (*this)(c.index);
        else
            fail("bad colour kind " + quoted(kind));
    }
    void operator()(AspectId& a) {
        int v = number<int>("aspect");
        if (v < 0 || v >= static_cast<int>(AspectId::Count_)) fail("bad aspect " + std::to_string(v));
        a = static_cast<AspectId>(v);
    }
    void operator()(Composition& c) {
        int v = number<int>("composition");
        if (v < 0 || v > 2) fail("bad composition " + std::to_string(v));
        c = static_cast<Composition>(v);
    }
    void operator()(geom::Curve& c) {
        (*this)(c.degree), (*this)(c.knots), (*this)(c.points), (*this)(c.weights);
    }
    void operator()(geom::Surface& s) {
        (*this)(s.degreeU), (*this)(s.degreeV), (*this)(s.knotsU), (*this)(s.knotsV), (*this)(s.countU),
            (*this)(s.countV), (*this)(s.points), (*this)(s.weights);
    }
    void operator()(TrimCurveDisplay& d) {
        (*this)(d.visible), (*this)(d.approximation), (*this)(d.approximationValue);
    }
    template <class A, class B>
    void operator()(std::pair<A, B>& p) {
        (*this)(p.first), (*this)(p.second);
    }
    template <class T>
    void operator()(std::vector<T>& list) {
        const std::size_t n = count(MinText<T>::value);
        list.clear();
        list.reserve(std::min(n, kReserveItems));
        for (std::size_t i = 0; i < n; ++i) (*this)(list.emplace_back());
    }
    void operator()(PointList& list) {
        std::vector<glm::dvec3> points;
        (*this)(points);
        list = PointList(points);
    }
};

template <std::size_t... I>
Element makeAlternative(std::size_t index, std::index_sequence<I...>) {
    Element result;
    ((index == I ? (result.template emplace<I>(), 0) : 0), ...);
    return result;
}

Element decodeElement(Reader& in) {
    const std::string_view token = in.token();
    ElementType type = ElementType::Count_;
    std::string name;
    if (token.size() <= 64) {  // longer than any type name
        name = token;
        for (char& c : name)
            if (c == '_') c = ' ';
        type = elementTypeFromName(name);
    }
    int index = payloadIndexOf(type);
    if (index < 0) in.fail("unknown element type " + quoted(token));
    Element element = makeAlternative(static_cast<std::size_t>(index),
                                      std::make_index_sequence<std::variant_size_v<Element>>{});
    std::visit(
        [&](auto& e) {
            if constexpr (requires { e.type; }) e.type = type;
            fields(in, e);
            if constexpr (requires { e.twoD; })
                e.twoD = type == ElementType::Polyline || type == ElementType::Polymarker ||
                         type == ElementType::FillArea || type == ElementType::FillAreaSet ||
                         type == ElementType::Text || type == ElementType::AnnotationTextRelative ||
                         type == ElementType::CellArray || type == ElementType::ModelClippingVolume ||
                         type == ElementType::GeneralizedDrawingPrimitive;
            if constexpr (requires { e.add; }) e.add = type == ElementType::AddNamesToSet;
        },
        element);
    if (elementType(element) != type) in.fail("element type '" + name + "' is not consistent");
    if (std::string reason = validateElement(element); !reason.empty()) in.fail(name + ": " + reason);
    // No archive written by PHIGS holds an index INSERT refuses: the file was made elsewhere.
    if (const IndexRange range = indexRangeError(element); range.error != 0)
        in.fail(name + ": index " + std::to_string(range.value) + " is out of range (error " +
                std::to_string(range.error) + " when inserted)");
    return element;
}

/// The fewest bytes of text any element takes: the line break before it, its type name and its
/// smallest fields ("LABEL 0").
std::size_t minElementText() {
    static const std::size_t bytes = [] {
        std::size_t least = std::numeric_limits<std::size_t>::max();
        for (int t = 0; t < static_cast<int>(ElementType::Count_); ++t) {
            const auto type = static_cast<ElementType>(t);
            const int index = payloadIndexOf(type);
            if (index < 0) continue;
            Element element = makeAlternative(static_cast<std::size_t>(index),
                                              std::make_index_sequence<std::variant_size_v<Element>>{});
            MinTextCounter counter;
            std::visit(
                [&](auto& e) {
                    if constexpr (requires { e.type; }) e.type = type;
                    fields(counter, e);
                },
                element);
            least = std::min(least, 1 + typeToken(type).size() + counter.total);
        }
        return least;
    }();
    return bytes;
}

std::uint64_t fnv1a(std::string_view bytes) {
    std::uint64_t hash = 1469598103934665603ull;
    for (unsigned char c : bytes) hash = (hash ^ c) * 1099511628211ull;
    return hash;
}

std::string hex(std::uint64_t v) {
    char buffer[17];
    std::snprintf(buffer, sizeof buffer, "%016llx", static_cast<unsigned long long>(v));
    return buffer;
}

/// `<archive>.tmp`: where the next version is written before it replaces the archive.
std::filesystem::path temporaryPath(const std::filesystem::path& archive) {
    std::filesystem::path p = archive;
    p += ".tmp";
    return p;
}

std::string errnoText(int number) {
    return std::error_code(number, std::generic_category()).message();
}

/// Writes `text` to a new file at `path` and flushes it to the disk; on failure removes what it
/// created and returns the cause.
std::string writeSynced(const std::filesystem::path& path, std::string_view text) {
    const int fd = ::open(path.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC | O_NOFOLLOW, 0666);
    if (fd < 0) return errnoText(errno);
    std::string cause;
    for (std::size_t done = 0; cause.empty() && done < text.size();) {
        const ssize_t n = ::write(fd, text.data() + done, text.size() - done);
        if (n > 0)
            done += static_cast<std::size_t>(n);
        else if (n == 0)
            cause = "no bytes written";
        else if (errno != EINTR)
            cause = errnoText(errno);
    }
    if (cause.empty() && ::fsync(fd) != 0) cause = errnoText(errno);
    if (::close(fd) != 0 && cause.empty()) cause = errnoText(errno);
    if (!cause.empty()) ::unlink(path.c_str());
    return cause;
}

/// Flushes the directory holding `path` to the disk, so that a rename into it lasts; the cause
/// when that fails (a file system that cannot flush a directory, EINVAL, has nothing to do).
std::string syncDirectory(const std::filesystem::path& path) {
    std::filesystem::path directory = path.parent_path();
    if (directory.empty()) directory = ".";
    const int fd = ::open(directory.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
    if (fd < 0) return errnoText(errno);
    std::string cause;
    if (::fsync(fd) != 0 && errno != EINVAL) cause = errnoText(errno);
    ::close(fd);
    return cause;
}

}  // namespace

ArchiveFile::ArchiveFile(std::filesystem::path path, ErrorLog* log, std::size_t maxFileBytes)
    : path_(replacedFile(std::move(path))), log_(log), maxFileBytes_(maxFileBytes) {
    const char* function = "OPEN ARCHIVE FILE";
    // A temporary file left by a killed write holds at most part of an archive; the archive
    // itself is still the last complete one.
    std::error_code ec;
    const std::filesystem::path temporary = temporaryPath(path_);
    const auto leftover = std::filesystem::symlink_status(temporary, ec).type();
    if (leftover == std::filesystem::file_type::regular || leftover == std::filesystem::file_type::symlink)
        std::filesystem::remove(temporary, ec);
    // A file that exists but is empty is a new archive too (a program may make the file first).
    const auto type = std::filesystem::status(path_, ec).type();
    const bool empty =
        type == std::filesystem::file_type::regular && std::filesystem::file_size(path_, ec) == 0 && !ec;
    if (type == std::filesystem::file_type::not_found || empty) {
        // A failed creation is error 400 alone: the write's own error (903) stays out of the log.
        ErrorLog* const kept = std::exchange(log_, nullptr);
        try {
            write({}, function);
            log_ = kept;
        } catch (const Error& e) {
            log_ = kept;
            raise(log_, errors::ArchiveCannotOpen, function,
                  path_.string() + ": cannot be created: " + e.detail());
        }
        return;
    }
    contents_ = decode(readText(function), path_.string(), log_);
}

std::string ArchiveFile::readText(const char* function) const {
    std::error_code ec;
    if (!std::filesystem::is_regular_file(path_, ec))
        raise(log_, errors::ArchiveCannotOpen, function, path_.string() + ": not a regular file");
    const std::uintmax_t size = std::filesystem::file_size(path_, ec);
    if (ec) raise(log_, errors::ArchiveCannotOpen, function, path_.string() + ": " + ec.message());
    if (size > maxFileBytes_)
        raise(log_, errors::NotAnArchive, function,
              path_.string() + ": " + std::to_string(size) + " bytes, more than the limit of " +
                  std::to_string(maxFileBytes_) + " bytes for an archive");
    std::ifstream in(path_, std::ios::binary);
    std::string text(static_cast<std::size_t>(size), '\0');
    in.read(text.data(), static_cast<std::streamsize>(size));
    if (!in || in.peek() != std::ifstream::traits_type::eof())
        raise(log_, errors::ArchiveCannotOpen, function, path_.string() + ": cannot be read whole");
    return text;
}

std::vector<int> ArchiveFile::structureIds() const {
    std::vector<int> ids;
    for (const auto& [id, e] : contents_) ids.push_back(id);
    return ids;
}

namespace {

/// Where an archive's text passed its limit: the structure and the element (from 1) being written.
struct EncodingStop {
    int structure = 0;
    std::size_t element = 0, elements = 0;
};

/// The archive text of `contents`, or where it passed `limit` bytes: an archive too large to
/// write never has much more than the limit of its text in memory.
std::variant<std::string, EncodingStop> encodeWithin(const std::map<int, std::vector<Element>>& contents,
                                                     std::size_t limit) {
    std::string out = "PHIGS-ARCHIVE " + std::to_string(ArchiveFile::kFormatVersion) + "\n";
    Writer w{out, limit};
    for (const auto& [id, elements] : contents) {
        out += "STRUCTURE";
        w(id), w(elements.size());
        out += '\n';
        for (std::size_t k = 0; k < elements.size(); ++k) {
            out += typeToken(elementType(elements[k]));
            std::visit([&](const auto& e) { fields(w, const_cast<std::decay_t<decltype(e)>&>(e)); },
                       elements[k]);
            out += '\n';
            if (w.full()) return EncodingStop{id, k + 1, elements.size()};
        }
    }
    std::uint64_t checksum = fnv1a(out);
    out += "END " + std::to_string(contents.size()) + " " + hex(checksum) + "\n";
    return out;
}

}  // namespace

std::string ArchiveFile::encode(const std::map<int, std::vector<Element>>& contents) {
    return std::get<std::string>(encodeWithin(contents, std::numeric_limits<std::size_t>::max()));
}

std::map<int, std::vector<Element>> ArchiveFile::decode(const std::string& text,
                                                        const std::string& sourceName, ErrorLog* log) {
    Reader in{text};
    std::map<int, std::vector<Element>> contents;
    try {
        if (in.token() != "PHIGS-ARCHIVE") in.fail("not a PHIGS archive (no PHIGS-ARCHIVE header)");
        in.version = in.number<int>("version");
        if (in.version < 1 || in.version > kFormatVersion)
            in.fail("unsupported archive version " + std::to_string(in.version) +
                    " (this reader reads 1 to " + std::to_string(kFormatVersion) + ")");
        while (true) {
            std::size_t tokenStart = (in.skipSpace(), in.at);
            std::string_view keyword = in.token();
            if (keyword == "END") {
                std::size_t count = in.number<std::size_t>("structure count");
                std::string_view sum = in.token();
                if (count != contents.size())
                    in.fail("END says " + std::to_string(count) + " structures, found " +
                            std::to_string(contents.size()));
                if (sum != hex(fnv1a(std::string_view(text).substr(0, tokenStart))))
                    in.fail("checksum mismatch: the archive is corrupt");
                if (!in.atEnd()) in.fail("data after END");
                break;
            }
            if (keyword != "STRUCTURE") in.fail("expected STRUCTURE or END, found " + quoted(keyword));
            int id = in.number<int>("structure id");
            if (contents.contains(id)) in.fail("structure " + std::to_string(id) + " appears twice");
            const std::size_t n = in.count(minElementText());
            std::vector<Element> elements;
            elements.reserve(std::min(n, kReserveItems));
            for (std::size_t i = 0; i < n; ++i) elements.push_back(decodeElement(in));
            contents.emplace(id, std::move(elements));
        }
    } catch (const std::runtime_error& e) {
        if (dynamic_cast<const Error*>(&e)) throw;
        raise(log, errors::NotAnArchive, "OPEN ARCHIVE FILE", sourceName + ": " + e.what());
    }
    return contents;
}

void ArchiveFile::commit(const std::map<int, std::vector<Element>>& put, const std::vector<int>& remove) {
    auto next = contents_;
    for (int id : remove) next.erase(id);
    for (const auto& [id, elements] : put) next[id] = elements;
    if (next == contents_) return;  // the file already says this
    write(std::move(next), "ARCHIVE STRUCTURES");
}

void ArchiveFile::write(std::map<int, std::vector<Element>> next, const char* function) {
    auto encoded = encodeWithin(next, maxFileBytes_);
    if (const EncodingStop* stop = std::get_if<EncodingStop>(&encoded))
        raise(log_, errors::WriteError, function,
              path_.string() + ": the archive would be more than the limit of " +
                  std::to_string(maxFileBytes_) + " bytes (passed at structure " +
                  std::to_string(stop->structure) + ", element " + std::to_string(stop->element) + " of " +
                  std::to_string(stop->elements) + ")");
    const std::string text = std::move(std::get<std::string>(encoded));
    if (text.size() > maxFileBytes_)
        raise(log_, errors::WriteError, function,
              path_.string() + ": the archive would be " + std::to_string(text.size()) +
                  " bytes, more than the limit of " + std::to_string(maxFileBytes_) + " bytes");
    const std::filesystem::path temporary = temporaryPath(path_);
    if (std::string cause = writeSynced(temporary, text); !cause.empty())
        raise(log_, errors::WriteError, function, temporary.string() + ": cannot be written (" + cause + ")");
    std::error_code ec;
    std::filesystem::rename(temporary, path_, ec);
    if (ec) {
        const std::string cause = ec.message();
        std::filesystem::remove(temporary, ec);
        raise(log_, errors::WriteError, function, path_.string() + ": cannot be replaced (" + cause + ")");
    }
    contents_ = std::move(next);
    // The rename itself is on the disk only once the directory is.
    if (std::string cause = syncDirectory(path_); !cause.empty())
        raise(log_, errors::WriteError, function,
              path_.string() + ": written, but its directory could not be flushed (" + cause +
                  "), so the change may not survive a crash");
}

}  // namespace phigs
