#include "IgesParameters.h"

#include "StepReals.h"

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <climits>
#include <cmath>
#include <cstdlib>
#include <vector>

namespace geom::exchange {

namespace {

/// A section's parameter text, its records' columns joined, with the file line each starts on.
struct ParameterText {
    std::string text;
    std::vector<std::pair<std::size_t, std::size_t>> lines;  // (offset in text, file line)

    void add(const std::string& columns, std::size_t line) {
        lines.emplace_back(text.size(), line);
        text += columns;
    }
    std::size_t lineAt(std::size_t offset) const {
        auto it = std::upper_bound(lines.begin(), lines.end(), std::make_pair(offset, std::size_t(-1)));
        return it == lines.begin() ? 0 : std::prev(it)->second;
    }
    void clear() { text.clear(), lines.clear(); }
};

bool digits(const std::string& s, std::size_t from, std::size_t to) {
    return to > from && std::all_of(s.begin() + std::ptrdiff_t(from), s.begin() + std::ptrdiff_t(to),
                                    [](char c) { return std::isdigit(static_cast<unsigned char>(c)) != 0; });
}

/// Why a trimmed parameter that is not a Hollerith string is no number (or one out of range),
/// or empty when it is a number: [+-] digits [. digits] [E|D [+-] digits], a digit somewhere
/// before the exponent.
std::string numberProblem(const std::string& token) {
    std::size_t i = !token.empty() && (token[0] == '+' || token[0] == '-') ? 1 : 0;
    const std::size_t mantissa = i;
    while (i < token.size() && std::isdigit(static_cast<unsigned char>(token[i]))) ++i;
    const bool whole = i > mantissa;
    bool real = false, fraction = false;
    if (i < token.size() && token[i] == '.') {
        real = true;
        const std::size_t from = ++i;
        while (i < token.size() && std::isdigit(static_cast<unsigned char>(token[i]))) ++i;
        fraction = i > from;
    }
    if (!whole && !fraction) return "is not a number";
    if (i < token.size() && std::string("EeDd").find(token[i]) != std::string::npos) {
        real = true;
        std::size_t from = ++i;
        if (from < token.size() && (token[from] == '+' || token[from] == '-')) ++from;
        if (!digits(token, from, token.size())) return "is not a number";
        i = token.size();
    }
    if (i != token.size()) return "is not a number";
    std::string plain = token;
    std::replace(plain.begin(), plain.end(), 'D', 'E');
    std::replace(plain.begin(), plain.end(), 'd', 'E');
    errno = 0;
    if (!real) {
        const long long value = std::strtoll(plain.c_str(), nullptr, 10);
        if (errno == ERANGE || value > INT_MAX || value < INT_MIN) return "is an integer beyond 32 bits";
        return {};
    }
    const double value = std::strtod(plain.c_str(), nullptr);
    if (beyondRealLimit(value, errno == ERANGE)) return kBeyondRealLimit;
    return {};
}

/// Checks the parameters of `text` up to its record delimiter; the first problem, if any.
std::optional<std::string> checkParameters(const ParameterText& p, char parameter, char record) {
    const std::string& t = p.text;
    std::size_t i = 0;
    while (i < t.size()) {
        while (i < t.size() && t[i] == ' ') ++i;
        const std::size_t start = i;
        // A Hollerith string: n H and n characters, delimiters among them.
        std::size_t h = i;
        while (h < t.size() && std::isdigit(static_cast<unsigned char>(t[h]))) ++h;
        if (h > i && h < t.size() && (t[h] == 'H' || t[h] == 'h') && h - i <= 9) {
            const std::size_t length = std::stoul(t.substr(i, h - i));
            if (h + 1 + length > t.size())
                return "line " + std::to_string(p.lineAt(start)) + ": a string of " + std::to_string(length) +
                       " characters runs past the end of its section or entity";
            i = h + 1 + length;
            while (i < t.size() && t[i] == ' ') ++i;
        } else {
            while (i < t.size() && t[i] != parameter && t[i] != record) ++i;
            std::string token = t.substr(start, i - start);
            token.erase(token.find_last_not_of(' ') + 1);
            if (!token.empty())
                if (const std::string problem = numberProblem(token); !problem.empty())
                    return "line " + std::to_string(p.lineAt(start)) + ": the parameter '" +
                           token.substr(0, 40) + "' " + problem;
        }
        if (i >= t.size())
            return "line " + std::to_string(p.lineAt(t.size())) + ": a parameter list with no end";
        if (t[i] == record) return std::nullopt;
        if (t[i] != parameter)
            return "line " + std::to_string(p.lineAt(i)) + ": a string followed by '" + std::string(1, t[i]) +
                   "', not a delimiter";
        ++i;
    }
    return "line " + std::to_string(p.lineAt(t.size())) + ": a parameter list with no end";
}

/// The delimiters the global section sets: its first two parameters, each "1Hc" or empty.
void readDelimiters(const std::string& global, char& parameter, char& record) {
    parameter = ',', record = ';';
    std::size_t i = global.find_first_not_of(' ');
    if (i != std::string::npos && global.compare(i, 2, "1H") == 0 && i + 2 < global.size()) {
        parameter = global[i + 2];
        i += 3;
    }
    i = global.find_first_not_of(' ', i);
    if (i != std::string::npos && global[i] == parameter) {
        i = global.find_first_not_of(' ', i + 1);
        if (i != std::string::npos && global.compare(i, 2, "1H") == 0 && i + 2 < global.size())
            record = global[i + 2];
    }
}

}  // namespace

std::optional<std::string> firstBadIgesParameter(std::istream& in) {
    ParameterText global, entity;
    std::string entityPointer;
    char parameter = ',', record = ';';
    bool globalDone = false;
    auto finishEntity = [&]() -> std::optional<std::string> {
        if (entity.text.empty()) return std::nullopt;
        std::optional<std::string> problem = checkParameters(entity, parameter, record);
        entity.clear();
        return problem;
    };
    std::string line;
    for (std::size_t number = 1; std::getline(in, line); ++number) {
        if (!line.empty() && line.back() == '\r') line.pop_back();
        // A record's section letter and sequence number are its last 8 columns (73-80), and a
        // parameter record's entity pointer the 8 before them: counted from the end, so that a
        // record made shorter or longer (which OpenCASCADE still reads) is read as it is.
        if (line.size() < 8) continue;
        const std::size_t data = line.size() - 8;
        const char section = line[data];
        if (section == 'G') {
            global.add(line.substr(0, data), number);
            continue;
        }
        if (!globalDone && !global.text.empty()) {
            globalDone = true;
            readDelimiters(global.text, parameter, record);
            if (std::optional<std::string> problem = checkParameters(global, parameter, record))
                return problem;
        }
        if (section != 'P' || data < 8) continue;
        const std::string pointer = line.substr(data - 8, 8);
        if (pointer != entityPointer) {
            if (std::optional<std::string> problem = finishEntity()) return problem;
            entityPointer = pointer;
        }
        entity.add(line.substr(0, data - 8), number);
    }
    return finishEntity();
}

std::vector<std::string> igesGlobalParameters(std::istream& in) {
    std::string global, line;
    while (std::getline(in, line)) {
        if (!line.empty() && line.back() == '\r') line.pop_back();
        if (line.size() < 8) continue;
        const char section = line[line.size() - 8];
        if (section == 'G')
            global += line.substr(0, line.size() - 8);
        else if (section != 'S')
            break;
    }
    char parameter = ',', record = ';';
    readDelimiters(global, parameter, record);
    std::vector<std::string> parameters;
    std::string token;
    for (std::size_t i = 0; i < global.size(); ++i) {
        const char c = global[i];
        if (c == parameter || c == record) {
            const std::size_t first = token.find_first_not_of(' ');
            parameters.push_back(first == std::string::npos
                                     ? ""
                                     : token.substr(first, token.find_last_not_of(' ') + 1 - first));
            token.clear();
            if (c == record) break;
            continue;
        }
        token += c;
        // A Hollerith string: n H and n characters, delimiters among them.
        const std::size_t first = token.find_first_not_of(' ');
        if ((c == 'H' || c == 'h') && first + 1 < token.size() && token.size() - first <= 10 &&
            digits(token, first, token.size() - 1)) {
            const std::size_t n = std::stoul(token.substr(first, token.size() - 1 - first));
            token = global.substr(i + 1, n);
            i += n;
            parameters.push_back(token);
            token.clear();
            // What follows up to the next delimiter is the string's end.
            while (i + 1 < global.size() && global[i + 1] != parameter && global[i + 1] != record) ++i;
            if (i + 1 < global.size() && global[i + 1] == record) break;
            ++i;
        }
    }
    return parameters;
}

}  // namespace geom::exchange
