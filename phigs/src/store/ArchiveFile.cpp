#include "phigs/store/ArchiveFile.h"

#include <charconv>
#include <cstdio>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <system_error>

namespace phigs {

namespace {

// ---- one list of fields per payload, shared by the writer and the reader. The leading type
// token already says 2D / 3D, add / remove and which tagged attribute, so those are not fields.
template <class V>
void fields(V& v, PolylineElement& e) {
    v(e.points);
}
template <class V>
void fields(V& v, PolymarkerElement& e) {
    v(e.points);
}
template <class V>
void fields(V& v, FillAreaElement& e) {
    v(e.points);
}
template <class V>
void fields(V& v, FillAreaSetElement& e) {
    v(e.contours);
}
template <class V>
void fields(V& v, TextElement& e) {
    v(e.position), v(e.direction1), v(e.direction2), v(e.text);
}
template <class V>
void fields(V& v, AnnotationTextElement& e) {
    v(e.reference), v(e.offset), v(e.text);
}
template <class V>
void fields(V& v, CellArrayElement& e) {
    v(e.p), v(e.q), v(e.r), v(e.columns), v(e.rows), v(e.colourIndices);
}
template <class V>
void fields(V& v, NurbsCurveElement& e) {
    v(e.curve), v(e.rangeStart), v(e.rangeEnd);
}
template <class V>
void fields(V& v, NurbsSurfaceElement& e) {
    v(e.surface), v(e.trimLoops);
}
template <class V>
void fields(V& v, FillAreaSetWithDataElement& e) {
    v(e.contours), v(e.vertexColours), v(e.vertexNormals), v(e.hasFacetColour), v(e.facetColour),
        v(e.hasFacetNormal), v(e.facetNormal);
}
template <class V>
void fields(V& v, TriangleStripElement& e) {
    v(e.points), v(e.vertexColours), v(e.vertexNormals);
}
template <class V>
void fields(V& v, QuadrilateralMeshElement& e) {
    v(e.rows), v(e.columns), v(e.points), v(e.vertexColours), v(e.vertexNormals);
}
template <class V>
void fields(V& v, IndexAttribute& e) {
    v(e.value);
}
template <class V>
void fields(V& v, RealAttribute& e) {
    v(e.value);
}
template <class V>
void fields(V& v, ColourAttribute& e) {
    v(e.colour);
}
template <class V>
void fields(V& v, UpVectorAttribute& e) {
    v(e.up);
}
template <class V>
void fields(V& v, AlignmentAttribute& e) {
    v(e.horizontal), v(e.vertical);
}
template <class V>
void fields(V& v, AreaPropertiesAttribute& e) {
    v(e.ambient), v(e.diffuse), v(e.specular), v(e.specularColour), v(e.specularExponent), v(e.transparency);
}
template <class V>
void fields(V& v, AsfAttribute& e) {
    v(e.aspect), v(e.individual);
}
template <class V>
void fields(V& v, ApproximationAttribute& e) {
    v(e.criteria), v(e.valueU), v(e.valueV);
}
template <class V>
void fields(V& v, SurfaceCharacteristicsAttribute& e) {
    v(e.style), v(e.placement), v(e.curvesU), v(e.curvesV);
}
template <class V>
void fields(V& v, LightSourceStateAttribute& e) {
    v(e.activate), v(e.deactivate);
}
template <class V>
void fields(V& v, TransformElement& e) {
    v(e.matrix), v(e.composition);
}
template <class V>
void fields(V& v, ModelClipElement& e) {
    v(e.op), v(e.halfSpaces);
}
template <class V>
void fields(V&, RestoreModelClipElement&) {
}
template <class V>
void fields(V& v, NameSetElement& e) {
    v(e.names);
}
template <class V>
void fields(V& v, ExecuteStructureElement& e) {
    v(e.structureId);
}
template <class V>
void fields(V& v, LabelElement& e) {
    v(e.label);
}
template <class V>
void fields(V& v, ApplicationDataElement& e) {
    v(e.data);
}

std::string typeToken(ElementType t) {
    std::string name(elementTypeName(t));
    for (char& c : name)
        if (c == ' ') c = '_';
    return name;
}

struct Writer {
    std::string& out;
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
        if (c.direct)
            out += "D", (*this)(c.rgb);
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
    template <class A, class B>
    void operator()(const std::pair<A, B>& p) {
        (*this)(p.first), (*this)(p.second);
    }
    template <class T>
    void operator()(const std::vector<T>& list) {
        (*this)(list.size());
        for (const T& item : list) (*this)(item);
    }
};

/// A token reader over the whole text that knows its line, so errors can say where.
struct Reader {
    const std::string& text;
    std::size_t at = 0;
    int line = 1;

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
            fail(std::string("bad ") + what + " '" + std::string(t) + "'");
        return value;
    }
    std::size_t count() {
        auto n = number<std::size_t>("count");
        if (n > text.size() - at) fail("list count " + std::to_string(n) + " exceeds the rest of the file");
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
        if (n > text.size() - colon - 1) fail("string runs past the end of the file (truncated archive)");
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
            c.direct = true, (*this)(c.rgb);
        else if (kind == "I")
            c.direct = false, (*this)(c.index);
        else
            fail("bad colour kind '" + std::string(kind) + "'");
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
    template <class A, class B>
    void operator()(std::pair<A, B>& p) {
        (*this)(p.first), (*this)(p.second);
    }
    template <class T>
    void operator()(std::vector<T>& list) {
        list.resize(count());
        for (T& item : list) (*this)(item);
    }
};

template <std::size_t... I>
Element makeAlternative(std::size_t index, std::index_sequence<I...>) {
    Element result;
    ((index == I ? (result.template emplace<I>(), 0) : 0), ...);
    return result;
}

Element decodeElement(Reader& in) {
    std::string name(in.token());
    for (char& c : name)
        if (c == '_') c = ' ';
    ElementType type = elementTypeFromName(name);
    int index = payloadIndexOf(type);
    if (index < 0) in.fail("unknown element type '" + name + "'");
    Element element = makeAlternative(static_cast<std::size_t>(index),
                                      std::make_index_sequence<std::variant_size_v<Element>>{});
    std::visit(
        [&](auto& e) {
            fields(in, e);
            if constexpr (requires { e.type; }) e.type = type;
            if constexpr (requires { e.twoD; })
                e.twoD = type == ElementType::Polyline || type == ElementType::Polymarker ||
                         type == ElementType::FillArea || type == ElementType::FillAreaSet ||
                         type == ElementType::Text || type == ElementType::AnnotationTextRelative ||
                         type == ElementType::CellArray || type == ElementType::ModelClippingVolume;
            if constexpr (requires { e.add; }) e.add = type == ElementType::AddNamesToSet;
        },
        element);
    if (elementType(element) != type) in.fail("element type '" + name + "' is not consistent");
    if (std::string reason = validateElement(element); !reason.empty()) in.fail(name + ": " + reason);
    return element;
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

}  // namespace

ArchiveFile::ArchiveFile(std::filesystem::path path, ErrorLog* log) : path_(std::move(path)), log_(log) {
    const char* function = "OPEN ARCHIVE FILE";
    std::error_code ec;
    if (!std::filesystem::exists(path_, ec)) {
        try {
            commit({}, {});
        } catch (const Error&) {
            raise(log_, errors::ArchiveCannotOpen, function, path_.string() + ": cannot be created");
        }
        return;
    }
    std::ifstream in(path_, std::ios::binary);
    if (!in) raise(log_, errors::ArchiveCannotOpen, function, path_.string() + ": cannot be read");
    std::stringstream buffer;
    buffer << in.rdbuf();
    contents_ = decode(buffer.str(), path_.string(), log_);
}

std::vector<int> ArchiveFile::structureIds() const {
    std::vector<int> ids;
    for (const auto& [id, e] : contents_) ids.push_back(id);
    return ids;
}

std::string ArchiveFile::encode(const std::map<int, std::vector<Element>>& contents) {
    std::string out = "PHIGS-ARCHIVE 1\n";
    Writer w{out};
    for (const auto& [id, elements] : contents) {
        out += "STRUCTURE";
        w(id), w(elements.size());
        out += '\n';
        for (const Element& element : elements) {
            out += typeToken(elementType(element));
            std::visit([&](const auto& e) { fields(w, const_cast<std::decay_t<decltype(e)>&>(e)); }, element);
            out += '\n';
        }
    }
    std::uint64_t checksum = fnv1a(out);
    out += "END " + std::to_string(contents.size()) + " " + hex(checksum) + "\n";
    return out;
}

std::map<int, std::vector<Element>> ArchiveFile::decode(const std::string& text,
                                                        const std::string& sourceName, ErrorLog* log) {
    Reader in{text};
    std::map<int, std::vector<Element>> contents;
    try {
        if (in.token() != "PHIGS-ARCHIVE") in.fail("not a PHIGS archive (no PHIGS-ARCHIVE header)");
        int version = in.number<int>("version");
        if (version != 1) in.fail("unsupported archive version " + std::to_string(version));
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
            if (keyword != "STRUCTURE")
                in.fail("expected STRUCTURE or END, found '" + std::string(keyword) + "'");
            int id = in.number<int>("structure id");
            if (contents.contains(id)) in.fail("structure " + std::to_string(id) + " appears twice");
            std::size_t n = in.count();
            std::vector<Element> elements;
            elements.reserve(n);
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
    std::string text = encode(next);
    std::filesystem::path temporary = path_;
    temporary += ".tmp";
    {
        std::ofstream out(temporary, std::ios::binary | std::ios::trunc);
        out.write(text.data(), static_cast<std::streamsize>(text.size()));
        out.flush();
        if (!out) {
            std::error_code ec;
            std::filesystem::remove(temporary, ec);
            raise(log_, errors::WriteError, "ARCHIVE STRUCTURES", temporary.string() + ": cannot be written");
        }
    }
    std::error_code ec;
    std::filesystem::rename(temporary, path_, ec);
    if (ec) {
        std::filesystem::remove(temporary, ec);
        raise(log_, errors::WriteError, "ARCHIVE STRUCTURES", path_.string() + ": cannot be replaced");
    }
    contents_ = std::move(next);
}

}  // namespace phigs
