#pragma once
// An XCAF document's shapes, names and colours as an IGES model (private to geom_exchange).

#include <IGESCAFControl_Writer.hxx>
#include <TDocStd_Document.hxx>
#include <TopoDS_Shape.hxx>

namespace geom::exchange {

/// OpenCASCADE's IGES writer without its shape processing: the faces written are B-spline
/// surfaces already, which the processing (DirectFaces) leaves as they are, while its record of
/// each face walks the whole shape (time in the square of a component's patches). Faces only
/// (type 144 on 128), whatever write.iges.brep.mode says.
class IgesDocumentWriter : public IGESCAFControl_Writer {
public:
    /// The document's free shapes, then their colours, layers and names, as `Transfer` does;
    /// false where a shape does not translate (`Transfer` would leave it out of the file).
    bool transferDocument(const opencascade::handle<TDocStd_Document>& document);

private:
    /// One shape's entities added to the model, with the global section's resolution and
    /// extent updated as `AddShape` updates them.
    bool addUnprocessed(const TopoDS_Shape& shape);
};

}  // namespace geom::exchange
