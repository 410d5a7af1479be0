#include "CadDocument.h"

#include <Quantity_Color.hxx>
#include <TDF_LabelSequence.hxx>
#include <TDataStd_Name.hxx>
#include <TopExp_Explorer.hxx>
#include <TopLoc_Location.hxx>
#include <XCAFDoc_ColorTool.hxx>
#include <XCAFDoc_DocumentTool.hxx>
#include <XCAFDoc_ShapeTool.hxx>

namespace geom::exchange {

namespace {

std::string nameOf(const TDF_Label& label) {
    opencascade::handle<TDataStd_Name> name;
    if (!label.FindAttribute(TDataStd_Name::GetID(), name)) return {};
    return TCollection_AsciiString(name->Get()).ToCString();
}

std::optional<glm::dvec3> colourOf(const opencascade::handle<XCAFDoc_ColorTool>& colours,
                                   const TDF_Label& label, const TopoDS_Shape& shape) {
    Quantity_Color c;
    bool found =
        colours->GetColor(label, XCAFDoc_ColorSurf, c) || colours->GetColor(label, XCAFDoc_ColorGen, c);
    // The IGES reader colours the faces rather than their group.
    for (TopExp_Explorer f(shape, TopAbs_FACE); !found && f.More(); f.Next())
        found = colours->GetColor(f.Current(), XCAFDoc_ColorSurf, c) ||
                colours->GetColor(f.Current(), XCAFDoc_ColorGen, c);
    if (!found) return std::nullopt;
    // The files' numbers are sRGB (OpenCASCADE keeps linear RGB inside), as our colours are:
    // display values, drawn as they are.
    double r = 0, g = 0, b = 0;
    c.Values(r, g, b, Quantity_TOC_sRGB);
    return glm::dvec3(r, g, b);
}

/// The leaves under `label` (an assembly or a part), placed by `location`.
void collect(const opencascade::handle<XCAFDoc_ShapeTool>& shapes,
             const opencascade::handle<XCAFDoc_ColorTool>& colours, const TDF_Label& label,
             const TopLoc_Location& location, std::vector<NamedShape>& parts, int depth) {
    if (depth > 64) return;  // a cyclic or absurdly deep assembly
    if (shapes->IsAssembly(label)) {
        TDF_LabelSequence components;
        XCAFDoc_ShapeTool::GetComponents(label, components);
        for (int i = 1; i <= components.Length(); ++i) {
            const TDF_Label& component = components.Value(i);
            TDF_Label referred;
            if (!XCAFDoc_ShapeTool::GetReferredShape(component, referred)) continue;
            collect(shapes, colours, referred, location * XCAFDoc_ShapeTool::GetLocation(component), parts,
                    depth + 1);
        }
        return;
    }
    const TopoDS_Shape shape = XCAFDoc_ShapeTool::GetShape(label);
    if (shape.IsNull()) return;
    parts.push_back({nameOf(label), location.IsIdentity() ? shape : shape.Moved(location),
                     colourOf(colours, label, shape)});
}

}  // namespace

void fillDocument(const opencascade::handle<TDocStd_Document>& document, const std::string& modelName,
                  const std::vector<NamedShape>& parts, CadFormat format) {
    const opencascade::handle<XCAFDoc_ShapeTool> shapes = XCAFDoc_DocumentTool::ShapeTool(document->Main());
    const opencascade::handle<XCAFDoc_ColorTool> colours = XCAFDoc_DocumentTool::ColorTool(document->Main());
    TDF_Label root;
    if (format == CadFormat::Step) {
        root = shapes->NewShape();
        TDataStd_Name::Set(root, modelName.c_str());
    }
    for (const NamedShape& part : parts) {
        const TDF_Label label = shapes->AddShape(part.shape, false);
        TDataStd_Name::Set(label, part.name.c_str());
        if (part.colour)
            colours->SetColor(
                label, Quantity_Color(part.colour->x, part.colour->y, part.colour->z, Quantity_TOC_sRGB),
                XCAFDoc_ColorSurf);
        if (format == CadFormat::Step) shapes->AddComponent(root, label, TopLoc_Location());
    }
    if (format == CadFormat::Step) shapes->UpdateAssemblies();
}

std::vector<NamedShape> documentParts(const opencascade::handle<TDocStd_Document>& document,
                                      std::string& modelName) {
    const opencascade::handle<XCAFDoc_ShapeTool> shapes = XCAFDoc_DocumentTool::ShapeTool(document->Main());
    const opencascade::handle<XCAFDoc_ColorTool> colours = XCAFDoc_DocumentTool::ColorTool(document->Main());
    TDF_LabelSequence free;
    shapes->GetFreeShapes(free);
    if (free.Length() == 1 && shapes->IsAssembly(free.First())) modelName = nameOf(free.First());
    std::vector<NamedShape> parts;
    for (int i = 1; i <= free.Length(); ++i)
        collect(shapes, colours, free.Value(i), TopLoc_Location(), parts, 0);
    return parts;
}

}  // namespace geom::exchange
