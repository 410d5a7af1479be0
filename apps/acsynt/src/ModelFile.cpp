#include "acsynt/ModelFile.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <istream>
#include <limits>
#include <optional>
#include <ostream>
#include <set>
#include <sstream>

namespace acsynt {
namespace {

constexpr std::size_t maxLineLength = kModelFileMaxLineLength;
constexpr std::uintmax_t maxFileBytes = kModelFileMaxBytes;
constexpr std::size_t maxComponents = kModelMaxComponents;
constexpr int maxSections = 200;
constexpr int maxPoints = 201;

std::vector<std::string_view> tokenize(std::string_view line) {
    std::vector<std::string_view> tokens;
    std::size_t i = 0;
    while (i < line.size()) {
        while (i < line.size() && (line[i] == ' ' || line[i] == '\t')) ++i;
        if (i >= line.size() || line[i] == '#') break;
        const std::size_t start = i;
        while (i < line.size() && line[i] != ' ' && line[i] != '\t' && line[i] != '#') ++i;
        tokens.push_back(line.substr(start, i - start));
    }
    return tokens;
}

std::string inQuotes(std::string_view s) {
    return "'" + std::string(s) + "'";
}

/// Reads one description line by line, with the place of every fault.
class Parser {
public:
    Parser(std::istream& in, std::string fileName) : in_(in), file_(std::move(fileName)) {}

    AircraftDescription parse() {
        AircraftDescription d;
        if (!next()) fail("the file is empty; it must start with 'acsynt-model 1'");
        if (tokens_[0] != "acsynt-model")
            fail("the file must start with 'acsynt-model " + std::to_string(aircraftDescriptionVersion) +
                 "', found " + inQuotes(tokens_[0]));
        expectCount(2, "acsynt-model VERSION");
        d.version = integer(1, "version");
        if (d.version != aircraftDescriptionVersion)
            fail("format version " + std::to_string(d.version) + " is not supported (this reads version " +
                 std::to_string(aircraftDescriptionVersion) + ")");
        std::set<std::string> names;
        std::size_t patches = 0, lofted = 0;  // mirror images included in both
        while (next()) {
            const std::string_view key = tokens_[0];
            if (key == "model") {
                if (!d.name.empty()) fail("'model' is given twice");
                expectCount(2, "model NAME");
                d.name = name(1, "model name");
            } else if (key == "component") {
                if (d.name.empty()) fail("'model NAME' must come before the first component");
                if (lofted == maxComponents)
                    fail("more than " + std::to_string(maxComponents) + " components");
                ComponentDescription c = component();
                const std::size_t images = c.mirrorName.empty() ? 1 : 2;
                lofted += images;
                if (lofted > maxComponents)
                    failAt(c.line, "more than " + std::to_string(maxComponents) +
                                       " components with this one's mirror image");
                patches += loftedPatchCount(c) * images;
                if (patches > kModelMaxPatches)
                    fail("the components so far loft to " + std::to_string(patches) +
                         " patches; the limit is " + std::to_string(kModelMaxPatches) + " per model");
                for (const std::string* n : {&c.name, &c.mirrorName}) {
                    if (n->empty()) continue;
                    if (!names.insert(*n).second)
                        failAt(c.line, "component name " + inQuotes(*n) + " is used twice");
                }
                d.components.push_back(std::move(c));
            } else {
                fail("unknown keyword " + inQuotes(key) + " (expected 'model' or 'component')");
            }
        }
        if (d.name.empty()) fail("the file has no 'model NAME' line");
        if (d.components.empty()) fail("the model has no components");
        return d;
    }

private:
    [[noreturn]] void fail(const std::string& reason) const { failAt(line_, reason); }
    [[noreturn]] void failAt(int line, const std::string& reason) const {
        throw ModelFileError(file_, line, reason);
    }

