#include "StepReals.h"

#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstdlib>

namespace geom::exchange {

namespace {

bool wordCharacter(int c) {
    return std::isalnum(c) != 0 || c == '_';
}

bool numberCharacter(int c) {
    return std::isdigit(c) != 0 || c == '.' || c == '+' || c == '-' || c == 'E' || c == 'e';
}

/// Longer numbers are refused outright (OpenCASCADE reads integers as reals too).
constexpr std::size_t kMaxNumberLength = 1 << 12;

/// Whether `token` (a run of number characters) is a number beyond the limit.
bool outOfRange(const std::string& token) {
    if (token.find_first_of("0123456789") == std::string::npos) return false;  // an enumeration's dots
    errno = 0;
    char* end = nullptr;
    const double value = std::strtod(token.c_str(), &end);
    if (end == token.c_str()) return false;
    return beyondRealLimit(value, errno == ERANGE);
}

}  // namespace

std::optional<std::string> firstOutOfRangeStepReal(std::istream& in) {
    enum class State { Text, String, Comment } state = State::Text;
    std::size_t line = 1;
    int previous = ' ';
    std::string token;
    for (int c = in.get(); c != std::char_traits<char>::eof(); previous = c, c = in.get()) {
        if (c == '\n') ++line;
        if (state == State::String) {
            if (c == '\'') state = State::Text;  // a doubled quote reopens at once
            continue;
        }
        if (state == State::Comment) {
            if (previous == '*' && c == '/') state = State::Text, c = ' ';
            continue;
        }
        if (c == '\'') {
            state = State::String;
            continue;
        }
        if (previous == '/' && c == '*') {
            state = State::Comment, c = ' ';
            continue;
        }
        if (!numberCharacter(c) || wordCharacter(previous)) continue;
        token.assign(1, char(c));
        while (numberCharacter(in.peek()) && token.size() <= kMaxNumberLength) token += char(in.get());
        if (token.size() > kMaxNumberLength)
            return "line " + std::to_string(line) + ": a number of more than " +
                   std::to_string(kMaxNumberLength) + " characters";
        if (outOfRange(token))
            return "line " + std::to_string(line) + ": the real " + token.substr(0, 40) + " " +
                   kBeyondRealLimit;
        c = token.back();
    }
    return std::nullopt;
}

}  // namespace geom::exchange
