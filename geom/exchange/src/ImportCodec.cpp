#include "ImportCodec.h"

#include <cstdint>
#include <cstring>
#include <stdexcept>

namespace geom::exchange {

namespace {

/// Appends plain values, sizes and strings.
struct Encoder {
    std::string bytes;

    template <class T>
    void put(const T& value) {
        bytes.append(reinterpret_cast<const char*>(&value), sizeof value);
    }
    void size(std::size_t n) { put(std::uint64_t(n)); }
    void text(const std::string& s) {
        size(s.size());
        bytes += s;
    }
    template <class T>
    void values(const std::vector<T>& v) {
        size(v.size());
        if (!v.empty()) bytes.append(reinterpret_cast<const char*>(v.data()), v.size() * sizeof(T));
    }
};

/// Reads them back in the same order, checking every length against what is left.
struct Decoder {
    const std::string& bytes;
    std::size_t at = 0;

    void need(std::size_t n) const {
        if (n > bytes.size() - at) throw std::runtime_error("the reader's answer is cut short");
    }
    template <class T>
    T get() {
        need(sizeof(T));
        T value;
        std::memcpy(&value, bytes.data() + at, sizeof value);
        at += sizeof value;
        return value;
    }
    std::size_t size() { return std::size_t(get<std::uint64_t>()); }
    /// A count of things of at least 8 bytes each (so a bad count cannot ask for more memory).
    std::size_t count() {
        const std::size_t n = size();
        if (n > (bytes.size() - at) / 8) throw std::runtime_error("the reader's answer is cut short");
        return n;
    }
    std::string text() {
        const std::size_t n = size();
        need(n);
        std::string s = bytes.substr(at, n);
        at += n;
        return s;
    }
    template <class T>
    std::vector<T> values() {
        const std::size_t n = size();
        if (n > (bytes.size() - at) / sizeof(T)) throw std::runtime_error("the reader's answer is cut short");
        std::vector<T> v(n);
        if (n > 0) std::memcpy(v.data(), bytes.data() + at, n * sizeof(T));
        at += n * sizeof(T);
        return v;
    }
};

void encodeSurface(Encoder& e, const CadSurface& s) {
    e.text(s.name);
    e.put(s.surface.degreeU);
    e.put(s.surface.degreeV);
    e.size(s.surface.countU);
    e.size(s.surface.countV);
    e.values(s.surface.knotsU);
    e.values(s.surface.knotsV);
    e.values(s.surface.points);
    e.values(s.surface.weights);
    e.put(char(s.colour.has_value()));
    e.put(s.colour.value_or(glm::dvec3(0)));
    e.size(s.curves.size());
    for (const SurfaceCurves& c : s.curves) {
        e.text(c.name);
        e.size(c.loops.size());
        for (const SurfaceLoop& l : c.loops) {
            e.values(l.uv);
            e.values(l.points);
        }
    }
}

CadSurface decodeSurface(Decoder& d) {
    CadSurface s;
    s.name = d.text();
    const int degreeU = d.get<int>(), degreeV = d.get<int>();
    const std::size_t countU = d.size(), countV = d.size();
    auto knotsU = d.values<double>(), knotsV = d.values<double>();
    auto points = d.values<glm::dvec3>();
    auto weights = d.values<double>();
    s.surface = Surface(degreeU, degreeV, std::move(knotsU), std::move(knotsV), countU, countV,
                        std::move(points), std::move(weights));
    const bool coloured = d.get<char>() != 0;
    const glm::dvec3 colour = d.get<glm::dvec3>();
    if (coloured) s.colour = colour;
    s.curves.resize(d.count());
    for (SurfaceCurves& c : s.curves) {
        c.name = d.text();
        c.loops.resize(d.count());
        for (SurfaceLoop& l : c.loops) {
            l.uv = d.values<glm::dvec2>();
            l.points = d.values<glm::dvec3>();
        }
    }
    return s;
}

}  // namespace

std::string encodeImport(const CadImport& import) {
    Encoder e;
    e.text(import.model.name);
    e.text(import.model.unit);
    e.text(import.fileUnit);
    e.size(import.warnings.size());
    for (const auto& w : import.warnings) e.text(w);
    e.size(import.model.surfaces.size());
    for (const auto& s : import.model.surfaces) encodeSurface(e, s);
    return std::move(e.bytes);
}

CadImport decodeImport(const std::string& bytes) {
    Decoder d{bytes};
    CadImport import;
    import.model.name = d.text();
    import.model.unit = d.text();
    import.fileUnit = d.text();
    const std::size_t warnings = d.count();
    for (std::size_t i = 0; i < warnings; ++i) import.warnings.push_back(d.text());
    const std::size_t surfaces = d.count();
    for (std::size_t i = 0; i < surfaces; ++i) import.model.surfaces.push_back(decodeSurface(d));
    if (d.at != bytes.size()) throw std::runtime_error("the reader's answer has bytes left over");
    return import;
}

}  // namespace geom::exchange
