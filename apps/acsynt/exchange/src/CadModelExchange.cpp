#include "acsynt/exchange/CadModelExchange.h"

#include "acsynt/ModelFile.h"
#include "geom/GeometryError.h"
#include "geom/exchange/Bicubic.h"
#include "geom/exchange/CadFile.h"
#include "geom/exchange/ExchangeError.h"
#include "geom/exchange/OcctConversion.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cctype>
#include <set>
#include <sstream>

namespace acsynt {

namespace {

/// A valid model or component name (1 to 20 of letters, digits, '_', '-', '.') from any text,
/// made unique among `taken`.
std::string validName(const std::string& text, std::set<std::string>& taken, const std::string& fallback) {
    std::string name;
    for (char c : text)
        if (name.size() < 20)
            name += std::isalnum((unsigned char)c) || c == '_' || c == '-' || c == '.' ? c : '_';
    if (name.empty()) name = fallback;
    const std::string stem = name.substr(0, 16);
    for (int k = 2; taken.count(name); ++k) name = stem + "_" + std::to_string(k);
    taken.insert(name);
    return name;
}

/// A curve file's name as the exchange files keep it (printable ASCII, no space at an end): each
/// other character, a UTF-8 sequence counted as one, becomes '_'. A mapping keeps any name its
/// file has, and exporting its model must not fail on it.
std::string writableName(const std::string& text) {
    std::string name;
    bool inSequence = false;  // after a UTF-8 lead byte
    for (unsigned char c : text) {
        const bool continuation = c >= 0x80 && c < 0xC0;
        if (!(continuation && inSequence)) name += c < 0x20 || c >= 0x7F ? '_' : char(c);
        inSequence = c >= 0xC0 || (continuation && inSequence);
    }
    const std::size_t first = name.find_first_not_of(' '), last = name.find_last_not_of(' ');
    return first == std::string::npos ? "curve" : name.substr(first, last - first + 1);
}

ComponentKind kindFromName(const std::string& name, bool closed) {
    auto has = [&](const char* word) { return name.find(word) != std::string::npos; };
    if (has("fuselage") || has("body")) return ComponentKind::Fuselage;
    if (has("htail") || has("stab")) return ComponentKind::HorizontalTail;
    if (has("fin") || has("vtail")) return ComponentKind::VerticalTail;
    if (has("engine") || has("nacelle")) return ComponentKind::Nacelle;
    if (has("wing")) return ComponentKind::Wing;
    return closed ? ComponentKind::Fuselage : ComponentKind::Wing;
}

std::size_t spans(const std::vector<double>& knots, int degree, std::size_t count) {
    std::size_t n = 0;
    for (std::size_t k = std::size_t(degree); k < count; ++k) n += knots[k] < knots[k + 1];
    return n;
}

/// Whether the surface closes on itself across its u (alongV false) or w boundaries: periodic, or
/// clamped with the first and last rows of points the same and going on across that seam rather
/// than folding back (the rows beside it on either side less than 90 degrees apart). A reduced
/// fuselage is such a clamped closed surface; a wing's trailing edge folds back and stays open.
bool closedAcross(const geom::Surface& s, bool alongV) {
    if (geom::exchange::periodicByConstruction(s, alongV)) return true;
    const std::size_t rows = alongV ? s.countU : s.countV, n = alongV ? s.countV : s.countU;
    if (n < 3) return false;
    const auto at = [&](std::size_t row, std::size_t k) {
        return alongV ? s.points[row * s.countV + k] : s.points[k * s.countV + row];
    };
    double size = 0.0;
    for (const glm::dvec3& p : s.points) size = std::max(size, glm::length(p));
    const double same = 1e-9 * std::max(size, 1.0);
    for (std::size_t row = 0; row < rows; ++row) {
        if (glm::length(at(row, 0) - at(row, n - 1)) > same) return false;
        const glm::dvec3 after = at(row, 1) - at(row, 0), before = at(row, n - 1) - at(row, n - 2);
        // A row collapsed at the seam (a nose) says nothing of the direction.
        if (glm::length(after) > same && glm::length(before) > same && glm::dot(after, before) <= 0.0)
            return false;
    }
    return true;
}

/// One imported surface as a component; its curve sets become mappings of the model.
Component componentOf(const geom::exchange::CadSurface& s, const std::string& name, ImportedModel& result,
                      std::size_t& patches, const std::string& file) {
    Component c;
    c.name = name;
    c.colour = s.colour.value_or(glm::dvec3(1.0));
    const geom::exchange::BicubicSurface bicubic = geom::exchange::toBicubic(s.surface, kImportTolerance);
    if (!bicubic.exact) {
        std::ostringstream error;
        error.precision(3);
        error << bicubic.maxError;  // to_string's fixed six decimals read 1e-6 m as 0.000001
        result.warnings.push_back(name + ": a " + (s.surface.rational() ? "rational" : "higher-degree") +
                                  " surface made bicubic within " + error.str() + " m");
    }
    c.surface = bicubic.surface;
    c.closedU = closedAcross(c.surface, false);
    c.closedW = closedAcross(c.surface, true);
    c.kind = kindFromName(name, c.closedW);
    patches += spans(c.surface.knotsU, 3, c.surface.countU) * spans(c.surface.knotsV, 3, c.surface.countV);
    if (patches > kModelMaxPatches)
        throw geom::exchange::ExchangeError(file, "more than " + std::to_string(kModelMaxPatches) +
                                                      " patches: the program's limit for a model");
    c.updatePatches();
    return c;
}

MappingRecord mappingOf(const geom::exchange::SurfaceCurves& curves, const Model& model, int component) {
    MappingRecord m;
    m.model = model.name;
    m.component = model.components[std::size_t(component)].name;
    m.curveFile = curves.name;
    m.reference.component = component;
    m.parts = 1;  // how the loops grouped into parts is not in the file
    m.loops = curves.loops.size();
    m.loopsPerPart = {m.loops};
    // One part holding every loop, so that SAVE_MODEL writes (and READ_MODEL reads) them.
    PartReport part;
    part.name = curves.name;
    part.outcome = PartOutcome::Mapped;
    part.loops = m.loops;
    m.partReports.push_back(std::move(part));
    for (const auto& loop : curves.loops) {
        m.polylines.push_back(loop.points);
        m.uvPolylines.push_back(loop.uv);
    }
    return m;
}

}  // namespace

geom::exchange::CadModel cadModelOf(const Model& model, const std::vector<MappingRecord>& mappings) {
    geom::exchange::CadModel cad;
    cad.name = model.name;
    cad.unit = "M";
    for (const Component& c : model.components) {
        geom::exchange::CadSurface s{c.name, c.surface, c.colour, {}};
        for (const MappingRecord& m : mappings) {
            if (m.model != model.name || m.component != c.name) continue;
            geom::exchange::SurfaceCurves curves{writableName(m.curveFile), {}};
            for (std::size_t l = 0; l < m.polylines.size() && l < m.uvPolylines.size(); ++l)
                curves.loops.push_back({m.uvPolylines[l], m.polylines[l]});
            s.curves.push_back(std::move(curves));
        }
        cad.surfaces.push_back(std::move(s));
    }
    return cad;
}

ImportedModel importCadModel(const std::filesystem::path& path) {
    const std::string file = path.string();
    geom::exchange::CadReadOptions options;
    options.unit = "M";
    geom::exchange::CadImport read = geom::exchange::readCadFile(path, options);
    if (read.model.surfaces.size() > kModelMaxComponents)
        throw geom::exchange::ExchangeError(
            file, std::to_string(read.model.surfaces.size()) + " surfaces: more than the " +
                      std::to_string(kModelMaxComponents) + " components a model may have");
    ImportedModel result;
    result.warnings = std::move(read.warnings);
    std::set<std::string> modelNames, names;
    Model& model = result.model;
    model.name = validName(read.model.name, modelNames, "imported");
    model.description.name = model.name;
    model.sourceFile = file;
    std::size_t patches = 0;
    try {
        for (std::size_t i = 0; i < read.model.surfaces.size(); ++i) {
            const auto& s = read.model.surfaces[i];
            model.components.push_back(componentOf(
                s, validName(s.name, names, "surface_" + std::to_string(i + 1)), result, patches, file));
            for (const auto& curves : s.curves) result.mappings.push_back(mappingOf(curves, model, int(i)));
        }
    } catch (const geom::GeometryError& e) {
        throw geom::exchange::ExchangeError(file,
                                            std::string("a surface the program cannot take: ") + e.what());
    }
    return result;
}

namespace {

std::size_t exportModel(const Model& model, const std::vector<MappingRecord>& mappings,
                        const std::filesystem::path& path) {
    const geom::exchange::CadModel cad = cadModelOf(model, mappings);
    geom::exchange::writeCadFile(cad, path);
    std::size_t curves = 0;
    for (const auto& s : cad.surfaces) curves += s.curves.size();
    return curves;
}

void checkFileName(const std::filesystem::path& path) {
    geom::exchange::cadFormatOf(path);
}

}  // namespace

}  // namespace acsynt

extern "C" __attribute__((visibility("default"))) const acsynt::ExchangeCalls* acsynt_exchange_calls() {
    static const acsynt::ExchangeCalls calls{&acsynt::importCadModel, &acsynt::exportModel,
                                             &acsynt::checkFileName};
    return &calls;
}
