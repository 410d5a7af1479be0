#include "phigs/input/ScriptInputSource.h"

#include <charconv>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <sstream>

namespace phigs {
namespace {

std::vector<std::string> splitWords(const std::string& line) {
    std::istringstream in(line);
    std::vector<std::string> words;
    for (std::string w; in >> w;) words.push_back(w);
    return words;
}

class LineParser {
public:
    LineParser(const std::string& name, int line, std::vector<std::string> words)
        : name_(name), line_(line), words_(std::move(words)) {}

    [[noreturn]] void fail(const std::string& reason) const {
        throw ScriptError(name_ + ":" + std::to_string(line_) + ": " + reason);
    }
    double number(std::size_t i, const char* what) const {
        if (i >= words_.size()) fail(std::string("missing ") + what + " after '" + words_[0] + "'");
        double value = 0;
        const std::string& w = words_[i];
        const auto [end, ec] = std::from_chars(w.data(), w.data() + w.size(), value);
        if (ec != std::errc() || end != w.data() + w.size() || !std::isfinite(value))
            fail(std::string(what) + " '" + w + "' is not a finite number");
        return value;
    }
    int integer(std::size_t i, const char* what) const {
        const double v = number(i, what);
        if (v != std::floor(v) || std::abs(v) > 1e9)
            fail(std::string(what) + " '" + words_[i] + "' is not an integer");
        return static_cast<int>(v);
    }
    /// Strips a trailing "device D" and returns D (1 when absent).
    int takeDevice() {
        if (words_.size() >= 3 && words_[words_.size() - 2] == "device") {
            const int d = integer(words_.size() - 1, "device number");
            if (d < 1) fail("device number must be at least 1");
            words_.resize(words_.size() - 2);
            return d;
        }
        return 1;
    }
    void expectCount(std::size_t n, const char* usage) const {
        if (words_.size() != n) fail(std::string("expected '") + usage + "'");
    }
    const std::vector<std::string>& words() const { return words_; }

private:
    const std::string& name_;
    int line_;
    std::vector<std::string> words_;
};

/// Whether the line's first word is "string": its text runs to the end of the line.
bool isStringLine(const std::string& raw) {
    const std::size_t first = raw.find_first_not_of(" \t");
    if (first == std::string::npos || raw.compare(first, 6, "string") != 0) return false;
    return first + 6 == raw.size() || raw[first + 6] == ' ' || raw[first + 6] == '\t';
}

std::string formatNumber(double v) {
    char buffer[64];
    const auto [end, ec] = std::to_chars(buffer, buffer + sizeof buffer, v);
    return std::string(buffer, end);
}

std::string deviceSuffix(int device) {
    return device == 1 ? "" : " device " + std::to_string(device);
}

}  // namespace

ScriptInputSource::ScriptInputSource(const std::string& text, std::string name,
                                     std::set<std::string> directives)
    : name_(std::move(name)) {
    std::istringstream in(text);
    std::string raw;
    int lineNumber = 0;
    while (std::getline(in, raw)) {
        ++lineNumber;
        if (!raw.empty() && raw.back() == '\r') raw.pop_back();
        if (raw.size() > kMaxScriptLineLength)
            throw ScriptError(name_ + ":" + std::to_string(lineNumber) + ": the line is " +
                              std::to_string(raw.size()) + " bytes long; the limit is " +
                              std::to_string(kMaxScriptLineLength));
        for (std::size_t k = 0; k < raw.size(); ++k)
            if (static_cast<unsigned char>(raw[k]) < 0x20 && raw[k] != '\t') {
                char code[16];
                std::snprintf(code, sizeof code, "0x%02x",
                              static_cast<unsigned>(static_cast<unsigned char>(raw[k])));
                throw ScriptError(name_ + ":" + std::to_string(lineNumber) + ": control character " + code +
                                  " at column " + std::to_string(k + 1));
            }
        const std::string line = isStringLine(raw) ? raw : raw.substr(0, raw.find('#'));
        const auto words = splitWords(line);
        if (words.empty()) continue;
        LineParser p(name_, lineNumber, words);
        InputAction a;
        a.line = lineNumber;
        a.text = line.substr(line.find_first_not_of(" \t"));
        while (!a.text.empty() && (a.text.back() == ' ' || a.text.back() == '\t')) a.text.pop_back();
        const std::string& verb = words[0];
        if (verb == "move") {
            const int device = p.takeDevice();
            p.expectCount(3, "move X Y [device D]");
            a.what = action::Move{glm::dvec2(p.number(1, "X"), p.number(2, "Y")), device};
        } else if (verb == "pick" || verb == "locator") {
            const int device = p.takeDevice();
            p.expectCount(3, verb == "pick" ? "pick X Y [device D]" : "locator X Y [device D]");
            const glm::dvec2 pos(p.number(1, "X"), p.number(2, "Y"));
            if (verb == "pick")
                a.what = action::Pick{pos, device};
            else
                a.what = action::Locate{pos, device};
        } else if (verb == "stroke") {
            const int device = p.takeDevice();
            const auto& w = p.words();
            if (w.size() < 3 || (w.size() - 1) % 2 != 0)
                p.fail("expected 'stroke X1 Y1 X2 Y2 ... [device D]'");
            action::Stroke s;
            s.device = device;
            for (std::size_t i = 1; i + 1 < w.size(); i += 2)
                s.points.emplace_back(p.number(i, "X"), p.number(i + 1, "Y"));
            a.what = std::move(s);
        } else if (verb == "valuator") {
            p.expectCount(3, "valuator DEVICE VALUE");
            const int device = p.integer(1, "device number");
            if (device < 1) p.fail("device number must be at least 1");
            a.what = action::Valuator{device, p.number(2, "VALUE")};
        } else if (verb == "choice") {
            const int device = p.takeDevice();
            p.expectCount(2, "choice N|NAME [device D]");
            const std::string& word = p.words()[1];
            const bool numeric = word.find_first_not_of("+-0123456789.eE") == std::string::npos;
            if (numeric)
                a.what = action::Choice{p.integer(1, "choice"), device, {}};
            else
                a.what = action::Choice{0, device, word};
        } else if (verb == "string") {
            const std::size_t start = line.find("string") + 6;
            std::string rest = start < line.size() ? line.substr(start) : std::string();
            const std::size_t first = rest.find_first_not_of(" \t");
            rest = first == std::string::npos ? std::string() : rest.substr(first);
            while (!rest.empty() && (rest.back() == ' ' || rest.back() == '\t')) rest.pop_back();
            a.what = action::String{rest, 1};
        } else if (verb == "break") {
            p.expectCount(1, "break");
            a.what = action::Break{};
        } else if (verb == "wait") {
            p.expectCount(1, "wait");
            a.what = action::Wait{};
        } else if (directives.count(verb)) {
            a.what = action::Directive{verb, std::vector<std::string>(words.begin() + 1, words.end())};
        } else {
            std::string known = "pick, locator, move, stroke, valuator, choice, string, break, wait";
            for (const auto& d : directives) known += ", " + d;
            p.fail("unknown action '" + verb + "' (known: " + known + ")");
        }
        actions_.push_back(std::move(a));
    }
}

ScriptInputSource ScriptInputSource::fromFile(const std::filesystem::path& path,
                                              std::set<std::string> directives) {
    std::error_code ec;
    if (std::filesystem::is_directory(path, ec))
        throw ScriptError(path.string() + ": is a directory, not a session script");
    // A device or a pipe (/dev/zero, a FIFO) could block the open or never end.
    if (std::filesystem::exists(path, ec) && !std::filesystem::is_regular_file(path, ec))
        throw ScriptError(path.string() + ": is not a regular file, not a session script");
    std::ifstream in(path, std::ios::binary);
    if (!in) throw ScriptError(path.string() + ": cannot open the session script");
    const auto size = std::filesystem::file_size(path, ec);
    if (!ec && size > kMaxScriptBytes)
        throw ScriptError(path.string() + ": the script is " + std::to_string(size) +
                          " bytes; the limit is " + std::to_string(kMaxScriptBytes));
    // Read with the limit in hand too: a file that grows while it is read stops there.
    std::string text;
    char chunk[1 << 16];
    while (in.read(chunk, sizeof chunk) || in.gcount() > 0) {
        text.append(chunk, static_cast<std::size_t>(in.gcount()));
        if (text.size() > kMaxScriptBytes)
            throw ScriptError(path.string() + ": the script is longer than the limit of " +
                              std::to_string(kMaxScriptBytes) + " bytes");
    }
    if (in.bad()) throw ScriptError(path.string() + ": cannot read the session script");
    return ScriptInputSource(text, path.string(), std::move(directives));
}

std::optional<InputAction> ScriptInputSource::next(std::chrono::milliseconds) {
    if (cursor_ >= actions_.size())
        throw InputExhausted(name_ + ": the script ended (after line " + std::to_string(lastLine_) +
                             ") while the application waits for input");
    lastLine_ = actions_[cursor_].line;
    return actions_[cursor_++];
}

std::string ScriptInputSource::position() const {
    return name_ + " line " + std::to_string(lastLine_);
}

std::string ScriptInputSource::format(const InputAction& a) {
    return std::visit(
        [](const auto& w) -> std::string {
            using T = std::decay_t<decltype(w)>;
            if constexpr (std::is_same_v<T, action::Pick>)
                return "pick " + formatNumber(w.position.x) + " " + formatNumber(w.position.y) +
                       deviceSuffix(w.device);
            else if constexpr (std::is_same_v<T, action::Move>)
                return "move " + formatNumber(w.position.x) + " " + formatNumber(w.position.y) +
                       deviceSuffix(w.device);
            else if constexpr (std::is_same_v<T, action::Locate>)
                return "locator " + formatNumber(w.position.x) + " " + formatNumber(w.position.y) +
                       deviceSuffix(w.device);
            else if constexpr (std::is_same_v<T, action::Stroke>) {
                std::string s = "stroke";
                for (const auto& p : w.points) s += " " + formatNumber(p.x) + " " + formatNumber(p.y);
                return s + deviceSuffix(w.device);
            } else if constexpr (std::is_same_v<T, action::Valuator>)
                return "valuator " + std::to_string(w.device) + " " + formatNumber(w.value);
            else if constexpr (std::is_same_v<T, action::Choice>)
                return "choice " + (w.name.empty() ? std::to_string(w.choice) : w.name) +
                       deviceSuffix(w.device);
            else if constexpr (std::is_same_v<T, action::String>)
                return "string " + w.text;
            else if constexpr (std::is_same_v<T, action::Break>)
                return "break";
            else if constexpr (std::is_same_v<T, action::Wait>)
                return "wait";
            else {
                std::string s = w.name;
                for (const auto& arg : w.arguments) s += " " + arg;
                return s;
            }
        },
        a.what);
}

bool ScriptInputSource::readsBack(const InputAction& action) {
    std::set<std::string> directives;
    if (const auto* d = std::get_if<action::Directive>(&action.what)) directives.insert(d->name);
    try {
        const ScriptInputSource parsed(format(action), "format", std::move(directives));
        return parsed.actions().size() == 1 && parsed.actions()[0].what == action.what;
    } catch (const ScriptError&) {
        return false;
    }
}

}  // namespace phigs
