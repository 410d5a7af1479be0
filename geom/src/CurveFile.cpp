#include "geom/CurveFile.h"

#include "EndsAtStart.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <iomanip>
#include <sstream>

namespace geom {

namespace {

const char* const kTitle = "CURVE INPUT FILE";
const char* const kPointsHeading = "Data-Points:";
const char* const kContinuitiesHeading = "Continuities:";
const char* const kConstraintsHeading = "Constraints:";
const char* const kNone = "None";

std::string trim(const std::string& s) {
    const auto first = s.find_first_not_of(" \t\r\n");
    if (first == std::string::npos) return {};
    const auto last = s.find_last_not_of(" \t\r\n");
    return s.substr(first, last - first + 1);
}

/// Line-by-line reader that skips blank lines and remembers the line number for errors.
class LineReader {
public:
    LineReader(std::istream& in, std::string source) : in_(in), source_(std::move(source)) {}

    /// The next non-blank line (trimmed); false at the end of the input. A line longer than
    /// kCurveFileMaxLineLength, or with a control character, is refused as it is read.
    bool next(std::string& line) {
        std::string raw;
        while (readLine(raw)) {
            line = trim(raw);
            if (!line.empty()) return true;
        }
        return false;
    }
    std::string require(const std::string& what) {
        std::string line;
        if (!next(line)) fail("the file ends where " + what + " was expected");
        return line;
    }
    [[noreturn]] void fail(const std::string& reason) const { throw CurveFileError(source_, line_, reason); }
    /// The number of the line read last.
    std::size_t lineNumber() const { return line_; }

private:
    bool readLine(std::string& raw) {
        raw.clear();
        std::streambuf* buffer = in_.rdbuf();
        int c = buffer ? buffer->sbumpc() : std::char_traits<char>::eof();
        if (c == std::char_traits<char>::eof()) return false;
        ++line_;
        for (; c != std::char_traits<char>::eof() && c != '\n'; c = buffer->sbumpc()) {
            if (c < 0x20 && c != '\t' && c != '\r') {
                char code[16];
                std::snprintf(code, sizeof code, "0x%02x", static_cast<unsigned>(c));
                fail(std::string("control character ") + code + " at column " +
                     std::to_string(raw.size() + 1));
            }
            if (raw.size() == kCurveFileMaxLineLength)
                fail("the line is longer than the limit of " + std::to_string(kCurveFileMaxLineLength) +
                     " characters");
            raw.push_back(static_cast<char>(c));
        }
        return true;
    }

