#include "IgesDocumentWriter.h"

#include <BRepBndLib.hxx>
#include <BRepToIGES_BREntity.hxx>
#include <Bnd_Box.hxx>
#include <IGESData_GlobalSection.hxx>
#include <IGESData_IGESEntity.hxx>
#include <IGESData_IGESModel.hxx>
#include <Interface_Static.hxx>
#include <ShapeAnalysis_ShapeTolerance.hxx>
#include <TDF_LabelSequence.hxx>
#include <XCAFDoc_DocumentTool.hxx>
#include <XCAFDoc_ShapeTool.hxx>
#include <XSAlgo.hxx>
#include <XSAlgo_AlgoContainer.hxx>
#include <gp_XYZ.hxx>

#include <algorithm>

namespace geom::exchange {

bool IgesDocumentWriter::transferDocument(const opencascade::handle<TDocStd_Document>& document) {
    TDF_LabelSequence labels;
    XCAFDoc_DocumentTool::ShapeTool(document->Main())->GetFreeShapes(labels);
    if (labels.Length() <= 0) return false;
    prepareUnit(labels.First());
    for (int i = 1; i <= labels.Length(); ++i) {
        const TopoDS_Shape shape = XCAFDoc_ShapeTool::GetShape(labels.Value(i));
        if (!shape.IsNull() && !addUnprocessed(shape)) return false;
    }
    if (GetColorMode()) WriteAttributes(labels);
    if (GetLayerMode()) WriteLayers(labels);
    if (GetNameMode()) WriteNames(labels);
    ComputeModel();
    return true;
}

bool IgesDocumentWriter::addUnprocessed(const TopoDS_Shape& shape) {
    XSAlgo::AlgoContainer()->PrepareForTransfer();  // the length unit of shapes in memory
    BRepToIGES_BREntity translator;
    translator.SetTransferProcess(TransferProcess());
    translator.SetModel(Model());
    const opencascade::handle<IGESData_IGESEntity> entity = translator.TransferShape(shape);
    if (entity.IsNull()) return false;
    const int before = Model()->NbEntities();
    AddEntity(entity);
    const int after = Model()->NbEntities();

    // The resolution: the mean of the shapes' vertex and edge tolerances, weighted by their
    // entities (the writer's default precision mode), or the setting in mode 2.
    IGESData_GlobalSection header = Model()->GlobalSection();
    const int mode = Interface_Static::IVal("write.precision.mode");
    double resolution = Interface_Static::RVal("write.precision.val");
    if (mode != 2) {
        ShapeAnalysis_ShapeTolerance tolerances;
        const double vertex = tolerances.Tolerance(shape, mode, TopAbs_VERTEX);
        const double edge = tolerances.Tolerance(shape, mode, TopAbs_EDGE);
        const double old = header.Resolution();
        if (mode == 0)
            resolution = after > 0 ? (old * before + 0.5 * (vertex + edge) * (after - before)) / after : old;
        else if (mode < 0)
            resolution = before > 0 ? std::min(old, std::min(vertex, edge)) : std::min(vertex, edge);
        else
            resolution = before > 0 ? std::max(old, std::max(vertex, edge)) : std::max(vertex, edge);
    }
    header.SetResolution(resolution / header.UnitValue());
    Bnd_Box box;
    BRepBndLib::Add(shape, box);
    if (!box.IsVoid() && !box.IsOpen()) {
        double xMin = 0, yMin = 0, zMin = 0, xMax = 0, yMax = 0, zMax = 0;
        box.Get(xMin, yMin, zMin, xMax, yMax, zMax);
        header.MaxMaxCoords(gp_XYZ(xMax, yMax, zMax) / header.UnitValue());
        header.MaxMaxCoords(gp_XYZ(xMin, yMin, zMin) / header.UnitValue());
    }
    Model()->SetGlobalSection(header);
    return true;
}

}  // namespace geom::exchange
