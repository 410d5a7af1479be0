#include "acsynt/session/ModelStateFile.h"

#include "acsynt/ModelFile.h"

#include "geom/BoundingBox.h"
#include "geom/Evaluate.h"
#include "geom/GeometryError.h"
#include "geom/curvemap/SurfaceDomain.h"

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <limits>
#include <sstream>

namespace acsynt {

namespace {

std::string hex(double v) {
    char buffer[64];
    std::snprintf(buffer, sizeof buffer, "%a", v);
    return buffer;
}

void writeVector(std::ostream& out, const char* key, const std::vector<double>& values) {
    out << key << " " << values.size();
    for (double v : values) out << " " << hex(v);
    out << "\n";
}

const char* kindKeyword(ComponentKind kind) {
    return componentKindKeyword(kind);
}

/// Line-by-line reader: each line a keyword and words; faults name file and line.
class Reader {
public:
    Reader(std::istream& in, std::string file) : in_(in), file_(std::move(file)) {}

    /// The next non-empty line's words: `keyword` and exactly `words - 1` values.
    std::vector<std::string> line(const std::string& keyword, std::size_t words = 1) {
        std::vector<std::string> out = lineWithText(keyword, words);
        if (out.size() != words)
            fail("'" + keyword + "' takes " + std::to_string(words - 1) + " values, not " +
                 std::to_string(out.size() - 1));
        return out;
    }
    /// The next non-empty line's words: `keyword`, at least `minWords - 1` values, then any text.
    std::vector<std::string> lineWithText(const std::string& keyword, std::size_t minWords) {
        std::vector<std::string> words = next();
        if (words.empty()) fail("the file ends where '" + keyword + "' was expected");
        if (words[0] != keyword) fail("expected '" + keyword + "', found '" + words[0] + "'");
        if (words.size() < minWords)
            fail("'" + keyword + "' needs " + std::to_string(minWords - 1) + " values");
        return words;
    }
    /// The next line's words (empty at the end of the file).
    std::vector<std::string> next() {
        std::string text;
        while (readTextLine(in_, text)) {
            ++number_;
            if (text.size() > 1u << 20) fail("a line longer than 1 MB");
            std::istringstream words(text);
            std::vector<std::string> out;
            for (std::string w; words >> w;) out.push_back(w);
            if (!out.empty() && out[0][0] != '#') return out;  // blank lines and comments are skipped
        }
        return {};
    }
    double real(const std::string& word) {
        char* end = nullptr;
        const double v = std::strtod(word.c_str(), &end);
        if (word.empty() || end != word.c_str() + word.size() || !std::isfinite(v))
            fail("'" + word + "' is not a finite number");
        return v;
    }
    /// A colour component, from 0 to 1.
    double fraction(const std::string& word) {
        const double v = real(word);
        if (!(v >= 0.0 && v <= 1.0)) fail("the colour component '" + word + "' is not from 0 to 1");
        return v;
    }
    /// A coordinate: a finite number within kModelStateMaxCoordinate (one beyond it, 1e301 say,
    /// made the view's bounds infinite).
    double coordinate(const std::string& word) {
        const double v = real(word);
        if (!isSavableCoordinate(v))
            fail("the coordinate '" + word + "' is beyond " + std::to_string(int(kModelStateMaxCoordinate)));
        return v;
    }
    std::size_t count(const std::string& word, std::size_t limit) {
        const double v = real(word);
        if (!(v >= 0) || v != std::floor(v) || v > double(limit))
            fail("'" + word + "' is not a count from 0 to " + std::to_string(limit));
        return std::size_t(v);
    }
    std::string name(const std::string& word) {
        if (!isValidName(word)) fail("'" + word + "' is not a valid name");
        return word;
    }
    std::vector<double> reals(const std::vector<std::string>& words, std::size_t from, std::size_t limit) {
        const std::size_t n = count(words.at(from), limit);
        if (words.size() != from + 1 + n) fail("expected " + std::to_string(n) + " numbers");
        std::vector<double> out;
        for (std::size_t i = 0; i < n; ++i) out.push_back(real(words[from + 1 + i]));
        return out;
    }
    [[noreturn]] void fail(const std::string& reason) const { failAt(number_, reason); }
    [[noreturn]] void failAt(int line, const std::string& reason) const {
        throw ModelFileError(file_, line, reason);
    }
    int lineNumber() const { return number_; }

private:
    std::istream& in_;
    std::string file_;
    int number_ = 0;
};

ComponentKind kindOf(Reader& r, const std::string& word) {
    for (ComponentKind k : {ComponentKind::Fuselage, ComponentKind::Wing, ComponentKind::HorizontalTail,
                            ComponentKind::VerticalTail, ComponentKind::Nacelle})
        if (word == kindKeyword(k)) return k;
    r.fail("unknown component kind '" + word + "'");
}

/// How near, relative to a surface's size, a point said to be on it (a loop vertex) or an edge
/// said to meet another (a closed direction's seam) must be: rounding, not a different place.
constexpr double kOnSurface = 1e-6;

/// The non-empty knot spans of a direction's domain: the patches it is cut into that way.
std::size_t spans(const std::vector<double>& knots, int degree, std::size_t count) {
    std::size_t n = 0;
    for (std::size_t i = static_cast<std::size_t>(degree); i < count; ++i) n += knots[i] < knots[i + 1];
    return n;
}

Component readComponent(Reader& r, std::size_t& points, std::size_t& patches) {
    const auto head = r.line("component", 5);
    const int headLine = r.lineNumber();
    Component c;
    c.name = r.name(head[1]);
    c.kind = kindOf(r, head[2]);
    c.closedU = r.count(head[3], 1) == 1;
    c.closedW = r.count(head[4], 1) == 1;
    const auto colour = r.line("colour", 4);
    c.colour = {r.fraction(colour[1]), r.fraction(colour[2]), r.fraction(colour[3])};
    const auto s = r.line("surface", 6);
    const int degreeU = int(r.count(s[1], 9)), degreeV = int(r.count(s[2], 9));
    const std::size_t countU = r.count(s[3], kModelStateMaxPoints),
                      countV = r.count(s[4], kModelStateMaxPoints);
    const bool rational = r.count(s[5], 1) == 1;
    if (countU * countV > kModelStateMaxPoints || (points += countU * countV) > kModelStateMaxPoints)
        r.fail("more than " + std::to_string(kModelStateMaxPoints) + " control points");
    std::vector<double> knotsU = r.reals(r.lineWithText("knots_u", 2), 1, countU + 10);
    std::vector<double> knotsV = r.reals(r.lineWithText("knots_w", 2), 1, countV + 10);
    // The patch limit is checked before the points are read and the patches made: a 2048 x 2048
    // net within the point limit is a quarter of a gigabyte of text and four million patches.
    // (Knot vectors of the wrong length are left to the surface's own check, below.)
    if (knotsU.size() == countU + std::size_t(degreeU) + 1 &&
        knotsV.size() == countV + std::size_t(degreeV) + 1 &&
        (patches += spans(knotsU, degreeU, countU) * spans(knotsV, degreeV, countV)) > kModelMaxPatches)
        r.fail("more than " + std::to_string(kModelMaxPatches) + " patches");
    std::vector<glm::dvec3> net;
    std::vector<double> weights;
    for (std::size_t i = 0; i < countU * countV; ++i) {
        const auto p = r.lineWithText("p", 1);
        if (p.size() != (rational ? 5u : 4u))
            r.fail("a control point has x y z" + std::string(rational ? " w" : ""));
        net.push_back({r.coordinate(p[1]), r.coordinate(p[2]), r.coordinate(p[3])});
        if (rational) weights.push_back(r.real(p[4]));
    }
    try {
        c.surface = geom::Surface(degreeU, degreeV, std::move(knotsU), std::move(knotsV), countU, countV,
                                  std::move(net), std::move(weights));
    } catch (const geom::GeometryError& e) {
        r.fail(std::string("component ") + c.name + ": " + e.what());
    }
    try {
        c.updatePatches();
    } catch (const geom::GeometryError& e) {
        r.fail(std::string("component ") + c.name + ": " + e.what());
    }
    // A direction said to be closed must close: mapping wraps loops across its seam.
    if (c.closedU && !geom::curvemap::closesInU(c.surface, kOnSurface))
        r.failAt(headLine, "component " + c.name + " is said to be closed in u, but its u ends are apart");
    if (c.closedW && !geom::curvemap::closesInV(c.surface, kOnSurface))
        r.failAt(headLine, "component " + c.name + " is said to be closed in w, but its w ends are apart");
    return c;
}

/// Whether (u, w) lies in the component's parameter domain (within rounding); a loop's vertices
/// may go on a period past it along a closed direction, where loops cross the seam.
bool inDomain(const Component& c, glm::dvec2 uw, bool acrossSeams) {
    const geom::Surface& s = c.surface;
    auto within = [&](double t, double start, double end, bool closed) {
        const double period = end - start, slack = 1e-9 * (1.0 + std::abs(period));
        const double reach = acrossSeams && closed ? period : 0.0;
        return t >= start - reach - slack && t <= end + reach + slack;
    };
    return within(uw.x, s.domainStartU(), s.domainEndU(), c.closedU) &&
           within(uw.y, s.domainStartV(), s.domainEndV(), c.closedW);
}

/// The component's point at (u, w): a closed coordinate taken back into its period, one within
/// inDomain's rounding of an end onto that end.
glm::dvec3 surfacePoint(const Component& c, glm::dvec2 uw) {
    const geom::curvemap::SurfaceDomain d = geom::curvemap::surfaceDomain(c.surface, c.closedU, c.closedW);
    const glm::dvec2 q = glm::clamp(d.wrap(uw), glm::dvec2(d.u0, d.w0), glm::dvec2(d.u1, d.w1));
    return geom::evaluate(c.surface, q.x, q.y);
}

MappingRecord readMapping(Reader& r, const std::vector<std::string>& head, const Model& model,
                          std::size_t& vertices) {
    MappingRecord m;
    m.model = model.name;
    m.curveFile = head.at(1);
    m.component = r.name(head.at(2));
    if (!model.find(m.component)) r.fail("no component " + m.component + " in the model");
    const auto ref = r.line("reference", 5);
    m.reference.component = int(r.count(ref[1], model.components.size() - 1));
    const Component& referenced = model.components[std::size_t(m.reference.component)];
    // Patches count from 1; 0 is a mapping with no reference point (one an IGES or STEP file
    // brought in: the loops, not how they were placed).
    m.reference.patch = int(r.count(ref[2], referenced.patches.size()));
    m.reference.u = r.real(ref[3]);
    m.reference.w = r.real(ref[4]);
    if (m.reference.patch > 0 && !inDomain(referenced, {m.reference.u, m.reference.w}, false))
        r.fail("the reference point (" + ref[3] + ", " + ref[4] + ") is outside " + referenced.name +
               "'s parameter domain");
    const Component& mapped = *model.find(m.component);
    if (m.reference.patch > 0) {
        // DEFINE POINT places the curve on the component it maps onto, in the patch it names.
        if (&referenced != &mapped)
            r.fail("the reference point is on " + referenced.name + ", the mapping on " + mapped.name);
        const Patch& p = referenced.patches.patches[std::size_t(m.reference.patch - 1)];
        const double slack = 1e-9 * (1.0 + std::abs(p.u1 - p.u0) + std::abs(p.w1 - p.w0));
        if (!(m.reference.u >= p.u0 - slack && m.reference.u <= p.u1 + slack &&
              m.reference.w >= p.w0 - slack && m.reference.w <= p.w1 + slack))
            r.fail("the reference point (" + ref[3] + ", " + ref[4] + ") is outside patch " + ref[2] +
                   " of " + referenced.name);
    }
    const double onSurface = kOnSurface * std::max(1.0, geom::boundingBox(mapped.surface).diagonal());
    const auto parts = r.line("parts", 2);
    m.parts = r.count(parts[1], 1u << 16);
    for (std::size_t i = 0; i < m.parts; ++i) {
        const auto p = r.lineWithText("part", 5);  // and the reason, when there is one
        PartReport report;
        report.name = p[1];
        if (p[2] == "MAPPED")
            report.outcome = PartOutcome::Mapped;
        else if (p[2] == "CLIPPED")
            report.outcome = PartOutcome::Clipped;
        else if (p[2] == "LOST")
            report.outcome = PartOutcome::Lost;
        else
            r.fail("unknown part outcome '" + p[2] + "'");
        report.loops = r.count(p[3], 1u << 20);
        report.boundaryWalks = r.count(p[4], 1u << 20);
        for (std::size_t k = 5; k < p.size(); ++k) report.reason += (k > 5 ? " " : "") + p[k];
        m.loopsPerPart.push_back(report.loops);
        m.loops += report.loops;
        m.boundaryWalks += report.boundaryWalks;
        m.partReports.push_back(std::move(report));
    }
    for (std::size_t l = 0; l < m.loops; ++l) {
        const auto loop = r.line("loop", 2);
        const std::size_t n = r.count(loop[1], kModelStateMaxVertices);
        if ((vertices += n) > kModelStateMaxVertices)
            r.fail("more than " + std::to_string(kModelStateMaxVertices) + " mapped vertices");
        std::vector<glm::dvec2> uv;
        std::vector<glm::dvec3> xyz;
        for (std::size_t i = 0; i < n; ++i) {
            const auto v = r.lineWithText("v", 1);
            if (v.size() != 6) r.fail("a loop vertex has u w x y z");
            uv.push_back({r.real(v[1]), r.real(v[2])});
            if (!inDomain(mapped, uv.back(), true))
                r.fail("the loop vertex (" + v[1] + ", " + v[2] + ") is outside " + mapped.name +
                       "'s parameter domain");
            xyz.push_back({r.coordinate(v[3]), r.coordinate(v[4]), r.coordinate(v[5])});
            if (!(glm::length(xyz.back() - surfacePoint(mapped, uv.back())) <= onSurface))
                r.fail("the loop vertex (" + v[3] + ", " + v[4] + ", " + v[5] + ") is not on " + mapped.name +
                       " at (" + v[1] + ", " + v[2] + ")");
        }
        m.uvPolylines.push_back(std::move(uv));
        m.polylines.push_back(std::move(xyz));
    }
    r.line("end");
    return m;
}

}  // namespace

void writeModelState(std::ostream& out, const Model& model, const std::vector<MappingRecord>& mappings) {
    out << "acsynt-surfaces " << modelStateVersion << "\n";
    out << "# " << model.name << ": B-spline surfaces and mapped curves, numbers in C99 hexadecimal\n";
    out << "model " << model.name << " " << model.components.size() << "\n";
    for (const Component& c : model.components) {
        const geom::Surface& s = c.surface;
        out << "component " << c.name << " " << kindKeyword(c.kind) << " " << c.closedU << " " << c.closedW
            << "\n";
        out << "colour " << hex(c.colour.x) << " " << hex(c.colour.y) << " " << hex(c.colour.z) << "\n";
        out << "surface " << s.degreeU << " " << s.degreeV << " " << s.countU << " " << s.countV << " "
            << s.rational() << "\n";
        writeVector(out, "knots_u", s.knotsU);
        writeVector(out, "knots_w", s.knotsV);
        for (std::size_t i = 0; i < s.points.size(); ++i) {
            out << "p " << hex(s.points[i].x) << " " << hex(s.points[i].y) << " " << hex(s.points[i].z);
            if (s.rational()) out << " " << hex(s.weights[i]);
            out << "\n";
        }
    }
    for (const MappingRecord& m : mappings) {
        if (m.model != model.name) continue;
        std::string file = m.curveFile;
        for (char& ch : file)
            if (ch == ' ' || ch == '\t' || ch == '\n' || ch == '\r') ch = '_';
        out << "mapping " << (file.empty() ? "-" : file) << " " << m.component << "\n";
        out << "reference " << m.reference.component << " " << m.reference.patch << " " << hex(m.reference.u)
            << " " << hex(m.reference.w) << "\n";
        out << "parts " << m.partReports.size() << "\n";
        for (const PartReport& p : m.partReports) {
            std::string reason = p.reason;
            for (char& ch : reason)
                if (ch == '\n' || ch == '\r') ch = ' ';
            std::string name = p.name.empty() ? std::string("-") : p.name;
            for (char& ch : name)
                if (ch == ' ' || ch == '\t' || ch == '\n' || ch == '\r') ch = '_';
            out << "part " << name << " " << outcomeName(p.outcome) << " " << p.loops << " "
                << p.boundaryWalks << (reason.empty() ? "" : " ") << reason << "\n";
        }
        for (std::size_t l = 0; l < m.polylines.size(); ++l) {
            out << "loop " << m.polylines[l].size() << "\n";
            for (std::size_t i = 0; i < m.polylines[l].size(); ++i) {
                const glm::dvec2 uv = m.uvPolylines[l][i];
                const glm::dvec3 p = m.polylines[l][i];
                out << "v " << hex(uv.x) << " " << hex(uv.y) << " " << hex(p.x) << " " << hex(p.y) << " "
                    << hex(p.z) << "\n";
            }
        }
        out << "end\n";
    }
    out << "end\n";
}

bool isModelStateFile(const std::filesystem::path& path) {
    std::error_code ec;
    if (!std::filesystem::is_regular_file(path, ec)) return false;
    std::ifstream in(path);
    std::string first;
    return in && readTextLine(in, first) && first.rfind("acsynt-surfaces", 0) == 0;
}

ModelState parseModelState(std::istream& in, const std::string& fileName) {
    Reader r(in, fileName);
    const auto heading = r.line("acsynt-surfaces", 2);
    if (heading[1] != std::to_string(modelStateVersion))
        r.fail("version " + heading[1] + " is not " + std::to_string(modelStateVersion));
    ModelState state;
    const auto model = r.line("model", 3);
    state.model.name = r.name(model[1]);
    state.model.sourceFile = fileName;
    // The limits of every other way in (READ MODEL, IMPORT): a file the session writes reads back
    // and exports, and a model with nothing to view is never made.
    const std::size_t components = r.count(model[2], kModelMaxComponents);
    if (components == 0) r.fail("a model has at least one component");
    std::size_t points = 0, patches = 0, vertices = 0;
    for (std::size_t i = 0; i < components; ++i) {
        Component c = readComponent(r, points, patches);
        if (state.model.find(c.name)) r.fail("a second component named " + c.name);
        state.model.components.push_back(std::move(c));
    }
    if (state.model.patchCount() > kModelMaxPatches)
        r.fail("more than " + std::to_string(kModelMaxPatches) + " patches");
    for (auto words = r.next();; words = r.next()) {
        if (words.empty()) r.fail("the file ends before 'end'");
        if (words[0] == "end") {
            if (words.size() != 1) r.fail("'end' takes no values");
            break;
        }
        if (words[0] != "mapping" || words.size() != 3) r.fail("expected 'mapping CURVE COMPONENT' or 'end'");
        state.mappings.push_back(readMapping(r, words, state.model, vertices));
    }
    if (const auto after = r.next(); !after.empty()) r.fail("'" + after[0] + "' after the model's 'end'");
    return state;
}

ModelState readModelState(const std::filesystem::path& path) {
    requireRegularFile(path);
    std::ifstream in(path);
    if (!in) throw ModelFileError(path.string(), 0, "cannot be opened");
    return parseModelState(in, path.string());
}

}  // namespace acsynt