    /// Advances to the next line with tokens; false at the end of the file.
    bool next() {
        std::string text;
        while (readTextLine(in_, text)) {
            ++line_;
            if (text.size() > maxLineLength)
                fail("line longer than " + std::to_string(maxLineLength) + " characters");
            for (std::size_t k = 0; k < text.size(); ++k)
                if (static_cast<unsigned char>(text[k]) < 0x20 && text[k] != '\t') {
                    char code[16];
                    std::snprintf(code, sizeof code, "0x%02x", static_cast<unsigned>(text[k]));
                    fail(std::string("control character ") + code + " at column " + std::to_string(k + 1));
                }
            // The tokens view text_, which keeps the line until the next one is read.
            text_ = std::move(text);
            tokens_ = tokenize(text_);
            if (!tokens_.empty()) return true;
        }
        if (in_.bad()) fail("read error");
        return false;
    }

    void expectCount(std::size_t count, const char* form) const {
        if (tokens_.size() < count)
            fail("missing value: " + inQuotes(tokens_[0]) + " takes the form '" + form + "'");
        if (tokens_.size() > count) fail("unexpected " + inQuotes(tokens_[count]) + " after '" + form + "'");
    }

    double number(std::size_t index, const std::string& what) const {
        const std::string_view t = tokens_[index];
        double value = 0.0;
        const auto [end, ec] = std::from_chars(t.data(), t.data() + t.size(), value);
        if (ec != std::errc() || end != t.data() + t.size())
            fail(what + ": " + inQuotes(t) + " is not a number");
        if (!std::isfinite(value)) fail(what + ": " + inQuotes(t) + " is not a finite number");
        return value;
    }

    double number(std::size_t index, const std::string& what, double lo, double hi) const {
        const double v = number(index, what);
        if (v < lo || v > hi)
            fail(what + " " + std::string(tokens_[index]) + " is outside [" + shortest(lo) + ", " +
                 shortest(hi) + "]");
        return v;
    }

    /// A place in model units: within a million of the origin, as sizes are, so that every point
    /// of a lofted model stays finite through the views and within a saved model's limits.
    double coordinate(std::size_t index, const std::string& what) const {
        return number(index, what, -kModelMaxLength, kModelMaxLength);
    }

    int integer(std::size_t index, const std::string& what) const {
        const std::string_view t = tokens_[index];
        int value = 0;
        const auto [end, ec] = std::from_chars(t.data(), t.data() + t.size(), value);
        if (ec == std::errc::result_out_of_range && end == t.data() + t.size())
            fail(what + ": " + inQuotes(t) + " is out of range (" +
                 std::to_string(std::numeric_limits<int>::min()) + " to " +
                 std::to_string(std::numeric_limits<int>::max()) + ")");
        if (ec != std::errc() || end != t.data() + t.size())
            fail(what + ": " + inQuotes(t) + " is not a whole number");
        return value;
    }

    std::string name(std::size_t index, const std::string& what) const {
        const std::string_view t = tokens_[index];
        if (!isValidName(t))
            fail(what + " " + inQuotes(t) + " must be 1 to 20 letters, digits, '_', '-' or '.'");
        return std::string(t);
    }

    static std::string shortest(double v) {
        char buffer[64];
        const auto r = std::to_chars(buffer, buffer + sizeof buffer, v);
        return std::string(buffer, r.ptr);
    }

    /// Marks a keyword as given once in the current component.
    void once(std::set<std::string, std::less<>>& seen) const {
        if (!seen.insert(std::string(tokens_[0])).second) fail(inQuotes(tokens_[0]) + " is given twice");
    }