    std::istream& in_;
    std::string source_;
    std::size_t line_ = 0;
};

std::vector<double> numbers(const std::string& line) {
    std::vector<double> values;
    std::istringstream s(line);
    std::string token;
    while (s >> token) {
        double v = 0.0;
        const auto [ptr, ec] = std::from_chars(token.data(), token.data() + token.size(), v);
        if (ec != std::errc() || ptr != token.data() + token.size() || !std::isfinite(v)) return {};
        values.push_back(v);
    }
    return values;
}

bool isCount(const std::string& line, long& value) {
    const auto [ptr, ec] = std::from_chars(line.data(), line.data() + line.size(), value);
    return ec == std::errc() && ptr == line.data() + line.size();
}

void expectHeading(LineReader& reader, const char* heading, const std::string& part) {
    const std::string line = reader.require(std::string("the heading '") + heading + "'");
    if (line != heading)
        reader.fail("expected the heading '" + std::string(heading) + "'" +
                    (part.empty() ? "" : " in part '" + part + "'") + ", found '" + line + "'");
}

glm::dvec3 readVector(LineReader& reader, const std::string& what) {
    const std::string line = reader.require(what);
    const std::vector<double> v = numbers(line);
    if (v.size() != 3) reader.fail(what + ": expected three numbers 'x y z', found '" + line + "'");
    return {v[0], v[1], v[2]};
}

bool closes(const CurvePart& part) {
    return detail::endsAtStart(part.points);
}

}  // namespace

CurveFileError::CurveFileError(std::string file, std::size_t line, const std::string& reason)
    : GeometryError(file + ":" + std::to_string(line) + ": " + reason), file_(std::move(file)), line_(line) {
}

CurveModel parseCurveFile(std::istream& in, const std::string& source) {
    LineReader reader(in, source);
    CurveModel model;
    std::size_t totalPoints = 0;
    const std::string title = reader.require("the title 'CURVE INPUT FILE'");
    if (title != kTitle)
        reader.fail("expected the title '" + std::string(kTitle) + "', found '" + title + "'");
    std::string line;
    while (reader.next(line)) {
        long count = 0;
        if (!isCount(line, count) || count < 3)
            reader.fail("expected the number of data points of a part (at least 3), found '" + line + "'");
        if (count > static_cast<long>(kCurveFileMaxPointsPerPart))
            reader.fail("a part of " + line + " data points; the limit is " +
                        std::to_string(kCurveFileMaxPointsPerPart) + " per part");
        if (model.parts.size() == kCurveFileMaxParts)
            reader.fail("more than " + std::to_string(kCurveFileMaxParts) + " parts; the limit is " +
                        std::to_string(kCurveFileMaxParts));
        totalPoints += static_cast<std::size_t>(count);
        if (totalPoints > kCurveFileMaxPoints)
            reader.fail("the parts so far declare " + std::to_string(totalPoints) +
                        " data points; the limit is " + std::to_string(kCurveFileMaxPoints) + " per file");
        CurvePart part;
        part.line = reader.lineNumber();
        part.name = reader.require("the part name");
        if (part.name == kPointsHeading)
            reader.fail("the part declared at line " + std::to_string(part.line) +
                        " has no name: a name line must come before '" + std::string(kPointsHeading) + "'");
        expectHeading(reader, kPointsHeading, part.name);
        double length = 0.0;
        for (long i = 0; i < count; ++i) {
            const std::string text = reader.require("data point " + std::to_string(i + 1));
            const std::vector<double> v = numbers(text);
            if (v.size() != 3)
                reader.fail("part '" + part.name + "' declares " + std::to_string(count) +
                            " data points but line " + std::to_string(i + 1) + " of them is '" + text +
                            "', not three numbers 'x y z'");
            part.points.push_back({v[0], v[1], v[2]});
            // The chord lengths parameterise the curve: their running sum must stay a number.
            if (i > 0 && !std::isfinite(length += glm::length(part.points[i] - part.points[i - 1])))
                reader.fail("data point " + std::to_string(i + 1) + " of part '" + part.name +
                            "' is too far from the ones before: the part's length is not a finite number");
        }
        if (!closes(part))
            reader.fail("part '" + part.name +
                        "' does not close: its last data point differs from the first");
        expectHeading(reader, kContinuitiesHeading, part.name);
        for (long i = 0; i < count; ++i) {
            const std::string text = reader.require("the continuity of data point " + std::to_string(i + 1));
            long c = -1;
            if (!isCount(text, c))
                reader.fail("part '" + part.name + "' declares " + std::to_string(count) +
                            " data points but continuity " + std::to_string(i + 1) + " is '" + text + "'");
            if (c < 0 || c > 2)
                reader.fail("continuity of data point " + std::to_string(i + 1) + " of part '" + part.name +
                            "' is " + text + "; it must be 0 (C0), 1 (C1) or 2 (C2)");
            part.continuities.push_back(static_cast<Continuity>(c));
        }
        if (part.continuities.back() != part.continuities.front())
            reader.fail("the closing point of part '" + part.name +
                        "' must have the continuity of its first point");
        expectHeading(reader, kConstraintsHeading, part.name);
        const std::size_t needed = constraintCount(part.continuities);
        if (needed == 0) {
            const std::string text = reader.require("'None'");
            if (text != kNone)
                reader.fail("part '" + part.name +
                            "' has only C2 points, so its constraints must be 'None', found '" + text + "'");
        }
        for (std::size_t i = 0; i < needed; ++i)
            part.constraints.push_back(readVector(reader, "tangent constraint " + std::to_string(i + 1) +
                                                              " of " + std::to_string(needed) + " of part '" +
                                                              part.name + "'"));
        model.parts.push_back(std::move(part));
    }
    if (model.parts.empty()) reader.fail("the file has a title but no curve part");
    return model;
}

CurveModel readCurveFile(const std::filesystem::path& path) {
    std::error_code ec;
    if (std::filesystem::is_directory(path, ec))
        throw CurveFileError(path.string(), 0, "is a directory, not a curve file");
    // A FIFO or a device would be read until its writer stops, if ever.
    if (std::filesystem::exists(path, ec) && !std::filesystem::is_regular_file(path, ec))
        throw CurveFileError(path.string(), 0, "is not a regular file, not a curve file");
    std::ifstream in(path);
    if (!in) throw CurveFileError(path.string(), 0, "cannot open the curve file");
    return parseCurveFile(in, path.string());
}

void writeCurveFile(std::ostream& out, const CurveModel& model) {
    for (const CurvePart& part : model.parts) {
        if (part.points.size() < 3 || part.continuities.size() != part.points.size() || !closes(part) ||
            part.constraints.size() != constraintCount(part.continuities) || part.name.empty() ||
            trim(part.name) != part.name)
            throw GeometryError("writeCurveFile: part '" + part.name +
                                "' would not read back (it needs a trimmed name, at least 3 points ending at "
                                "the first, one continuity per point and 2 constraints per C0, 1 per C1)");
    }
    const auto vec = [&out](const glm::dvec3& p) {
        out << std::setprecision(17) << p.x << ' ' << p.y << ' ' << p.z << '\n';
    };
    out << kTitle << '\n';
    for (const CurvePart& part : model.parts) {
        out << part.points.size() << '\n' << part.name << '\n' << kPointsHeading << '\n';
        for (const glm::dvec3& p : part.points) vec(p);
        out << kContinuitiesHeading << '\n';
        for (Continuity c : part.continuities) out << static_cast<int>(c) << '\n';
        out << kConstraintsHeading << '\n';
        if (part.constraints.empty()) out << kNone << '\n';
        for (const glm::dvec3& t : part.constraints) vec(t);
    }
}

void writeCurveFile(const std::filesystem::path& path, const CurveModel& model) {
    std::ostringstream text;
    writeCurveFile(text, model);  // validates before the file is touched
    std::ofstream out(path);
    if (!out) throw GeometryError("writeCurveFile: cannot open '" + path.string() + "' for writing");
    out << text.str();
    if (!out) throw GeometryError("writeCurveFile: writing '" + path.string() + "' failed");
}

Curve interpolatePart(const CurvePart& part, Parameterization parameterization) {
    InterpolationData data;
    data.points = part.points;
    data.continuities = part.continuities;
    data.tangents = part.constraints;
    data.parameterization = parameterization;
    data.closed = true;
    try {
        return interpolateCubic(data);
    } catch (const GeometryError& e) {
        throw GeometryError("curve part '" + part.name + "': " + e.what());
    }
}

std::vector<Curve> interpolateModel(const CurveModel& model, Parameterization parameterization) {
    std::vector<Curve> curves;
    for (const CurvePart& part : model.parts) curves.push_back(interpolatePart(part, parameterization));
    return curves;
}

}  // namespace geom
