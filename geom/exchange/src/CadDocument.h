#pragma once
// The XCAF document between a CadModel and a file (private to geom_exchange).

#include "geom/exchange/CadFile.h"

#include <TDocStd_Document.hxx>
#include <TopoDS_Shape.hxx>

#include <glm/vec3.hpp>

#include <optional>
#include <string>
#include <vector>

namespace geom::exchange {

/// One named part of a model: a surface's patch faces or a curve set's trimmed faces.
struct NamedShape {
    std::string name;
    TopoDS_Shape shape;
    std::optional<glm::dvec3> colour;
};

/// Fills an empty document: for STEP an assembly named `modelName` with one part per shape (the
/// products); for IGES the parts as free shapes (the writer makes each a named group).
void fillDocument(const opencascade::handle<TDocStd_Document>& document, const std::string& modelName,
                  const std::vector<NamedShape>& parts, CadFormat format);

/// A read document's parts: the leaves of its assemblies (their product names, locations
/// applied) or its free shapes; `modelName` is the name of a single free assembly, if any.
std::vector<NamedShape> documentParts(const opencascade::handle<TDocStd_Document>& document,
                                      std::string& modelName);

}  // namespace geom::exchange