    ComponentDescription component() {
        expectCount(3, "component KIND NAME");
        ComponentDescription c;
        c.line = line_;
        const std::string_view kind = tokens_[1];
        if (kind == "fuselage") {
            c.kind = ComponentKind::Fuselage;
            c.shape = FuselageShape{};
        } else if (kind == "wing" || kind == "htail" || kind == "vtail") {
            c.kind = kind == "wing"    ? ComponentKind::Wing
                     : kind == "htail" ? ComponentKind::HorizontalTail
                                       : ComponentKind::VerticalTail;
            c.shape = LiftingSurfaceShape{};
        } else if (kind == "nacelle") {
            c.kind = ComponentKind::Nacelle;
            c.shape = NacelleShape{};
        } else {
            fail("unknown component kind " + inQuotes(kind) + " (fuselage, wing, htail, vtail or nacelle)");
        }
        c.name = name(2, "component name");
        const std::string label = std::string(kind) + " " + inQuotes(c.name);
        std::set<std::string, std::less<>> seen;
        int sections = 0;
        while (true) {
            if (!next()) fail("the file ends inside " + label + " (missing 'end')");
            const std::string_view key = tokens_[0];
            if (key == "end") {
                expectCount(1, "end");
                break;
            }
            if (key == "component") fail(label + " is not closed with 'end' before the next component");
            if (key == "colour") {
                once(seen);
                expectCount(4, "colour R G B");
                c.colour = {number(1, "colour red", 0, 1), number(2, "colour green", 0, 1),
                            number(3, "colour blue", 0, 1)};
            } else if (key == "points") {
                once(seen);
                expectCount(2, "points N");
                c.points = integer(1, "points");
                if (c.kind == ComponentKind::Fuselage || c.kind == ComponentKind::Nacelle) {
                    if (c.points < 4 || c.points > maxPoints - 1)
                        fail("points " + std::to_string(c.points) + ": a closed section needs 4 to " +
                             std::to_string(maxPoints - 1) + " points");
                } else if (c.points < 5 || c.points > maxPoints || c.points % 2 == 0) {
                    fail("points " + std::to_string(c.points) +
                         ": an airfoil section needs an odd number of " + "points from 5 to " +
                         std::to_string(maxPoints));
                }
            } else if (key == "sections") {
                once(seen);
                expectCount(2, "sections N");
                sections = integer(1, "sections");
                if (sections < 4 || sections > maxSections)
                    fail("sections " + std::to_string(sections) + ": a bicubic loft needs 4 to " +
                         std::to_string(maxSections) + " sections");
            } else if (key == "mirror" && c.kind != ComponentKind::Fuselage) {
                once(seen);
                expectCount(2, "mirror NAME");
                c.mirrorName = name(1, "mirror name");
                if (c.mirrorName == c.name) fail("the mirror image needs a name of its own");
            } else if (auto* f = std::get_if<FuselageShape>(&c.shape)) {
                fuselageLine(*f);
            } else if (auto* w = std::get_if<LiftingSurfaceShape>(&c.shape)) {
                liftingSurfaceLine(*w, seen);
            } else {
                nacelleLine(std::get<NacelleShape>(c.shape), seen);
            }
        }
        // Checks of the whole component, reported at its 'end' line.
        auto require = [&](const char* key) {
            if (!seen.contains(key)) fail(label + " lacks " + inQuotes(key));
        };
        require("points");
        require("sections");
        if (auto* f = std::get_if<FuselageShape>(&c.shape)) {
            if (static_cast<int>(f->stations.size()) != sections)
                fail(label + " declares " + std::to_string(sections) + " sections but lists " +
                     std::to_string(f->stations.size()) + " stations");
            for (std::size_t i = 1; i + 1 < f->stations.size(); ++i)
                if (f->stations[i].halfWidth == 0.0)
                    failAt(f->stations[i].line, "only the first and last station may be a point section");
        } else if (auto* w = std::get_if<LiftingSurfaceShape>(&c.shape)) {
            w->sections = sections;
            require("airfoil");
            require("position");
            require("root_chord");
            require("span");
        } else {
            auto& n = std::get<NacelleShape>(c.shape);
            require("position");
            if (static_cast<int>(n.profile.size()) != sections)
                fail(label + " declares " + std::to_string(sections) + " sections but lists " +
                     std::to_string(n.profile.size()) + " profile stations");
            for (std::size_t i = 1; i + 1 < n.profile.size(); ++i)
                if (n.profile[i].radius == 0.0)
                    failAt(n.profile[i].line, "only the first and last profile station may have radius 0");
        }
        return c;
    }

