#pragma once
// Entities of a file read by OpenCASCADE, named as a user finds them (private to geom_exchange).

#include <Interface_InterfaceModel.hxx>
#include <TopoDS_Shape.hxx>
#include <XSControl_WorkSession.hxx>

#include <cstddef>
#include <map>
#include <string>
#include <vector>

namespace geom::exchange {

/// How a user finds the entity in its file: "#76" (STEP) or "DE 59" (IGES, its directory entry).
std::string entityLabel(const opencascade::handle<Interface_InterfaceModel>& model,
                        const opencascade::handle<Standard_Transient>& entity);

/// The faces of a read: which entity each transferred face came from, and the faces of the file
/// that OpenCASCADE did not transfer at all (an invalid surface: decreasing knots, degree 0, ...).
struct FileFaces {
    std::map<const void*, std::string> labels;  ///< by the face's TopoDS_TShape
    std::vector<std::string> lost;              ///< "LABEL: a face left out: CAUSE", one a face

    /// The label of a face read, or "" where it is not known.
    std::string labelOf(const TopoDS_Shape& face) const;
};

/// The faces of the session's file after its transfer: a face is a STEP face entity, or an IGES
/// trimmed (144), bounded (143) or solid (510) face, or an IGES surface no face or curve on a
/// surface refers to. A face not transferred is lost, with the first failure OpenCASCADE noted
/// on it or on what it refers to (for a STEP B-spline surface, which rule it breaks).
FileFaces fileFaces(const opencascade::handle<XSControl_WorkSession>& session);

}  // namespace geom::exchange