    void fuselageLine(FuselageShape& f) {
        const std::string_view key = tokens_[0];
        if (key != "station") fail("unknown keyword " + inQuotes(key) + " in a fuselage");
        expectCount(8, "station PART X HALF_WIDTH UPPER_HEIGHT LOWER_HEIGHT Z_CENTRE EXPONENT");
        FuselageStation s;
        s.line = line_;
        const std::string_view part = tokens_[1];
        if (part == "nose")
            s.part = FuselagePart::Nose;
        else if (part == "mid")
            s.part = FuselagePart::Mid;
        else if (part == "aft")
            s.part = FuselagePart::Afterbody;
        else
            fail("station part " + inQuotes(part) + " must be nose, mid or aft");
        s.x = coordinate(2, "station x");
        s.halfWidth = number(3, "station half width", 0, kModelMaxLength);
        s.upperHeight = number(4, "station upper height", 0, kModelMaxLength);
        s.lowerHeight = number(5, "station lower height", 0, kModelMaxLength);
        s.zCentre = coordinate(6, "station z centre");
        s.exponent = number(7, "station exponent", 1, 10);
        const bool point = s.halfWidth == 0.0 && s.upperHeight == 0.0 && s.lowerHeight == 0.0;
        const bool solid = s.halfWidth > 0.0 && s.upperHeight > 0.0 && s.lowerHeight > 0.0;
        if (!point && !solid)
            fail("a station's half width and heights must all be positive, or all zero for a point section");
        if (!f.stations.empty()) {
            const FuselageStation& prev = f.stations.back();
            if (!(s.x > prev.x))
                fail("station x " + std::string(tokens_[2]) +
                     " does not increase on the previous station x " + shortest(prev.x));
            if (s.part < prev.part) fail("station part " + inQuotes(part) + " comes after a later part");
        }
        if (f.stations.size() >= static_cast<std::size_t>(maxSections)) fail("too many stations");
        f.stations.push_back(s);
    }

    void liftingSurfaceLine(LiftingSurfaceShape& w, std::set<std::string, std::less<>>& seen) {
        const std::string_view key = tokens_[0];
        auto angle = [&](double& target, double limit) {
            once(seen);
            expectCount(2, "KEYWORD DEGREES");
            target = number(1, std::string(key), -limit, limit);
        };
        if (key == "airfoil") {
            once(seen);
            if (tokens_.size() < 2) fail("missing value: 'airfoil' takes the form 'airfoil ROOT [TIP]'");
            if (tokens_.size() > 3) fail("unexpected " + inQuotes(tokens_[3]) + " after 'airfoil ROOT TIP'");
            try {
                w.rootAirfoil = parseNaca4(tokens_[1]);
                w.tipAirfoil = tokens_.size() == 3 ? parseNaca4(tokens_[2]) : w.rootAirfoil;
            } catch (const std::invalid_argument& e) {
                fail(e.what());
            }
        } else if (key == "position") {
            once(seen);
            expectCount(4, "position X Y Z");
            w.position = {coordinate(1, "position x"), coordinate(2, "position y"),
                          coordinate(3, "position z")};
        } else if (key == "root_chord") {
            once(seen);
            expectCount(2, "root_chord LENGTH");
            w.rootChord = number(1, "root_chord", 0, kModelMaxLength);
            if (w.rootChord == 0.0) fail("root_chord must be positive");
        } else if (key == "taper") {
            once(seen);
            expectCount(2, "taper RATIO");
            w.taper = number(1, "taper", 0, 10);
            if (w.taper == 0.0) fail("taper must be positive");
        } else if (key == "span") {
            once(seen);
            expectCount(2, "span LENGTH");
            w.span = number(1, "span", 0, kModelMaxLength);
            if (w.span == 0.0) fail("span must be positive");
        } else if (key == "sweep") {
            angle(w.sweep, 80);
        } else if (key == "dihedral") {
            angle(w.dihedral, 90);
        } else if (key == "incidence") {
            angle(w.incidence, 30);
        } else if (key == "twist") {
            angle(w.twist, 30);
        } else {
            fail("unknown keyword " + inQuotes(key) + " in a wing or tail");
        }
    }

    void nacelleLine(NacelleShape& n, std::set<std::string, std::less<>>& seen) {
        const std::string_view key = tokens_[0];
        if (key == "position") {
            once(seen);
            expectCount(4, "position X Y Z");
            n.position = {coordinate(1, "position x"), coordinate(2, "position y"),
                          coordinate(3, "position z")};
        } else if (key == "profile") {
            expectCount(3, "profile X RADIUS");
            NacelleStation s{coordinate(1, "profile x"), number(2, "profile radius", 0, kModelMaxLength),
                             line_};
            if (!n.profile.empty() && !(s.x > n.profile.back().x))
                fail("profile x " + std::string(tokens_[1]) +
                     " does not increase on the previous profile x " + shortest(n.profile.back().x));
            if (n.profile.size() >= static_cast<std::size_t>(maxSections)) fail("too many profile stations");
            n.profile.push_back(s);
        } else {
            fail("unknown keyword " + inQuotes(key) + " in a nacelle");
        }
    }

    std::istream& in_;
    std::string file_;
    int line_ = 0;
    std::string text_;
    std::vector<std::string_view> tokens_;
};

std::string shortestNumber(double v) {
    char buffer[64];
    const auto r = std::to_chars(buffer, buffer + sizeof buffer, v);
    return std::string(buffer, r.ptr);
}

const char* partKeyword(FuselagePart part) {
    switch (part) {
        case FuselagePart::Nose:
            return "nose";
        case FuselagePart::Mid:
            return "mid";
        case FuselagePart::Afterbody:
            return "aft";
    }
    return "mid";
}

}  // namespace

ModelFileError::ModelFileError(std::string file, int line, std::string reason)
    : std::runtime_error(file + ":" + std::to_string(line) + ": " + reason),
      file_(std::move(file)),
      line_(line),
      reason_(std::move(reason)) {
}

const char* componentKindKeyword(ComponentKind kind) {
    switch (kind) {
        case ComponentKind::Fuselage:
            return "fuselage";
        case ComponentKind::Wing:
            return "wing";
        case ComponentKind::HorizontalTail:
            return "htail";
        case ComponentKind::VerticalTail:
            return "vtail";
        case ComponentKind::Nacelle:
            return "nacelle";
    }
    return "fuselage";
}

std::size_t loftedPatchCount(const ComponentDescription& c) {
    // A cubic interpolating n data points in an open direction has n - 3 knot spans; a periodic
    // one (closed sections round w) has one span per data point.
    std::size_t sections = 0;
    if (const auto* f = std::get_if<FuselageShape>(&c.shape))
        sections = f->stations.size();
    else if (const auto* w = std::get_if<LiftingSurfaceShape>(&c.shape))
        sections = static_cast<std::size_t>(std::max(w->sections, 0));
    else
        sections = std::get<NacelleShape>(c.shape).profile.size();
    const bool closed = c.kind == ComponentKind::Fuselage || c.kind == ComponentKind::Nacelle;
    const std::size_t points = static_cast<std::size_t>(std::max(c.points, 0));
    const std::size_t spansU = sections > 3 ? sections - 3 : 0;
    const std::size_t spansW = closed ? points : (points > 3 ? points - 3 : 0);
    return spansU * spansW;
}

bool isValidName(std::string_view name) {
    if (name.empty() || name.size() > 20) return false;
    return std::all_of(name.begin(), name.end(), [](char c) {
        return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '_' ||
               c == '-' || c == '.';
    });
}

AircraftDescription parseAircraftDescription(std::istream& in, const std::string& fileName) {
    return Parser(in, fileName).parse();
}

void requireRegularFile(const std::filesystem::path& path, const std::string& suffix) {
    std::error_code ec;
    if (std::filesystem::is_directory(path, ec))
        throw ModelFileError(path.string(), 0, "is a directory" + suffix);
    if (std::filesystem::exists(path, ec) && !std::filesystem::is_regular_file(path, ec))
        throw ModelFileError(path.string(), 0, "is not a regular file" + suffix);
}

bool readTextLine(std::istream& in, std::string& line) {
    line.clear();
    const std::istream::sentry ready(in, true);
    if (!ready) return false;
    std::streambuf& text = *in.rdbuf();
    for (;;) {
        const int c = text.sbumpc();
        if (c == std::char_traits<char>::eof()) {
            in.setstate(line.empty() ? std::ios::eofbit | std::ios::failbit : std::ios::eofbit);
            if (line.empty()) return false;
            break;
        }
        if (c == '\n' || c == '\r') {
            if (c == '\r' && text.sgetc() == '\n') text.sbumpc();
            break;
        }
        line.push_back(static_cast<char>(c));
    }
    // A UTF-8 byte-order mark (Windows editors begin a file with one) is not part of the line.
    if (line.rfind("\xEF\xBB\xBF", 0) == 0) line.erase(0, 3);
    return true;
}

AircraftDescription readAircraftDescription(const std::filesystem::path& path) {
    requireRegularFile(path, ", not an aircraft description");
    std::error_code ec;
    std::ifstream in(path);
    if (!in) throw ModelFileError(path.string(), 0, "cannot open the file");
    if (const auto size = std::filesystem::file_size(path, ec); !ec && size > maxFileBytes)
        throw ModelFileError(
            path.string(), 0,
            "the file is " + std::to_string(size) + " bytes; the limit is " + std::to_string(maxFileBytes));
    return parseAircraftDescription(in, path.string());
}

void writeAircraftDescription(std::ostream& out, const AircraftDescription& d) {
    const auto n = shortestNumber;
    out << "acsynt-model " << aircraftDescriptionVersion << "\n";
    out << "model " << d.name << "\n";
    for (const ComponentDescription& c : d.components) {
        out << "\ncomponent " << componentKindKeyword(c.kind) << " " << c.name << "\n";
        out << "  colour " << n(c.colour.x) << " " << n(c.colour.y) << " " << n(c.colour.z) << "\n";
        out << "  points " << c.points << "\n";
        if (!c.mirrorName.empty()) out << "  mirror " << c.mirrorName << "\n";
        if (const auto* f = std::get_if<FuselageShape>(&c.shape)) {
            out << "  sections " << f->stations.size() << "\n";
            for (const FuselageStation& s : f->stations)
                out << "  station " << partKeyword(s.part) << " " << n(s.x) << " " << n(s.halfWidth) << " "
                    << n(s.upperHeight) << " " << n(s.lowerHeight) << " " << n(s.zCentre) << " "
                    << n(s.exponent) << "\n";
        } else if (const auto* w = std::get_if<LiftingSurfaceShape>(&c.shape)) {
            out << "  sections " << w->sections << "\n";
            out << "  airfoil " << w->rootAirfoil.code << " " << w->tipAirfoil.code << "\n";
            out << "  position " << n(w->position.x) << " " << n(w->position.y) << " " << n(w->position.z)
                << "\n";
            out << "  root_chord " << n(w->rootChord) << "\n";
            out << "  taper " << n(w->taper) << "\n";
            out << "  span " << n(w->span) << "\n";
            out << "  sweep " << n(w->sweep) << "\n";
            out << "  dihedral " << n(w->dihedral) << "\n";
            out << "  incidence " << n(w->incidence) << "\n";
            out << "  twist " << n(w->twist) << "\n";
        } else {
            const auto& s = std::get<NacelleShape>(c.shape);
            out << "  sections " << s.profile.size() << "\n";
            out << "  position " << n(s.position.x) << " " << n(s.position.y) << " " << n(s.position.z)
                << "\n";
            for (const NacelleStation& p : s.profile)
                out << "  profile " << n(p.x) << " " << n(p.radius) << "\n";
        }
        out << "end\n";
    }
}

}  // namespace acsynt
